"""The frame algebra on `Geo` values: what ``a @ b``, ``a + b``, ``a - b``, ``-a``, ``a * s`` give.

Which *kind* an operation yields, and whether it is valid geometry, is `geolint.algebra`'s table, shared with
the linter and checked against the runtime; this module adds what only the type checker has: the frames, which
are mypy types here (a frame class, ``Literal["camera"]``, a TypeVar), and the carriers that exist only as
annotations. Each function returns None when the operands are not its business (mypy's own answer stands), else
an `Outcome`: the result kind and frames, and the problem to report, if any. Rules (column vectors;
``X[dst <- src]``):

- ``X[A <- B] @ p[B] -> p[A]``; ``X[A <- B] @ X[B <- C] -> X[A <- C]``; any other inner frame is ``geo-frame``.
- Row vectors: ``p[A] @ R[A <- B] -> p[B]`` (that is ``p @ R_BA.T``), so ``p_B @ R_AB`` without ``.T`` is
  ``geo-frame``.
- A translation reaching a vector (``R @ v + t``, ``R @ v - t``, w=1 under a 4x4 matrix) is ``geo-translation``.
- Hand-written inverses and compositions of arrays are typed through origin offsets: ``R[A <- B] @ t[B <- C]``
  is the offset from B's origin to C's, in A's axes; plus ``t[A <- B]`` it is ``t[A <- C]``. ``-t[A <- B]`` runs
  from B's origin to A's, so ``-R.T @ t`` is the inverse's translation. Offsets in different axes do not add.
- Affine combinations of point arrays (``(a + b) / 2``, ``0.25 * a + 0.75 * b``): see `affine`.
"""

from __future__ import annotations

from dataclasses import dataclass

from mypy.errorcodes import ErrorCode

from geolint import algebra as shared
from geolint.algebra import Kind
from geolint.mypy import messages
from geolint.mypy.errorcodes import GEO_FRAME, GEO_KIND, GEO_TRANSLATION
from geolint.mypy.geometry import (
    ARRAY,
    CLOUD,
    COVARIANCE,
    DIRECTION,
    HOMOGENEOUS_POINT,
    HOMOGENEOUS_VECTOR,
    NEGATED_ROTATION,
    ORIGIN_OFFSET,
    POINT,
    ROTATION,
    RUNTIME,
    TRANSFORM,
    TRANSLATION,
    TWIST,
    VECTOR,
    VECTOR_WITH_W1,
    WRENCH,
    Geo,
    same_frame,
)

FREE_KINDS = frozenset({VECTOR, DIRECTION})
LOCATED_KINDS = frozenset({POINT}) | FREE_KINDS
OPERATORS = frozenset({TRANSFORM, ROTATION})
OFFSET_KINDS = frozenset({TRANSLATION, ORIGIN_OFFSET})


@dataclass(frozen=True)
class Problem:
    code: ErrorCode
    message: str


@dataclass(frozen=True)
class Outcome:
    """The result of an operation (None: leave mypy's type) and the problem to report (None: fine)."""

    result: Geo | None
    problem: Problem | None = None


# What ``@`` can reach for each carrier (column vectors). A 4x4 matrix applied to a 3-vector is a shape error,
# not a frame error, and a runtime Transform takes any runtime value; the shared table says what comes out.
_APPLIES_TO = {
    (RUNTIME, TRANSFORM): frozenset({POINT, VECTOR, DIRECTION, CLOUD, TWIST, WRENCH, COVARIANCE}),
    (ARRAY, ROTATION): frozenset({POINT, VECTOR, DIRECTION}),
    (ARRAY, TRANSFORM): frozenset({HOMOGENEOUS_POINT, HOMOGENEOUS_VECTOR, VECTOR_WITH_W1}),
}


def shared_kind(kind: str) -> Kind | None:
    """The shared algebra's name for one of the plugin's kinds (None: a carrier only the plugin has, such as a
    point cloud or an origin offset, whose rules live here)."""
    try:
        return Kind(kind)
    except ValueError:
        return None


def matmul(left: Geo, right: Geo) -> Outcome | None:
    """``left @ right``: apply, compose, or rotate row vectors."""
    if left.family != right.family:
        return None
    if left.kind in OPERATORS and right.kind == left.kind:
        return _compose(left, right)
    if left.family == ARRAY and left.kind in (ROTATION, NEGATED_ROTATION) and right.kind in OFFSET_KINDS:
        return _rotate_offset(left, right)
    if left.kind in OPERATORS and right.kind in _APPLIES_TO.get((left.family, left.kind), ()):
        return _apply(left, right)
    if left.kind in LOCATED_KINDS and right.kind == ROTATION:
        return _rotate_rows(left, right)
    return None


def add(left: Geo, right: Geo) -> Outcome | None:
    """``left + right`` (either order of a translation)."""
    if left.family != right.family:
        return None
    if left.kind in OFFSET_KINDS and right.kind in OFFSET_KINDS:
        return _chain_offsets("+", left, right, left, right)
    if right.kind in OFFSET_KINDS and left.kind in LOCATED_KINDS:
        return _add_translation("+", left, right)
    if left.kind in OFFSET_KINDS and right.kind in LOCATED_KINDS:
        return _add_translation("+", right, left)
    return _same_frame_kinds("+", left, right, _shared(shared.add, left, right))


