"""Bad input to the runtime raises a `GeolintError` subclass that says what is wrong (issue 13, "The runtime").

Each case used to return a value (silently wrong or full of NaN/inf) or raise a bare numpy/Python error.
"""

from __future__ import annotations

import numpy as np
import pytest

from geolint import (
    Covariance,
    Direction,
    FrameTree,
    GeolintError,
    GeometryTypeError,
    GeometryValueError,
    Point,
    PointCloud,
    Transform,
    Vector,
)


def batch(dst: str, src: str, n: int) -> Transform:
    return Transform[dst, src](rotation=np.stack([np.eye(3)] * n), translation=np.arange(3.0 * n).reshape(n, 3))


def test_a_batch_of_one_pose_does_not_broadcast_against_a_batch_of_three():
    with pytest.raises(GeometryValueError, match="batches of 1 and 3 poses"):
        batch("world", "cam", 1) @ batch("cam", "base", 3)
    with pytest.raises(GeometryValueError, match="batches of 3 and 1 poses"):
        batch("world", "cam", 3) @ batch("cam", "base", 1)
    # One pose (not a batch) with a batch still applies to every pose, as documented.
    single = Transform["world", "cam"](translation=[1, 0, 0])
    assert len(single @ batch("cam", "base", 3)) == 3


@pytest.mark.parametrize(
    "index", [(slice(None), slice(None, 3)), (0, 1), (Ellipsis, 0), (0, slice(None), slice(None)), None]
)
def test_a_pose_batch_is_indexed_by_pose_only(index):
    poses = batch("cam", "base", 3)
    with pytest.raises(GeometryTypeError, match="pose"):
        poses[index]
    # Whole-pose indexing still works and gives well-formed transforms.
    assert poses[1].matrix.shape == (4, 4)
    assert len(poses[1:]) == 2 and len(poses[[0, 2]]) == 2 and len(poses[np.array([True, False, True])]) == 2


def test_a_point_batch_is_indexed_by_value_only():
    points = Point["w"](np.arange(9.0).reshape(3, 3))
    with pytest.raises(GeometryTypeError, match="by value only"):
        points[:, 0]
    with pytest.raises(GeometryTypeError, match="whole values"):
        points[None]
    assert points[1:].shape == (2, 3)


def stamped_tree() -> FrameTree:
    tree = FrameTree()
    pose = Transform["world", "cam"](translation=[1, 0, 0])
    tree.add(pose, stamp=0.0)
    tree.add(pose, stamp=1.0)
    return tree


@pytest.mark.parametrize(
    ("at", "error", "words"),
    [
        (float("nan"), GeometryValueError, "finite"),
        (np.float32("nan"), GeometryValueError, "finite"),
        (float("inf"), GeometryValueError, "finite"),
        ("0.5", GeometryTypeError, "str"),
        ([0.5], GeometryTypeError, "list"),
        (True, GeometryTypeError, "bool"),
        (np.bool_(True), GeometryTypeError, "bool"),
    ],
)
def test_lookup_at_a_bad_time(at, error, words):
    with pytest.raises(error, match=words):
        stamped_tree().lookup("world", "cam", at=at)


def test_a_stamp_is_a_finite_number_not_a_bool():
    tree = FrameTree()
    with pytest.raises(GeometryTypeError, match="bool"):
        tree.add(Transform["world", "cam"](), stamp=True)
    assert stamped_tree().lookup("world", "cam", at=np.float64(0.5)).is_close(
        Transform["world", "cam"](translation=[1, 0, 0])
    )


@pytest.mark.parametrize(
    "make",
    [
        lambda: Transform["world", "cam"](translation=[1e200, 0, 0]),
        lambda: Point["cam"]([0, 1e160, 0]),
        lambda: Vector["cam"]([[0, 0, 1], [0, -1e300, 0]]),
        lambda: PointCloud["cam"]([[1e155, 0, 0]]),
        lambda: Covariance["cam"](np.eye(3) * 1e200),
    ],
)
def test_values_large_enough_to_overflow_are_refused(make):
    with pytest.raises(GeometryValueError, match="overflow"):
        make()


