"""Frame-aware signatures for third-party calls that move points and vectors.

Written as plugin hooks rather than ``.pyi`` stubs on purpose: trimesh and pytransform3d ship their own
annotations (``py.typed``), and a second stub package for them would shadow or clash with those. A hook
only refines the return type of a call the package's own stubs already accepted, and reports when a vector
is about to be translated. Covered:

- ``trimesh.transform_points(points, matrix, translate=True)``: a ``VectorArray``/``DirectionArray`` with
  ``translate`` not literally False is ``geo-translation``; frames follow ``TransformMatrix[A, B]``.
- ``pytransform3d.transformations.vector_to_point(v)`` on a vector is ``geo-translation`` (it sets w=1);
  ``vector_to_point(PointArray[F])`` is ``HomogeneousPoints[F]``, ``vector_to_direction(VectorArray[F])``
  is ``HomogeneousVectors[F]``.
- ``pytransform3d.transformations.transform(A2B, PA)``: frames follow ``TransformMatrix[A, B]`` like ``@``.
"""

from __future__ import annotations

from mypy.nodes import NameExpr
from mypy.plugin import FunctionContext
from mypy.types import Type

from geolint.mypy import algebra, geometry, messages
from geolint.mypy.algebra import Outcome, Problem
from geolint.mypy.errorcodes import GEO_TRANSLATION
from geolint.mypy.geometry import (
    ARRAY,
    DIRECTION,
    POINT,
    TRANSFORM,
    VECTOR,
    Geo,
)
from geolint.mypy.plugin_api import report_and_build


def trimesh_transform_points(ctx: FunctionContext) -> Type:
    points, matrix = _argument(ctx, "points"), _argument(ctx, "matrix")
    if points is None or points.family != ARRAY or points.kind not in (POINT, VECTOR, DIRECTION):
        return ctx.default_return_type
    translates = not _is_false(ctx, "translate")
    if translates and points.kind != POINT:
        problem = Problem(GEO_TRANSLATION, messages.translating_call("trimesh.transform_points", points))
        return report_and_build(ctx, Outcome(points, problem))
    if matrix is None or matrix.family != ARRAY or matrix.kind != TRANSFORM:
        return ctx.default_return_type
    # transform_points takes (N, 3) rows but applies the matrix as ``T @ p``: the column-vector rule.
    as_rotation = matrix.with_frames(matrix.dst, matrix.src, kind=geometry.ROTATION)
    outcome = algebra.matmul(as_rotation, points)
    if outcome is not None and outcome.problem is not None:
        problem = Problem(outcome.problem.code, messages.applied_to_wrong_frame(matrix, points))
        outcome = Outcome(outcome.result, problem)
    return report_and_build(ctx, outcome)


def pytransform3d_vector_to_point(ctx: FunctionContext) -> Type:
    """``vector_to_point(v)`` appends w = 1; a vector given it is reported here, at the call that translates it."""
    value = _argument(ctx, "v")
    outcome = algebra.homogenize(value, 1) if value is not None else None
    if outcome is None or outcome.result is None:
        return ctx.default_return_type
    if value is not None and outcome.result.kind == geometry.VECTOR_WITH_W1:
        outcome = Outcome(outcome.result, Problem(GEO_TRANSLATION, messages.vector_made_point("vector_to_point", value)))
    return report_and_build(ctx, outcome)


def pytransform3d_vector_to_direction(ctx: FunctionContext) -> Type:
    """``vector_to_direction(v)`` appends w = 0."""
    value = _argument(ctx, "v")
    outcome = algebra.homogenize(value, 0) if value is not None else None
    if outcome is None:
        return ctx.default_return_type
    return report_and_build(ctx, outcome)


def pytransform3d_transform(ctx: FunctionContext) -> Type:
    matrix, value = _argument(ctx, "A2B"), _argument(ctx, "PA")
    if matrix is None or value is None:
        return ctx.default_return_type
    return report_and_build(ctx, algebra.matmul(matrix, value))


def _argument(ctx: FunctionContext, name: str) -> Geo | None:
    if name not in ctx.callee_arg_names:
        return None
    types = ctx.arg_types[ctx.callee_arg_names.index(name)]
    return geometry.read(types[0]) if len(types) == 1 else None


def _is_false(ctx: FunctionContext, name: str) -> bool:
    if name not in ctx.callee_arg_names:
        return False
    exprs = ctx.args[ctx.callee_arg_names.index(name)]
    return len(exprs) == 1 and isinstance(exprs[0], NameExpr) and exprs[0].fullname == "builtins.False"
