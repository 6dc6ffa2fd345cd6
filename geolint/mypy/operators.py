"""Binary operators on framed values: ``T @ p``, ``p - q``, ``R @ v + t``, ``2.0 * v``.

The typing trick is a pair of hooks per operator method:

1. a *method signature hook* reads the operand types. When both are framed kinds and `algebra` has an
   answer, it rewrites every overload item to ``(other: <the operand's type>) -> <the inferred result>``, so
   mypy accepts the call without its generic "Unsupported operand types" error (which names no frame);
2. the *method hook* then reports the precise problem under a geolint error code (``geo-frame``,
   ``geo-kind``, ``geo-translation``) and returns the inferred result type.

When either operand is not framed (a raw ndarray, a float), both hooks leave mypy's own behaviour alone.
mypy names the method after the receiver's class, so the hooks fire for ``PointArray.__add__`` even
though the method is numpy's.
"""

from __future__ import annotations

from typing import Callable

from mypy.nodes import Context, Expression, OpExpr
from mypy.plugin import CheckerPluginInterface, MethodContext, MethodSigContext
from mypy.subtypes import is_same_type
from mypy.types import CallableType, FunctionLike, Instance, Type, get_proper_type

from geolint.mypy import affine, algebra, fullnames as names, geometry, messages
from geolint.mypy.algebra import Outcome, Problem
from geolint.mypy.errorcodes import GEO_FRAME, GEO_KIND
from geolint.mypy.geometry import Geo

BinaryRule = Callable[[Geo, Geo], "Outcome | None"]

# operator method -> (rule, whether the receiver is the left operand)
BINARY_RULES: dict[str, tuple[BinaryRule, bool]] = {
    "__matmul__": (algebra.matmul, True),
    "__add__": (algebra.add, True),
    "__rmatmul__": (algebra.matmul, False),
    "__radd__": (algebra.add, False),
    "__sub__": (algebra.subtract, True),
    "__rsub__": (algebra.subtract, False),
}
SCALING_OPERATORS = frozenset({"__mul__", "__rmul__", "__truediv__", "__neg__"})
# The runtime refuses a bare ndarray here (it cannot know its kind or frame); so does the plugin, statically.
_SYMBOL = {"__matmul__": "@", "__add__": "+", "__sub__": "-"}


def outcome(
    operator: str,
    receiver: Type,
    operand: Type | None,
    receiver_is_left: bool | None = None,
    context: Context | None = None,
    api: CheckerPluginInterface | None = None,
) -> Outcome | None:
    """What `algebra` says about ``receiver <operator> operand`` (None: not a framed operation)."""
    combination = affine.at(context) if context is not None and api is not None else None
    if combination is not None and api is not None:
        judged = _affine_outcome(api, combination)
        if judged is not None:
            return judged
    receiver_geo = geometry.read(receiver)
    operand_geo = geometry.read(operand) if operand is not None else None
    rule, receiver_is_left_by_name = BINARY_RULES.get(operator, (None, True))
    if receiver_is_left is None:
        receiver_is_left = receiver_is_left_by_name
    refused = _raw_array_refused(operator, receiver, receiver_geo, operand, operand_geo, receiver_is_left)
    if refused is not None:
        return refused
    if receiver_geo is None:
        return None
    for geo in (receiver_geo, operand_geo):
        misread = geometry.misread_string_frame(geo) if geo is not None else None
        if geo is not None and misread is not None:
            return Outcome(None, Problem(GEO_FRAME, messages.misread_string_frame(geo, misread)))
    if operator in SCALING_OPERATORS:
        if operand_geo is not None:
            return None  # vector * vector is numpy's elementwise product; no frame meaning to add
        if operator == "__neg__":
            return algebra.negate(receiver_geo)
        return algebra.scale(receiver_geo)
    if operand_geo is None or rule is None:
        return None
    if receiver_is_left:
        return rule(receiver_geo, operand_geo)
    return rule(operand_geo, receiver_geo)


def _raw_array_refused(
    operator: str,
    receiver: Type,
    receiver_geo: Geo | None,
    operand: Type | None,
    operand_geo: Geo | None,
    receiver_is_left: bool,
) -> Outcome | None:
    """A runtime value meeting a bare ndarray in ``@``, ``+``, ``-`` (either side): the runtime raises, so the
    plugin reports ``geo-kind``. mypy would otherwise accept it through numpy's reflected operator."""
    symbol = _SYMBOL.get(operator.replace("__r", "__", 1))
    if symbol is None or operand is None:
        return None
    if receiver_geo is not None and receiver_geo.family == geometry.RUNTIME and _is_raw_array(operand, operand_geo):
        value = receiver_geo
    elif (
        not receiver_is_left  # ``array - point`` is numpy's business; only its reflected call follows a refusal
        and operand_geo is not None
        and operand_geo.family == geometry.RUNTIME
        and _is_raw_array(receiver, receiver_geo)
    ):
        value = operand_geo
    else:
        return None
    return Outcome(None, Problem(GEO_KIND, messages.raw_array_operand(symbol, value)))