def test_no_operation_overflows_to_inf():
    far = 1e150  # the largest accepted magnitude
    T = Transform["world", "cam"](translation=[far, far, far])
    results = [
        T @ Point["cam"]([far, far, far]),
        Point["w"]([far, 0, 0]) - Point["w"]([-far, 0, 0]),
        Point["w"]([far, 0, 0]) + Vector["w"]([far, 0, 0]),
        (T @ Transform["cam", "base"](translation=[far, far, far])).translation,
    ]
    for value in results:
        assert np.isfinite(np.asarray(value)).all()
    assert np.isfinite(Vector["w"]([far, far, far]).norm())
    with pytest.raises(GeometryValueError, match="overflow"):
        Vector["w"]([far, 0, 0]) * 1e10
    with pytest.raises(GeometryValueError, match="overflow"):
        Vector["w"]([far, 0, 0]) / 1e-10


@pytest.mark.parametrize("size", [1e200, 1e300, 1.7e308, 1e-200])
def test_a_normal_of_any_finite_magnitude_normalises_right(size):
    expected = np.array([1, 1, 0]) / np.sqrt(2)
    if size < 1e-12:  # below the zero-length threshold: refused, never a wrong unit vector
        with pytest.raises(GeometryValueError, match="zero-length"):
            Direction["w"]([size, size, 0])
        return
    assert np.allclose(Direction["w"]([size, size, 0]).xyz, expected)
    cloud = PointCloud["w"]([[0, 0, 0]], normals=[[size, size, 0]])
    assert np.allclose(np.asarray(cloud.normals), expected)


@pytest.mark.parametrize("tolerance", [float("nan"), float("inf"), -1e-9])
def test_covariance_tolerance_must_be_a_finite_number(tolerance):
    asymmetric = np.array([[1.0, 5.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    with pytest.raises(GeometryValueError, match="tolerance"):
        Covariance["w"](asymmetric, tolerance=tolerance)
    with pytest.raises(GeometryTypeError, match="tolerance"):
        Covariance["w"](np.eye(3), tolerance="1e-9")  # type: ignore[arg-type]


def test_an_asymmetric_covariance_is_refused_even_next_to_a_large_one():
    large = np.eye(3) * 1e12
    asymmetric = np.array([[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    with pytest.raises(GeometryValueError, match=r"symmetric.*matrix 1 of the batch"):
        Covariance["w"](np.stack([large, asymmetric]))
    indefinite = np.diag([1.0, 1.0, -0.5])
    with pytest.raises(GeometryValueError, match=r"positive semi-definite.*matrix 1 of the batch"):
        Covariance["w"](np.stack([large, indefinite]))


def test_rotation_tolerance_must_be_a_finite_number():
    with pytest.raises(GeometryValueError, match="tolerance"):
        Transform["a", "b"](rotation=np.eye(3) * 1.1, tolerance=float("nan"))
    with pytest.raises(GeometryValueError, match="tolerance"):
        Transform["a", "b"].from_quat([0, 0, 0, 2], order="xyzw", tolerance=float("nan"))


def write_matrix(T):
    T.matrix[0, 3] = 5.0


def write_rotation(T):
    T.rotation[0] = [1, 0, 0]


def add_to_translation(T):
    translation = T.translation
    translation += 1


def write_covariance(_):
    Covariance["w"](np.eye(3)).matrix[0, 0] = 2.0


def write_xyz(_):
    Point["w"]([1, 2, 3]).xyz[0] = 0.0


@pytest.mark.parametrize("write", [write_matrix, write_rotation, add_to_translation, write_covariance, write_xyz])
def test_writing_into_a_value_says_it_is_immutable(write):
    T = Transform["world", "cam"](translation=[1, 2, 3])
    with pytest.raises(GeolintError, match="immutable"):
        write(T)
    assert T.translation.tolist() == [1, 2, 3]
    # What is computed from those arrays is an ordinary array again.
    doubled = T.matrix * 2
    assert type(doubled) is np.ndarray
    doubled[0, 0] = 7.0
