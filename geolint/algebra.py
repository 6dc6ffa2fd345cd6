"""The geometry algebra, stated once: the kinds a value can have and what each operation makes of them.

Dependency-free (no numpy, no mypy, no libcst), so the linter's fact base, the frames graph, the mypy
plugin and the runtime all read the same table, and ``p - q`` is the same kind everywhere.

Conventions: column vectors, ``X[dst <- src]`` (an operator maps values expressed in ``src`` into
``dst``). Every function is pure and total: it returns an `Outcome` (the result kind and, when the
operation is not valid geometry, the `Problem`), or ``None`` when the operation is not the algebra's
business (say, ``rotation + point``: array math nobody can judge) — callers then know nothing.

Decisions worth stating:

- ``p - q`` is a free VECTOR (not a unit direction): a displacement has a length.
- Negating a unit DIRECTION gives a DIRECTION (``-n`` is still a unit normal, still only rotated);
  negating a POINT is an error (it depends on where the origin is).
- A DIRECTION scaled, or added to another free vector, is a plain VECTOR.
- ``R @ x`` keeps the kind of x (a point rotated about the origin is still a point); ``R @ x + t``
  is a rigid motion: fine for a point, an error for a free vector (it must not be translated).
  Rows (``x @ R.T``) are rotated the same way.
- Two rotations compose to a rotation; a rigid transform composed with a rotation or a transform, on
  either side, is a rigid transform (a rotation is one without translation).
- ``x / |x|`` is a unit DIRECTION, whatever located value x was (for a point: its direction from the origin).
- ``T @ [x; w]``: w = 1 marks a point, w = 0 a free vector; a free vector with w = 1 is translated
  (error), a point with w = 0 loses its translation (error).
- Affine combinations ``sum(w_i p_i)`` of points are a POINT when the weights sum to 1 (midpoints,
  centroids, lerp), a VECTOR when they sum to 0, and an error otherwise.
- The transpose of a rotation is its inverse; the transpose of a 4x4 rigid transform is NOT its
  inverse (the translation ends up in the bottom row): the result is UNKNOWN and the operation a problem.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import Final, Iterable, Sequence


class Kind(str, Enum):
    """The geometric kind of a value. The values match the mypy plugin's kind names."""

    POINT = "point"  # a location: rotated and translated (w = 1)
    VECTOR = "vector"  # a free vector (displacement, velocity, force): rotated only (w = 0)
    DIRECTION = "direction"  # a unit free vector (normal, axis, ray direction)
    ROTATION = "rotation"  # a 3x3 rotation matrix, quaternion or rotation object
    TRANSLATION = "translation"  # the translation part of a rigid transform
    TRANSFORM = "transform"  # a rigid transform / pose (4x4 or an object)
    HOMOGENEOUS_POINT = "homogeneous point"  # [x; 1]
    HOMOGENEOUS_VECTOR = "homogeneous vector"  # [v; 0]
    TWIST = "twist"  # a spatial velocity (6-vector)
    WRENCH = "wrench"  # a spatial force (6-vector)
    UNKNOWN = "unknown"


class Problem(str, Enum):
    """Why an operation is not valid geometry. Each maps onto a lint rule family."""

    POINT_PLUS_POINT = "point-plus-point"  # GEO103
    DIRECTION_TRANSLATED = "direction-translated"  # GEO101
    POINT_NOT_TRANSLATED = "point-not-translated"  # GEO102
    VECTOR_MINUS_POINT = "vector-minus-point"
    POINT_NEGATED = "point-negated"
    POINT_SCALED = "point-scaled"
    BAD_AFFINE_WEIGHTS = "bad-affine-weights"
    FRAME_MISMATCH = "frame-mismatch"  # GEO201/GEO202
    TRANSPOSE_AS_INVERSE = "transpose-as-inverse"  # GEO204
    KIND_MISMATCH = "kind-mismatch"  # twist + wrench and the like


@dataclass(frozen=True)
class Outcome:
    """What an operation yields, and what is wrong with it (None: valid)."""

    kind: Kind
    problem: Problem | None = None


FREE: Final = frozenset({Kind.VECTOR, Kind.DIRECTION})
LOCATED = frozenset({Kind.POINT}) | FREE
OPERATORS: Final = frozenset({Kind.ROTATION, Kind.TRANSFORM})
HOMOGENEOUS: Final = frozenset({Kind.HOMOGENEOUS_POINT, Kind.HOMOGENEOUS_VECTOR})
SPATIAL: Final = frozenset({Kind.TWIST, Kind.WRENCH})


