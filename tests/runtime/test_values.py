"""Points, vectors, directions: construction, frames, the algebra and its refusals, error messages."""

from __future__ import annotations

import pickle
import typing

import numpy as np
import pytest

import geolint
from geolint import (
    Direction,
    Frame,
    FrameMismatchError,
    GeolintError,
    GeometryTypeError,
    GeometryValueError,
    Point,
    Vector,
)


class World(Frame):
    pass


class Camera(Frame):
    pass


class BaseLink(Frame, name="base_link"):
    pass


# ---- frames and subscripting ----------------------------------------------------------------------------


def test_class_and_string_frames_name_the_same_frame() -> None:
    assert Point[World] is Point["World"]
    assert Point[BaseLink] is Point["base_link"]
    assert Point[typing.Literal["base_link"]] is Point[BaseLink]
    assert Point[BaseLink]([1, 2, 3]).frame == "base_link"
    assert Vector["camera"]([1, 0, 0]).frame == "camera"


def test_each_kind_has_its_own_framed_classes() -> None:
    assert Point[World] is not Vector[World]
    assert Direction[World] is not Vector[World]
    assert issubclass(Point[World], Point) and issubclass(Direction[World], Vector)
    assert isinstance(Point[World]([0, 0, 0]), Point[World])
    assert not isinstance(Point[World]([0, 0, 0]), Point[Camera])


def test_typevar_subscripts_stay_generic_aliases() -> None:
    F = typing.TypeVar("F")
    alias = Point[F]
    assert typing.get_origin(alias) is Point
    assert typing.get_args(alias) == (F,)


@pytest.mark.parametrize("bad", [3, None, "", " padded ", Frame, object])
def test_bad_frame_arguments_are_refused(bad: object) -> None:
    with pytest.raises(GeometryTypeError):
        Point[bad]  # type: ignore[valid-type]


def test_frame_arity_is_checked() -> None:
    with pytest.raises(GeometryTypeError, match=r"Point takes one frame"):
        Point[World, Camera]  # type: ignore[misc]
    with pytest.raises(GeometryTypeError, match=r"Transform takes 2 frames"):
        geolint.Transform[World]  # type: ignore[misc]
    with pytest.raises(GeometryTypeError, match="already has its frames"):
        Point[World][Camera]  # type: ignore[index]


def test_frames_are_not_instantiated_and_values_need_a_frame() -> None:
    with pytest.raises(GeometryTypeError, match="has no instances"):
        World()
    with pytest.raises(GeometryTypeError, match=r"Point needs a frame: write Point\[World\]\(xyz\)"):
        Point([1, 2, 3])


# ---- construction, arrays, repr --------------------------------------------------------------------------


def test_coordinates_are_copied_read_only_float64() -> None:
    source = np.array([1, 2, 3])
    p = Point[World](source)
    source[0] = 100
    coords = np.asarray(p)
    assert coords.dtype == np.float64 and coords.tolist() == [1.0, 2.0, 3.0]
    with pytest.raises(ValueError):
        coords[0] = 5.0
    assert np.array(p, dtype=np.float32).dtype == np.float32


def test_repr_shows_kind_frame_and_coordinates() -> None:
    assert repr(Point[World]([0.3, 0.3, 0.5])) == "Point[World]([0.3, 0.3, 0.5])"
    assert repr(Vector["camera"]([0.1 + 0.2, 0, -1])) == "Vector[camera]([0.3, 0.0, -1.0])"
    assert repr(Direction[World]([0, 0, 2])) == "Direction[World]([0.0, 0.0, 1.0])"


