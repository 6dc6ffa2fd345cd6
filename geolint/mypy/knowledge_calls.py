"""Library calls judged from the knowledge base (`stubs/`), the same entries the linter reads.

For a call whose fully qualified name the knowledge base knows, the hook binds mypy's arguments to
the stub's parameters (by the library's own parameter names), reports a quaternion typed in one
component order (`QuaternionWXYZ`) passed where the stub says the other, and gives the call the
return type the stub states (`Rotation.as_quat()` is a `QuaternionXYZW`). Nothing else changes:
mypy has already checked the call against the library's own annotations.
"""

from __future__ import annotations

from functools import lru_cache, partial
from typing import Any, Callable

from mypy.nodes import Expression, IntExpr, MemberExpr, NameExpr, StrExpr
from mypy.plugin import FunctionContext, MethodContext
from mypy.types import CallableType, Instance, Overloaded, ProperType, Type, TypeType, get_proper_type

from geolint.knowledge import SCALAR_FIRST, SCALAR_LAST, Api, Bound, Signature, agreed, knowledge_base
from geolint.knowledge.binding import UNDECIDED, CallShape, bind_shape
from geolint.algebra import HOMOGENEOUS, Kind
from geolint.mypy import algebra, geometry, messages
from geolint.mypy.algebra import Outcome, Problem
from geolint.mypy.errorcodes import GEO_QUATERNION_ORDER, GEO_TRANSLATION
from geolint.mypy.geometry import ARRAY, DIRECTION, ROTATION, TRANSFORM, VECTOR, VECTOR_WITH_W1, Geo, lookup_class
from geolint.mypy.plugin_api import report_and_build

_ORDER_CLASSES = {SCALAR_LAST: "geolint.typing.QuaternionXYZW", SCALAR_FIRST: "geolint.typing.QuaternionWXYZ"}
_CLASS_ORDERS = {fullname: order for order, fullname in _ORDER_CLASSES.items()}
_CallContext = FunctionContext | MethodContext


@lru_cache(maxsize=None)
def hook_for(fullname: str) -> Callable[[Any], Type] | None:
    """The hook for a call of `fullname`, when its stub says something about quaternions. mypy names
    an overloaded method called on its class `"from_quat of Rotation"`: the class then comes from the
    call's receiver type."""
    method, of, owner = fullname.partition(" of ")
    if of:
        if not any(api.qualified_name.endswith(f".{owner}.{method}") for api in _quaternion_apis()):
            return None
        return lambda ctx: _check_method_of_receiver(ctx, method)
    api = knowledge_base().api(fullname)
    if api is not None and api.signatures and all(signature.applies_transform for signature in api.signatures):
        return lambda ctx: _check_moving_call(ctx, api)
    if api is None or api not in _quaternion_apis():
        return None
    return lambda ctx: _check_call(ctx, api)


@lru_cache(maxsize=1)
def _quaternion_apis() -> frozenset[Api]:
    return frozenset(api for api in knowledge_base().apis() if any(_states_quaternions(signature) for signature in api.signatures))


def _check_method_of_receiver(ctx: MethodContext, method: str) -> Type:
    found = (knowledge_base().api(name) for name in _receiver_names(get_proper_type(ctx.type), method))
    api = next((api for api in found if api is not None), None)
    return _check_call(ctx, api) if api is not None else ctx.default_return_type


def _receiver_names(receiver: ProperType, method: str) -> list[str]:
    """Qualified names the method may have: from the overload's definition, from the class it returns (a
    `from_*` constructor), or from the class it is on."""
    if isinstance(receiver, Overloaded):
        first = receiver.items[0]
        names = [first.definition.fullname] if first.definition is not None and first.definition.fullname.endswith(f".{method}") else []
        returned = get_proper_type(first.ret_type)
        return names + ([f"{returned.type.fullname}.{method}"] if isinstance(returned, Instance) else [])
    if isinstance(receiver, TypeType) and isinstance(receiver.item, Instance):
        return [f"{receiver.item.type.fullname}.{method}"]
    if isinstance(receiver, CallableType) and receiver.is_type_obj():
        return [f"{receiver.type_object().fullname}.{method}"]
    if isinstance(receiver, Instance):
        return [f"{receiver.type.fullname}.{method}"]
    return []


def _states_quaternions(signature: Signature) -> bool:
    returns = signature.returns
    if returns is not None and returns.quaternion_order is not None:
        return True
    return any(parameter.geometry is not None and parameter.geometry.quaternion_order for parameter in signature.parameters)


def _check_call(ctx: _CallContext, api: Api) -> Type:
    arguments = _arguments(ctx)
    bounds = bind_shape(api, CallShape([], arguments), _literal)
    for name, expression in arguments.items():
        wanted = agreed(bounds, partial(_parameter_order, name=name))
        given = _order_of_type(ctx.api.expr_checker.accept(expression)) if wanted is not None else None  # type: ignore[attr-defined]
        if wanted is not None and given is not None and given != wanted:
            ctx.api.fail(
                f"{api.qualified_name.rsplit('.', 2)[-2] if api.qualified_name.count('.') > 1 else api.qualified_name}"
                f".{api.qualified_name.rpartition('.')[2]} reads `{name}` as ({', '.join(wanted)}), "
                f"but it is a quaternion in ({', '.join(given)}) order",
                expression,
                code=GEO_QUATERNION_ORDER,
            )
    produced = agreed(bounds, lambda bound: bound.signature.returns.quaternion_order if bound.signature.returns else None)
    return _quaternion_type(ctx, produced) or ctx.default_return_type