def is_free(kind: Kind) -> bool:
    """A free vector (rotated only, never translated)."""
    return kind in FREE


# --- operators applied to values ----------------------------------------------------------

# `op @ x`: which kinds an operator applies to and what it makes of them. A rigid transform
# applied to a runtime Point / Vector knows the kind and does the right thing; applied to a
# homogeneous array the w decides. A 4x4 applied to a plain 3-vector is a shape error, not ours.
_APPLY: Final[dict[tuple[Kind, Kind], Kind]] = {
    (Kind.ROTATION, Kind.POINT): Kind.POINT,
    (Kind.ROTATION, Kind.VECTOR): Kind.VECTOR,
    (Kind.ROTATION, Kind.DIRECTION): Kind.DIRECTION,
    (Kind.ROTATION, Kind.TRANSLATION): Kind.TRANSLATION,
    (Kind.ROTATION, Kind.ROTATION): Kind.ROTATION,
    (Kind.TRANSFORM, Kind.POINT): Kind.POINT,
    (Kind.TRANSFORM, Kind.VECTOR): Kind.VECTOR,
    (Kind.TRANSFORM, Kind.DIRECTION): Kind.DIRECTION,
    (Kind.TRANSFORM, Kind.HOMOGENEOUS_POINT): Kind.HOMOGENEOUS_POINT,
    (Kind.TRANSFORM, Kind.HOMOGENEOUS_VECTOR): Kind.HOMOGENEOUS_VECTOR,
    (Kind.TRANSFORM, Kind.TRANSFORM): Kind.TRANSFORM,
    (Kind.ROTATION, Kind.TRANSFORM): Kind.TRANSFORM,
    (Kind.TRANSFORM, Kind.ROTATION): Kind.TRANSFORM,
    (Kind.TRANSFORM, Kind.TWIST): Kind.TWIST,  # the adjoint
    (Kind.TRANSFORM, Kind.WRENCH): Kind.WRENCH,
}


def apply(operator: Kind, value: Kind) -> Outcome | None:
    """``operator @ value`` (column vectors): rotate, transform, or compose."""
    result = _APPLY.get((operator, value))
    return None if result is None else Outcome(result)


def apply_rows(value: Kind, operator: Kind) -> Outcome | None:
    """``x @ operator`` with x as rows (``(N, 3) @ (3, 3)``): ``(operator.T @ x.T).T``, so what `apply` makes of
    x under the operator's transpose. A rigid transform's transpose is not its inverse: None."""
    if value not in LOCATED:
        return None
    transposed = transpose(operator)
    if transposed is None or transposed.problem is not None:
        return None
    return apply(transposed.kind, value)


def rigid_apply(value: Kind) -> Outcome | None:
    """``R @ x + t``: a rigid motion written out. A free vector must not be translated."""
    if value == Kind.POINT:
        return Outcome(Kind.POINT)
    if value in FREE:
        return Outcome(value, Problem.DIRECTION_TRANSLATED)
    return None


def rotate_only(value: Kind) -> Outcome | None:
    """``R @ x`` where x came from a rigid transform's rotation block alone (``T[:3, :3] @ x``)."""
    if value in FREE:
        return Outcome(value)
    if value == Kind.POINT:
        return Outcome(Kind.POINT, Problem.POINT_NOT_TRANSLATED)
    return None


# --- homogeneous coordinates ---------------------------------------------------------------


def marked_by_w(w: float) -> Kind | None:
    """The kind a homogeneous w marks: 1 a point (a transform translates it), 0 a free vector (it is only
    rotated); None for any other w."""
    if w == 1:
        return Kind.POINT
    if w == 0:
        return Kind.VECTOR
    return None


def homogenize(value: Kind, w: float) -> Outcome | None:
    """``[x; w]``: w = 1 for a point, w = 0 for a free vector; the other pairings are errors."""
    marked = marked_by_w(w)
    if marked is None:
        return None
    if value == Kind.POINT:
        if marked == Kind.POINT:
            return Outcome(Kind.HOMOGENEOUS_POINT)
        return Outcome(Kind.HOMOGENEOUS_VECTOR, Problem.POINT_NOT_TRANSLATED)
    if value in FREE:
        if marked in FREE:
            return Outcome(Kind.HOMOGENEOUS_VECTOR)
        return Outcome(Kind.HOMOGENEOUS_POINT, Problem.DIRECTION_TRANSLATED)
    return None


