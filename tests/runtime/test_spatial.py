"""PointCloud, Twist, Wrench, Covariance: each moves by its own rule, checked against independent physics."""

from __future__ import annotations

import numpy as np
import pytest

from geolint import (
    Covariance,
    Frame,
    FrameMismatchError,
    GeometryTypeError,
    GeometryValueError,
    Point,
    PointCloud,
    Transform,
    Twist,
    Vector,
    Wrench,
)


class A(Frame):
    pass


class B(Frame):
    pass


def random_pose(seed: int) -> Transform[A, B]:
    rng = np.random.default_rng(seed)
    q = rng.normal(size=4)
    return Transform[A, B].from_quat(q / np.linalg.norm(q), rng.normal(size=3) * 2, order="wxyz")


def test_point_cloud_moves_points_fully_and_normals_by_rotation_only() -> None:
    T = random_pose(1)
    rng = np.random.default_rng(2)
    points, normals = rng.normal(size=(100, 3)), rng.normal(size=(100, 3))
    cloud = PointCloud[B](points=points, normals=normals)
    np.testing.assert_allclose(np.linalg.norm(np.asarray(cloud.normals), axis=1), 1.0)  # normalised on input
    moved = T @ cloud
    assert moved.frame == "A" and len(moved) == 100
    np.testing.assert_allclose(np.asarray(moved.points), np.asarray(T @ Point[B](points)), atol=1e-12)
    np.testing.assert_allclose(np.asarray(moved.normals), np.asarray(T @ cloud.normals), atol=1e-12)
    np.testing.assert_allclose(moved.normal_lengths(), 1.0, atol=1e-12)
    bare = T @ PointCloud[B](points=points)
    assert bare.normals is None
    assert repr(moved) == "PointCloud[A](<100 points with normals>)"


def test_point_cloud_input_errors() -> None:
    with pytest.raises(GeometryValueError, match="3 points but 2 normals"):
        PointCloud[B](points=np.zeros((3, 3)), normals=np.ones((2, 3)))
    with pytest.raises(GeometryValueError, match="zero-length"):
        PointCloud[B](points=np.zeros((2, 3)), normals=[[0, 0, 1], [0, 0, 0]])
    with pytest.raises(GeometryValueError, match=r"points must have shape \(N, 3\)"):
        PointCloud[B](points=[1, 2, 3])
    with pytest.raises(FrameMismatchError, match=r"applied to PointCloud\[A\]: expected a PointCloud\[B\]"):
        random_pose(0) @ PointCloud[A](points=np.zeros((1, 3)))  # type: ignore[operator]
    with pytest.raises(GeometryTypeError, match="normals get the rotation only"):
        np.eye(4) @ PointCloud[B](points=np.zeros((1, 3)))


def test_twist_adjoint_agrees_with_rigid_body_point_velocities() -> None:
    # A rigid body moving with twist (v, w) referred to B's origin: its point at p has velocity v + w x p.
    # That physical velocity, expressed in A, must be v' + w' x p' with the transformed twist.
    T = random_pose(3)
    rng = np.random.default_rng(4)
    v, w = rng.normal(size=3), rng.normal(size=3)
    moved = T @ Twist[B](linear=v, angular=w)
    assert moved.frame == "A"
    for p in rng.normal(size=(5, 3)):
        velocity_b = Vector[B](v + np.cross(w, p))
        p_a = np.asarray(T @ Point[B](p))
        velocity_a = np.asarray(moved.linear) + np.cross(np.asarray(moved.angular), p_a)
        np.testing.assert_allclose(velocity_a, np.asarray(T @ velocity_b), atol=1e-10)
    np.testing.assert_allclose(np.asarray(moved.angular), T.rotation @ w, atol=1e-12)


