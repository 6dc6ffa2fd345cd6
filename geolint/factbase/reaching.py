"""Which bindings of a name can reach one use of it: flow-sensitive reads within a body.

`x = points; ...; x = normals; T @ hom(x)` uses the normals: the index records every binding of
`x` in the function, and without order the two kinds cancel out (the fact base then says
nothing). Here a use sees the last binding that always runs before it (a statement earlier in the
same block or an enclosing one, or a parameter), plus the bindings after that one that may run
before it (in branches), plus, inside a loop, the bindings later in that loop that the next
iteration carries back, unless the always-running one sits in the same loop.

It is a reaching-definitions analysis on statement blocks, deliberately conservative: `try`
bodies, branches and loop bodies never always-run for code after them, and whenever a binding
cannot be placed (`global`), every binding counts, as before. A comprehension's target (which the
index binds in the enclosing function) is the one binding its comprehension reads, and reaches
nothing outside it. An assignment expression `(n := value)` binds where it is evaluated: before the
blocks of the statement it is in (`if (n := f()) is not None: use(n)`) and the statements after
it; it always runs with its statement unless it sits where evaluation may skip it (after `and` /
`or`, in a branch of `a if c else b`, in a comprehension, whose `:=` binds the function's name);
a read in the same statement as a `:=` of its name has no one definition (there source order is
not evaluation order: `use(n) if (n := f()) else 0`).

The same flow answers the pose rules' questions about one use (`single_definition`, `value_of`,
`resolve`, `binding_of`, `parameter_of`): the one definition that reaches it, if only one can. For
them an augmented assignment `x -= t` is a definition too (`x = x - t`, whose `x` reads the value
before), and `R, t = split_pose(T)` gives each name an element of the unpacked value (`Unpacked`).
"""

from __future__ import annotations

import ast
from ast import (
    AST, AnnAssign, Assert, Assign, AsyncFor, AsyncFunctionDef, AsyncWith, AugAssign, BinOp, BoolOp, ClassDef,
    DictComp, ExceptHandler, For, FunctionDef, GeneratorExp, IfExp, Import, ImportFrom, Lambda, ListComp, Load, Name,
    NamedExpr, SetComp, Starred, Try, While, With,
)
from bisect import bisect_right
from dataclasses import dataclass
from typing import Any, Callable, Final, Iterator, Sequence

from geolint.factbase.index import (
    Binding, LoopBinding, ModuleIndex, OpaqueBinding, ParamBinding, Scope, UnpackBinding, statement_list_fields,
)

_MAX_BINDINGS: Final = 64  # past this many rebindings of one name, order is not worth its cost: all count
_LOOPS: Final = (For, AsyncFor, While)
_BLOCK_FIELDS: Final = ("body", "orelse", "finalbody")
_ARMS: Final = frozenset({"handlers", "cases"})  # lists of `except` handlers and `match` cases, whose bodies hold statements
_NESTED_SCOPES: Final = (FunctionDef, AsyncFunctionDef, ClassDef)


@dataclass(frozen=True)
class Augmented:
    """`x op= value`, read as `x = x op value`: `value` is that `BinOp` (made once per statement),
    whose `x`, a copy of the target, reads what x held before the statement."""

    statement: AugAssign
    value: BinOp


@dataclass(frozen=True)
class Definition:
    """One binding of a name: `statement` binds it, effective from `point` on."""

    binding: Binding | Augmented
    statement: ast.stmt
    point: tuple[int, int]
    only_inside: bool  # a loop target: bound in the loop's body only, maybe never (zero iterations)
    within: AST | None = None  # a comprehension's target: bound inside that comprehension only
    walrus: NamedExpr | None = None  # `(name := value)`, somewhere in `statement`'s own expressions


@dataclass(frozen=True)
class Unpacked:
    """`R, t = split_pose(T)`: element `index` of `value`, unpacked into `names` ("" for a target
    that is not a plain name) by `statement`."""

    value: ast.expr
    index: int
    names: tuple[str, ...]
    statement: ast.stmt


