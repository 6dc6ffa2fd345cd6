"""The pre-pass that keeps mypy from looking up string frames before the plugin's hook can see them.

mypy resolves some names inside types on its own, with no hook involved: while searching a ``def`` signature
for type variables, and when it analyzes each argument of a type application (``Point["camera"](xyz)``,
``CamPoint = Point["camera"]``) separately. Either would report "Name 'camera' is not defined".

`protect_string_frames` runs on a module right after parsing, before semantic analysis (the plugin calls it
from ``get_additional_deps``), and only in modules that import geolint. It rewrites the string arguments of
geolint's framed classes, found by the names the module imported them under:

- in signatures, ``Point["camera"]``'s argument becomes a raw string-literal type node, which the type-variable
  search skips and `string_frames` reads;
- in type applications, the string becomes the *string* ``"Point['\\x01geolint-frame:camera']"``: mypy parses a
  string argument into a type without any per-argument lookup, the control character stops the inner parse
  (raw text again), and the framed class's hook answers ``Literal["camera"]`` for that stand-in.
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
    Decorator,
    DictExpr,
    Expression,
    ExpressionStmt,
    ForStmt,
    FuncDef,
    GeneratorExpr,
    IfStmt,
    Import,
    ImportFrom,
    IndexExpr,
    LambdaExpr,
    ListComprehension,
    ListExpr,
    MemberExpr,
    MypyFile,
    NameExpr,
    OperatorAssignmentStmt,
    OpExpr,
    OverloadedFuncDef,
    ReturnStmt,
    SetComprehension,
    SetExpr,
    StarExpr,
    Statement,
    StrExpr,
    TryStmt,
    TupleExpr,
    UnaryExpr,
    WhileStmt,
    WithStmt,
)
from mypy.types import CallableType, RawExpressionType, Type, TypeList, UnboundType, UnionType

from geolint.mypy.geometry import FRAMED_CLASSES

LITERAL_MARKER = "\x01geolint-frame:"

def protect_string_frames(file: MypyFile) -> None:
    """Rewrite a freshly parsed module's string frames so that mypy never looks them up (see the module doc)."""
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