def dehomogenize(value: Kind) -> Outcome | None:
    """``x[:3]`` of a homogeneous value (after division by w for a point)."""
    if value == Kind.HOMOGENEOUS_POINT:
        return Outcome(Kind.POINT)
    if value == Kind.HOMOGENEOUS_VECTOR:
        return Outcome(Kind.VECTOR)
    return None


# --- affine arithmetic ---------------------------------------------------------------------


def add(left: Kind, right: Kind) -> Outcome | None:
    """``left + right`` (euclid's affine algebra; a translation moves points only)."""
    pair = (left, right)
    if pair == (Kind.POINT, Kind.POINT):
        return Outcome(Kind.POINT, Problem.POINT_PLUS_POINT)
    if Kind.POINT in pair and (left in FREE or right in FREE):
        return Outcome(Kind.POINT)
    if left in FREE and right in FREE:
        return Outcome(Kind.VECTOR)
    if Kind.TRANSLATION in pair:
        other = right if left == Kind.TRANSLATION else left
        if other == Kind.POINT:
            return Outcome(Kind.POINT)
        if other in FREE:
            return Outcome(other, Problem.DIRECTION_TRANSLATED)
        if other == Kind.TRANSLATION:
            return Outcome(Kind.TRANSLATION)
        return None
    if left in SPATIAL and right in SPATIAL:
        return Outcome(left) if left == right else Outcome(Kind.UNKNOWN, Problem.KIND_MISMATCH)
    return None


def sub(left: Kind, right: Kind) -> Outcome | None:
    """``left - right``: point - point is a vector, point - vector a point, vector - point an error."""
    if right == Kind.TRANSLATION:
        return _minus_translation(left)
    if left == Kind.POINT and right == Kind.POINT:
        return Outcome(Kind.VECTOR)
    if left == Kind.POINT and right in FREE:
        return Outcome(Kind.POINT)
    if left in FREE and right == Kind.POINT:
        return Outcome(Kind.UNKNOWN, Problem.VECTOR_MINUS_POINT)
    if left in FREE and right in FREE:
        return Outcome(Kind.VECTOR)
    if left in SPATIAL and right in SPATIAL:
        return Outcome(left) if left == right else Outcome(Kind.UNKNOWN, Problem.KIND_MISMATCH)
    return None


def _minus_translation(left: Kind) -> Outcome | None:
    """``left - t``: a point moved back; a free vector must not be translated; two translations differ by the
    translation between their origins (as `add` chains them)."""
    if left in (Kind.POINT, Kind.TRANSLATION):
        return Outcome(left)
    if left in FREE:
        return Outcome(Kind.VECTOR, Problem.DIRECTION_TRANSLATED)
    return None


def negate(value: Kind) -> Outcome | None:
    """``-value``: a direction stays a unit direction; a point has no negation."""
    if value == Kind.POINT:
        return Outcome(Kind.UNKNOWN, Problem.POINT_NEGATED)
    if value in FREE or value in SPATIAL or value == Kind.TRANSLATION:
        return Outcome(value)
    return None


def scale(value: Kind) -> Outcome | None:
    """``value * s`` for a scalar s: a scaled direction is no longer unit; a scaled point depends on the origin."""
    if value == Kind.POINT:
        return Outcome(Kind.POINT, Problem.POINT_SCALED)
    if value in FREE:
        return Outcome(Kind.VECTOR)
    if value in SPATIAL or value == Kind.TRANSLATION:
        return Outcome(value)
    return None


def normalize(value: Kind) -> Outcome | None:
    """``x / |x|``: a unit direction, for any located value x (UNKNOWN included: the division says it);
    normalising an operator (a quaternion) is not this algebra's business."""
    if value in LOCATED or value == Kind.UNKNOWN:
        return Outcome(Kind.DIRECTION)
    return None


def affine_combination(kinds: Sequence[Kind], weights: Sequence[float], tolerance: float = 1e-9) -> Outcome | None:
    """``sum(w_i * x_i)``: points with weights summing to 1 give a point, to 0 a vector.

    Free vectors in the sum may carry any weight (they do not count towards the point weights).
    """
    if len(kinds) != len(weights) or not kinds:
        return None
    if any(kind not in LOCATED for kind in kinds):
        return None
    point_weight = sum(weight for kind, weight in zip(kinds, weights) if kind == Kind.POINT)
    if not any(kind == Kind.POINT for kind in kinds):
        return Outcome(Kind.VECTOR)
    if abs(point_weight - 1.0) <= tolerance:
        return Outcome(Kind.POINT)
    if abs(point_weight) <= tolerance:
        return Outcome(Kind.VECTOR)
    return Outcome(Kind.UNKNOWN, Problem.BAD_AFFINE_WEIGHTS)