def reaching_bindings(index: ModuleIndex, scope: Scope, use: Name, bindings: Sequence[Binding]) -> Sequence[Binding]:
    """The bindings of `use.id` (all of them: `bindings`) that can reach `use`: `bindings` itself
    when all can (a list every such use shares: never change it)."""
    if len(bindings) < 2 or len(bindings) > _MAX_BINDINGS or not isinstance(use.ctx, Load):
        return bindings
    uses = _memo(index, "reaching_uses")
    known = uses.get(id(use))
    if known is None:
        placed = _events(index, scope, use.id, bindings, augmented=False)
        reached = _reached(index, scope, use, placed) if placed is not None else None
        known = uses[id(use)] = [event.binding for event in reached] if reached is not None else bindings  # type: ignore[misc]
    return known  # type: ignore[no-any-return]


def every_binding_reaches(bindings: Sequence[Binding]) -> bool:
    """Whether `reaching_bindings` gives every use of the name all of `bindings`, past order's
    cost (more of them than it is kept for): then the answer about one use is the answer about all."""
    return len(bindings) > _MAX_BINDINGS


class _Placed:
    """A name's definitions in one scope, in order, with what `_reached` looks up in them: those
    bound outside comprehensions (`plain`) and their points, for bisection; those a comprehension
    binds, by comprehension; the statements whose `:=` binds the name."""

    __slots__ = ("events", "plain", "points", "within", "walrus_statements")

    def __init__(self, events: list[Definition]) -> None:
        self.events = events
        self.within: dict[int, list[Definition]] = {}
        for event in events:
            if event.within is not None:
                self.within.setdefault(id(event.within), []).append(event)
        self.plain = [event for event in events if event.within is None] if self.within else events
        self.points = [event.point for event in self.plain]
        self.walrus_statements = {id(event.statement) for event in self.plain if event.walrus is not None}


def _reached(index: ModuleIndex, scope: Scope, use: Name, placed: _Placed, most: int | None = None) -> list[Definition] | None:
    """The definitions among `placed` (all of the name's, in order) that can reach `use`; None when
    none is placed before it (a loop's later one, or a closure's read), or as soon as more than
    `most` can (when given). Bisection on the definitions' points and the loops' ends keeps the
    cost to what reaches the use, not every definition of the name."""
    ancestors = _ancestors(index, use, scope.node)
    if placed.within:
        # a comprehension's target is the only binding its comprehension reads, and none outside it
        for node in ancestors:
            inside = placed.within.get(id(node))
            if inside and not _in_first_iterable(node, use, ancestors):
                return inside if most is None or len(inside) <= most else None
    events, points = placed.plain, placed.points
    if placed.walrus_statements and id(statement_of(index, use)) in placed.walrus_statements:
        return None  # a `:=` in the read's own statement: source order is not evaluation order there
    position = (use.lineno, use.col_offset)
    cut = bisect_right(points, position)
    if cut == 0:
        return None
    # the last definition that always runs before the use starts the reaching ones (past `most`
    # from the end, there are too many whichever it is)
    last = -1 if most is None else max(cut - 1 - most, -1)
    start = 0
    for number in range(cut - 1, last, -1):
        if _always_runs_before(index, events[number], ancestors):
            start = number
            break
    else:
        if most is not None and cut > most:
            return None
    reaching = events[start:cut]
    dominating = events[start] if _always_runs_before(index, events[start], ancestors) else None
    for loop in (node for node in ancestors if isinstance(node, _LOOPS)):
        if dominating is not None and _repeats_in(index, dominating, loop):
            break  # re-bound on every iteration before the use: nothing is carried back past it
        # a definition inside the loop is placed no later than the loop's end
        end = bisect_right(points, (loop.end_lineno or loop.lineno, loop.end_col_offset or 0), cut)
        for event in events[cut:end]:
            if _repeats_in(index, event, loop):
                reaching.append(event)
                if most is not None and len(reaching) > most:
                    return None
    return reaching


def _events(index: ModuleIndex, scope: Scope, name: str, bindings: Sequence[Binding], augmented: bool) -> _Placed | None:
    """Every definition of `name` in the scope's body, placed, in order (augmented assignments when
    `augmented`); None when one of the index's `bindings` cannot be placed."""
    memo = _memo(index, "events")
    key = (id(scope.node), name, augmented)
    if key in memo:
        return memo[key]  # type: ignore[no-any-return]
    table = _scope_definitions(index, scope)
    placed = None
    if table is not None:
        first: ast.stmt = scope.node.body[0]  # type: ignore[index]  # a body that is a list (`table`)
        events = [Definition(binding, first, (0, 0), False) for binding in bindings if isinstance(binding, ParamBinding)]
        events.extend(event for event in table.get(name, ()) if augmented or not isinstance(event.binding, Augmented))
        matched = _match(events, bindings)
        placed = _Placed(matched) if matched is not None else None
    memo[key] = placed
    return placed


