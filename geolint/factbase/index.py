"""One walk over a module's `ast`: parents, scopes and their bindings, imports, and nodes by type.

Everything the fact base (`geolint.factbase.model`) and the rules need to look up is gathered
here in a single iterative pass (no recursion, so absurdly deep expressions cannot overflow the
stack), and the rules iterate the per-type node lists instead of walking the tree again.
"""

from __future__ import annotations

import ast
import operator
import os
import threading
from ast import (
    AST,
    AnnAssign,
    Assign,
    AsyncFor,
    AsyncFunctionDef,
    Attribute,
    AugAssign,
    BinOp,
    Break,
    Call,
    ClassDef,
    Constant,
    Continue,
    Del,
    ExceptHandler,
    For,
    FunctionDef,
    Global,
    Import,
    ImportFrom,
    Lambda,
    Load,
    MatMult,
    Module,
    Name,
    NamedExpr,
    Nonlocal,
    Pass,
    Return,
    Starred,
    Store,
    Subscript,
)
from collections import OrderedDict
from dataclasses import dataclass, field
from typing import Any, Callable, Final, Union

from geolint.lint_types import Config
from geolint.parsing import parse_module
from geolint.source_text import split_lines  # \n, \r\n and \r, not \f: as ast counts lines

ScopeNode = Union[Module, FunctionDef, AsyncFunctionDef, ClassDef, Lambda]
FUNCTION_NODES: Final = (FunctionDef, AsyncFunctionDef)


@dataclass(frozen=True)
class LoopBinding:
    """`for target in iterable` (and comprehensions): one element of `iterable`.

    `position` is the index in a tuple target (`for i, n in enumerate(normals)`), else None.
    """

    iterable: ast.expr
    position: int | None = None


@dataclass(frozen=True)
class ParamBinding:
    """A function parameter: its default and annotation are the local evidence about it."""

    arg: ast.arg
    default: ast.expr | None
    function: AST


@dataclass(frozen=True)
class UnpackBinding:
    """`a, b = value`: element `position` of `value` (a tuple literal, or a call's returned tuple)."""

    value: ast.expr
    position: int


@dataclass(frozen=True)
class OpaqueBinding:
    """A binding nothing is known about (`with ... as`, imports, `global`)."""


Binding = Union[ast.expr, LoopBinding, ParamBinding, UnpackBinding, OpaqueBinding]


@dataclass
class Scope:
    """The names bound directly in one module, class or function body."""

    node: ScopeNode
    parent: Scope | None
    bindings: dict[str, list[Binding]] = field(default_factory=dict)
    # `buf[:3] = x`: name -> [(subscript target, value)]
    subscript_stores: dict[str, list[tuple[Subscript, ast.expr]]] = field(default_factory=dict)
    # `obj.attr = value`
    attribute_stores: list[tuple[Attribute, ast.expr]] = field(default_factory=list)
    augmented: set[str] = field(default_factory=set)
    # `buf[:3, 1:3] *= -1`: names whose items are updated in place (not block stores: no value is written)
    item_augmented: set[str] = field(default_factory=set)
    # names used as an operand of a matrix product (`T @ x`, `x.dot(M)`)
    matmul_operands: set[str] = field(default_factory=set)
    returns: list[ast.expr] = field(default_factory=list)

    def bind(self, name: str, binding: Binding) -> None:
        self.bindings.setdefault(name, []).append(binding)