def _check_moving_call(ctx: _CallContext, api: Api) -> Type:
    """A call that moves points or vectors (`Signature.applies_transform`), as GEO101/GEO102 read it: a free
    vector where the stub moves a point is `geo-translation`; otherwise the result is the argument made
    homogeneous, or moved by the transform argument into its frame."""
    arguments = _arguments(ctx)
    bounds = bind_shape(api, CallShape([], arguments), _literal)
    values = {name: geometry.read(types[0]) for name, types in zip(ctx.callee_arg_names, ctx.arg_types) if name is not None and len(types) == 1}
    matrix = values.get(agreed(bounds, _transform_parameter) or "")
    homogeneous = agreed(bounds, lambda bound: bound.signature.returns.kind if bound.signature.returns and bound.signature.returns.kind in HOMOGENEOUS else None)
    called = _callee_text(ctx)
    for name, value in values.items():
        moved_as = agreed(bounds, partial(_parameter_kind, name=name))
        if value is None or value.family != ARRAY or value is matrix or (moved_as is None and value.kind not in HOMOGENEOUS):
            continue
        if homogeneous is not None:
            outcome = algebra.homogenize(value, 1 if homogeneous is Kind.HOMOGENEOUS_POINT else 0)
            if outcome is not None and outcome.result is not None and outcome.result.kind == VECTOR_WITH_W1:
                outcome = Outcome(outcome.result, Problem(GEO_TRANSLATION, messages.vector_made_point(called.rpartition(".")[2], value)))
            return report_and_build(ctx, outcome)
        if moved_as is Kind.POINT and value.kind in (VECTOR, DIRECTION):
            return report_and_build(ctx, Outcome(value, Problem(GEO_TRANSLATION, messages.translating_call(called, value))))
        if matrix is None or matrix.family != ARRAY or matrix.kind != TRANSFORM:
            return ctx.default_return_type
        return report_and_build(ctx, _moved_by(matrix, value))
    return ctx.default_return_type


def _moved_by(matrix: Geo, value: Geo) -> Outcome | None:
    """A homogeneous value times the 4x4; a 3-vector by the column rule on its rotation block (the call
    adds the translation itself), reported in the call's own words."""
    if value.kind in HOMOGENEOUS:
        return algebra.matmul(matrix, value)
    outcome = algebra.matmul(matrix.with_frames(matrix.dst, matrix.src, kind=ROTATION), value)
    if outcome is not None and outcome.problem is not None:
        return Outcome(outcome.result, Problem(outcome.problem.code, messages.applied_to_wrong_frame(matrix, value)))
    return outcome


def _arguments(ctx: _CallContext) -> dict[str, Expression]:
    return {name: expressions[0] for name, expressions in zip(ctx.callee_arg_names, ctx.args) if name is not None and len(expressions) == 1}


def _transform_parameter(bound: Bound) -> str | None:
    return next((parameter.name for parameter in bound.signature.parameters if parameter.geometry is not None and parameter.geometry.kind is Kind.TRANSFORM), None)


def _parameter_kind(bound: Bound, name: str) -> Kind | None:
    parameter = bound.signature.parameter(name)
    kind = parameter.geometry.kind if parameter is not None and parameter.geometry is not None else None
    return kind if kind in (Kind.POINT, Kind.VECTOR, Kind.DIRECTION) else None


def _callee_text(ctx: _CallContext) -> str:
    """The callee as written (`trimesh.transform_points`, `pt.vector_to_point`), for messages."""
    callee = getattr(ctx.context, "callee", None)
    parts: list[str] = []
    while isinstance(callee, MemberExpr):
        parts.append(callee.name)
        callee = callee.expr
    if isinstance(callee, NameExpr):
        parts.append(callee.name)
    return ".".join(reversed(parts))


def _parameter_order(bound: Bound, name: str) -> str | None:
    parameter = bound.signature.parameter(name)
    return parameter.geometry.quaternion_order if parameter is not None and parameter.geometry is not None else None


def _literal(expression: Expression) -> object:
    if isinstance(expression, NameExpr) and expression.fullname in ("builtins.True", "builtins.False", "builtins.None"):
        return {"builtins.True": True, "builtins.False": False, "builtins.None": None}[expression.fullname]
    if isinstance(expression, (IntExpr, StrExpr)):
        return expression.value
    return UNDECIDED


def _order_of_type(typ: Type) -> str | None:
    proper = get_proper_type(typ)
    return _CLASS_ORDERS.get(proper.type.fullname) if isinstance(proper, Instance) else None


def _quaternion_type(ctx: _CallContext, order: str | None) -> Type | None:
    if order is None:
        return None
    info = lookup_class(ctx.api, _ORDER_CLASSES[order])
    return Instance(info, []) if info is not None else None  # None: geolint.typing is not part of this build