def _scope_definitions(index: ModuleIndex, scope: Scope) -> dict[str, list[Definition]] | None:
    """The definitions each statement of the scope's body makes, by name (one pass per scope);
    None for a body that is an expression (a lambda)."""
    memo = _memo(index, "scope_definitions")
    key = id(scope.node)
    if key in memo:
        return memo[key]  # type: ignore[no-any-return]
    body = getattr(scope.node, "body", None)
    table: dict[str, list[Definition]] | None = None
    if isinstance(body, list) and body:
        table = {}
        for statement in _statements(body):
            for name, event in _bound_by(index, statement):
                table.setdefault(name, []).append(event)
        for comprehension in _comprehensions(index).get(key, ()):
            holder = statement_of(index, comprehension)
            if holder is None:
                continue  # its targets stay unplaced: every binding of theirs counts
            for generator in comprehension.generators:  # type: ignore[attr-defined]
                iterable = generator.iter
                point = (iterable.end_lineno or iterable.lineno, iterable.end_col_offset or 0)
                for name, event in _loop_events(generator.target, iterable, holder, point):
                    table.setdefault(name, []).append(
                        Definition(event.binding, event.statement, event.point, event.only_inside, comprehension, event.walrus)
                    )
        for walrus in _walruses(index).get(key, ()):
            holder = statement_of(index, walrus)
            if holder is not None and isinstance(walrus.target, Name):
                point = (walrus.end_lineno or walrus.lineno, walrus.end_col_offset or 0)
                definition = Definition(walrus.value, holder, point, False, walrus=walrus)
                table.setdefault(walrus.target.id, []).append(definition)
    memo[key] = table
    return table


_COMPREHENSIONS: Final = (ListComp, SetComp, DictComp, GeneratorExp)


def _comprehensions(index: ModuleIndex) -> dict[int, list[AST]]:
    """The module's comprehensions by the scope their targets are bound in (the index binds them
    in the enclosing function's), in source order."""
    by_scope = index.flow.get("comprehensions")
    if by_scope is None:
        by_scope = index.flow["comprehensions"] = {}
        for comprehension in index.nodes(*_COMPREHENSIONS):
            by_scope.setdefault(id(index.scope_of(comprehension).node), []).append(comprehension)
    return by_scope


def _walruses(index: ModuleIndex) -> dict[int, list[NamedExpr]]:
    """The module's assignment expressions by the scope they bind in (the index's: a comprehension's
    `:=` binds in the enclosing function, PEP 572)."""
    by_scope = index.flow.get("walruses")
    if by_scope is None:
        by_scope = index.flow["walruses"] = {}
        for walrus in index.nodes(NamedExpr):
            by_scope.setdefault(id(index.scope_of(walrus).node), []).append(walrus)
    return by_scope


# where evaluation may skip an expression although its statement runs: the node's fields that
# always run (none of a comprehension's: it may iterate no time)
_MAYBE_SKIPPED: Final[dict[type, tuple[str, ...]]] = {
    IfExp: ("test",),
    ListComp: (), SetComp: (), DictComp: (), GeneratorExp: (),
    ExceptHandler: (), ast.match_case: (), Lambda: (),
    Assert: ("test",),
}  # fmt: skip


def _always_evaluated(index: ModuleIndex, walrus: NamedExpr, statement: ast.stmt) -> bool:
    """Whether `walrus` runs whenever `statement` does (no `and`/`or` tail, conditional branch,
    comprehension, handler or case guard between them)."""
    child: AST = walrus
    current = index.parents.get(walrus)
    while current is not None:
        if isinstance(current, BoolOp) and child is not current.values[0]:
            return False
        kept = _MAYBE_SKIPPED.get(type(current))
        if kept is not None and not any(getattr(current, field, None) is child for field in kept):
            return False
        if current is statement:
            return True
        child, current = current, index.parents.get(current)
    return False


