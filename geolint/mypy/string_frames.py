"""String frames in annotations: ``Point["camera"]``, ``Transform["world", "camera"]``.

mypy reads a string inside a subscript as a forward reference, so ``Point["camera"]`` would fail with
"Name 'camera' is not defined". A *type-analyze hook* on every framed class takes over the analysis of its
subscript: an argument that was written as a string and does not name a type in scope becomes
``Literal["camera"]``; every other argument (a frame class, a TypeVar, a real forward reference such as
``Point["World"]`` before ``class World`` is defined) is analyzed normally.

Before the hook runs, mypy looks some of those strings up on its own (type variables in a ``def`` signature,
each argument of a type application such as ``Point["camera"](xyz)``); `string_frame_prepass` rewrites them
first so that no lookup happens, and leaves the answer to this hook.

Literal types are ordinary, cacheable mypy types, distinct per string and invariant in the generic, so a
``Point["camera"]`` is not a ``Point["world"]``, and ``Point[Literal["camera"]]`` (which needs no plugin and
also works in pyright) is the very same type. The runtime accepts all three spellings too.
"""

from __future__ import annotations

from mypy.nodes import PlaceholderNode, TypeAlias, TypeInfo, TypeVarLikeExpr
from mypy.plugin import AnalyzeTypeContext
from mypy.types import AnyType, LiteralType, RawExpressionType, Type, TypeOfAny, UnboundType

from geolint.mypy.config import PluginConfig
from geolint.mypy.string_frame_prepass import LITERAL_MARKER

TYPE_NODES = (TypeInfo, TypeAlias, PlaceholderNode, TypeVarLikeExpr)


def analyze_framed_subscript(
    ctx: AnalyzeTypeContext, fullname: str, arity: int | None, settings: PluginConfig
) -> Type:
    """``Kind[frame, ...]`` with string frames turned into Literal types (the type-analyze hook)."""
    unbound = ctx.type
    marked = _marked_literal(unbound)
    if marked is not None:  # the pre-pass's stand-in for one frame
        return LiteralType(settings.canonical_frame(marked), ctx.api.named_type("builtins.str", []))
    if not unbound.args:
        omitted = AnyType(TypeOfAny.from_omitted_generics)
        return ctx.api.named_type(fullname, [omitted] * (arity or 0))
    if arity is not None and len(unbound.args) != arity:
        want = "1 frame" if arity == 1 else f"{arity} frames"
        ctx.api.fail(
            f'"{fullname.rsplit(".", 1)[1]}" expects {want}, got {len(unbound.args)}', ctx.context
        )
        return AnyType(TypeOfAny.from_error)
    args = [_frame_argument(ctx, arg, settings) for arg in unbound.args]
    return ctx.api.named_type(fullname, args)


def string_frame_name(ctx: AnalyzeTypeContext, arg: Type) -> str | None:
    """The frame name when `arg` was written as a string that is not a forward reference, else None."""
    if isinstance(arg, RawExpressionType) and isinstance(arg.literal_value, str):
        if arg.literal_value.isidentifier() and _names_a_type(ctx, arg.literal_value):
            return None  # protected by the pre-pass, yet a forward reference
        return arg.literal_value  # e.g. "base_link/camera": not even parseable as a name
    if isinstance(arg, UnboundType) and arg.original_str_expr is not None and not arg.args:
        if _names_a_type(ctx, arg.name):
            return None  # Point["World"]: a forward reference to a frame class
        return arg.original_str_expr
    return None


def _marked_literal(unbound: UnboundType) -> str | None:
    if len(unbound.args) != 1:
        return None
    arg = unbound.args[0]
    text = arg.literal_value if isinstance(arg, RawExpressionType) else None
    if isinstance(text, str) and text.startswith(LITERAL_MARKER):
        return text[len(LITERAL_MARKER) :]
    return None


def _frame_argument(ctx: AnalyzeTypeContext, arg: Type, settings: PluginConfig) -> Type:
    name = string_frame_name(ctx, arg)
    if name is None:
        if isinstance(arg, RawExpressionType) and isinstance(arg.literal_value, str):
            arg = UnboundType(arg.literal_value, line=arg.line, column=arg.column)
        return ctx.api.analyze_type(arg)
    name = settings.canonical_frame(name)
    return LiteralType(name, ctx.api.named_type("builtins.str", []), line=arg.line, column=arg.column)


def _names_a_type(ctx: AnalyzeTypeContext, name: str) -> bool:
    lookup = getattr(ctx.api, "lookup_qualified", None)
    if lookup is None:
        return False
    symbol = lookup(name, ctx.context, suppress_errors=True)
    if symbol is None or not isinstance(symbol.node, TYPE_NODES):
        return False
    # "map", "filter", "range" are common frame names (ROS's map frame) and builtin classes: a frame there.
    return not (symbol.fullname or "").startswith("builtins.")
