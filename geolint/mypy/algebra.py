"""The frame algebra, as plain functions over `Geo` values: what ``a @ b``, ``a + b``, ``a - b`` give.

Written once for both families (runtime classes and annotated ndarrays). Each function returns None when the
operands are not its business (mypy's own answer stands), else an `Outcome`: the result kind and frames, and
the problem to report, if any. Rules (column vectors; ``X[dst <- src]``):

- ``X[A <- B] @ p[B] -> p[A]`` (points, vectors, directions, homogeneous arrays); ``X[A <- B] @ X[B <- C] ->
  X[A <- C]``; any other inner frame is ``geo-frame``.
- Row vectors: ``p[A] @ R[A <- B] -> p[B]`` (that is ``p @ R_BA.T``), so ``p_B @ R_AB`` without ``.T`` is
  ``geo-frame``.
- A vector homogenized with w=1 under a 4x4 matrix, or ``v + t`` with a translation, is ``geo-translation``.
- euclid's affine algebra: point - point = vector, point +/- vector = point, vector +/- vector = vector;
  point + point and vector - point are ``geo-kind``.
"""

from __future__ import annotations

from dataclasses import dataclass

from mypy.errorcodes import ErrorCode

from geolint.mypy import messages
from geolint.mypy.errorcodes import GEO_FRAME, GEO_KIND, GEO_TRANSLATION
from geolint.mypy.geometry import (
    DIRECTION,
    HOMOGENEOUS_POINT,
    HOMOGENEOUS_VECTOR,
    POINT,
    CLOUD,
    COVARIANCE,
    ROTATION,
    TRANSFORM,
    TWIST,
    WRENCH,
    TRANSLATION,
    VECTOR,
    VECTOR_WITH_W1,
    Geo,
    same_frame,
)

FREE_KINDS = frozenset({VECTOR, DIRECTION})
LOCATED_KINDS = frozenset({POINT}) | FREE_KINDS
OPERATORS = frozenset({TRANSFORM, ROTATION})
SPATIAL_KINDS = frozenset({TWIST, WRENCH})  # six-vectors: summed only with their own kind, in one frame


@dataclass(frozen=True)
class Problem:
    code: ErrorCode
    message: str


@dataclass(frozen=True)
class Outcome:
    """The result of an operation (None: leave mypy's type) and the problem to report (None: fine)."""

    result: Geo | None
    problem: Problem | None = None


def matmul(left: Geo, right: Geo) -> Outcome | None:
    """``left @ right``: apply, compose, or rotate row vectors."""
    if left.family != right.family:
        return None
    if left.kind in OPERATORS and right.kind == left.kind:
        return _compose(left, right)
    if left.kind in OPERATORS and right.kind in _APPLIES_TO[left.family, left.kind]:
        return _apply(left, right)
    if left.kind in LOCATED_KINDS and right.kind == ROTATION:
        return _rotate_rows(left, right)
    return None


def add(left: Geo, right: Geo) -> Outcome | None:
    """``left + right`` (either order of a translation)."""
    if left.family != right.family:
        return None
    if right.kind == TRANSLATION and left.kind in LOCATED_KINDS:
        return _add_translation(left, right)
    if left.kind == TRANSLATION and right.kind in LOCATED_KINDS:
        return _add_translation(right, left)
    if left.kind == right.kind and left.kind in SPATIAL_KINDS:
        return _same_frame_result("+", left, right, left)
    if left.kind not in LOCATED_KINDS or right.kind not in LOCATED_KINDS:
        return None
    if left.kind == POINT and right.kind == POINT:
        return Outcome(None, Problem(GEO_KIND, messages.points_added(left, right)))
    result_kind = POINT if POINT in (left.kind, right.kind) else VECTOR
    return _same_frame_result("+", left, right, left.with_frames(left.frame, kind=result_kind))


def subtract(left: Geo, right: Geo) -> Outcome | None:
    """``left - right``."""
    if left.family == right.family and left.kind == right.kind and left.kind in SPATIAL_KINDS:
        return _same_frame_result("-", left, right, left)
    if left.family != right.family or left.kind not in LOCATED_KINDS or right.kind not in LOCATED_KINDS:
        return None
    if left.kind in FREE_KINDS and right.kind == POINT:
        return Outcome(None, Problem(GEO_KIND, messages.point_subtracted_from_vector(left, right)))
    result_kind = VECTOR if left.kind == right.kind == POINT else left.kind
    if left.kind == DIRECTION:
        result_kind = VECTOR  # a difference of unit vectors is not unit
    return _same_frame_result("-", left, right, left.with_frames(left.frame, kind=result_kind))


def scale(value: Geo) -> Outcome | None:
    """``v * s``, ``s * v``, ``v / s``, ``-v``: a scaled vector stays a vector in its frame (not a direction)."""
    if value.kind in FREE_KINDS:
        return Outcome(value.with_frames(value.frame, kind=VECTOR))
    return None


# Which kinds each operator applies to by ``@`` (column vectors).
_APPLIES_TO = {
    ("runtime", TRANSFORM): frozenset({POINT, VECTOR, DIRECTION, CLOUD, TWIST, WRENCH, COVARIANCE}),
    ("array", ROTATION): frozenset({POINT, VECTOR, DIRECTION}),
    ("array", TRANSFORM): frozenset({HOMOGENEOUS_POINT, HOMOGENEOUS_VECTOR, VECTOR_WITH_W1}),
}


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


def _add_translation(value: Geo, translation: Geo) -> Outcome:
    result = value.with_frames(value.frame)
    if value.kind in FREE_KINDS:
        return Outcome(result, Problem(GEO_TRANSLATION, messages.translation_added_to_vector(value, translation)))
    if same_frame(value.frame, translation.dst) is False:
        return Outcome(result, Problem(GEO_FRAME, messages.mixed_frames("+", value, translation)))
    return Outcome(result)


def _same_frame_result(operator: str, left: Geo, right: Geo, result: Geo) -> Outcome:
    if same_frame(left.frame, right.frame) is False:
        return Outcome(result, Problem(GEO_FRAME, messages.mixed_frames(operator, left, right)))
    return Outcome(result)
