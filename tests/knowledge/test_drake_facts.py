"""Drake's facts in stubs/, checked against pydrake where it installs (skipped where it does not: the dev
extra does not install Drake)."""

from __future__ import annotations

import ast
import math

import numpy as np
import pytest

from geolint.knowledge import agreed, bind, knowledge_base
from tests.knowledge.facts_helpers import QUARTER_TURN_Z, _quarter_turn, _stated

eigen_geometry = pytest.importorskip("pydrake.common.eigen_geometry")
drake_math = pytest.importorskip("pydrake.math")


def test_quaternions_are_w_first_by_array_and_by_components() -> None:
    order = _stated("pydrake.common.eigen_geometry.Quaternion", "Quaternion(q)", "wxyz")
    quaternion = eigen_geometry.Quaternion(wxyz=np.array(_quarter_turn(order)))
    assert np.allclose(drake_math.RotationMatrix(quaternion).matrix(), QUARTER_TURN_Z)
    api = knowledge_base().api("pydrake.all.Quaternion")
    assert api is not None
    call = ast.parse("Quaternion(a, b, c, d)", mode="eval").body
    assert isinstance(call, ast.Call)
    components = agreed(bind(api, call), lambda bound: bound.signature.components)
    assert components is not None
    quaternion = eigen_geometry.Quaternion(*_quarter_turn(components))
    assert np.allclose(drake_math.RotationMatrix(quaternion).matrix(), QUARTER_TURN_Z)


def test_angles_are_radians() -> None:
    assert _stated("pydrake.math.RollPitchYaw", "RollPitchYaw(r, p, y)", "yaw", "angle_unit") == "radians"
    assert np.allclose(drake_math.RollPitchYaw(0.0, 0.0, math.pi / 2).ToRotationMatrix().matrix(), QUARTER_TURN_Z)
    assert _stated("pydrake.math.RotationMatrix.MakeZRotation", "RotationMatrix.MakeZRotation(t)", "theta", "angle_unit") == "radians"
    assert np.allclose(drake_math.RotationMatrix.MakeZRotation(math.pi / 2).matrix(), QUARTER_TURN_Z)


def test_a_rigid_transform_moves_points_by_rotation_and_translation() -> None:
    from geolint.algebra import Kind

    api = knowledge_base().api("pydrake.all.RigidTransform.multiply")
    assert api is not None and all(signature.applies_transform for signature in api.signatures)
    assert {signature.returns.kind for signature in api.signatures if signature.returns is not None} == {Kind.POINT, None}
    pose = drake_math.RigidTransform(drake_math.RotationMatrix(QUARTER_TURN_Z), [1.0, 2.0, 3.0])
    point = np.array([1.0, 0.0, 0.0])
    moved = QUARTER_TURN_Z @ point + [1.0, 2.0, 3.0]
    assert np.allclose(pose.multiply(point), moved) and np.allclose(pose @ point, moved)
    assert np.allclose(pose.GetAsMatrix4()[:3, 3], [1.0, 2.0, 3.0])
