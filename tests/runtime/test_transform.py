"""Transform[Dst, Src]: construction and validation, quaternions, scipy interop, batches, errors."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

from geolint import (
    Direction,
    Frame,
    FrameMismatchError,
    GeometryTypeError,
    GeometryValueError,
    InvalidRotationError,
    Point,
    Transform,
    Vector,
)
from geolint.runtime import rotation as rotation_module


class World(Frame):
    pass


class Camera(Frame):
    pass


class Base(Frame):
    pass


def rot_z(degrees: float) -> np.ndarray:
    a = np.radians(degrees)
    return np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])


def test_parts_and_frames() -> None:
    T = Transform[World, Camera](rotation=rot_z(90), translation=[0.3, 0.1, 0.5])
    assert (T.dst, T.src) == ("World", "Camera")
    np.testing.assert_allclose(T.rotation, rot_z(90))
    np.testing.assert_allclose(T.translation, [0.3, 0.1, 0.5])
    np.testing.assert_allclose(T.matrix[3], [0, 0, 0, 1])
    np.testing.assert_allclose(T.matrix[:3, :3], rot_z(90))
    assert not T.matrix.flags.writeable
    assert not T.is_batch


def test_defaults_are_identity_rotation_and_zero_translation() -> None:
    np.testing.assert_array_equal(Transform[World, Camera]().matrix, np.eye(4))
    np.testing.assert_array_equal(Transform[World, Camera](translation=[1, 2, 3]).rotation, np.eye(3))


def test_identity() -> None:
    I = Transform.identity(World)
    assert (I.dst, I.src) == ("World", "World")
    p = Point[World]([1, 2, 3])
    np.testing.assert_array_equal(np.asarray(I @ p), np.asarray(p))
    assert Transform.identity("map").dst == "map"


def test_repr_and_describe() -> None:
    T = Transform[World, Camera](translation=[0.3, 0.1, 0.5])
    assert repr(T) == (
        "Transform[World, Camera](rotation=[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], "
        "translation=[0.3, 0.1, 0.5])"
    )
    batch = Transform[World, Camera](translation=np.zeros((4, 3)))
    assert repr(batch) == "Transform[World, Camera](<batch of 4 poses>)"


def test_a_transform_needs_its_frames() -> None:
    with pytest.raises(GeometryTypeError, match="needs its two frames"):
        Transform()
    with pytest.raises(GeometryTypeError, match="needs its two frames"):
        Transform.from_matrix(np.eye(4))


def test_apply_follows_the_point_versus_vector_contract() -> None:
    T = Transform[World, Camera](rotation=rot_z(90), translation=[1, 2, 3])
    np.testing.assert_allclose(np.asarray(T @ Point[Camera]([1, 0, 0])), [1, 3, 3], atol=1e-12)
    np.testing.assert_allclose(np.asarray(T @ Vector[Camera]([1, 0, 0])), [0, 1, 0], atol=1e-12)
    d = T @ Direction[Camera]([1, 1, 0])
    assert type(d) is Direction[World] and d.norm() == pytest.approx(1.0, abs=1e-12)
    points = np.random.default_rng(1).normal(size=(50, 3))
    np.testing.assert_allclose(np.asarray(T @ Point[Camera](points)), points @ rot_z(90).T + [1, 2, 3], atol=1e-12)


def test_frame_mismatch_message() -> None:
    T = Transform[World, Camera]()
    with pytest.raises(FrameMismatchError) as caught:
        T @ Point[Base]([0, 0, 0])  # type: ignore[operator]
    assert str(caught.value) == "Transform[World <- Camera] applied to Point[Base]: expected a Point[Camera]"
    with pytest.raises(FrameMismatchError, match=r"applied to Direction\[Base\]: expected a Direction\[Camera\]"):
        T @ Direction[Base]([0, 0, 1])  # type: ignore[operator]


def test_composition_checks_the_inner_frames() -> None:
    T_wc = Transform[World, Camera](rotation=rot_z(30), translation=[1, 0, 0])
    T_cb = Transform[Camera, Base](rotation=rot_z(60), translation=[0, 1, 0])
    T_wb = T_wc @ T_cb
    assert (T_wb.dst, T_wb.src) == ("World", "Base")
    np.testing.assert_allclose(T_wb.matrix, T_wc.matrix @ T_cb.matrix)
    with pytest.raises(FrameMismatchError) as caught:
        T_cb @ T_wc  # type: ignore[operator]
    assert str(caught.value).startswith(
        "Transform[Camera <- Base] @ Transform[World <- Camera]: composing needs the inner frames to match"
    )


def test_inverse_swaps_frames_and_undoes_the_pose() -> None:
    T = Transform[World, Camera](rotation=rot_z(37), translation=[0.3, -2, 1])
    inv = T.inverse()
    assert (inv.dst, inv.src) == ("Camera", "World")
    np.testing.assert_allclose((inv @ T).matrix, np.eye(4), atol=1e-12)
    np.testing.assert_allclose(inv.matrix, np.linalg.inv(T.matrix), atol=1e-12)


def test_raw_ndarray_on_the_right_says_how_to_wrap_it() -> None:
    T = Transform[World, Camera]()
    with pytest.raises(GeometryTypeError) as caught:
        T @ np.zeros(3)  # type: ignore[operator]
    message = str(caught.value)
    assert isinstance(caught.value, TypeError)
    assert "Point[Camera](array)" in message and "Vector[Camera](array)" in message
    with pytest.raises(GeometryTypeError, match="write T.matrix"):
        np.eye(4) @ T  # type: ignore[operator]
    with pytest.raises(GeometryTypeError, match="not a geometric value"):
        T @ [1, 2, 3]  # type: ignore[operator]


# ---- validation -------------------------------------------------------------------------------------------


def test_non_orthonormal_rotation_says_by_how_much() -> None:
    off = rot_z(20) * 1.001
    with pytest.raises(InvalidRotationError) as caught:
        Transform[World, Camera](rotation=off)
    message = str(caught.value)
    assert "max |R^T R - I| = 0.002" in message and "tolerance 1e-06" in message and "orthonormalize=True" in message


def test_tolerance_is_configurable() -> None:
    slightly_off = rot_z(20) + 1e-5
    with pytest.raises(InvalidRotationError):
        Transform[World, Camera](rotation=slightly_off)
    T = Transform[World, Camera](rotation=slightly_off, tolerance=1e-4)
    np.testing.assert_array_equal(T.rotation, slightly_off)  # accepted as given, not silently changed
    assert rotation_module.DEFAULT_TOLERANCE == 1e-6


def test_reflection_is_refused_even_when_orthonormal() -> None:
    with pytest.raises(InvalidRotationError, match=r"reflection.*determinant -1"):
        Transform[World, Camera](rotation=np.diag([1.0, 1.0, -1.0]))
    with pytest.raises(InvalidRotationError, match="reflection"):
        Transform[World, Camera](rotation=np.diag([1.0, 1.0, -1.0]) + 1e-4, orthonormalize=True)


def test_orthonormalize_projects_onto_so3() -> None:
    rng = np.random.default_rng(3)
    noisy = rot_z(33) + rng.normal(scale=1e-3, size=(3, 3))
    T = Transform[World, Camera].from_matrix(np.block([[noisy, np.ones((3, 1))], [np.zeros((1, 3)), np.ones((1, 1))]]), orthonormalize=True)
    R = T.rotation
    np.testing.assert_allclose(R.T @ R, np.eye(3), atol=1e-12)
    assert np.linalg.det(R) == pytest.approx(1.0)
    np.testing.assert_allclose(R, rot_z(33), atol=5e-3)
    np.testing.assert_array_equal(T.translation, [1, 1, 1])
    with pytest.raises(InvalidRotationError, match="too far from a rotation"):
        Transform[World, Camera](rotation=2 * rot_z(10), orthonormalize=True)


def test_from_matrix_checks_shape_bottom_row_and_finiteness() -> None:
    with pytest.raises(GeometryValueError, match=r"matrix must have shape \(4, 4\) or \(N, 4, 4\), got \(3, 4\)"):
        Transform[World, Camera].from_matrix(np.zeros((3, 4)))
    bad = np.eye(4)
    bad[3, 0] = 0.5
    with pytest.raises(GeometryValueError, match=r"bottom row .* must be \[0, 0, 0, 1\], got \[0.5, 0.0, 0.0, 1.0\]"):
        Transform[World, Camera].from_matrix(bad)
    nan = np.eye(4)
    nan[0, 3] = np.nan
    with pytest.raises(GeometryValueError, match="non-finite"):
        Transform[World, Camera].from_matrix(nan)
    with pytest.raises(GeometryValueError, match="translation must have shape"):
        Transform[World, Camera](translation=[1, 2])


def test_batch_validation_names_the_bad_pose() -> None:
    rotations = np.stack([rot_z(a) for a in range(0, 50, 10)])
    rotations[3] *= 1.01
    with pytest.raises(InvalidRotationError, match="matrix 3 of the batch"):
        Transform[World, Camera](rotation=rotations)


# ---- quaternions and scipy --------------------------------------------------------------------------------


def test_from_quat_requires_the_order() -> None:
    with pytest.raises(TypeError, match="order"):
        Transform[World, Camera].from_quat([0, 0, 0, 1])  # type: ignore[call-arg]
    with pytest.raises(GeometryValueError, match="'xyzw' .* or 'wxyz'"):
        Transform[World, Camera].from_quat([0, 0, 0, 1], order="ijkw")  # type: ignore[arg-type]


def test_quaternion_orders_give_the_same_rotation() -> None:
    half = np.radians(90) / 2
    xyzw = [0, 0, np.sin(half), np.cos(half)]
    wxyz = [np.cos(half), 0, 0, np.sin(half)]
    a = Transform[World, Camera].from_quat(xyzw, [1, 2, 3], order="xyzw")
    b = Transform[World, Camera].from_quat(wxyz, [1, 2, 3], order="wxyz")
    np.testing.assert_allclose(a.rotation, rot_z(90), atol=1e-12)
    np.testing.assert_allclose(a.matrix, b.matrix, atol=1e-12)
    np.testing.assert_allclose(a.as_quat("wxyz"), wxyz, atol=1e-12)
    # The classic bug: reading a wxyz quaternion as xyzw gives a different (valid!) rotation.
    swapped = Transform[World, Camera].from_quat(wxyz, order="xyzw")
    assert not np.allclose(swapped.rotation, rot_z(90), atol=1e-3)


def test_non_unit_quaternion_is_refused_unless_normalize() -> None:
    with pytest.raises(InvalidRotationError, match=r"not unit length: \| \|q\| - 1 \| = 1"):
        Transform[World, Camera].from_quat([0, 0, 0, 2], order="xyzw")
    T = Transform[World, Camera].from_quat([0, 0, 0, 2], order="xyzw", normalize=True)
    np.testing.assert_allclose(T.rotation, np.eye(3))
    with pytest.raises(InvalidRotationError, match="zero quaternion"):
        Transform[World, Camera].from_quat([0, 0, 0, 0], order="xyzw", normalize=True)


def test_quaternion_round_trip_matches_scipy() -> None:
    Rotation = pytest.importorskip("scipy.spatial.transform").Rotation
    rotations = Rotation.random(200, random_state=7)
    T = Transform[World, Camera].from_scipy(rotations, np.zeros((200, 3)))
    np.testing.assert_allclose(T.rotation, rotations.as_matrix(), atol=1e-12)
    ours = T.as_quat("xyzw")
    theirs = rotations.as_quat()
    theirs *= np.sign(theirs[:, 3:4])
    np.testing.assert_allclose(ours, theirs, atol=1e-9)
    back = Transform[World, Camera].from_quat(ours, order="xyzw")
    np.testing.assert_allclose(back.rotation, T.rotation, atol=1e-9)


def test_scipy_interop_round_trip() -> None:
    pytest.importorskip("scipy", minversion="1.16", reason="RigidTransform is new in scipy 1.16 (Python 3.10 gets 1.15)")
    transform = pytest.importorskip("scipy.spatial.transform")
    T = Transform[World, Camera](rotation=rot_z(25), translation=[1, 2, 3])
    rigid = T.as_scipy()
    assert isinstance(rigid, transform.RigidTransform)
    np.testing.assert_allclose(rigid.apply([1, 0, 0]), np.asarray(T @ Point[Camera]([1, 0, 0])), atol=1e-12)
    again = Transform[World, Camera].from_scipy(rigid)
    np.testing.assert_allclose(again.matrix, T.matrix, atol=1e-12)
    np.testing.assert_allclose(T.as_scipy_rotation().as_matrix(), rot_z(25), atol=1e-12)
    with pytest.raises(GeometryTypeError, match="expects a scipy Rotation"):
        Transform[World, Camera].from_scipy(np.eye(3))


# ---- batches ----------------------------------------------------------------------------------------------


def test_batches_apply_pose_i_to_point_i_and_compose_pairwise() -> None:
    rotations = np.stack([rot_z(a) for a in (0, 90, 180)])
    T = Transform[World, Camera](rotation=rotations, translation=[[1, 0, 0], [0, 1, 0], [0, 0, 1]])
    assert T.is_batch and len(T) == 3
    moved = T @ Point[Camera]([[1, 0, 0], [1, 0, 0], [1, 0, 0]])
    np.testing.assert_allclose(np.asarray(moved), [[2, 0, 0], [0, 2, 0], [-1, 0, 1]], atol=1e-12)
    one_point_all_poses = T @ Point[Camera]([1, 0, 0])
    np.testing.assert_allclose(np.asarray(one_point_all_poses), np.asarray(moved), atol=1e-12)
    np.testing.assert_allclose(np.asarray(T @ Vector[Camera]([[1, 0, 0]] * 3)), [[1, 0, 0], [0, 1, 0], [-1, 0, 0]], atol=1e-12)
    composed = T @ Transform[Camera, Base](translation=[0, 0, 5])
    np.testing.assert_allclose(composed.matrix, T.matrix @ Transform[Camera, Base](translation=[0, 0, 5]).matrix)
    pairwise = T @ T.inverse()
    np.testing.assert_allclose(pairwise.matrix, np.broadcast_to(np.eye(4), (3, 4, 4)), atol=1e-12)
    np.testing.assert_allclose(T[1].matrix, T.matrix[1])


def test_batch_size_mismatches_are_refused() -> None:
    T = Transform[World, Camera](translation=np.zeros((3, 3)))
    with pytest.raises(GeometryValueError, match="batch of 3 poses but the value has 2 rows"):
        T @ Point[Camera](np.zeros((2, 3)))
    with pytest.raises(GeometryValueError, match="batches of 3 and 2 poses"):
        T @ Transform[Camera, Base](translation=np.zeros((2, 3)))
    with pytest.raises(GeometryValueError, match="3 rotations but 2 translations"):
        Transform[World, Camera](rotation=np.stack([np.eye(3)] * 3), translation=np.zeros((2, 3)))


def test_transform_pickles() -> None:
    T = Transform[World, Camera](rotation=rot_z(10), translation=[1, 2, 3])
    again = pickle.loads(pickle.dumps(T))
    assert type(again) is type(T)
    np.testing.assert_array_equal(again.matrix, T.matrix)
    assert T.is_close(again) and not T.is_close(Transform[World, Camera]())


def test_computed_values_are_read_only_to_callers() -> None:
    T = Transform[World, Camera](rotation=rot_z(30), translation=[1, 2, 3])
    composed = T @ Transform[Camera, Base](translation=[0, 0, 1])
    moved = T @ Point[Camera]([[1, 0, 0], [0, 1, 0]])
    for array in (composed.matrix, composed.rotation, composed.translation, np.asarray(moved), moved.xyz, T.inverse().matrix):
        with pytest.raises(ValueError, match="read-only"):
            array[0] = 7.0
    np.testing.assert_allclose(np.asarray(moved), np.asarray(T @ Point[Camera]([[1, 0, 0], [0, 1, 0]])))


def test_empty_batches_are_fine() -> None:
    T = Transform[World, Camera](rotation=np.zeros((0, 3, 3)), translation=np.zeros((0, 3)))
    assert len(T) == 0
    assert len(T @ Point[Camera](np.zeros((0, 3)))) == 0
    assert len(Transform[World, Camera]() @ Point[Camera](np.zeros((0, 3)))) == 0
    assert Transform[World, Camera].from_quat(np.zeros((0, 4)), np.zeros((0, 3)), order="xyzw").is_batch
