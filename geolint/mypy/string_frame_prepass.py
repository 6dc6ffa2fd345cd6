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

from dataclasses import dataclass
from typing import Callable, Iterable

from mypy.nodes import (
    AssertStmt,
    AssertTypeExpr,
    AssignmentExpr,
    AssignmentStmt,
    AwaitExpr,
    Block,
    CallExpr,
    CastExpr,
    ClassDef,
    ComparisonExpr,
    ConditionalExpr,
    Decorator,
    DelStmt,
    DictExpr,
    DictionaryComprehension,
    Expression,
    ExpressionStmt,
    ForStmt,
    FuncDef,
    FuncItem,
    GeneratorExpr,
    IfStmt,
    Import,
    ImportAll,
    ImportFrom,
    IndexExpr,
    ListComprehension,
    ListExpr,
    MatchStmt,
    MemberExpr,
    MypyFile,
    NameExpr,
    Node,
    OperatorAssignmentStmt,
    OpExpr,
    OverloadedFuncDef,
    RaiseStmt,
    ReturnStmt,
    RevealExpr,
    SetComprehension,
    SetExpr,
    SliceExpr,
    StarExpr,
    StrExpr,
    TryStmt,
    TupleExpr,
    UnaryExpr,
    WhileStmt,
    WithStmt,
    YieldExpr,
    YieldFromExpr,
)
from mypy.types import CallableType, RawExpressionType, Type, TypeList, UnboundType, UnionType

from geolint.mypy import affine
from geolint.mypy.geometry import FRAMED_CLASSES

LITERAL_MARKER = "\x01geolint-frame:"


def protect_string_frames(file: MypyFile) -> None:
    """Rewrite a freshly parsed module's string frames so that mypy never looks them up (see the module doc)."""
    from_geolint, from_elsewhere = _local_names_of_framed_classes(file)
    affine.forget(file.path)
    if from_geolint or from_elsewhere:
        top_level = _top_level_names(file) if from_elsewhere else frozenset()
        _walk(file.defs, _Protection(from_geolint, from_elsewhere, top_level), file.path)


@dataclass(frozen=True)
class _Protection:
    """Which subscripted names get their strings rewritten (see `_local_names_of_framed_classes`)."""

    from_geolint: frozenset[str]
    from_elsewhere: frozenset[str]
    top_level: frozenset[str]  # names a string from elsewhere must not be (it would be a forward reference)

    def in_application(self, name: str | None) -> bool:
        return name in self.from_geolint or name in self.from_elsewhere

    def in_signature(self, name: str, frame: str) -> bool:
        if name in self.from_geolint:
            return True
        return name in self.from_elsewhere and frame.split(".", 1)[0] not in self.top_level


def _top_level_names(file: MypyFile) -> frozenset[str]:
    names: set[str] = set()
    for node in file.imports:
        if isinstance(node, ImportFrom):
            names.update(alias or name for name, alias in node.names)
        elif isinstance(node, Import):
            names.update((alias or module).split(".", 1)[0] for module, alias in node.ids)
    for statement in file.defs:
        if isinstance(statement, (ClassDef, FuncDef)):
            names.add(statement.name)
        elif isinstance(statement, AssignmentStmt):
            names.update(lvalue.name for lvalue in statement.lvalues if isinstance(lvalue, NameExpr))
    return frozenset(names)


FRAMED_CLASS_NAMES = frozenset(fullname.rsplit(".", 1)[1] for fullname in FRAMED_CLASSES)


def _local_names_of_framed_classes(file: MypyFile) -> tuple[frozenset[str], frozenset[str]]:
    """How this module spells the framed classes, imported from geolint (``Point``, ``P`` for an import alias,
    ``gt.PointArray``, ``from geolint import *``) and from elsewhere (a project module that re-exports
    geolint's ``Point``). With a name from elsewhere, a string in a signature is taken for a frame only when it
    names nothing at the module's top level (``Transform["World"]`` of another library stays a forward
    reference).
    """
    from_geolint: set[str] = set()
    from_elsewhere: set[str] = set()
    for node in file.imports:
        if isinstance(node, ImportFrom):
            names = {alias or name for name, alias in node.names if name in FRAMED_CLASS_NAMES}
            (from_geolint if _is_geolint(node.id) else from_elsewhere).update(names)
        elif isinstance(node, ImportAll) and _is_geolint(node.id):
            from_geolint.update(FRAMED_CLASS_NAMES)
        elif isinstance(node, Import):
            for module, alias in node.ids:
                if _is_geolint(module):
                    from_geolint.update(f"{alias or module}.{name}" for name in FRAMED_CLASS_NAMES)
    return frozenset(from_geolint), frozenset(from_elsewhere)


def _is_geolint(module: str) -> bool:
    return module == "geolint" or module.startswith("geolint.")


def _walk(roots: Iterable[Node | None], protection: _Protection, path: str) -> None:
    """Visit every statement and expression under `roots`: protect type applications and signatures.

    A plain walk over an explicit table of child nodes (mypy's compiled visitor classes cannot be subclassed
    from interpreted code); a node type missing from `_CHILDREN` hides only what is written inside it.
    """
    stack = [node for node in roots if node is not None]
    while stack:
        node = stack.pop()
        if isinstance(node, (OpExpr, UnaryExpr)):
            affine.register(node, path)  # the same walk finds weighted combinations (see `affine`)
        elif isinstance(node, IndexExpr):
            _protect_type_application(node, protection)
        elif isinstance(node, FuncItem) and isinstance(node.type, CallableType):
            for typ in [*node.type.arg_types, node.type.ret_type]:
                _protect(typ, protection)
        children = _CHILDREN.get(type(node))
        if children is None:
            children = _children_by_base(node)
        stack.extend(child for child in children(node) if child is not None)