@pytest.mark.parametrize(
    ("xyz", "message"),
    [
        ([1.0, 2.0], r"xyz must have shape \(3,\) or \(N, 3\), got \(2,\)"),
        (np.zeros((4, 2)), r"got \(4, 2\)"),
        (np.zeros((2, 3, 3)), r"got \(2, 3, 3\)"),
        ([1.0, np.nan, 3.0], r"non-finite entry \(nan at index \(1,\)\)"),
        ([[0, 0, 0], [1, np.inf, 0]], r"non-finite entry \(inf at index \(1, 1\)\)"),
        (["a", "b", "c"], "must hold real numbers"),
        ([1 + 2j, 0, 0], "must hold real numbers"),
        ([True, False, True], "must hold real numbers"),
    ],
)
def test_bad_coordinates_raise_a_clear_error(xyz: object, message: str) -> None:
    with pytest.raises(GeometryValueError, match=message) as caught:
        Point[World](xyz)  # type: ignore[arg-type]
    assert isinstance(caught.value, ValueError) and isinstance(caught.value, GeolintError)


def test_relabelling_a_value_through_a_constructor_is_refused() -> None:
    p = Point[Camera]([1, 2, 3])
    with pytest.raises(GeometryTypeError, match="explicit: pass np.asarray"):
        Point[World](p)
    assert Point[World](np.asarray(p)).frame == "World"  # the explicit spelling works


def test_direction_is_normalised_and_rejects_zero() -> None:
    d = Direction[World]([3.0, 0.0, 4.0])
    np.testing.assert_allclose(np.asarray(d), [0.6, 0.0, 0.8])
    batch = Direction[World]([[0, 0, 2], [1, 1, 0]])
    np.testing.assert_allclose(batch.norm(), [1.0, 1.0])
    with pytest.raises(GeometryValueError, match="zero-length"):
        Direction[World]([0, 0, 0])
    with pytest.raises(GeometryValueError, match=r"row 1"):
        Direction[World]([[1, 0, 0], [0, 0, 0]])


def test_values_pickle_round_trip() -> None:
    for value in (Point[World]([1, 2, 3]), Direction["cam"]([0, 1, 0]), Vector[BaseLink]([[1, 2, 3], [4, 5, 6]])):
        copy = pickle.loads(pickle.dumps(value))
        assert type(copy) is type(value)
        np.testing.assert_array_equal(np.asarray(copy), np.asarray(value))


# ---- the algebra ------------------------------------------------------------------------------------------


def test_valid_algebra() -> None:
    p, q = Point[World]([1, 2, 3]), Point[World]([0, 1, 1])
    v = Vector[World]([1, 0, 0])
    assert isinstance(p - q, Vector) and (p - q).frame == "World"
    np.testing.assert_allclose(np.asarray(p - q), [1, 1, 2])
    assert type(p + v) is Point[World]
    np.testing.assert_allclose(np.asarray(p + v), [2, 2, 3])
    assert type(v + p) is Point[World]
    assert type(p - v) is Point[World]
    np.testing.assert_allclose(np.asarray(v + v), [2, 0, 0])
    np.testing.assert_allclose(np.asarray(2 * v), [2, 0, 0])
    np.testing.assert_allclose(np.asarray(v * np.float32(0.5)), [0.5, 0, 0])
    np.testing.assert_allclose(np.asarray(v / 4), [0.25, 0, 0])
    np.testing.assert_allclose(np.asarray(-v), [-1, 0, 0])
    d = Direction[World]([0, 0, 1])
    assert type(d + d) is Vector[World] and (d + d).norm() == pytest.approx(2.0)
    assert type(3 * d) is Vector[World]
    assert p.distance_to(q) == pytest.approx(np.sqrt(6))
    assert v.dot(Vector[World]([2, 5, 0])) == pytest.approx(2.0)
    np.testing.assert_allclose(np.asarray(v.cross(Vector[World]([0, 1, 0]))), [0, 0, 1])
    assert type(Vector[World]([0, 0, 5]).direction()) is Direction[World]


