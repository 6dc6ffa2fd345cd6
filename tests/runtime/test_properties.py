"""Property tests (hypothesis, derandomized): round trips, associativity, kept lengths, frame errors.

Tolerances: poses have |t| <= 10 and unit quaternion rotations, so float64 round trips agree to 1e-9
absolute; lengths kept by rotations to 1e-9 relative.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from geolint import (
    Direction,
    FrameMismatchError,
    GeometryTypeError,
    Point,
    PointCloud,
    Transform,
    Twist,
    Vector,
    Wrench,
)

PROPERTY = settings(derandomize=True, max_examples=60, deadline=None)
ATOL = 1e-9

finite = st.floats(min_value=-10, max_value=10, allow_nan=False, allow_infinity=False)
xyz = arrays(np.float64, 3, elements=finite)
quaternions = arrays(np.float64, 4, elements=st.floats(-1, 1, allow_nan=False)).filter(
    lambda q: np.linalg.norm(q) > 0.1
)


@st.composite
def poses(draw: st.DrawFn, dst: str, src: str) -> Transform:  # type: ignore[type-arg]
    q = draw(quaternions)
    return Transform[dst, src].from_quat(q, draw(xyz), order="xyzw", normalize=True)  # type: ignore[misc]


@given(poses("a", "b"), xyz)
@PROPERTY
def test_inverse_round_trips(T: Transform, p: np.ndarray) -> None:  # type: ignore[type-arg]
    inverse = T.inverse()
    assert (inverse.dst, inverse.src) == ("b", "a")
    there_and_back = inverse @ (T @ Point["b"](p))
    np.testing.assert_allclose(np.asarray(there_and_back), p, atol=ATOL)
    np.testing.assert_allclose((T @ inverse).matrix, np.eye(4), atol=ATOL)
    np.testing.assert_allclose(inverse.inverse().matrix, T.matrix, atol=ATOL)


@given(poses("a", "b"), poses("b", "c"), poses("c", "d"), xyz)
@PROPERTY
def test_composition_is_associative_and_matches_applying_in_turn(T_ab, T_bc, T_cd, p) -> None:  # type: ignore[no-untyped-def]
    left = (T_ab @ T_bc) @ T_cd
    right = T_ab @ (T_bc @ T_cd)
    assert (left.dst, left.src) == ("a", "d")
    np.testing.assert_allclose(left.matrix, right.matrix, atol=ATOL)
    point = Point["d"](p)
    np.testing.assert_allclose(np.asarray(left @ point), np.asarray(T_ab @ (T_bc @ (T_cd @ point))), atol=ATOL)


@given(poses("a", "b"), xyz, xyz)
@PROPERTY
def test_vectors_keep_their_length_and_differences_of_points_move_as_vectors(T, u, w) -> None:  # type: ignore[no-untyped-def]
    v = Vector["b"](u)
    moved = T @ v
    assert moved.norm() == pytest.approx(v.norm(), rel=1e-9, abs=1e-12)
    # Translation cancels in p - q: moving the points then subtracting equals moving the difference.
    p, q = Point["b"](u), Point["b"](w)
    np.testing.assert_allclose(np.asarray((T @ p) - (T @ q)), np.asarray(T @ (p - q)), atol=ATOL)
    # Distances between points are kept by a rigid pose.
    assert (T @ p).distance_to(T @ q) == pytest.approx(p.distance_to(q), rel=1e-9, abs=1e-9)
    if np.linalg.norm(u) > 1e-6:
        assert (T @ Direction["b"](u)).norm() == pytest.approx(1.0, abs=1e-12)


def _values_in(frame: str) -> list[object]:
    return [
        Point[frame]([1, 2, 3]),
        Vector[frame]([1, 2, 3]),
        Direction[frame]([1, 2, 3]),
        PointCloud[frame](points=[[1, 2, 3]], normals=[[0, 0, 1]]),
        Twist[frame](linear=[1, 0, 0], angular=[0, 1, 0]),
        Wrench[frame](force=[1, 0, 0], torque=[0, 1, 0]),
        Transform[frame, "elsewhere"](),
    ]


FRAMES = ["world", "camera", "base_link", "tool"]


@given(st.sampled_from(FRAMES), st.sampled_from(FRAMES), st.integers(0, 6))
@PROPERTY
def test_every_frame_mismatch_is_refused(src: str, value_frame: str, which: int) -> None:
    T = Transform["dst", src]()
    value = _values_in(value_frame)[which]
    if value_frame == src:
        T @ value  # type: ignore[operator]  # same frame: fine
        return
    with pytest.raises(FrameMismatchError) as caught:
        T @ value  # type: ignore[operator]
    assert f"Transform[dst <- {src}]" in str(caught.value) and value_frame in str(caught.value)


@pytest.mark.parametrize(("left", "right"), list(itertools.permutations(FRAMES, 2)))
def test_every_binary_operation_across_frames_is_refused(left: str, right: str) -> None:
    p, q = Point[left]([1, 2, 3]), Point[right]([4, 5, 6])
    v, w = Vector[left]([1, 0, 0]), Vector[right]([0, 1, 0])
    for operation in (lambda: p - q, lambda: p + w, lambda: p - w, lambda: v + w, lambda: v - w, lambda: w + p, lambda: v.dot(w), lambda: v.cross(w)):
        with pytest.raises(FrameMismatchError, match=f"{left} vs {right}|{right} vs {left}"):
            operation()
    with pytest.raises(GeometryTypeError):
        p + q  # type: ignore[operator]


@given(poses("odom", "base"), poses("odom", "base"), st.floats(0.0, 1.0), st.floats(-100, 100), st.floats(0.01, 50))
@PROPERTY
def test_stamped_lookups_hit_samples_and_interpolate_symmetrically(T0, T1, fraction, start, span) -> None:  # type: ignore[no-untyped-def]
    from geolint import FrameTree

    tree = FrameTree()
    tree.add(T0, stamp=start)
    tree.add(T1, stamp=start + span)
    np.testing.assert_allclose(tree.lookup("odom", "base", at=start).matrix, T0.matrix, atol=ATOL)
    np.testing.assert_allclose(tree.lookup("odom", "base", at=start + span).matrix, T1.matrix, atol=ATOL)
    between = tree.lookup("odom", "base", at=start + fraction * span)
    np.testing.assert_allclose(between.rotation.T @ between.rotation, np.eye(3), atol=1e-9)
    np.testing.assert_allclose(
        between.translation, (1 - fraction) * T0.translation + fraction * T1.translation, atol=1e-6
    )

    def angle(a: np.ndarray, b: np.ndarray) -> float:
        return float(np.arccos(np.clip((np.trace(a.T @ b) - 1) / 2, -1, 1)))

    # slerp moves along the shortest arc at constant rate: the angles to both ends split in fraction : 1 - fraction.
    total = angle(T0.rotation, T1.rotation)
    assert angle(T0.rotation, between.rotation) == pytest.approx(fraction * total, abs=1e-6)
    assert angle(between.rotation, T1.rotation) == pytest.approx((1 - fraction) * total, abs=1e-6)
