"""RoMa's facts in stubs/, checked against the library where it installs (skipped where it does not:
it needs torch, which the dev extra does not install)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.knowledge.facts_helpers import (
    QUARTER_TURN_Z,
    _quarter_turn,
    _quaternion_parts,
    _same_rotation,
    _stated,
)

torch = pytest.importorskip("torch")
roma = pytest.importorskip("roma")


class TestRoma:
    torch = torch
    roma = roma

    def test_quaternions_are_read_and_returned_in_the_stated_order(self) -> None:
        order = _stated("roma.unitquat_to_rotmat", "unitquat_to_rotmat(q)", "quat")
        matrix = self.roma.unitquat_to_rotmat(self.torch.tensor(_quarter_turn(order), dtype=self.torch.float64))
        assert np.allclose(matrix.numpy(), QUARTER_TURN_Z)
        order = _stated("roma.rotmat_to_unitquat", "rotmat_to_unitquat(R)", "return")
        produced = self.roma.rotmat_to_unitquat(self.torch.tensor(QUARTER_TURN_Z)).numpy()
        assert _same_rotation(_quaternion_parts(produced, order), _quaternion_parts(_quarter_turn(order), order))  # type: ignore[arg-type]
        # the quaternion of unitquat_to_euler is its second argument
        order = _stated("roma.unitquat_to_euler", "unitquat_to_euler('xyz', q)", "quat")
        angles = self.roma.unitquat_to_euler("xyz", self.torch.tensor(_quarter_turn(order), dtype=self.torch.float64))
        assert np.allclose(angles.numpy(), [0.0, 0.0, math.pi / 2])

    @pytest.mark.parametrize(("call", "angle"), [("euler_to_rotmat('xyz', a)", math.pi / 2), ("euler_to_rotmat('xyz', a, degrees=True)", 90.0)])
    def test_euler_angles_are_read_in_the_stated_unit(self, call: str, angle: float) -> None:
        unit = _stated("roma.euler_to_rotmat", call, "angles", "angle_unit")
        assert unit == ("degrees" if "degrees=True" in call else "radians")
        matrix = self.roma.euler_to_rotmat("xyz", [0.0, 0.0, angle], degrees=unit == "degrees", dtype=self.torch.float64)
        assert np.allclose(matrix.numpy(), QUARTER_TURN_Z)