def _flat(groups: Iterable[Iterable[Node | None]]) -> list[Node | None]:
    return [node for group in groups for node in group]


def _function_children(node: FuncItem) -> list[Node | None]:
    return [*(argument.initializer for argument in node.arguments), node.body]


def _children_by_base(node: Node) -> Callable[[Node], Iterable[Node | None]]:
    if isinstance(node, FuncItem):  # FuncDef, LambdaExpr
        return _function_children  # type: ignore[return-value]
    return lambda _: ()


# node type -> its child statements and expressions (types and patterns are not walked)
_CHILDREN: dict[type, Callable[..., Iterable[Node | None]]] = {
    Block: lambda n: n.body,
    Decorator: lambda n: [*n.decorators, n.func],
    OverloadedFuncDef: lambda n: [*n.items, n.impl],
    ClassDef: lambda n: [*n.decorators, *n.base_type_exprs, *n.keywords.values(), n.defs],
    ExpressionStmt: lambda n: [n.expr],
    AssignmentStmt: lambda n: [*n.lvalues, n.rvalue],
    OperatorAssignmentStmt: lambda n: [n.lvalue, n.rvalue],
    ReturnStmt: lambda n: [n.expr],
    AssertStmt: lambda n: [n.expr, n.msg],
    DelStmt: lambda n: [n.expr],
    RaiseStmt: lambda n: [n.expr, n.from_expr],
    IfStmt: lambda n: [*n.expr, *n.body, n.else_body],
    WhileStmt: lambda n: [n.expr, n.body, n.else_body],
    ForStmt: lambda n: [n.index, n.expr, n.body, n.else_body],
    WithStmt: lambda n: [*n.expr, *n.target, n.body],
    TryStmt: lambda n: [n.body, *n.types, *n.handlers, n.else_body, n.finally_body],
    MatchStmt: lambda n: [n.subject, *n.guards, *n.bodies],
    IndexExpr: lambda n: [n.base, n.index],
    CallExpr: lambda n: [n.callee, *n.args],
    MemberExpr: lambda n: [n.expr],
    UnaryExpr: lambda n: [n.expr],
    StarExpr: lambda n: [n.expr],
    AwaitExpr: lambda n: [n.expr],
    YieldExpr: lambda n: [n.expr],
    YieldFromExpr: lambda n: [n.expr],
    CastExpr: lambda n: [n.expr],
    AssertTypeExpr: lambda n: [n.expr],
    RevealExpr: lambda n: [n.expr],
    OpExpr: lambda n: [n.left, n.right],
    ComparisonExpr: lambda n: n.operands,
    SliceExpr: lambda n: [n.begin_index, n.end_index, n.stride],
    TupleExpr: lambda n: n.items,
    ListExpr: lambda n: n.items,
    SetExpr: lambda n: n.items,
    DictExpr: lambda n: _flat(n.items),
    ConditionalExpr: lambda n: [n.cond, n.if_expr, n.else_expr],
    AssignmentExpr: lambda n: [n.target, n.value],
    ListComprehension: lambda n: [n.generator],
    SetComprehension: lambda n: [n.generator],
    GeneratorExpr: lambda n: [n.left_expr, *n.sequences, *_flat(n.condlists)],
    DictionaryComprehension: lambda n: [n.key, n.value, *n.sequences, *_flat(n.condlists)],
}


def _protect_type_application(expr: IndexExpr, protection: _Protection) -> None:
    base_name = _expression_name(expr.base)
    if not protection.in_application(base_name):
        return
    items = expr.index.items if isinstance(expr.index, TupleExpr) else [expr.index]
    for item in items:
        if isinstance(item, StrExpr) and LITERAL_MARKER not in item.value:
            item.value = f"{base_name}[{LITERAL_MARKER + item.value!r}]"


def _protect(typ: Type, protection: _Protection) -> None:
    if isinstance(typ, (UnionType, TypeList)):  # X | None, Callable[[X], Y]
        for item in typ.items:
            _protect(item, protection)
        return
    if not isinstance(typ, UnboundType):
        return
    typ.args = tuple(_as_literal_node(typ.name, arg, protection) for arg in typ.args)
    for arg in typ.args:
        _protect(arg, protection)


def _expression_name(expr: Expression) -> str | None:
    if isinstance(expr, NameExpr):
        return expr.name
    if isinstance(expr, MemberExpr):
        owner = _expression_name(expr.expr)
        return f"{owner}.{expr.name}" if owner else None
    return None


def _as_literal_node(name: str, arg: Type, protection: _Protection) -> Type:
    if (
        isinstance(arg, UnboundType)
        and arg.original_str_expr is not None
        and not arg.args
        and protection.in_signature(name, arg.original_str_expr)
    ):
        return RawExpressionType(arg.original_str_expr, "builtins.str", line=arg.line, column=arg.column)
    return arg