# --- inverse and transpose -----------------------------------------------------------------


def inverse(value: Kind) -> Outcome | None:
    """``inv(x)``: an operator's inverse is an operator of the same kind (frames swapped)."""
    if value in OPERATORS:
        return Outcome(value)
    return None


def transpose(value: Kind) -> Outcome | None:
    """``x.T``: a rotation's inverse; a rigid transform's transpose is not its inverse."""
    if value == Kind.ROTATION:
        return Outcome(Kind.ROTATION)
    if value == Kind.TRANSFORM:
        return Outcome(Kind.UNKNOWN, Problem.TRANSPOSE_AS_INVERSE)
    if value in LOCATED or value in HOMOGENEOUS:
        return Outcome(value)  # row form of the same values
    return None


def block_of(value: Kind, block: str) -> Kind | None:
    """The kind of a block of a 4x4 transform: ``"rotation"`` (``[:3, :3]``) or ``"translation"`` (``[:3, 3]``)."""
    if value != Kind.TRANSFORM:
        return None
    return {"rotation": Kind.ROTATION, "translation": Kind.TRANSLATION}.get(block)


# --- frames --------------------------------------------------------------------------------


@dataclass(frozen=True)
class Frames:
    """The frames of an operator (``dst <- src``) or a value (``frame``); None where unknown."""

    dst: str | None = None
    src: str | None = None
    frame: str | None = None

    @property
    def is_operator(self) -> bool:
        return self.dst is not None or self.src is not None

    def inverted(self) -> Frames:
        return Frames(dst=self.src, src=self.dst)


@dataclass(frozen=True)
class FrameOutcome:
    frames: Frames
    problem: Problem | None = None
    # the two frames that disagree, (expected, found), when problem is FRAME_MISMATCH
    disagreement: tuple[str, str] | None = None


def _differ(a: str | None, b: str | None, same: object = None) -> bool:
    """Whether two frames are known to differ. `same` answers True, False, or None when the two names cannot
    be compared (then they are not known to differ)."""
    if a is None or b is None:
        return False
    if callable(same):
        return same(a, b) is False
    return a != b


def compose_frames(left: Frames, right: Frames, same: object = None) -> FrameOutcome:
    """``X_ab @ X_bc = X_ac``: the inner frames must agree. `same` compares two frame names (default ==;
    True, False, or None for names it cannot compare)."""
    result = Frames(dst=left.dst, src=right.src)
    if _differ(left.src, right.dst, same):
        return FrameOutcome(result, Problem.FRAME_MISMATCH, (left.src, right.dst))  # type: ignore[arg-type]
    return FrameOutcome(result)


def apply_frames(operator: Frames, value: Frames, same: object = None) -> FrameOutcome:
    """``X_ab @ x_b = x_a``: the operator's source frame must be the value's frame."""
    result = Frames(frame=operator.dst)
    if _differ(operator.src, value.frame, same):
        return FrameOutcome(result, Problem.FRAME_MISMATCH, (operator.src, value.frame))  # type: ignore[arg-type]
    return FrameOutcome(result)


def combine_frames(left: Frames, right: Frames, same: object = None) -> FrameOutcome:
    """``x_a + y_a`` / ``x_a - y_a``: both operands must be in one frame."""
    frame = left.frame if left.frame is not None else right.frame
    if _differ(left.frame, right.frame, same):
        return FrameOutcome(Frames(frame=frame), Problem.FRAME_MISMATCH, (left.frame, right.frame))  # type: ignore[arg-type]
    return FrameOutcome(Frames(frame=frame))


def chain(operators: Iterable[Frames], same: object = None) -> FrameOutcome:
    """A left-to-right product ``X_1 @ X_2 @ ... @ X_n``: the first mismatch, or the composed frames."""
    items = list(operators)
    if not items:
        return FrameOutcome(Frames())
    current = FrameOutcome(items[0])
    for item in items[1:]:
        step = compose_frames(current.frames, item, same)
        if step.problem is not None:
            return step
        current = step
    return current