class ModuleIndex:
    """The facts of one module that do not depend on the config."""

    def __init__(self, tree: Module, source: str, depth_limit: int | None = None) -> None:
        self.tree = tree
        self.source = source
        self.parents: dict[AST, AST] = {}
        self.scope_of_node: dict[AST, Scope] = {}
        self.scopes: dict[AST, Scope] = {}
        self.imports: dict[str, str] = {}  # local name -> qualified name
        self.imported_modules: set[str] = set()
        self.star_imports: list[str] = []  # `from .geometry import *`: the modules, with their leading dots
        self.functions: dict[str, FunctionDef | AsyncFunctionDef] = {}  # module level
        self.methods: dict[str, list[FunctionDef | AsyncFunctionDef]] = {}  # by name, in classes
        self.by_type: dict[type, list[AST]] = {}  # in source (pre-)order
        self.self_attribute_stores: dict[str, list[ast.expr]] = {}  # `self.x = value` anywhere in a class
        self._lines: list[str] | None = None
        # where each line starts in the source, and the lines (`model._offset`'s character offsets)
        self.line_starts: list[int] | None = None
        self.line_texts: list[str] | None = None
        # Past `depth_limit` levels (the module node is level 1) the walk stops: `too_deep` is then
        # True and `too_deep_at` the first node (source order) on the first level past it that has
        # a position (the guards' depth check, measured on the same walk)
        self.depth_limit = depth_limit
        self.too_deep = False
        self.too_deep_at: AST | None = None
        self._merged: dict[tuple[type, ...], list[AST]] = {}
        self.flow: dict[str, dict] = {}  # type: ignore[type-arg]  # `geolint.factbase.reaching`'s tables, built on first use
        self._build(depth_limit if depth_limit is not None else 1 << 62)

    # -- the walk ----------------------------------------------------------------------
    def _build(self, depth_limit: int) -> None:
        root = Scope(self.tree, None)
        self.scopes[self.tree] = root
        by_type = self.by_type
        parents = self.parents
        scope_of = self.scope_of_node
        recorders = _RECORDERS
        reversed_fields = _REVERSED_CHILD_FIELDS
        role_of = _ROLE
        scope_makers = _SCOPE_MAKERS
        call_type, attribute_type, node_type = Call, Attribute, AST  # locals: each is read once per node
        # (node, scope the node's code runs in, its level); an explicit stack, so depth costs no recursion
        stack: list[tuple[AST, Scope, int]] = [(self.tree, root, 1)]
        pop, push = stack.pop, stack.append
        while stack:
            node, scope, depth = pop()
            if depth > depth_limit:
                if self._past_the_limit(node):
                    return
                continue
            scope_of[node] = scope
            kind = type(node)
            bucket = by_type.get(kind)
            if bucket is None:
                by_type[kind] = [node]
            else:
                bucket.append(node)
            if kind is call_type:  # the commonest recorded node, inlined: `_record_call`
                func = node.func  # type: ignore[attr-defined]
                if type(func) is attribute_type and func.attr in _MATMUL_METHODS:
                    _matmul_operands(scope, func.value, *node.args)  # type: ignore[attr-defined]
                inner = scope
            else:
                recorder = recorders.get(kind)
                inner = recorder(self, node, scope) if recorder is not None else scope
            depth += 1
            childless_inline = depth <= depth_limit  # past the limit, a childless node is pushed for the depth check
            if kind in scope_makers:
                for child in reversed(child_nodes(node)):
                    parents[child] = node
                    child_scope = inner if _runs_in_inner_scope(node, child) else scope
                    if childless_inline and type(child) in _NO_CHILDREN:
                        scope_of[child] = child_scope
                    else:
                        push((child, child_scope, depth))
                continue
            # `child_nodes` inlined, fields and lists read backwards and pushed at once (so nodes come
            # off the stack in source pre-order); a childless child (`Name`, `Constant`: nearly half
            # the nodes, not listed by type) is recorded here rather than pushed and popped. This
            # loop runs once per node of every module.
            fields = reversed_fields.get(kind)
            if fields is None:
                fields = reversed_fields[kind] = _reversed_child_fields(kind)
            for name in fields:
                value: Any = getattr(node, name, None)
                if type(value) is list:
                    for child in reversed(value):
                        role = role_of.get(type(child))
                        if role is None:  # not a node (`Global.names`' strings), or a node type not seen yet
                            role = _WALKED if isinstance(child, node_type) else _SKIPPED
                        if role == _SKIPPED:
                            continue
                        parents[child] = node
                        if role == _CHILDLESS and childless_inline:
                            scope_of[child] = scope
                        else:
                            push((child, scope, depth))
                else:
                    role = role_of.get(type(value))
                    if role is None:  # a string or a number, or a node type not seen yet
                        role = _WALKED if isinstance(value, node_type) else _SKIPPED
                    if role == _SKIPPED:
                        continue
                    parents[value] = node
                    if role == _CHILDLESS and childless_inline:
                        scope_of[value] = scope
                    else:
                        push((value, scope, depth))

    def _past_the_limit(self, node: AST) -> bool:
        """`node` is one level past the limit: the tree is too deep. Whether to stop the walk now:
        the guards name the first node of that level, in source order, that has a position (nodes
        past the limit are never expanded, so the walk goes on through that level only)."""
        self.too_deep = True
        if hasattr(node, "lineno"):
            self.too_deep_at = node
            return True
        return False

    def _record(self, node: AST, scope: Scope) -> Scope:
        """Record what `node` binds in `scope`; return the scope its body runs in."""
        recorder = _RECORDERS.get(type(node))
        return recorder(self, node, scope) if recorder is not None else scope

    def _record_function(self, node: FunctionDef | AsyncFunctionDef, scope: Scope) -> Scope:
        scope.bind(node.name, OpaqueBinding())
        if isinstance(scope.node, Module):
            self.functions[node.name] = node
        elif isinstance(scope.node, ClassDef):
            self.methods.setdefault(node.name, []).append(node)
        inner = Scope(node, scope)
        self.scopes[node] = inner
        self._bind_arguments(node.args, inner, node)
        return inner

    def _record_lambda(self, node: Lambda, scope: Scope) -> Scope:
        inner = Scope(node, scope)
        self.scopes[node] = inner
        self._bind_arguments(node.args, inner, node)
        return inner

    def _record_class(self, node: ClassDef, scope: Scope) -> Scope:
        scope.bind(node.name, OpaqueBinding())
        inner = Scope(node, scope)
        self.scopes[node] = inner
        return inner

    def _record_assign(self, node: Assign, scope: Scope) -> Scope:
        for target in node.targets:
            self._bind_target(target, node.value, scope)
        return scope

    def _record_annotated(self, node: AnnAssign, scope: Scope) -> Scope:
        self._bind_target(node.target, node.value if node.value is not None else OpaqueBinding(), scope)
        return scope

    def _record_augmented(self, node: AugAssign, scope: Scope) -> Scope:
        if isinstance(node.target, Name):
            scope.augmented.add(node.target.id)
        elif isinstance(node.target, Attribute):
            scope.attribute_stores.append((node.target, node.value))
        elif isinstance(node.target, Subscript) and isinstance(node.target.value, Name):
            scope.item_augmented.add(node.target.value.id)
        return scope

    def _record_walrus(self, node: NamedExpr, scope: Scope) -> Scope:
        self._bind_target(node.target, node.value, scope)
        return scope

    def _record_loop(self, node: For | AsyncFor | ast.comprehension, scope: Scope) -> Scope:
        self._bind_loop(node.target, node.iter, scope)
        return scope

    def _record_with_item(self, node: ast.withitem, scope: Scope) -> Scope:
        if node.optional_vars is not None:
            self._bind_target(node.optional_vars, OpaqueBinding(), scope)
        return scope

    def _record_handler(self, node: ExceptHandler, scope: Scope) -> Scope:
        if node.name:
            scope.bind(node.name, OpaqueBinding())
        return scope

    def _record_binary(self, node: BinOp, scope: Scope) -> Scope:
        if type(node.op) is MatMult:
            _matmul_operands(scope, node.left, node.right)
        return scope

    def _record_call(self, node: Call, scope: Scope) -> Scope:
        func = node.func
        if type(func) is Attribute and func.attr in _MATMUL_METHODS:
            _matmul_operands(scope, func.value, *node.args)
        return scope

    def _record_return(self, node: Return, scope: Scope) -> Scope:
        if node.value is not None:
            scope.returns.append(node.value)
        return scope

    def _record_declaration(self, node: Global | Nonlocal, scope: Scope) -> Scope:
        for name in node.names:
            scope.bind(name, OpaqueBinding())
        return scope

    def _record_import(self, node: Import, scope: Scope) -> Scope:
        for alias in node.names:
            if alias.asname:
                local = alias.asname
                self.imports[local] = alias.name
            else:
                local = alias.name.split(".")[0]
                self.imports[local] = local
            self.imported_modules.add(local)
            scope.bind(local, OpaqueBinding())
        return scope

    def _record_import_from(self, node: ImportFrom, scope: Scope) -> Scope:
        # a relative import keeps its leading dots (`.utils.to_homogeneous`), resolved by summaries
        module = "." * node.level + (node.module or "")
        if module:
            for alias in node.names:
                if alias.name == "*":
                    self.star_imports.append(module)
                    continue
                local = alias.asname or alias.name
                self.imports[local] = f"{module}.{alias.name}" if node.module else f"{module}{alias.name}"
                scope.bind(local, OpaqueBinding())
        return scope

    def _bind_arguments(self, args: ast.arguments, scope: Scope, function: AST) -> None:
        positional = [*args.posonlyargs, *args.args]
        defaults: list[ast.expr | None] = [None] * (len(positional) - len(args.defaults)) + list(args.defaults)
        for arg, default in zip(positional, defaults):
            scope.bind(arg.arg, ParamBinding(arg, default, function))
        for arg, default in zip(args.kwonlyargs, args.kw_defaults):
            scope.bind(arg.arg, ParamBinding(arg, default, function))
        for star in (args.vararg, args.kwarg):
            if star is not None:
                scope.bind(star.arg, OpaqueBinding())

    def _bind_target(self, target: ast.expr, value: Binding, scope: Scope) -> None:
        if isinstance(target, Name):
            scope.bind(target.id, value)
        elif isinstance(target, (ast.Tuple, ast.List)):
            for position, element in enumerate(target.elts):
                if isinstance(element, Name) and isinstance(value, ast.expr):
                    scope.bind(element.id, UnpackBinding(value, position))
                else:
                    self._bind_target(element, OpaqueBinding(), scope)
        elif isinstance(target, Starred):
            self._bind_target(target.value, OpaqueBinding(), scope)
        elif isinstance(target, Subscript) and isinstance(target.value, Name):
            if isinstance(value, ast.expr):
                scope.subscript_stores.setdefault(target.value.id, []).append((target, value))
        elif isinstance(target, Attribute) and isinstance(value, ast.expr):
            scope.attribute_stores.append((target, value))
            if isinstance(target.value, Name) and target.value.id == "self":
                self.self_attribute_stores.setdefault(target.attr, []).append(value)

    def _bind_loop(self, target: ast.expr, iterable: ast.expr, scope: Scope) -> None:
        if isinstance(target, Name):
            scope.bind(target.id, LoopBinding(iterable))
        elif isinstance(target, (ast.Tuple, ast.List)):
            for position, element in enumerate(target.elts):
                if isinstance(element, Name):
                    scope.bind(element.id, LoopBinding(iterable, position))
                else:
                    self._bind_target(element, OpaqueBinding(), scope)

    def forget_derived(self) -> None:
        """Drop what queries built on the index (merged node lists, lines, flow tables): they are
        rebuilt on demand, and a kept index then takes no more memory than a fresh one."""
        self._merged = {}
        self._lines = None
        self.flow = {}

    # -- queries ------------------------------------------------------------------------
    def nodes(self, *kinds: type) -> list[AST]:
        """Every node of these types, in source order (a list several rules share: never change it).
        Types without child nodes (`Name`, `Constant`...) are not listed."""
        if not _NO_CHILDREN.isdisjoint(kinds):
            raise ValueError(f"nodes of {', '.join(kind.__name__ for kind in kinds)}: childless types are not listed")
        if len(kinds) == 1:
            return self.by_type.get(kinds[0], [])
        found = self._merged.get(kinds)
        if found is None:
            found = [node for kind in kinds for node in self.by_type.get(kind, [])]
            positioned = all("lineno" in getattr(kind, "_attributes", ()) for kind in kinds)  # then in C, not `_position`
            found.sort(key=_LINE_AND_COLUMN if positioned else _position)
            self._merged[kinds] = found
        return found

    def parent(self, node: AST) -> AST | None:
        return self.parents.get(node)

    def scope_of(self, node: AST) -> Scope:
        return self.scope_of_node.get(node) or self.scopes[self.tree]

    def lookup(self, name: str, scope: Scope) -> list[Binding] | None:
        """The bindings `name` resolves to from `scope` (class bodies are skipped, as in Python)."""
        if name in scope.bindings:
            return scope.bindings[name]
        current = scope.parent
        while current is not None:
            if not isinstance(current.node, ClassDef) and name in current.bindings:
                return current.bindings[name]
            current = current.parent
        return None

    def code_of(self, node: AST) -> str:
        """The source text of a node (normalised to one line when it spans several)."""
        segment = self._source_segment(node)
        if segment is None:
            try:
                return ast.unparse(node)
            except Exception:  # noqa: BLE001 - a message must never crash the run
                return "?"
        return " ".join(segment.split()) if "\n" in segment else segment

    def segment(self, node: AST) -> str:
        """The exact source text of a node's span (what a replacement replaces)."""
        return self._source_segment(node) or ""

    def _source_segment(self, node: AST) -> str | None:
        """`ast.get_source_segment` on lines split once per module (it re-splits the whole source on
        every call, which made a module with many findings quadratic in its size)."""
        try:
            first, last = node.lineno - 1, node.end_lineno - 1  # type: ignore[attr-defined, operator]
            start, end = node.col_offset, node.end_col_offset  # type: ignore[attr-defined]
        except (AttributeError, TypeError):
            return None
        if end is None:
            return None
        lines = self._lines
        if lines is None:
            lines = self._lines = split_lines(self.source)
        if not 0 <= first <= last < len(lines):
            return None
        if first == last:
            return lines[first].encode()[start:end].decode(errors="replace")
        head = lines[first].encode()[start:].decode(errors="replace")
        tail = lines[last].encode()[:end].decode(errors="replace")
        return "".join([head, *lines[first + 1 : last], tail])


