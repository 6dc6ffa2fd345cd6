"""The design text (section 4.2) as tests: its step-through, worked example, exercise 4.2.1 and lab."""

from __future__ import annotations

import numpy as np
import pytest

from geolint import Direction, Frame, Point, PointCloud, Transform, Vector


class Base(Frame):
    pass


class Tool(Frame):
    pass


R_BASE_TOOL = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])  # 90 degrees about z
T_BASE_TOOL = np.array([0.30, 0.10, 0.50])


@pytest.fixture
def pose() -> Transform[Base, Tool]:
    return Transform[Base, Tool](rotation=R_BASE_TOOL, translation=T_BASE_TOOL)


def test_step_through_point_gets_rotation_and_translation(pose: Transform[Base, Tool]) -> None:
    p_base = pose @ Point[Tool]([0.20, 0.0, 0.0])
    assert p_base.frame == "Base"
    np.testing.assert_allclose(np.asarray(p_base), [0.30, 0.30, 0.50], atol=1e-12)


def test_step_through_normal_gets_rotation_only_and_stays_unit(pose: Transform[Base, Tool]) -> None:
    n_base = pose @ Direction[Tool]([1.0, 0.0, 0.0])
    np.testing.assert_allclose(np.asarray(n_base), [0.0, 1.0, 0.0], atol=1e-12)
    assert n_base.norm() == pytest.approx(1.0, abs=1e-12)
    v_base = pose @ Vector[Tool]([1.0, 0.0, 0.0])
    np.testing.assert_allclose(np.asarray(v_base), [0.0, 1.0, 0.0], atol=1e-12)


def test_step_through_normal_wrongly_given_w_1_lands_off_and_inflated(pose: Transform[Base, Tool]) -> None:
    # The bug the runtime prevents, reproduced with the raw matrix: the normal as a homogeneous point.
    wrongly_homogeneous = pose.matrix @ np.array([1.0, 0.0, 0.0, 1.0])
    np.testing.assert_allclose(wrongly_homogeneous[:3], [0.30, 1.10, 0.50], atol=1e-12)
    # The design text says "length 1.18", but |(0.30, 1.10, 0.50)| = sqrt(0.09 + 1.21 + 0.25) = 1.245: its
    # figure contradicts its own coordinates (which this test confirms). The point stands: inflated by ~25%.
    assert np.linalg.norm(wrongly_homogeneous[:3]) == pytest.approx(np.sqrt(1.55), abs=1e-12)
    assert np.linalg.norm(wrongly_homogeneous[:3]) == pytest.approx(1.245, abs=0.0005)
    # ... and the runtime's answer for the same normal differs from it by exactly the translation.
    correct = np.asarray(pose @ Direction[Tool]([1.0, 0.0, 0.0]))
    np.testing.assert_allclose(wrongly_homogeneous[:3] - correct, T_BASE_TOOL, atol=1e-12)


def test_homogeneous_coordinate_is_kept(pose: Transform[Base, Tool]) -> None:
    # Step 6 of the algorithm: the trailing coordinate of T x~ equals w, for points (1) and vectors (0).
    for w in (0.0, 1.0):
        assert (pose.matrix @ np.array([0.2, -0.4, 0.7, w]))[3] == w


def test_worked_example_matches_the_plain_numpy_fragment(pose: Transform[Base, Tool]) -> None:
    p_tool, v_tool = np.array([0.20, 0.00, 0.00]), np.array([1.00, 0.00, 0.00])
    np.testing.assert_allclose(np.asarray(pose @ Point[Tool](p_tool)), R_BASE_TOOL @ p_tool + T_BASE_TOOL)
    np.testing.assert_allclose(np.asarray(pose @ Vector[Tool](v_tool)), R_BASE_TOOL @ v_tool)


@pytest.mark.parametrize("translation", [[0.0, 0.0, 0.0], [0.3, -1.2, 2.0], [5.0, 0.0, 0.0]])
def test_exercise_4_2_1_only_the_point_changes_by_the_translation(translation: list[float]) -> None:
    rotation_only = Transform[Base, Tool](rotation=R_BASE_TOOL)
    full = Transform[Base, Tool](rotation=R_BASE_TOOL, translation=translation)
    p, v = Point[Tool]([0.4, 0.1, -0.3]), Vector[Tool]([0.0, 2.0, 1.0])
    np.testing.assert_allclose(np.asarray(full @ p) - np.asarray(rotation_only @ p), translation, atol=1e-12)
    np.testing.assert_allclose(np.asarray(full @ v), np.asarray(rotation_only @ v), atol=0)


def torus_with_normals(n_major: int = 60, n_minor: int = 30, major: float = 0.3, minor: float = 0.1):
    """Points and outward unit normals of a torus about z, made with numpy (no downloads)."""
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, n_major, endpoint=False), np.linspace(0, 2 * np.pi, n_minor, endpoint=False))
    u, v = u.ravel(), v.ravel()
    normals = np.stack([np.cos(v) * np.cos(u), np.cos(v) * np.sin(u), np.sin(v)], axis=1)
    centres = np.stack([major * np.cos(u), major * np.sin(u), np.zeros_like(u)], axis=1)
    return centres + minor * normals, normals


def rotation_about(axis: np.ndarray, degrees: float) -> np.ndarray:
    axis = axis / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    a = np.radians(degrees)
    return np.eye(3) + np.sin(a) * k + (1 - np.cos(a)) * k @ k


@pytest.mark.parametrize("translation_m", [0.0, 0.5, 5.0])
@pytest.mark.parametrize("angle_deg", [45.0, 170.0])
def test_lab_translated_normals_in_a_point_cloud(translation_m: float, angle_deg: float) -> None:
    points, normals = torus_with_normals()
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-12)
    rotation = rotation_about(np.array([1.0, 2.0, 0.5]), angle_deg)
    translation = translation_m * np.array([0.6, 0.0, 0.8])  # |t| = translation_m
    T = Transform[Base, Tool](rotation=rotation, translation=translation)

    # Correct path: the runtime partitions the cloud by kind.
    moved = T @ PointCloud[Tool](points=points, normals=normals)
    assert moved.frame == "Base"
    np.testing.assert_allclose(moved.normal_lengths(), 1.0, atol=1e-12)
    np.testing.assert_allclose(np.asarray(moved.points), points @ rotation.T + translation, atol=1e-12)

    # Buggy path (the common bug): the full 4x4 applied to the normals as if they were points.
    homogeneous = np.hstack([normals, np.ones((len(normals), 1))])
    buggy_normals = (homogeneous @ T.matrix.T)[:, :3]
    buggy_lengths = np.linalg.norm(buggy_normals, axis=1)
    if translation_m == 0.0:
        np.testing.assert_allclose(buggy_lengths, 1.0, atol=1e-12)
    else:
        # Inflated with the translation: |R n + t| ranges over [|t| - 1, |t| + 1], mean growing with |t|.
        assert buggy_lengths.max() > 1.0 + 0.4 * translation_m
        assert abs(buggy_lengths.mean() - 1.0) > 0.05
        if translation_m > 2:
            assert buggy_lengths.min() >= translation_m - 1 - 1e-9
        # The buggy normals are exactly the correct ones shifted by t: they all fan towards one point.
        np.testing.assert_allclose(buggy_normals - np.asarray(moved.normals), np.broadcast_to(translation, buggy_normals.shape), atol=1e-12)