def _repeats_in(index: ModuleIndex, event: Definition, loop: AST) -> bool:
    """Whether `event` binds anew on each iteration of `loop` (a `:=` in a `for`'s iterable runs once)."""
    if event.walrus is None:
        return _inside(index, event.statement, loop)
    if isinstance(loop, (For, AsyncFor)) and _inside(index, event.walrus, loop.iter):
        return False
    return _inside(index, event.walrus, loop)


def _match(events: list[Definition], bindings: Sequence[Binding]) -> list[Definition] | None:
    """The events in source order, each holding the index's own binding object; None unless every
    binding of the index is found (an unplaced binding makes order unsafe). Augmented assignments,
    which the index does not bind, pass as they are. Each event takes the first binding of the index
    not taken yet that records the same thing (`_identity`): one look-up per event."""
    unmatched: dict[object, list[Binding]] = {}
    for binding in reversed(bindings):  # reversed: each list pops its first binding off its end
        unmatched.setdefault(_identity(binding), []).append(binding)
    matched: list[Definition] = []
    for event in events:
        if isinstance(event.binding, Augmented):
            matched.append(event)
            continue
        candidates = unmatched.get(_identity(event.binding))
        if not candidates:
            return None
        binding = candidates.pop()
        # the constructor, not `dataclasses.replace`: this runs for every binding of every scope
        matched.append(Definition(binding, event.statement, event.point, event.only_inside, event.within, event.walrus))
    if any(unmatched.values()):
        return None
    matched.sort(key=lambda event: event.point)
    return matched


def _identity(binding: Binding) -> object:
    """What a binding records, as a key: two bindings with one key are the same binding (every
    `OpaqueBinding` is like every other; a loop or unpacked element is its value and position)."""
    if isinstance(binding, OpaqueBinding):
        return OpaqueBinding
    if isinstance(binding, LoopBinding):
        return (LoopBinding, id(binding.iterable), binding.position)
    if isinstance(binding, UnpackBinding):
        return (UnpackBinding, id(binding.value), binding.position)
    return id(binding)


def _statements(body: list[ast.stmt]) -> Iterator[ast.stmt]:
    """Every statement of a body, nested blocks included, not those of nested functions or classes."""
    stack = list(reversed(body))
    while stack:
        statement = stack.pop()
        yield statement
        if isinstance(statement, _NESTED_SCOPES):
            continue
        nested: list[ast.stmt] = []
        for field in statement_list_fields(statement):
            if field in _ARMS:
                for arm in getattr(statement, field):
                    nested.extend(arm.body)
            else:
                nested.extend(getattr(statement, field))
        stack.extend(reversed(nested))


def _bound_by(index: ModuleIndex, statement: ast.stmt) -> Iterator[tuple[str, Definition]]:
    """The names `statement` itself binds (not its nested blocks), with their definitions."""
    end = (statement.end_lineno or statement.lineno, statement.end_col_offset or 0)
    if isinstance(statement, Assign):
        for target in statement.targets:
            yield from _target_events(target, statement.value, statement, end)
    elif isinstance(statement, AnnAssign):
        if isinstance(statement.target, Name):
            value = statement.value if statement.value is not None else OpaqueBinding()
            yield statement.target.id, Definition(value, statement, end, False)
    elif isinstance(statement, AugAssign):
        if isinstance(statement.target, Name):
            yield statement.target.id, Definition(_augmented(index, statement), statement, end, False)
    elif isinstance(statement, (For, AsyncFor)):
        iterable = statement.iter
        point = (iterable.end_lineno or iterable.lineno, iterable.end_col_offset or 0)
        yield from _loop_events(statement.target, iterable, statement, point)
    elif isinstance(statement, (With, AsyncWith)):
        for item in statement.items:
            if item.optional_vars is not None:
                for name in _names_in(item.optional_vars):
                    yield name, Definition(OpaqueBinding(), statement, (item.context_expr.lineno, item.context_expr.col_offset), False)
    elif isinstance(statement, _NESTED_SCOPES):
        yield statement.name, Definition(OpaqueBinding(), statement, end, False)
    elif isinstance(statement, (Import, ImportFrom)):
        for alias in statement.names:
            if alias.name != "*":
                yield alias.asname or alias.name.split(".")[0], Definition(OpaqueBinding(), statement, end, False)
    elif isinstance(statement, Try) or type(statement).__name__ == "TryStar":
        for handler in statement.handlers:  # type: ignore[attr-defined]
            if handler.name:
                yield handler.name, Definition(OpaqueBinding(), handler.body[0], (handler.lineno, handler.col_offset), True)


