"""The geometry algebra's table, and the runtime agreeing with it operation by operation."""

from __future__ import annotations

import pytest

from geolint import algebra
from geolint.algebra import Frames, Kind, Outcome, Problem

K = Kind


@pytest.mark.parametrize(
    ("left", "right", "expected"),
    [
        (K.POINT, K.POINT, Outcome(K.POINT, Problem.POINT_PLUS_POINT)),
        (K.POINT, K.VECTOR, Outcome(K.POINT)),
        (K.VECTOR, K.POINT, Outcome(K.POINT)),
        (K.DIRECTION, K.DIRECTION, Outcome(K.VECTOR)),
        (K.POINT, K.TRANSLATION, Outcome(K.POINT)),
        (K.DIRECTION, K.TRANSLATION, Outcome(K.DIRECTION, Problem.DIRECTION_TRANSLATED)),
        (K.TRANSLATION, K.VECTOR, Outcome(K.VECTOR, Problem.DIRECTION_TRANSLATED)),
        (K.TWIST, K.TWIST, Outcome(K.TWIST)),
        (K.TWIST, K.WRENCH, Outcome(K.UNKNOWN, Problem.KIND_MISMATCH)),
        (K.ROTATION, K.POINT, None),
        (K.UNKNOWN, K.POINT, None),
    ],
)
def test_add(left: Kind, right: Kind, expected: Outcome | None) -> None:
    assert algebra.add(left, right) == expected


@pytest.mark.parametrize(
    ("left", "right", "expected"),
    [
        (K.POINT, K.POINT, Outcome(K.VECTOR)),  # a displacement, not a unit direction
        (K.POINT, K.DIRECTION, Outcome(K.POINT)),
        (K.VECTOR, K.POINT, Outcome(K.UNKNOWN, Problem.VECTOR_MINUS_POINT)),
        (K.DIRECTION, K.VECTOR, Outcome(K.VECTOR)),
        (K.UNKNOWN, K.UNKNOWN, None),
    ],
)
def test_sub(left: Kind, right: Kind, expected: Outcome | None) -> None:
    assert algebra.sub(left, right) == expected


def test_negation_and_scaling() -> None:
    assert algebra.negate(K.DIRECTION) == Outcome(K.DIRECTION)
    assert algebra.negate(K.POINT) == Outcome(K.UNKNOWN, Problem.POINT_NEGATED)
    assert algebra.scale(K.DIRECTION) == Outcome(K.VECTOR)
    assert algebra.scale(K.POINT) == Outcome(K.POINT, Problem.POINT_SCALED)


@pytest.mark.parametrize(
    ("operator", "value", "expected"),
    [
        (K.ROTATION, K.POINT, K.POINT),
        (K.ROTATION, K.DIRECTION, K.DIRECTION),
        (K.TRANSFORM, K.HOMOGENEOUS_POINT, K.HOMOGENEOUS_POINT),
        (K.TRANSFORM, K.HOMOGENEOUS_VECTOR, K.HOMOGENEOUS_VECTOR),
        (K.TRANSFORM, K.TRANSFORM, K.TRANSFORM),
        (K.TRANSFORM, K.TWIST, K.TWIST),
        (K.POINT, K.ROTATION, None),
    ],
)
def test_apply(operator: Kind, value: Kind, expected: Kind | None) -> None:
    outcome = algebra.apply(operator, value)
    assert (outcome.kind if outcome else None) == expected


def test_rows_compositions_and_normalisation() -> None:
    assert algebra.apply_rows(K.POINT, K.ROTATION) == Outcome(K.POINT)  # `pts @ R.T`
    assert algebra.apply_rows(K.DIRECTION, K.ROTATION) == Outcome(K.DIRECTION)
    assert algebra.apply_rows(K.POINT, K.TRANSFORM) is None  # a 4x4's transpose is not its inverse
    assert algebra.apply_rows(K.ROTATION, K.ROTATION) is None  # not rows of values
    assert algebra.apply(K.ROTATION, K.TRANSFORM) == Outcome(K.TRANSFORM)
    assert algebra.apply(K.TRANSFORM, K.ROTATION) == Outcome(K.TRANSFORM)
    assert algebra.normalize(K.VECTOR) == Outcome(K.DIRECTION)
    assert algebra.normalize(K.UNKNOWN) == Outcome(K.DIRECTION)
    assert algebra.normalize(K.ROTATION) is None
    assert algebra.sub(K.TRANSLATION, K.TRANSLATION) == Outcome(K.TRANSLATION)
    assert algebra.sub(K.VECTOR, K.TRANSLATION) == Outcome(K.VECTOR, Problem.DIRECTION_TRANSLATED)


def test_rigid_motion_translates_points_only() -> None:
    assert algebra.rigid_apply(K.POINT) == Outcome(K.POINT)
    assert algebra.rigid_apply(K.DIRECTION) == Outcome(K.DIRECTION, Problem.DIRECTION_TRANSLATED)
    assert algebra.rotate_only(K.POINT) == Outcome(K.POINT, Problem.POINT_NOT_TRANSLATED)
    assert algebra.rotate_only(K.VECTOR) == Outcome(K.VECTOR)


def test_homogeneous_w() -> None:
    assert algebra.homogenize(K.POINT, 1) == Outcome(K.HOMOGENEOUS_POINT)
    assert algebra.homogenize(K.DIRECTION, 0) == Outcome(K.HOMOGENEOUS_VECTOR)
    assert algebra.homogenize(K.DIRECTION, 1).problem == Problem.DIRECTION_TRANSLATED
    assert algebra.homogenize(K.POINT, 0).problem == Problem.POINT_NOT_TRANSLATED
    assert algebra.homogenize(K.POINT, 2) is None
    assert algebra.dehomogenize(K.HOMOGENEOUS_POINT) == Outcome(K.POINT)
    assert [algebra.marked_by_w(w) for w in (1, 1.0, 0, 2)] == [K.POINT, K.POINT, K.VECTOR, None]