# Nodes nothing asks about (`Load`, `Add`...): not indexed, not walked.
_LEAVES: Final = frozenset(
    {Load, Store, Del, *ast.operator.__subclasses__(), *ast.unaryop.__subclasses__(),
     *ast.cmpop.__subclasses__(), *ast.boolop.__subclasses__()}
)  # fmt: skip
# Nodes without child nodes worth walking (`Name`'s only child is its `Load`).
_NO_CHILDREN: Final = frozenset({Name, Constant, ast.alias, Pass, Break, Continue})
# Fields that never hold a node (or hold only `_LEAVES`): skipped without a look.
_NOT_CHILD_FIELDS: Final = frozenset(
    {"ctx", "op", "id", "attr", "arg", "name", "kind", "type_comment", "level", "module", "asname", "is_async", "conversion", "simple"}
)
_CHILD_FIELDS: Final[dict[type, tuple[str, ...]]] = {}
_REVERSED_CHILD_FIELDS: Final[dict[type, tuple[str, ...]]] = {}
# What the walk does with a child of each node type: skip it (`_LEAVES`), record it without pushing
# it (`_NO_CHILDREN`), or walk it; one dictionary look-up per child instead of three tests.
_SKIPPED: Final = 0
_CHILDLESS: Final = 1
_WALKED: Final = 2