def _augmented(index: ModuleIndex, statement: AugAssign) -> Augmented:
    """`x op= value` as `x op value`, its nodes placed under the statement (`statement_of`, `scope_of`)."""
    target = statement.target
    assert isinstance(target, Name)
    current = ast.copy_location(Name(id=target.id, ctx=Load()), target)
    value = ast.copy_location(BinOp(left=current, op=statement.op, right=statement.value), statement)
    made = _memo(index, "made_parents")
    made[value] = statement
    made[current] = value
    return Augmented(statement, value)


def _target_events(target: ast.expr, value: ast.expr, statement: ast.stmt, end: tuple[int, int]) -> Iterator[tuple[str, Definition]]:
    """`name = value`, `a, name = value`: as the index binds an assignment's targets."""
    return _unpacked(target, value, lambda position: UnpackBinding(value, position), statement, end, False)


def _loop_events(target: ast.expr, iterable: ast.expr, statement: ast.stmt, point: tuple[int, int]) -> Iterator[tuple[str, Definition]]:
    """`for name in iterable`, `for i, name in ...`: as the index binds a loop's targets."""
    whole = LoopBinding(iterable)
    return _unpacked(target, whole, lambda position: LoopBinding(iterable, position), statement, point, True)


def _unpacked(
    target: ast.expr,
    whole: Binding,
    element: Callable[[int], Binding],
    statement: ast.stmt,
    point: tuple[int, int],
    only_inside: bool,
) -> Iterator[tuple[str, Definition]]:
    if isinstance(target, Name):
        yield target.id, Definition(whole, statement, point, only_inside)
    elif isinstance(target, (ast.Tuple, ast.List)):
        for position, item in enumerate(target.elts):
            if isinstance(item, Name):
                yield item.id, Definition(element(position), statement, point, only_inside)
            else:
                for name in _names_in(item):
                    yield name, Definition(OpaqueBinding(), statement, point, only_inside)
    elif isinstance(target, Starred):
        for name in _names_in(target.value):
            yield name, Definition(OpaqueBinding(), statement, point, only_inside)


def _names_in(target: ast.expr) -> list[str]:
    """The distinct names a nested target binds, as the index binds them: through tuples, lists and
    stars, not the names an item or attribute target (`a[i]`, `self.x`) writes into."""
    names: list[str] = []
    stack = [target]
    while stack:
        node = stack.pop()
        if isinstance(node, Name):
            names.append(node.id)
        elif isinstance(node, (ast.Tuple, ast.List)):
            stack.extend(reversed(node.elts))
        elif isinstance(node, Starred):
            stack.append(node.value)
    return list(dict.fromkeys(names))


def _in_first_iterable(comprehension: AST, use: AST, ancestors: list[AST]) -> bool:
    """`[... for x in <here>]`: the first iterable is read in the enclosing scope, not the comprehension's."""
    first = comprehension.generators[0].iter  # type: ignore[attr-defined]
    return use is first or any(node is first for node in ancestors)


def _ancestors(index: ModuleIndex, node: AST, stop: AST) -> list[AST]:
    """The nodes enclosing `node`, innermost first, up to (not including) the scope node `stop`."""
    found = []
    current = _parent(index, node)
    while current is not None and current is not stop:
        found.append(current)
        current = index.parents.get(current)
    return found


def _always_runs_before(index: ModuleIndex, event: Definition, ancestors: list[AST]) -> bool:
    """Whether `event`'s binding runs on every path to the use whose enclosing nodes are `ancestors`."""
    if event.point == (0, 0):
        return True  # a parameter
    statement = event.statement
    if event.walrus is not None:
        if not _always_evaluated(index, event.walrus, statement):
            return False
        if any(node is statement for node in ancestors):
            return True  # the read is in a block of the statement whose test, iterable... binds it
    if event.only_inside:
        # a loop target reaches its own body for sure (a `for` with zero iterations never runs it)
        return any(node is statement for node in ancestors) and _in_block(index, statement, "body", ancestors)
    parent = index.parents.get(statement)
    for node in ancestors:
        if index.parents.get(node) is parent and node is not statement:
            return _same_block(index, parent, statement, node)
        if node is statement:
            # the use sits inside the binding statement's own blocks (`with ... as x:` body)
            return isinstance(statement, (With, AsyncWith))
    return False