@pytest.mark.parametrize(
    ("weights", "expected"),
    [((0.5, 0.5), Outcome(K.POINT)), ((1.0, -1.0), Outcome(K.VECTOR)), ((1.0, 1.0), Outcome(K.UNKNOWN, Problem.BAD_AFFINE_WEIGHTS))],
)
def test_affine_combination_of_points(weights: tuple[float, float], expected: Outcome) -> None:
    assert algebra.affine_combination([K.POINT, K.POINT], weights) == expected


def test_transpose_is_an_inverse_only_for_rotations() -> None:
    assert algebra.transpose(K.ROTATION) == Outcome(K.ROTATION)
    assert algebra.transpose(K.TRANSFORM) == Outcome(K.UNKNOWN, Problem.TRANSPOSE_AS_INVERSE)
    assert algebra.inverse(K.TRANSFORM) == Outcome(K.TRANSFORM)
    assert algebra.block_of(K.TRANSFORM, "rotation") == K.ROTATION
    assert algebra.block_of(K.TRANSFORM, "translation") == K.TRANSLATION


def test_frames() -> None:
    world_cam, cam_lidar = Frames(dst="world", src="cam"), Frames(dst="cam", src="lidar")
    assert algebra.compose_frames(world_cam, cam_lidar).frames == Frames(dst="world", src="lidar")
    bad = algebra.compose_frames(cam_lidar, world_cam)
    assert bad.problem == Problem.FRAME_MISMATCH and bad.disagreement == ("lidar", "world")
    assert algebra.apply_frames(world_cam, Frames(frame="cam")) == algebra.FrameOutcome(Frames(frame="world"))
    assert algebra.apply_frames(world_cam, Frames(frame="lidar")).problem == Problem.FRAME_MISMATCH
    assert algebra.apply_frames(world_cam, Frames()).problem is None  # unknown frame: say nothing
    assert world_cam.inverted() == Frames(dst="cam", src="world")
    assert algebra.chain([world_cam, cam_lidar, Frames(dst="lidar", src="imu")]).frames == Frames("world", "imu")
    assert algebra.combine_frames(Frames(frame="a"), Frames(frame="b")).problem == Problem.FRAME_MISMATCH
    # a comparison that cannot tell (None) is no mismatch; one that must be sure says False
    assert algebra.compose_frames(world_cam, Frames("camera", "lidar"), same=lambda a, b: None).problem is None
    assert algebra.compose_frames(world_cam, Frames("camera", "lidar"), same=lambda a, b: False).problem == Problem.FRAME_MISMATCH


# --- the runtime agrees with the table ----------------------------------------------------

np = pytest.importorskip("numpy")
runtime = pytest.importorskip("geolint.runtime")

RUNTIME_KIND = {K.POINT: "Point", K.VECTOR: "Vector", K.DIRECTION: "Direction"}


def make(kind: Kind, frame: str = "world"):  # type: ignore[no-untyped-def]
    return getattr(runtime, RUNTIME_KIND[kind])[frame]([0.3, 0.4, 0.5])


def kind_of(value) -> Kind:  # type: ignore[no-untyped-def]
    for kind in (K.DIRECTION, K.POINT, K.VECTOR):  # most specific first: Direction is a Vector
        if isinstance(value, getattr(runtime, RUNTIME_KIND[kind])):
            return kind
    raise AssertionError(value)


PAIRS = [(a, b) for a in RUNTIME_KIND for b in RUNTIME_KIND]


@pytest.mark.parametrize(("symbol", "table"), [("+", algebra.add), ("-", algebra.sub)])
@pytest.mark.parametrize(("left", "right"), PAIRS)
def test_runtime_arithmetic_agrees(symbol: str, table, left: Kind, right: Kind) -> None:  # type: ignore[no-untyped-def]
    expected = table(left, right)
    a, b = make(left), make(right)
    if expected is None or expected.problem is not None:
        with pytest.raises(runtime.GeometryTypeError):
            a + b if symbol == "+" else a - b
        return
    result = a + b if symbol == "+" else a - b
    assert kind_of(result) == expected.kind


@pytest.mark.parametrize("kind", list(RUNTIME_KIND))
def test_runtime_negation_agrees(kind: Kind) -> None:
    expected = algebra.negate(kind)
    if expected.problem is not None:
        with pytest.raises(runtime.GeometryTypeError):
            -make(kind)
    else:
        assert kind_of(-make(kind)) == expected.kind


@pytest.mark.parametrize("kind", list(RUNTIME_KIND))
def test_runtime_transform_application_agrees(kind: Kind) -> None:
    pose = runtime.Transform["map", "world"](np.eye(3), [1.0, 2.0, 3.0])
    moved = pose @ make(kind)
    assert kind_of(moved) == algebra.apply(K.TRANSFORM, kind).kind
    assert moved.frame == algebra.apply_frames(Frames("map", "world"), Frames(frame="world")).frames.frame


def test_runtime_composition_and_inverse_agree() -> None:
    a = runtime.Transform["map", "world"](np.eye(3), [1.0, 0.0, 0.0])
    b = runtime.Transform["world", "cam"](np.eye(3), [0.0, 1.0, 0.0])
    composed = algebra.compose_frames(Frames("map", "world"), Frames("world", "cam")).frames
    assert ((a @ b).dst, (a @ b).src) == (composed.dst, composed.src)
    assert (a.inverse().dst, a.inverse().src) == (Frames("map", "world").inverted().dst, "map")
    with pytest.raises(runtime.FrameMismatchError):
        b @ b
