"""pybullet's facts in stubs/, checked against pybullet where it installs (skipped where it does not: the
dev extra does not install it)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.knowledge.facts_helpers import QUARTER_TURN_Z, _quarter_turn, _quaternion_parts, _same_rotation, _stated

pybullet = pytest.importorskip("pybullet")


def test_quaternions_are_x_y_z_w_and_angles_radians() -> None:
    order = _stated("pybullet.getMatrixFromQuaternion", "getMatrixFromQuaternion(q)", "quaternion")
    assert np.allclose(np.array(pybullet.getMatrixFromQuaternion(_quarter_turn(order))).reshape(3, 3), QUARTER_TURN_Z)
    assert _stated("pybullet.getQuaternionFromEuler", "getQuaternionFromEuler(e)", "eulerAngles", "angle_unit") == "radians"
    order = _stated("pybullet.getQuaternionFromEuler", "getQuaternionFromEuler(e)", "return")
    produced = pybullet.getQuaternionFromEuler([0.0, 0.0, math.pi / 2])
    assert _same_rotation(_quaternion_parts(produced, order), _quaternion_parts(_quarter_turn(order), order))  # type: ignore[arg-type]
    assert np.allclose(pybullet.getEulerFromQuaternion(_quarter_turn(order)), [0.0, 0.0, math.pi / 2])


def test_a_client_forwards_to_the_module() -> None:
    from pybullet_utils import bullet_client

    client = bullet_client.BulletClient(connection_mode=pybullet.DIRECT)
    try:
        assert client.getQuaternionFromEuler([0.0, 0.0, math.pi / 2]) == pybullet.getQuaternionFromEuler([0.0, 0.0, math.pi / 2])
    finally:
        client.disconnect()