def module_constant(index: ModuleIndex, name: str) -> ast.expr | None:
    """The value of a module-level name assigned exactly once (never augmented, nor rebound by a
    function through `global`): what every reader of the name sees."""
    module = index.scopes[index.tree]
    found = module.bindings.get(name) or []
    if len(found) != 1 or not isinstance(found[0], ast.expr) or name in module.augmented:
        return None
    if any(name in node.names for node in index.nodes(Global)):  # type: ignore[attr-defined]
        return None
    return found[0]


def _node_types(base: type[AST] = AST) -> list[type[AST]]:
    """Every `ast` node class."""
    found: list[type[AST]] = []
    for sub in base.__subclasses__():
        found += [sub, *_node_types(sub)]
    return found


_ROLE: Final[dict[type, int]] = {
    type(None): _SKIPPED,
    **{kind: _SKIPPED if kind in _LEAVES else _CHILDLESS if kind in _NO_CHILDREN else _WALKED for kind in _node_types()},
}
_MATMUL_METHODS: Final = ("dot", "matmul")
_SCOPE_MAKERS: Final = frozenset({FunctionDef, AsyncFunctionDef, Lambda, ClassDef})
# What the walk records for the nodes that bind names, make scopes, return or multiply matrices
# (by exact type, as `ast` makes them: one dictionary look-up per node).
_RECORDERS: Final[dict[type, Callable[[ModuleIndex, Any, Scope], Scope]]] = {
    FunctionDef: ModuleIndex._record_function, AsyncFunctionDef: ModuleIndex._record_function,
    Lambda: ModuleIndex._record_lambda, ClassDef: ModuleIndex._record_class,
    Assign: ModuleIndex._record_assign, AnnAssign: ModuleIndex._record_annotated,
    AugAssign: ModuleIndex._record_augmented, NamedExpr: ModuleIndex._record_walrus,
    For: ModuleIndex._record_loop, AsyncFor: ModuleIndex._record_loop, ast.comprehension: ModuleIndex._record_loop,
    ast.withitem: ModuleIndex._record_with_item, ExceptHandler: ModuleIndex._record_handler,
    BinOp: ModuleIndex._record_binary, Call: ModuleIndex._record_call, Return: ModuleIndex._record_return,
    Global: ModuleIndex._record_declaration, Nonlocal: ModuleIndex._record_declaration,
    Import: ModuleIndex._record_import, ImportFrom: ModuleIndex._record_import_from,
}  # fmt: skip