def _same_block(index: ModuleIndex, parent: AST | None, first: ast.stmt, second: AST) -> bool:
    """Whether `first` and `second` are statements of one block of `parent` (then `first`, being
    earlier, always runs before `second`)."""
    if parent is None:
        return False
    blocks = _blocks_of(index, parent)
    field = blocks.get(id(first))
    return field is not None and blocks.get(id(second)) == field


def _in_block(index: ModuleIndex, statement: ast.stmt, field: str, ancestors: list[AST]) -> bool:
    """Whether one of `ancestors` is a statement of `statement`'s block `field`."""
    blocks = _blocks_of(index, statement)
    return any(blocks.get(id(node)) == field for node in ancestors)


def _blocks_of(index: ModuleIndex, holder: AST) -> dict[int, str]:
    """Which of `holder`'s blocks (`body`, `orelse`, `finalbody`) each of its statements is in,
    by statement: one pass over a block, not one per question about it."""
    memo = _memo(index, "blocks")
    blocks = memo.get(id(holder))
    if blocks is None:
        blocks = memo[id(holder)] = {}
        for field in reversed(_BLOCK_FIELDS):  # reversed: a statement in two lists is the first list's
            block = getattr(holder, field, None)
            if isinstance(block, list):
                blocks.update((id(item), field) for item in block)
    return blocks  # type: ignore[no-any-return]


def _inside(index: ModuleIndex, node: AST, container: AST) -> bool:
    current: AST | None = node
    while current is not None:
        if current is container:
            return True
        current = index.parents.get(current)
    return False


def _parent(index: ModuleIndex, node: AST) -> AST | None:
    """The node enclosing `node`, for the nodes an augmented assignment's value is made of too."""
    parent = index.parents.get(node)
    return parent if parent is not None else _memo(index, "made_parents").get(node)


def _memo(index: ModuleIndex, name: str) -> dict[Any, Any]:
    """A table kept on the module's index (dropped with what else was derived from it, `forget_derived`)."""
    memo = index.flow.get(name)
    if memo is None:
        memo = index.flow[name] = {}
    return memo


# --- the one definition that reaches a use -------------------------------------------------------


def single_definition(index: ModuleIndex, use: Name) -> Definition | None:
    """The one definition of `use.id` in its own scope that reaches `use` (a parameter, or an
    assignment certainly run before it with no other reaching it); None when several can reach it,
    none is placed before it, or the name is not bound in its scope."""
    memo = _memo(index, "single_definitions")
    key = id(use)
    if key in memo:
        return memo[key]  # type: ignore[no-any-return]
    found = None
    scope = scope_of(index, use)
    bindings = scope.bindings.get(use.id)
    if bindings is not None and isinstance(scope.node, Lambda):
        if len(bindings) == 1 and isinstance(bindings[0], ParamBinding):  # its body is one expression
            found = Definition(bindings[0], scope.node.body, (0, 0), False)  # type: ignore[arg-type]
    elif bindings is not None or use.id in scope.augmented:
        placed = _events(index, scope, use.id, bindings or (), augmented=True)
        reached = _reached(index, scope, use, placed, most=1) if placed is not None else None
        if reached is not None and len(reached) == 1:
            found = reached[0]
    memo[key] = found
    return found


def value_of(index: ModuleIndex, use: Name) -> ast.expr | Unpacked | None:
    """The value `use` certainly holds: the one reaching definition's value (`x op value` for an
    augmented one, a literal's element or an `Unpacked` for a tuple target); None when unknown."""
    definition = single_definition(index, use)
    if definition is None:
        return None
    binding = definition.binding
    if isinstance(binding, Augmented):
        return binding.value
    if isinstance(binding, ast.expr):
        return binding
    if isinstance(binding, UnpackBinding) and isinstance(definition.statement, Assign):
        return _element(binding, definition.statement, use.id)
    return None


