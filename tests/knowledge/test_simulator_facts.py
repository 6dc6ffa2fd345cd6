"""MuJoCo's, pinocchio's and GTSAM's facts in stubs/, checked against the libraries where they install
(skipped where they do not: the dev extra installs none of them)."""

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


def test_mujoco_reads_quaternions_and_angles_as_stated() -> None:
    mujoco = pytest.importorskip("mujoco")
    order = _stated("mujoco.mju_quat2Mat", "mju_quat2Mat(res, q)", "quat")
    matrix = np.zeros(9)
    mujoco.mju_quat2Mat(matrix, np.array(_quarter_turn(order)))
    assert np.allclose(matrix.reshape(3, 3), QUARTER_TURN_Z)
    assert _stated("mujoco.mju_axisAngle2Quat", "mju_axisAngle2Quat(res, axis, angle)", "angle", "angle_unit") == "radians"
    quaternion = np.zeros(4)
    mujoco.mju_axisAngle2Quat(quaternion, np.array([0.0, 0.0, 1.0]), math.pi / 2)
    assert _same_rotation(_quaternion_parts(quaternion, order), _quaternion_parts(_quarter_turn(order), order))  # type: ignore[arg-type]


def test_mujoco_state_arrays_hold_quaternions_in_the_stated_order() -> None:
    mujoco = pytest.importorskip("mujoco")
    from geolint.knowledge import knowledge_base

    attributes = {
        name: knowledge_base().api(f"mujoco.{name}")
        for name in ("MjData.xquat", "MjModel.body_quat", "MjModel.geom_quat", "MjModel.site_quat", "MjModel.cam_quat")
    }
    assert all(api is not None and api.is_attribute for api in attributes.values())
    orders = {api.signatures[0].returns.quaternion_order for api in attributes.values()}  # type: ignore[union-attr]
    assert len(orders) == 1
    order = orders.pop()
    turn = " ".join(str(value) for value in _quarter_turn(order))  # type: ignore[arg-type]
    model = mujoco.MjModel.from_xml_string(
        f'<mujoco><worldbody><body quat="{turn}"><freejoint/><geom size=".1" quat="{turn}"/>'
        f'<site quat="{turn}"/><camera quat="{turn}"/></body></worldbody></mujoco>'
    )
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    assert np.allclose(data.xmat[1].reshape(3, 3), QUARTER_TURN_Z)  # the body's world rotation
    for stored in (data.xquat[1], model.body_quat[1], model.geom_quat[0], model.site_quat[0], model.cam_quat[0]):
        assert _same_rotation(_quaternion_parts(stored, order), _quaternion_parts(_quarter_turn(order), order))  # type: ignore[arg-type]


def test_pinocchio_quaternion_reads_four_scalars_and_one_vector_differently() -> None:
    pinocchio = pytest.importorskip("pinocchio")
    from geolint.knowledge import agreed, bind, knowledge_base

    api = knowledge_base().api("pinocchio.Quaternion")
    assert api is not None
    import ast

    four = ast.parse("Quaternion(a, b, c, d)", mode="eval").body
    assert isinstance(four, ast.Call)
    components = agreed(bind(api, four), lambda bound: bound.signature.components)
    assert components is not None
    assert np.allclose(pinocchio.Quaternion(*_quarter_turn(components)).toRotationMatrix(), QUARTER_TURN_Z)
    order = _stated("pinocchio.Quaternion", "Quaternion(v)", "vec4")
    assert order != components
    assert np.allclose(pinocchio.Quaternion(np.array(_quarter_turn(order))).toRotationMatrix(), QUARTER_TURN_Z)
    assert _stated("pinocchio.rpy.rpyToMatrix", "rpyToMatrix(r, p, y)", "yaw", "angle_unit") == "radians"
    assert np.allclose(pinocchio.rpy.rpyToMatrix(0.0, 0.0, math.pi / 2), QUARTER_TURN_Z)


def test_gtsam_rot3_reads_as_stated() -> None:
    gtsam = pytest.importorskip("gtsam")
    from geolint.knowledge import knowledge_base

    api = knowledge_base().api("gtsam.Rot3.Quaternion")
    assert api is not None
    (signature,) = api.signatures
    assert signature.components is not None
    assert np.allclose(gtsam.Rot3.Quaternion(*_quarter_turn(signature.components)).matrix(), QUARTER_TURN_Z)
    assert _stated("gtsam.Rot3.Ypr", "Rot3.Ypr(y, p, r)", "y", "angle_unit") == "radians"
    assert np.allclose(gtsam.Rot3.Ypr(math.pi / 2, 0.0, 0.0).matrix(), QUARTER_TURN_Z)
    assert np.allclose(gtsam.Rot3.Rz(math.pi / 2).rpy(), [0.0, 0.0, math.pi / 2])