def _affine_outcome(api: CheckerPluginInterface, combination: affine.Combination) -> Outcome | None:
    """An operation inside a weighted combination of annotated arrays (see `affine`), judged on all its terms."""
    lookup = getattr(api, "lookup_type_or_none", None)
    if lookup is None:
        return None
    geos: list[Geo] = []
    for term, _ in combination.terms:
        known = lookup(term)
        geo = geometry.read(known) if known is not None else None
        if geo is None or geo.family != geometry.ARRAY or geo.kind not in algebra.LOCATED_KINDS:
            return None
        geos.append(geo)
    points = [geo for geo in geos if geo.kind == geometry.POINT]
    if not points or combination.outermost and len(points) < 2:
        return None  # p + 0.5 * v and the like: the ordinary rules know those
    mixed = next((geo for geo in geos if geometry.same_frame(geos[0].frame, geo.frame) is False), None)
    if mixed is not None:
        verdict: Outcome | None = Outcome(None, Problem(GEO_FRAME, messages.mixed_frames("+", geos[0], mixed)))
    else:
        weights = [weight for _, weight in combination.terms]
        verdict = algebra.combination([geo.kind for geo in geos], weights, points[0])
    if verdict is not None and verdict.problem is not None and not combination.outermost:
        return Outcome(points[0])  # a step on the way (the a + b of (a + b) / 2): the outermost one judges
    return verdict


class _LastAnswer:
    """mypy asks the signature hook once per overload item of the same operation (the runtime's ``__matmul__``
    has about ten): the answer for the previous item, reused while the operation is the same objects."""

    key: tuple[object, ...] = ()
    answer: tuple[Outcome | None, Type | None] = (None, None)


def signature_hook(operator: str) -> Callable[[MethodSigContext], FunctionLike]:
    def hook(ctx: MethodSigContext) -> FunctionLike:
        operand_expr = _single_operand(ctx.args)
        if operand_expr is None and operator != "__neg__":
            return ctx.default_signature
        operand = _operand_type(ctx.api, operand_expr) if operand_expr is not None else None
        key = (ctx.context, operator, ctx.type, operand)
        if len(key) == len(_LastAnswer.key) and all(a is b for a, b in zip(key, _LastAnswer.key)):
            result, built = _LastAnswer.answer
        else:
            receiver_is_left = _receiver_is_left(ctx.api, ctx.context, operand_expr, ctx.type)
            result = outcome(operator, ctx.type, operand, receiver_is_left, ctx.context, ctx.api)
            built = geometry.build(ctx.api, result.result) if result is not None and result.result else None
            _LastAnswer.key, _LastAnswer.answer = key, (result, built)
        if result is None or result.result is None and result.problem is None:
            return ctx.default_signature
        # Only rewrite when both operands are framed: then the plugin owns the answer (and its error).
        if operator not in SCALING_OPERATORS or result.problem is not None:
            return _accepting(ctx.default_signature, operand, built or _built(ctx.api, result, ctx.default_signature))
        return ctx.default_signature

    return hook


def method_hook(operator: str) -> Callable[[MethodContext], Type]:
    def hook(ctx: MethodContext) -> Type:
        operand = ctx.arg_types[0][0] if ctx.arg_types and ctx.arg_types[0] else None
        operand_expr = _single_operand(ctx.args)
        receiver_is_left = _receiver_is_left(ctx.api, ctx.context, operand_expr, ctx.type)
        result = outcome(operator, ctx.type, operand, receiver_is_left, ctx.context, ctx.api)
        if result is None:
            return ctx.default_return_type
        if result.problem is not None:
            ctx.api.fail(result.problem.message, ctx.context, code=result.problem.code)
        return _built(ctx.api, result, ctx.default_return_type)

    return hook


def _built(api: CheckerPluginInterface, result: Outcome, default: Type) -> Type:
    if result.result is None:
        return default.ret_type if isinstance(default, CallableType) else default
    return geometry.build(api, result.result) or (
        default.ret_type if isinstance(default, CallableType) else default
    )


def _is_raw_array(operand: Type | None, operand_geo: Geo | None) -> bool:
    """An ndarray that is not a runtime value: plain, or annotated with geolint.typing (still plain at runtime)."""
    if operand_geo is not None:
        return operand_geo.family == geometry.ARRAY
    proper = get_proper_type(operand) if operand is not None else None
    return isinstance(proper, Instance) and proper.type.has_base(names.NDARRAY)


def _receiver_is_left(
    api: CheckerPluginInterface, context: Context, operand_expr: Expression | None, receiver: Type
) -> bool | None:
    """Which side of ``a <op> b`` the receiver is, read from the expression itself (None: go by the name).

    mypy before 2.0 checks the reflected variant under the *forward* method name (``b.__matmul__(a)`` for
    ``a @ b``), and passes the left operand as a stand-in node, so neither the name nor the node identity
    always tells; the operand types mypy already recorded for ``a`` and ``b`` do.
    """
    if not isinstance(context, OpExpr) or operand_expr is None:
        return None
    if operand_expr is context.right:
        return True
    if operand_expr is context.left:
        return False
    lookup = getattr(api, "lookup_type_or_none", None)
    if lookup is None:
        return None
    left, right = lookup(context.left), lookup(context.right)
    if left is not None and is_same_type(left, receiver):
        return True
    if right is not None and is_same_type(right, receiver):
        return False
    return None


def _single_operand(args: list[list[Expression]]) -> Expression | None:
    if len(args) >= 1 and len(args[0]) == 1:
        return args[0][0]
    return None


def _operand_type(api: CheckerPluginInterface, expr: Expression) -> Type:
    """The operand's type, read from mypy's type map when mypy has already inferred it (it has, for an
    operator): inferring it again would re-check the whole operand once per overload item, which grows
    exponentially with nesting such as ``T1 @ (T2 @ (T3 @ p))``."""
    lookup = getattr(api, "lookup_type_or_none", None)
    known = lookup(expr) if lookup is not None else None
    return known if known is not None else api.get_expression_type(expr)


def _accepting(signature: CallableType, operand: Type | None, result: Type) -> CallableType:
    arg_types = list(signature.arg_types)
    if operand is not None and arg_types:
        arg_types[0] = operand
    return signature.copy_modified(arg_types=arg_types, ret_type=result, variables=[])
