"""Open3D's facts in stubs/, checked against the library where it installs (skipped where it does not:
its wheel is large and needs libusb)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.knowledge.facts_helpers import QUARTER_TURN_Z, _quarter_turn, _stated

geometry = pytest.importorskip("open3d.geometry")


class TestOpen3d:
    geometry = geometry

    def test_quaternion_and_euler_matrices(self) -> None:
        order = _stated("open3d.geometry.get_rotation_matrix_from_quaternion", "get_rotation_matrix_from_quaternion(q)", "rotation")
        assert np.allclose(self.geometry.get_rotation_matrix_from_quaternion(np.array(_quarter_turn(order))), QUARTER_TURN_Z)
        unit = _stated("open3d.geometry.get_rotation_matrix_from_xyz", "get_rotation_matrix_from_xyz(r)", "rotation", "angle_unit")
        assert unit == "radians"
        assert np.allclose(self.geometry.get_rotation_matrix_from_xyz(np.array([0.0, 0.0, math.pi / 2])), QUARTER_TURN_Z)