def child_nodes(node: AST) -> list[AST]:
    """`ast.iter_child_nodes(node)` as a list, less the leaves nothing asks about (`Load`, operators)."""
    kind = type(node)
    fields = _CHILD_FIELDS.get(kind)
    if fields is None:
        fields = _CHILD_FIELDS[kind] = tuple(f for f in kind._fields if f not in _NOT_CHILD_FIELDS)
    children = []
    for name in fields:
        value = getattr(node, name, None)
        if type(value) is list:
            for child in value:
                role = _ROLE.get(type(child))
                if role is None:  # not a node, or a node type not seen yet
                    role = _WALKED if isinstance(child, AST) else _SKIPPED
                if role != _SKIPPED:
                    children.append(child)
        else:
            role = _ROLE.get(type(value))
            if role is None:
                role = _WALKED if isinstance(value, AST) else _SKIPPED
            if role != _SKIPPED:
                children.append(value)
    return children


_STATEMENT_LIST_FIELDS: Final = ("body", "orelse", "finalbody", "handlers", "cases")
_statement_lists_of: dict[type, tuple[str, ...]] = {}


def statement_list_fields(node: AST) -> tuple[str, ...]:
    """Which of `body`, `orelse`, `finalbody`, `handlers` and `cases` a statement (or an `except`
    handler, or a `match` case) holds, in that order. Asked instead of `getattr` with a default,
    which for each simple statement would first raise and format an `AttributeError`."""
    kind = type(node)
    fields = _statement_lists_of.get(kind)
    if fields is None:
        fields = _statement_lists_of[kind] = tuple(f for f in _STATEMENT_LIST_FIELDS if f in kind._fields)
    return fields


