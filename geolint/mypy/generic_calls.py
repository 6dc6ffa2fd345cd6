"""Calls of frame-generic functions: ``to_world(T: Transform[World, F], p: Point[F])`` given a
``Transform[World, Camera]`` and a ``Point[Body]``.

mypy would only say "Cannot infer value of type parameter F". A *function signature hook*, consulted for every
call but returning at once unless the callee is generic, reads which frame each framed argument gives each type
variable; when two arguments disagree it reports them by name (``geo-frame``) and hands mypy the signature with
that variable set to Any, so the vaguer message does not follow.
"""

from __future__ import annotations

from mypy.expandtype import expand_type
from mypy.nodes import Expression
from mypy.plugin import FunctionSigContext
from mypy.types import (
    AnyType,
    CallableType,
    FunctionLike,
    Instance,
    ProperType,
    Type,
    TypeOfAny,
    TypeVarType,
    get_proper_type,
)

from geolint.mypy import geometry, messages
from geolint.mypy.errorcodes import GEO_FRAME
from geolint.mypy.geometry import Geo


def check_frames(ctx: FunctionSigContext) -> FunctionLike:
    signature = ctx.default_signature
    if not signature.variables or not any(geometry.read(arg) for arg in signature.arg_types):
        return signature
    variables = {variable.id for variable in signature.variables}
    seen: dict[object, tuple[ProperType, str, Geo]] = {}
    for index, actuals in enumerate(ctx.args):
        formal = geometry.read(signature.arg_types[index]) if index < len(signature.arg_types) else None
        if formal is None or len(actuals) != 1:
            continue
        binds = [
            (position, frame) for position, frame in enumerate(formal.frames)
            if isinstance(frame, TypeVarType) and frame.id in variables
        ]
        actual_type = _type_of(ctx, actuals[0]) if binds else None
        actual = geometry.read(actual_type) if actual_type is not None else None
        if actual is None or not _is_a(actual_type, signature.arg_types[index]):
            continue  # another kind altogether: mypy's arg-type error says it
        name = signature.arg_names[index] or f"argument {index + 1}"
        for position, variable in binds:
            frame = actual.frames[position]
            earlier = seen.setdefault(variable.id, (frame, name, actual))
            if earlier[1] != name and geometry.same_frame(earlier[0], frame) is False:
                message = messages.generic_frames_disagree(
                    signature.name or "the call", variable.name or "?", earlier, (frame, name, actual)
                )
                ctx.api.fail(message, ctx.context, code=GEO_FRAME)
                return _without(signature, variable)
    return signature


def _is_a(actual: ProperType | None, formal_type: Type) -> bool:
    formal = get_proper_type(formal_type)
    return (
        isinstance(actual, Instance)
        and isinstance(formal, Instance)
        and actual.type.has_base(formal.type.fullname)
        and len(actual.args) == len(formal.args)
    )


def _type_of(ctx: FunctionSigContext, expr: Expression) -> ProperType | None:
    lookup = getattr(ctx.api, "lookup_type_or_none", None)
    known = lookup(expr) if lookup is not None else None
    return get_proper_type(known if known is not None else ctx.api.get_expression_type(expr))


def _without(signature: CallableType, variable: TypeVarType) -> CallableType:
    expanded = expand_type(signature, {variable.id: AnyType(TypeOfAny.from_error)})
    assert isinstance(expanded, CallableType)
    return expanded.copy_modified(variables=[v for v in signature.variables if v.id != variable.id])