def test_wrench_adjoint_keeps_power_and_matches_the_formula() -> None:
    T = random_pose(5)
    rng = np.random.default_rng(6)
    v, w, f, tau = rng.normal(size=(4, 3))
    twist, wrench = Twist[B](linear=v, angular=w), Wrench[B](force=f, torque=tau)
    moved_twist, moved_wrench = T @ twist, T @ wrench
    power_b = v @ f + w @ tau
    power_a = np.asarray(moved_twist.linear) @ np.asarray(moved_wrench.force) + np.asarray(
        moved_twist.angular
    ) @ np.asarray(moved_wrench.torque)
    assert power_a == pytest.approx(power_b, rel=1e-10)
    R, t = T.rotation, T.translation
    np.testing.assert_allclose(np.asarray(moved_wrench.force), R @ f, atol=1e-12)
    np.testing.assert_allclose(np.asarray(moved_wrench.torque), R @ tau + np.cross(t, R @ f), atol=1e-12)
    assert repr(Wrench[B](force=[1, 0, 0], torque=[0, 0, 2])) == "Wrench[B](force=[1.0, 0.0, 0.0], torque=[0.0, 0.0, 2.0])"


def test_twist_and_wrench_batches_and_errors() -> None:
    rng = np.random.default_rng(8)
    T = random_pose(7)
    batch = Twist[B](linear=rng.normal(size=(4, 3)), angular=rng.normal(size=(4, 3)))
    moved = T @ batch
    for i in range(4):
        single = T @ Twist[B](linear=np.asarray(batch.linear)[i], angular=np.asarray(batch.angular)[i])
        np.testing.assert_allclose(np.asarray(moved.linear)[i], np.asarray(single.linear), atol=1e-12)
    with pytest.raises(GeometryValueError, match=r"linear has shape \(3,\) but angular has \(2, 3\)"):
        Twist[B](linear=[0, 0, 0], angular=np.zeros((2, 3)))
    with pytest.raises(GeometryTypeError, match=r"Twist needs a frame"):
        Twist(linear=[0, 0, 0], angular=[0, 0, 0])
    total = Wrench[B](force=[1, 0, 0], torque=[0, 0, 0]) + Wrench[B](force=[0, 1, 0], torque=[0, 0, 1])
    np.testing.assert_allclose(np.asarray(total.force), [1, 1, 0])
    with pytest.raises(FrameMismatchError):
        Wrench[B](force=[1, 0, 0], torque=[0, 0, 0]) + Wrench[A](force=[1, 0, 0], torque=[0, 0, 0])  # type: ignore[operator]
    with pytest.raises(GeometryTypeError, match="only values of the same kind add"):
        Wrench[B](force=[1, 0, 0], torque=[0, 0, 0]) + Twist[B](linear=[1, 0, 0], angular=[0, 0, 0])  # type: ignore[operator]


def test_covariance_rotates_as_r_s_rt_and_ignores_translation() -> None:
    T = random_pose(9)
    rng = np.random.default_rng(10)
    L = rng.normal(size=(3, 3))
    S = L @ L.T
    moved = T @ Covariance[B](S)
    R = T.rotation
    np.testing.assert_allclose(moved.matrix, R @ S @ R.T, atol=1e-12)
    # The variance along a direction d in B equals the variance along R d in A.
    d = rng.normal(size=3)
    d /= np.linalg.norm(d)
    assert (R @ d) @ moved.matrix @ (R @ d) == pytest.approx(d @ S @ d, rel=1e-10)
    # Samples: the covariance of moved samples is R S R^T whatever the translation.
    samples = rng.multivariate_normal(np.zeros(3), S, size=200_000)
    moved_samples = np.asarray(T @ Point[B](samples))
    np.testing.assert_allclose(np.cov(moved_samples.T), moved.matrix, atol=0.05 * np.abs(S).max())


def test_covariance_validation() -> None:
    with pytest.raises(GeometryValueError, match="symmetric"):
        Covariance[B]([[1, 0.5, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(GeometryValueError, match="positive semi-definite; its smallest eigenvalue is -1"):
        Covariance[B](np.diag([1.0, -1.0, 2.0]))
