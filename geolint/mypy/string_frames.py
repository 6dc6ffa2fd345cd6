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

from typing import Iterable

from mypy.nodes import (
    AssertStmt,
    AssignmentExpr,
    AssignmentStmt,
    AwaitExpr,
    Block,
    CallExpr,
    ClassDef,
    ComparisonExpr,
    ConditionalExpr,
    DictExpr,
    Expression,
    ExpressionStmt,
    ForStmt,
    GeneratorExpr,
    IndexExpr,
    LambdaExpr,
    ListComprehension,
    ListExpr,
    MemberExpr,
    NameExpr,
    OperatorAssignmentStmt,
    OpExpr,
    ReturnStmt,
    SetComprehension,
    SetExpr,
    StarExpr,
    StrExpr,
    TryStmt,
    TupleExpr,
    UnaryExpr,
    WhileStmt,
    WithStmt,
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
    TypeList,
    TypeOfAny,
    UnboundType,
    UnionType,
)

from geolint.mypy.config import PluginConfig
from geolint.mypy.geometry import FRAMED_CLASSES

TYPE_NODES = (TypeInfo, TypeAlias, PlaceholderNode, TypeVarLikeExpr)


def analyze_framed_subscript(
    ctx: AnalyzeTypeContext, fullname: str, arity: int | None, settings: PluginConfig
) -> Type:
    """``Kind[frame, ...]`` with string frames turned into Literal types (the type-analyze hook)."""
    unbound = ctx.type
    marked = _marked_literal(unbound)
    if marked is not None:  # the stand-in made by `_marked_frame`: just the frame
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


def _protect_statements(statements: Iterable[Statement | None], framed_names: frozenset[str]) -> None:
    # A plain walk: mypy's compiled visitor classes cannot be subclassed from interpreted code.
    for statement in statements:
        if statement is None:
            continue
        if isinstance(statement, Decorator):
            _protect_expressions(statement.decorators, framed_names)
            statement = statement.func
        if isinstance(statement, OverloadedFuncDef):
            _protect_statements([*statement.items, statement.impl], framed_names)
        elif isinstance(statement, FuncDef):
            if isinstance(statement.type, CallableType):
                for typ in [*statement.type.arg_types, statement.type.ret_type]:
                    _protect(typ, framed_names)
            _protect_statements(statement.body.body, framed_names)
        elif isinstance(statement, ClassDef):
            _protect_statements(statement.defs.body, framed_names)
        elif isinstance(statement, Block):
            _protect_statements(statement.body, framed_names)
        else:
            _protect_expressions(_statement_expressions(statement), framed_names)
            _protect_statements(_statement_blocks(statement), framed_names)


def _statement_expressions(statement: Statement) -> list[Expression | None]:
    if isinstance(statement, (AssignmentStmt, OperatorAssignmentStmt)):
        return [statement.rvalue]
    if isinstance(statement, (ExpressionStmt, ReturnStmt, IfStmt, WhileStmt, ForStmt, AssertStmt)):
        return list(statement.expr) if isinstance(statement.expr, list) else [statement.expr]
    if isinstance(statement, WithStmt):
        return list(statement.expr)
    return []


def _statement_blocks(statement: Statement) -> list[Statement | None]:
    if isinstance(statement, IfStmt):
        return [*statement.body, statement.else_body]
    if isinstance(statement, (WhileStmt, ForStmt)):
        return [statement.body, statement.else_body]
    if isinstance(statement, WithStmt):
        return [statement.body]
    if isinstance(statement, TryStmt):
        return [statement.body, *statement.handlers, statement.else_body, statement.finally_body]
    return []


def _protect_expressions(expressions: Iterable[Expression | None], framed_names: frozenset[str]) -> None:
    for expr in expressions:
        if expr is None:
            continue
        if isinstance(expr, IndexExpr):
            _protect_type_application(expr, framed_names)
            _protect_expressions([expr.base, expr.index], framed_names)
        elif isinstance(expr, CallExpr):
            _protect_expressions([expr.callee, *expr.args], framed_names)
        elif isinstance(expr, (MemberExpr, UnaryExpr, StarExpr, AwaitExpr)):
            _protect_expressions([expr.expr], framed_names)
        elif isinstance(expr, OpExpr):
            _protect_expressions([expr.left, expr.right], framed_names)
        elif isinstance(expr, ComparisonExpr):
            _protect_expressions(expr.operands, framed_names)
        elif isinstance(expr, (TupleExpr, ListExpr, SetExpr)):
            _protect_expressions(expr.items, framed_names)
        elif isinstance(expr, DictExpr):
            _protect_expressions([item for pair in expr.items for item in pair], framed_names)
        elif isinstance(expr, ConditionalExpr):
            _protect_expressions([expr.cond, expr.if_expr, expr.else_expr], framed_names)
        elif isinstance(expr, AssignmentExpr):
            _protect_expressions([expr.value], framed_names)
        elif isinstance(expr, (ListComprehension, SetComprehension)):
            _protect_expressions([expr.generator], framed_names)
        elif isinstance(expr, GeneratorExpr):
            _protect_expressions([expr.left_expr, *expr.sequences], framed_names)
        elif isinstance(expr, LambdaExpr):
            _protect_statements(expr.body.body, framed_names)


# A type application (``Point["camera"](xyz)``, ``CamPoint = Point["camera"]``) has each argument analyzed on
# its own, where no hook can see it. The pre-pass rewrites the argument "camera" into the *string*
# ``"Point['\x01geolint-frame:camera']"``: a string argument is parsed into a type by mypy without any
# per-argument lookup, the parse gives ``Point[<raw text>]`` (the control character stops the inner parse),
# and the framed class's hook answers a bare ``Literal["camera"]`` for that stand-in.
LITERAL_MARKER = "\x01geolint-frame:"


def _protect_type_application(expr: IndexExpr, framed_names: frozenset[str]) -> None:
    base_name = _expression_name(expr.base)
    if base_name not in framed_names:
        return
    items = expr.index.items if isinstance(expr.index, TupleExpr) else [expr.index]
    for item in items:
        if isinstance(item, StrExpr) and LITERAL_MARKER not in item.value:
            item.value = f"{base_name}[{LITERAL_MARKER + item.value!r}]"


def _protect(typ: Type, framed_names: frozenset[str]) -> None:
    if isinstance(typ, (UnionType, TypeList)):  # X | None, Callable[[X], Y]
        for item in typ.items:
            _protect(item, framed_names)
        return
    if not isinstance(typ, UnboundType):
        return
    if typ.name in framed_names:
        typ.args = tuple(_as_literal_node(arg) for arg in typ.args)
    for arg in typ.args:
        _protect(arg, framed_names)


def _expression_name(expr: Expression) -> str | None:
    if isinstance(expr, NameExpr):
        return expr.name
    if isinstance(expr, MemberExpr):
        owner = _expression_name(expr.expr)
        return f"{owner}.{expr.name}" if owner else None
    return None


def _as_literal_node(arg: Type) -> Type:
    if isinstance(arg, UnboundType) and arg.original_str_expr is not None and not arg.args:
        return RawExpressionType(arg.original_str_expr, "builtins.str", line=arg.line, column=arg.column)
    return arg