def subtract(left: Geo, right: Geo) -> Outcome | None:
    """``left - right``."""
    if left.family != right.family:
        return None
    if left.kind in OFFSET_KINDS and right.kind in OFFSET_KINDS:
        return _chain_offsets("-", left, right, left, _reversed_offset(right))
    if right.kind in OFFSET_KINDS and left.kind in LOCATED_KINDS:
        return _add_translation("-", left, right)
    return _same_frame_kinds("-", left, right, _shared(shared.sub, left, right))


def negate(value: Geo) -> Outcome | None:
    """``-value``: a direction stays a unit direction; an offset runs the other way; ``-R`` is kept for ``-R.T @ t``."""
    if value.family == ARRAY and value.kind in OFFSET_KINDS:
        return Outcome(_reversed_offset(value))
    if value.family == ARRAY and value.kind in (ROTATION, NEGATED_ROTATION):
        return Outcome(value.with_frames(*value.frames, kind=NEGATED_ROTATION if value.kind == ROTATION else ROTATION))
    if value.kind not in LOCATED_KINDS:
        return None
    verdict = shared.negate(Kind(value.kind))
    if verdict is None or verdict.problem is not None:
        # -p: the runtime has no such operator (mypy says so); on arrays a reflected point is left alone
        return None
    return Outcome(value.with_frames(value.frame, kind=verdict.kind.value))


def scale(value: Geo) -> Outcome | None:
    """``v * s``, ``s * v``, ``v / s``: a scaled vector stays a vector in its frame (a direction does not stay unit).

    A scaled point is left to mypy (plain ndarray for arrays): ``pts * 1e-3`` is a unit conversion, and inside an
    affine combination `affine` decides.
    """
    if value.kind not in FREE_KINDS:
        return None
    verdict = shared.scale(Kind(value.kind))
    if verdict is None:
        return None
    return Outcome(value.with_frames(value.frame, kind=verdict.kind.value), _problem(verdict.problem, value, value))


def homogenize(value: Geo, w: float) -> Outcome | None:
    """``[x; w]`` of a located array, by the shared table: w = 1 makes a point homogeneous, w = 0 a free vector.
    A free vector given w = 1 is carried as ``VectorWithW1`` (the result, no problem: the caller decides whether
    to report it now or when a 4x4 product meets it); a point given w = 0 is left to mypy."""
    if value.family != ARRAY or value.kind not in LOCATED_KINDS:
        return None
    verdict = shared.homogenize(Kind(value.kind), w)
    if verdict is None:
        return None
    if verdict.problem == shared.Problem.DIRECTION_TRANSLATED:
        return Outcome(value.with_frames(value.frame, kind=VECTOR_WITH_W1))
    if verdict.problem is not None:
        return None
    return Outcome(value.with_frames(value.frame, kind=verdict.kind.value))


def combination(kinds: list[str], weights: list[float], sample: Geo) -> Outcome | None:
    """``sum(w_i * x_i)`` of located arrays in one frame (`sample`'s): a point when the point weights sum to 1,
    a vector when they sum to 0; the problem says what the weights summed to otherwise."""
    shared_kinds = [shared_kind(kind) for kind in kinds]
    if any(kind is None for kind in shared_kinds):
        return None
    verdict = shared.affine_combination(shared_kinds, weights)  # type: ignore[arg-type]
    if verdict is None:
        return None
    if verdict.problem is not None:
        point_weight = sum(weight for kind, weight in zip(kinds, weights) if kind == POINT)
        return Outcome(None, Problem(GEO_KIND, messages.bad_affine_weights(sample, point_weight)))
    return Outcome(sample.with_frames(sample.frame, kind=verdict.kind.value))


def _shared(operation: object, left: Geo, right: Geo) -> shared.Outcome | None:
    left_kind, right_kind = shared_kind(left.kind), shared_kind(right.kind)
    if left_kind is None or right_kind is None or left.kind not in _ARITHMETIC or right.kind not in _ARITHMETIC:
        return None
    return operation(left_kind, right_kind)  # type: ignore[operator,no-any-return]


# Kinds whose sums and differences the shared table judges (operators and homogeneous arrays are array math).
_ARITHMETIC = LOCATED_KINDS | {TWIST, WRENCH}


def _same_frame_kinds(operator: str, left: Geo, right: Geo, verdict: shared.Outcome | None) -> Outcome | None:
    if verdict is None:
        return None
    problem = _problem(verdict.problem, left, right, operator)
    if problem is not None:
        return Outcome(None, problem)
    result = left.with_frames(left.frame, kind=verdict.kind.value)
    if same_frame(left.frame, right.frame) is False:
        return Outcome(result, Problem(GEO_FRAME, messages.mixed_frames(operator, left, right)))
    return Outcome(result)