def _reversed_child_fields(kind: type[AST]) -> tuple[str, ...]:
    fields = _CHILD_FIELDS.get(kind)
    if fields is None:
        fields = _CHILD_FIELDS[kind] = tuple(f for f in kind._fields if f not in _NOT_CHILD_FIELDS)
    return fields[::-1]


def _runs_in_inner_scope(node: AST, child: AST) -> bool:
    """Whether `child` of a scope-making `node` belongs to the new scope (not defaults, decorators, bases)."""
    if isinstance(node, FUNCTION_NODES):
        return not (child is node.args or child is node.returns or any(child is d for d in node.decorator_list))
    if isinstance(node, Lambda):
        return child is node.body
    if isinstance(node, ClassDef):
        return not any(child is other for other in (*node.bases, *node.keywords, *node.decorator_list))
    return True


_LINE_AND_COLUMN: Final = operator.attrgetter("lineno", "col_offset")


def _position(node: AST) -> tuple[int, int]:
    return (getattr(node, "lineno", 0), getattr(node, "col_offset", 0))


def _matmul_operands(scope: Scope, *operands: ast.expr) -> None:
    for operand in operands:
        while isinstance(operand, Attribute) and operand.attr == "T":
            operand = operand.value
        if isinstance(operand, Name):
            scope.matmul_operands.add(operand.id)


