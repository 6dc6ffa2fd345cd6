"""evo's and autolab_core's facts in stubs/, checked against the libraries where they install (skipped
where they do not: the dev extra installs neither)."""

from __future__ import annotations

import numpy as np
import pytest

from tests.knowledge.facts_helpers import QUARTER_TURN_Z, _quarter_turn, _quaternion_parts, _same_rotation, _stated


def test_evo_trajectories_take_and_hold_the_stated_order() -> None:
    trajectory = pytest.importorskip("evo.core.trajectory")
    order = _stated("evo.core.trajectory.PosePath3D", "PosePath3D(positions_xyz=p, orientations_quat_wxyz=q)", "orientations_quat_wxyz")
    path = trajectory.PosePath3D(positions_xyz=np.zeros((1, 3)), orientations_quat_wxyz=np.array([_quarter_turn(order)]))
    assert np.allclose(path.poses_se3[0][:3, :3], QUARTER_TURN_Z)
    transformations = pytest.importorskip("evo.core.transformations")
    order = _stated("evo.core.transformations.quaternion_matrix", "quaternion_matrix(q)", "quaternion")
    assert np.allclose(transformations.quaternion_matrix(_quarter_turn(order))[:3, :3], QUARTER_TURN_Z)


def test_autolab_core_rigid_transforms_are_w_first_and_its_transformations_w_last() -> None:
    autolab_core = pytest.importorskip("autolab_core")
    order = _stated("autolab_core.RigidTransform.rotation_from_quaternion", "RigidTransform.rotation_from_quaternion(q)", "q_wxyz")
    rotation = autolab_core.RigidTransform.rotation_from_quaternion(_quarter_turn(order))
    assert np.allclose(rotation, QUARTER_TURN_Z)
    held = _stated("autolab_core.RigidTransform.quaternion", "T.quaternion()", "return")
    produced = autolab_core.RigidTransform(rotation=QUARTER_TURN_Z).quaternion
    assert _same_rotation(_quaternion_parts(produced, held), _quaternion_parts(_quarter_turn(held), held))  # type: ignore[arg-type]
    order = _stated("autolab_core.transformations.quaternion_matrix", "quaternion_matrix(q)", "quaternion")
    assert np.allclose(autolab_core.transformations.quaternion_matrix(_quarter_turn(order))[:3, :3], QUARTER_TURN_Z)
