"""String frames in annotations: ``Point["camera"]``, ``Transform["world", "camera"]``.

mypy reads a string inside a subscript as a forward reference, so ``Point["camera"]`` would fail with
"Name 'camera' is not defined". A *type-analyze hook* on every framed class takes over the analysis of its
subscript: an argument that was written as a string and does not name a type in scope becomes
``Literal["camera"]``; every other argument (a frame class, a TypeVar, a real forward reference such as
``Point["World"]`` before ``class World`` is defined) is analyzed normally.

One pre-pass is needed: before the hook runs, mypy's search for type variables in a ``def`` signature looks
up every name in it, and would still report "camera" as undefined. `protect_string_frames` runs when a module
that imports geolint is parsed (the plugin's ``get_additional_deps``) and turns each string argument of a
geolint class in a signature into a string literal node, which that search skips; the hook then reads it.

Literal types are ordinary, cacheable mypy types, distinct per string and invariant in the generic, so a
``Point["camera"]`` is not a ``Point["world"]``, and ``Point[Literal["camera"]]`` (which needs no plugin and
also works in pyright) is the very same type. The runtime accepts all three spellings too.
"""

from __future__ import annotations

from mypy.nodes import (
    ClassDef,
    Decorator,
    FuncDef,
    IfStmt,
    OverloadedFuncDef,
    Statement,
    Import,
    ImportFrom,
    MypyFile,
    PlaceholderNode,
    TypeAlias,
    TypeInfo,
    TypeVarLikeExpr,
)
from mypy.plugin import AnalyzeTypeContext
from mypy.types import (
    AnyType,
    CallableType,
    LiteralType,
    RawExpressionType,
    Type,
    TypeOfAny,
    UnboundType,
)

from geolint.mypy.config import PluginConfig
from geolint.mypy.geometry import FRAMED_CLASSES

TYPE_NODES = (TypeInfo, TypeAlias, PlaceholderNode, TypeVarLikeExpr)


def analyze_framed_subscript(
    ctx: AnalyzeTypeContext, fullname: str, arity: int | None, settings: PluginConfig
) -> Type:
    """``Kind[frame, ...]`` with string frames turned into Literal types (the type-analyze hook)."""
    unbound = ctx.type
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
    return symbol is not None and isinstance(symbol.node, TYPE_NODES)


def protect_string_frames(file: MypyFile) -> None:
    """Pre-pass over a freshly parsed module: string frames in ``def`` signatures become literal nodes."""
    framed_names = _local_names_of_framed_classes(file)
    if framed_names:
        _protect_statements(file.defs, framed_names)


FRAMED_CLASS_NAMES = frozenset(fullname.rsplit(".", 1)[1] for fullname in FRAMED_CLASSES)


def _local_names_of_framed_classes(file: MypyFile) -> frozenset[str]:
    """How this module spells geolint's framed classes: ``Point``, ``P`` (an import alias), ``gt.PointArray``."""
    local: set[str] = set()
    for node in file.imports:
        if isinstance(node, ImportFrom) and _is_geolint(node.id):
            local.update(alias or name for name, alias in node.names if name in FRAMED_CLASS_NAMES)
        elif isinstance(node, Import):
            for module, alias in node.ids:
                if _is_geolint(module):
                    local.update(f"{alias or module}.{name}" for name in FRAMED_CLASS_NAMES)
    return frozenset(local)


def _is_geolint(module: str) -> bool:
    return module == "geolint" or module.startswith("geolint.")


def _protect_statements(statements: list[Statement], framed_names: frozenset[str]) -> None:
    # A plain walk: mypy's compiled visitor classes cannot be subclassed from interpreted code.
    for statement in statements:
        if isinstance(statement, Decorator):
            statement = statement.func
        if isinstance(statement, OverloadedFuncDef):
            _protect_statements(list(statement.items), framed_names)
            if statement.impl is not None:
                _protect_statements([statement.impl], framed_names)
        elif isinstance(statement, FuncDef):
            if isinstance(statement.type, CallableType):
                for typ in [*statement.type.arg_types, statement.type.ret_type]:
                    _protect(typ, framed_names)
            _protect_statements(statement.body.body, framed_names)
        elif isinstance(statement, ClassDef):
            _protect_statements(statement.defs.body, framed_names)
        elif isinstance(statement, IfStmt):
            for block in [*statement.body, statement.else_body]:
                if block is not None:
                    _protect_statements(block.body, framed_names)


def _protect(typ: Type, framed_names: frozenset[str]) -> None:
    if not isinstance(typ, UnboundType):
        return
    if typ.name in framed_names:
        typ.args = tuple(_as_literal_node(arg) for arg in typ.args)
    for arg in typ.args:
        _protect(arg, framed_names)


def _as_literal_node(arg: Type) -> Type:
    if isinstance(arg, UnboundType) and arg.original_str_expr is not None and not arg.args:
        return RawExpressionType(arg.original_str_expr, "builtins.str", line=arg.line, column=arg.column)
    return arg