# --- the project modules parsed in this process ------------------------------------------------
# A project module that helpers' summaries parse (`index_of_file`, and the naming votes'
# `parse_of_file`) is kept here, and its lint takes the tree and index when it comes (the engine's
# own trees are not kept: few are imported after they are linted). Kept least recently used first,
# up to a total text size (a tree and its index take about 40 bytes per character).
_SHARED_BUDGET: Final = 1_000_000  # characters
_DEFAULT_DEPTH_LIMIT: Final = Config.max_nesting_depth
_shared: OrderedDict[str, _SharedModule] = OrderedDict()
_shared_size = 0
_shared_lock = threading.Lock()


class _SharedModule:
    """One module's text and parse; `signature` (size, mtime) once the text was checked against the file."""

    __slots__ = ("source", "tree", "index", "signature")

    def __init__(self, source: str, tree: Module | None, index: ModuleIndex | None, signature: tuple[int, int] | None) -> None:
        self.source = source
        self.tree = tree  # None: the text does not parse
        self.index = index  # built on first use when the engine left only a tree
        self.signature = signature


def index_of_file(file: str | os.PathLike[str]) -> ModuleIndex | None:
    """The index of the project module at `file` (its text decoded as UTF-8, bad bytes replaced), or
    None when it cannot be read or does not parse. Shared by the whole process, and valid while the
    file's size and mtime (or, for a tree the engine left, its very text) are unchanged."""
    key = os.path.abspath(file)
    try:
        stat = os.stat(key)
    except OSError:
        return None
    signature = (stat.st_size, stat.st_mtime_ns)
    entry = _shared_entry(key)
    if entry is None or entry.signature != signature:
        try:
            with open(key, "rb") as stream:
                source = stream.read().decode("utf-8", errors="replace")
        except OSError:
            return None
        if entry is not None and entry.source == source:
            entry.signature = signature  # a tree of this very text (the naming votes' parse)
        else:
            entry = _parse_and_share(key, source, signature)
    if entry.tree is None:
        return None
    index = entry.index
    if index is None or index.too_deep:
        # walked against the default depth limit, so the engine can take it for a file it lints
        # (past it, walked whole: the summaries read every function)
        index = ModuleIndex(entry.tree, entry.source, _DEFAULT_DEPTH_LIMIT)
        if index.too_deep:
            index = ModuleIndex(entry.tree, entry.source)
        entry.index = index
    return index


def parse_of_file(file: str, source: str, signature: tuple[int, int]) -> Module | None:
    """The tree of `source`, the text of `file` (read by a caller that has its size and mtime), or None
    when it does not parse: parsed once and kept like `index_of_file`'s trees, so linting the file or
    importing it later takes this tree (the naming votes read a project's files before any is linted)."""
    key = os.path.abspath(file)
    entry = _shared_entry(key)
    if entry is not None and entry.source == source:
        return entry.tree
    return _parse_and_share(key, source, signature).tree


def _parse_and_share(key: str, source: str, signature: tuple[int, int]) -> _SharedModule:
    """Parse a project module's text (None for a text that does not parse) and keep it under `key`."""
    try:
        tree: Module | None = parse_module(source)
    except (SyntaxError, ValueError, MemoryError, RecursionError):
        tree = None
    entry = _SharedModule(source, tree, None, signature)
    _share(key, entry)
    return entry


def shared_parse(path: str, source: str) -> tuple[Module, ModuleIndex | None] | None:
    """The tree (and index, if built) of the module at `path` when one was kept for exactly `source`."""
    if path.startswith("<"):
        return None
    entry = _shared_entry(os.path.abspath(path))
    if entry is None or entry.tree is None or entry.source != source:
        return None
    return entry.tree, entry.index


def _shared_entry(key: str) -> _SharedModule | None:
    with _shared_lock:
        entry = _shared.get(key)
        if entry is not None:
            _shared.move_to_end(key)
        return entry


def _share(key: str, entry: _SharedModule) -> None:
    global _shared_size
    with _shared_lock:
        old = _shared.pop(key, None)
        if old is not None:
            _shared_size -= len(old.source)
        if len(entry.source) > _SHARED_BUDGET:
            return
        _shared[key] = entry
        _shared_size += len(entry.source)
        while _shared_size > _SHARED_BUDGET:
            _, evicted = _shared.popitem(last=False)
            _shared_size -= len(evicted.source)