def test_batches_broadcast_with_single_values() -> None:
    points = Point[World]([[0, 0, 0], [1, 1, 1]])
    moved = points + Vector[World]([1, 0, 0])
    np.testing.assert_allclose(np.asarray(moved), [[1, 0, 0], [2, 1, 1]])
    assert len(points) == 2
    assert type(points[1]) is Point[World]
    np.testing.assert_allclose(np.asarray(points[1]), [1, 1, 1])
    np.testing.assert_allclose(np.asarray(Vector[World]([[1, 0, 0], [0, 2, 0]]) * np.array([2.0, 0.5])), [[2, 0, 0], [0, 1, 0]])
    with pytest.raises(GeometryTypeError, match="single value"):
        len(Point[World]([0, 0, 0]))


def test_point_plus_point_is_a_geometry_type_error() -> None:
    p = Point[World]([1, 2, 3])
    with pytest.raises(GeometryTypeError, match=r"Point\[World\] \+ Point\[World\]: adding two points is not defined") as caught:
        p + p  # type: ignore[operator]
    assert isinstance(caught.value, TypeError)


@pytest.mark.parametrize(
    ("operation", "message"),
    [
        (lambda p, v: 2 * p, "scaling a point depends on where the origin is"),
        (lambda p, v: p * 2, "scaling a point"),
        (lambda p, v: -p, "negating a point"),
        (lambda p, v: v - p, "a vector minus a point is not defined"),
        (lambda p, v: p + np.ones(3), r"wrap the array first, e\.g\. Vector\[World\]\(array\)"),
        (lambda p, v: np.ones(3) + p, "wrap the array first"),
        (lambda p, v: v + np.ones(3), "wrap the array first"),
        (lambda p, v: np.eye(3) @ p, r"ndarray of shape \(3, 3\) @ Point\[World\]: a raw matrix"),
        (lambda p, v: np.eye(3) @ v, "a raw matrix"),
        (lambda p, v: p @ v, "a transform goes on the left"),
        (lambda p, v: v * "2", "scales by a real number only"),
        (lambda p, v: v * v, "scales by a real number only"),
        (lambda p, v: bool(p), "ambiguous"),
    ],
)
def test_invalid_operations_are_refused_with_a_reason(operation, message: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(GeometryTypeError, match=message):
        operation(Point[World]([1, 2, 3]), Vector[World]([1, 0, 0]))


def test_numpy_ufuncs_refuse_wrapped_values() -> None:
    with pytest.raises(TypeError):
        np.add(Point[World]([1, 2, 3]), 1.0)
    with pytest.raises(TypeError):
        np.matmul(np.eye(3), Vector[World]([1, 2, 3]))


@pytest.mark.parametrize(
    ("operation", "text"),
    [
        (lambda a, b: a - b, "Point[World] - Point[Camera]"),
        (lambda a, b: a + (b - b), "Point[World] + Vector[Camera]"),
        (lambda a, b: (a - a) + (b - b), "Vector[World] + Vector[Camera]"),
        (lambda a, b: (a - a).dot(b - b), "Vector[World] dot Vector[Camera]"),
        (lambda a, b: (a - a).cross(b - b), "Vector[World] cross Vector[Camera]"),
    ],
)
def test_frame_mismatches_name_both_frames_and_the_operation(operation, text: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(FrameMismatchError) as caught:
        operation(Point[World]([1, 2, 3]), Point[Camera]([1, 2, 3]))
    assert text in str(caught.value)
    assert "(World vs Camera)" in str(caught.value)
    assert isinstance(caught.value, ValueError)


def test_scalars_must_be_finite_and_division_by_zero_is_refused() -> None:
    v = Vector[World]([1, 0, 0])
    with pytest.raises(GeometryValueError, match="finite"):
        v * float("nan")
    with pytest.raises(GeometryValueError, match="division by zero"):
        v / 0


def test_is_close_compares_kind_frame_and_coordinates() -> None:
    p = Point[World]([1, 2, 3])
    assert p.is_close(Point["World"]([1, 2, 3 + 1e-12]))
    assert not p.is_close(Point[World]([1, 2, 3.1]))
    assert not p.is_close(Point[Camera]([1, 2, 3]))
    assert not p.is_close(Vector[World]([1, 2, 3]))
    assert not p.is_close(Point[World]([[1, 2, 3]]))