def _problem(problem: shared.Problem | None, left: Geo, right: Geo, operator: str = "+") -> Problem | None:
    """The shared table's verdict as a mypy error: its code and the plugin's message, which names the frames."""
    if problem is None:
        return None
    if problem == shared.Problem.POINT_PLUS_POINT:
        return Problem(GEO_KIND, messages.points_added(left, right))
    if problem == shared.Problem.VECTOR_MINUS_POINT:
        return Problem(GEO_KIND, messages.point_subtracted_from_vector(left, right))
    if problem == shared.Problem.KIND_MISMATCH:
        return Problem(GEO_KIND, messages.different_kinds(operator, left, right))
    if problem == shared.Problem.DIRECTION_TRANSLATED:
        vector, translation = (left, right) if left.kind in FREE_KINDS else (right, left)
        return Problem(GEO_TRANSLATION, messages.translation_added_to_vector(operator, vector, translation))
    return None


def _compose(left: Geo, right: Geo) -> Outcome:
    result = left.with_frames(left.dst, right.src)
    if same_frame(left.src, right.dst) is False:
        return Outcome(result, Problem(GEO_FRAME, messages.composed_across_frames(left, right)))
    return Outcome(result)


def _apply(operator: Geo, value: Geo) -> Outcome:
    if same_frame(operator.src, value.frame) is False:
        result = value.with_frames(operator.dst)
        return Outcome(result, Problem(GEO_FRAME, messages.applied_to_wrong_frame(operator, value)))
    if value.kind == VECTOR_WITH_W1:
        problem = Problem(GEO_TRANSLATION, messages.translation_through_matrix(operator, value))
        return Outcome(None, problem)
    return Outcome(value.with_frames(operator.dst))


def _rotate_rows(rows: Geo, rotation: Geo) -> Outcome:
    result = rows.with_frames(rotation.src)
    if same_frame(rows.frame, rotation.dst) is False:
        return Outcome(result, Problem(GEO_FRAME, messages.rows_in_wrong_frame(rows, rotation)))
    return Outcome(result)


def _as_offset(value: Geo) -> Geo:
    """A translation ``t[A <- B]`` as the offset (in A, from A's origin, to B's origin)."""
    if value.kind == TRANSLATION:
        return value.with_frames(value.dst, value.dst, value.src, kind=ORIGIN_OFFSET)
    return value


def _reversed_offset(value: Geo) -> Geo:
    axes, start, end = _as_offset(value).frames
    return value.with_frames(axes, end, start, kind=ORIGIN_OFFSET)


def _rotate_offset(rotation: Geo, value: Geo) -> Outcome:
    """``R[A <- B] @ offset`` (in B) is the same offset in A's axes; ``-R`` also reverses it."""
    axes, start, end = _as_offset(value).frames
    result = value.with_frames(rotation.dst, start, end, kind=ORIGIN_OFFSET)
    if rotation.kind == NEGATED_ROTATION:
        result = _reversed_offset(result)
    if same_frame(rotation.src, axes) is False:
        return Outcome(result, Problem(GEO_FRAME, messages.applied_to_wrong_frame(rotation, value)))
    return Outcome(result)


def _chain_offsets(operator: str, left: Geo, right: Geo, first: Geo, second: Geo) -> Outcome | None:
    """``first + second`` of two offsets in the same axes: one must start where the other ends."""
    axes, start, end = _as_offset(first).frames
    other_axes, other_start, other_end = _as_offset(second).frames
    if same_frame(axes, other_axes) is False:
        return Outcome(None, Problem(GEO_FRAME, messages.mixed_frames(operator, left, right)))
    if same_frame(end, other_start):
        return Outcome(first.with_frames(axes, start, other_end, kind=ORIGIN_OFFSET))
    if same_frame(other_end, start):
        return Outcome(first.with_frames(axes, other_start, end, kind=ORIGIN_OFFSET))
    if same_frame(start, other_start) and same_frame(end, other_end):
        return None  # two estimates of one offset (averaged, compared): array math, not a composition
    if None in (same_frame(end, other_start), same_frame(other_end, start)):
        return None  # a frame we cannot read
    return Outcome(None, Problem(GEO_FRAME, messages.offsets_do_not_chain(operator, left, right)))


def _add_translation(operator: str, value: Geo, translation: Geo) -> Outcome | None:
    """``p + t``, ``p - t`` (``t`` the translation of a transform into p's frame); a vector must not be translated."""
    if translation.kind == ORIGIN_OFFSET and same_frame(translation.frames[0], translation.frames[1]) is not True:
        return None  # an offset between two other origins: not a translation of this value's frame
    result = value.with_frames(value.frame)
    if value.kind in FREE_KINDS:
        message = messages.translation_added_to_vector(operator, value, translation)
        return Outcome(result, Problem(GEO_TRANSLATION, message))
    if same_frame(value.frame, translation.dst) is False:
        return Outcome(result, Problem(GEO_FRAME, messages.mixed_frames(operator, value, translation)))
    return Outcome(result)