def _element(binding: UnpackBinding, statement: Assign, name: str) -> ast.expr | Unpacked | None:
    for target in statement.targets:
        if not isinstance(target, (ast.Tuple, ast.List)) or binding.position >= len(target.elts):
            continue
        element = target.elts[binding.position]
        if not (isinstance(element, Name) and element.id == name):
            continue
        value = binding.value
        if isinstance(value, (ast.Tuple, ast.List)) and len(value.elts) == len(target.elts):
            return value.elts[binding.position]
        names = tuple(item.id if isinstance(item, Name) else "" for item in target.elts)
        return Unpacked(value, binding.position, names, statement)
    return None


def resolve(index: ModuleIndex, node: ast.expr, depth: int = 8) -> ast.expr | Unpacked:
    """Follow local names to the value they certainly hold (the last name reached when unknown)."""
    while isinstance(node, Name) and depth > 0:
        value = value_of(index, node)
        if value is None:
            return node
        if isinstance(value, Unpacked):
            return value
        node = value
        depth -= 1
    return node


def binding_of(index: ModuleIndex, use: Name) -> object:
    """Which definition `use` reads, as a comparable token (a rebound name reads another); a name
    its scope does not bind reads the enclosing one's, `("free", name)`; None when several reach."""
    scope = scope_of(index, use)
    if use.id not in scope.bindings and use.id not in scope.augmented:
        return ("free", use.id)
    definition = single_definition(index, use)
    if definition is None:
        return None
    if isinstance(definition.binding, ParamBinding):
        return ("param", id(scope.node), use.id)
    return id(definition.walrus or definition.statement)


def parameter_of(index: ModuleIndex, use: Name) -> ast.arg | None:
    """The parameter `use` reads, when nothing assigned in its function can reach it instead."""
    definition = single_definition(index, use)
    return definition.binding.arg if definition is not None and isinstance(definition.binding, ParamBinding) else None


def assigned_values(index: ModuleIndex, use: Name) -> list[ast.expr | Unpacked | None]:
    """Every value `use.id` is given in its scope, in order (None for a parameter, a loop target or
    anything else whose value is unknown), whichever of them reaches `use` (one list per name and
    scope, shared by its uses: never change it)."""
    scope = scope_of(index, use)
    memo = _memo(index, "assigned_values")
    key = (id(scope.node), use.id)
    values = memo.get(key)
    if values is None:
        values = memo[key] = _assigned_values(index, scope, use.id)
    return values  # type: ignore[no-any-return]


def _assigned_values(index: ModuleIndex, scope: Scope, name: str) -> list[ast.expr | Unpacked | None]:
    bindings = scope.bindings.get(name) or ()
    placed = _events(index, scope, name, bindings, augmented=True)
    if placed is None:  # not every binding placed: the index's own, in its order
        return [binding if isinstance(binding, ast.expr) else None for binding in bindings]
    values: list[ast.expr | Unpacked | None] = []
    for event in placed.events:
        binding = event.binding
        if isinstance(binding, Augmented):
            values.append(binding.value)
        elif isinstance(binding, ast.expr):
            values.append(binding)
        elif isinstance(binding, UnpackBinding) and isinstance(event.statement, Assign):
            values.append(_element(binding, event.statement, name))
        else:
            values.append(None)
    return values


def scope_of(index: ModuleIndex, node: AST) -> Scope:
    """The scope whose names `node` reads (an augmented assignment's made nodes: its statement's)."""
    scope = index.scope_of_node.get(node)
    if scope is not None:
        return scope
    parent = _memo(index, "made_parents").get(node)
    return scope_of(index, parent) if parent is not None else index.scope_of(node)


def statement_of(index: ModuleIndex, node: AST) -> ast.stmt | None:
    """The statement `node` is part of."""
    current: AST | None = node
    while current is not None and not isinstance(current, ast.stmt):
        current = _parent(index, current)
    return current


def runs_before(index: ModuleIndex, statement: ast.stmt, node: AST) -> bool:
    """`statement` runs, earlier, on every path to `node`: it sits in a block that encloses `node`."""
    scope = scope_of(index, statement)
    event = Definition(OpaqueBinding(), statement, (statement.end_lineno or statement.lineno, statement.end_col_offset or 0), False)
    return _always_runs_before(index, event, _ancestors(index, node, scope.node))
