"""numpy calls that keep or check frames: ``np.dot``, ``np.matmul``, ``np.asarray``, ``np.append``,
``np.linalg.inv``, and slicing a ``TransformMatrix`` into its rotation and translation.

Each is a plain function/method hook: numpy's own stubs still decide whether the call is valid, the hook
only refines the returned ndarray into a framed one (and reports frame problems through `algebra`).
"""

from __future__ import annotations

from functools import cache
from typing import Callable

from mypy.nodes import CallExpr, Expression, FloatExpr, IntExpr, RefExpr, SliceExpr, TupleExpr, UnaryExpr

from mypy.plugin import AttributeContext, FunctionContext, MethodContext
from mypy.types import Type

from geolint.knowledge import knowledge_base
from geolint.knowledge.markers import ArrayOperation
from geolint.mypy import algebra, fullnames as names, geometry
from geolint.mypy.geometry import (
    ARRAY,
    ROTATION,
    TRANSFORM,
    TRANSLATION,
)
from geolint.mypy.plugin_api import report_and_build


def dot(ctx: FunctionContext) -> Type:
    """``np.dot(a, b)``: the same frame algebra as ``a @ b``."""
    return _matmul_call(ctx, ctx.arg_types)


def matmul_ufunc_call(ctx: MethodContext) -> Type:
    """``np.matmul(a, b)``: a method call on numpy's gufunc object, told apart by the callee's name."""
    call = ctx.context
    if not (isinstance(call, CallExpr) and isinstance(call.callee, RefExpr)):
        return ctx.default_return_type
    if array_operation(call.callee.fullname) != ArrayOperation.MATMUL:
        return ctx.default_return_type
    return _matmul_call(ctx, ctx.arg_types)


def array_operation(fullname: str) -> str | None:
    """What a function of the array library geolint.typing builds on does to matrices, by the name mypy
    gives it (`KnowledgeBase.api_defined_as`); None for any other library's function."""
    base = knowledge_base()
    api = base.api_defined_as(fullname)
    if api is None or api.library != _array_library():
        return None
    return base.array_operation(api.qualified_name)


def is_array_library_method(fullname: str) -> bool:
    """A method of a class of that array library (`<ufunc class>.__call__`, where `np.matmul` lands)."""
    library = knowledge_base().library_of_module(fullname.partition(".")[0])
    return library is not None and library.name == _array_library()


@cache
def _array_library() -> str | None:
    library = knowledge_base().library_of_module(names.NDARRAY.partition(".")[0])
    return None if library is None else library.name


def asarray(ctx: FunctionContext) -> Type:
    """``np.asarray(Point[F])`` is a ``PointArray[F]`` (and so on for each runtime kind)."""
    value = _first_argument(ctx.arg_types)
    if value is None or value.family != geometry.RUNTIME:
        return ctx.default_return_type
    array = geometry.Geo(ARRAY, value.kind, value.frames)
    return geometry.build(ctx.api, array) or ctx.default_return_type


def append(ctx: FunctionContext) -> Type:
    """``np.append(v, 0)`` homogenizes a vector, ``np.append(p, 1)`` a point (`algebra.homogenize`);
    ``np.append(v, 1)`` marks the vector as carrying w=1, which a later 4x4 product reports as ``geo-translation``."""
    value = _first_argument(ctx.arg_types)
    if value is None or len(ctx.args) < 2 or len(ctx.args[1]) != 1:
        return ctx.default_return_type
    w = _number(ctx.args[1][0])
    outcome = algebra.homogenize(value, w) if w is not None else None
    if outcome is None or outcome.result is None:
        return ctx.default_return_type
    return geometry.build(ctx.api, outcome.result) or ctx.default_return_type


def inverse(ctx: FunctionContext) -> Type:
    """``np.linalg.inv(TransformMatrix[A, B])`` is a ``TransformMatrix[B, A]`` (same for rotations)."""
    value = _first_argument(ctx.arg_types)
    if value is None or value.family != ARRAY or value.kind not in (TRANSFORM, ROTATION):
        return ctx.default_return_type
    return geometry.build(ctx.api, value.with_frames(value.src, value.dst)) or ctx.default_return_type


def transform_matrix_item(ctx: MethodContext) -> Type:
    """``T[:3, :3]`` is the ``RotationMatrix[Dst, Src]`` of a ``TransformMatrix[Dst, Src]``, and ``T[:3, 3]``
    (or ``T[:3, -1]``, ``T[0:3, 3]``) its ``Translation[Dst, Src]``."""
    transform = geometry.read(ctx.type)
    if transform is None or not ctx.args or len(ctx.args[0]) != 1:
        return ctx.default_return_type
    index = ctx.args[0][0]
    if not (isinstance(index, TupleExpr) and len(index.items) == 2 and _is_first_three(index.items[0])):
        return ctx.default_return_type
    column = index.items[1]
    if _is_first_three(column):
        kind = ROTATION
    elif _number(column) in (3, -1):
        kind = TRANSLATION
    else:
        return ctx.default_return_type
    return geometry.build(ctx.api, transform.with_frames(transform.dst, transform.src, kind=kind)) or (
        ctx.default_return_type
    )


_TRANSFORM_PARTS = {"matrix": TRANSFORM, "rotation": ROTATION, "translation": TRANSLATION}


def transform_part(attribute: str) -> Callable[[AttributeContext], Type]:
    """``T.matrix`` / ``T.rotation`` / ``T.translation`` of a ``Transform[Dst, Src]`` are the framed ndarrays
    ``TransformMatrix[Dst, Src]`` / ``RotationMatrix[Dst, Src]`` / ``Translation[Dst, Src]``, so the raw
    matrix keeps its frames (``T.matrix @ np.append(v, 1)`` is then a ``geo-translation``)."""

    def hook(ctx: AttributeContext) -> Type:
        transform = geometry.read(ctx.type)
        # (AttributeContext.is_lvalue arrived after mypy 1.10)
        if transform is None or transform.kind != TRANSFORM or getattr(ctx, "is_lvalue", False):
            return ctx.default_attr_type
        part = geometry.Geo(ARRAY, _TRANSFORM_PARTS[attribute], transform.frames)
        return geometry.build(ctx.api, part) or ctx.default_attr_type

    return hook


def _matmul_call(ctx: FunctionContext | MethodContext, arg_types: list[list[Type]]) -> Type:
    if len(arg_types) < 2 or len(arg_types[0]) != 1 or len(arg_types[1]) != 1:
        return ctx.default_return_type
    left, right = geometry.read(arg_types[0][0]), geometry.read(arg_types[1][0])
    if left is None or right is None:
        return ctx.default_return_type
    return report_and_build(ctx, algebra.matmul(left, right))


def _first_argument(arg_types: list[list[Type]]) -> geometry.Geo | None:
    if not arg_types or len(arg_types[0]) != 1:
        return None
    return geometry.read(arg_types[0][0])


def _number(expr: Expression) -> float | None:
    if isinstance(expr, (IntExpr, FloatExpr)):
        return expr.value
    if isinstance(expr, UnaryExpr) and expr.op == "-" and isinstance(expr.expr, (IntExpr, FloatExpr)):
        return -expr.expr.value
    return None


def _is_first_three(expr: Expression) -> bool:
    """``:3`` or ``0:3``."""
    if not isinstance(expr, SliceExpr) or expr.stride is not None:
        return False
    begins_at_zero = expr.begin_index is None or _number(expr.begin_index) == 0
    return begins_at_zero and expr.end_index is not None and _number(expr.end_index) == 3


