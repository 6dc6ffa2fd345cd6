"""Which bindings of a name can reach one use of it: flow-sensitive reads within a body.

`x = points; ...; x = normals; T @ hom(x)` uses the normals: the index records every binding of
`x` in the function, and without order the two kinds cancel out (the fact base then says
nothing). Here a use sees the last binding that always runs before it (a statement earlier in the
same block or an enclosing one, or a parameter), plus the bindings after that one that may run
before it (in branches), plus, inside a loop, the bindings later in that loop that the next
iteration carries back, unless the always-running one sits in the same loop.

It is a reaching-definitions analysis on statement blocks, deliberately conservative: `try`
bodies, branches and loop bodies never always-run for code after them, and whenever a binding
cannot be placed (comprehension variables, `:=`, `global`), every binding counts, as before.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass
from typing import Callable, Iterator, Sequence

from geolint.factbase.index import Binding, LoopBinding, ModuleIndex, OpaqueBinding, ParamBinding, Scope, UnpackBinding

_MAX_BINDINGS = 64  # past this many rebindings of one name, order is not worth its cost: all count
_LOOPS = (ast.For, ast.AsyncFor, ast.While)
_BLOCK_FIELDS = ("body", "orelse", "finalbody")
_NESTED_SCOPES = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)


@dataclass(frozen=True)
class _Event:
    """One binding of the name: `statement` binds it, effective from `point` on."""

    binding: Binding
    statement: ast.stmt
    point: tuple[int, int]
    only_inside: bool  # a loop target: bound in the loop's body only, maybe never (zero iterations)


def reaching_bindings(index: ModuleIndex, scope: Scope, use: ast.Name, bindings: Sequence[Binding]) -> list[Binding]:
    """The bindings of `use.id` (all of them: `bindings`) that can reach `use`."""
    if len(bindings) < 2 or len(bindings) > _MAX_BINDINGS or not isinstance(use.ctx, ast.Load):
        return list(bindings)
    uses = _memo(index, "_reaching_uses")
    known = uses.get(id(use))
    if known is None:
        known = uses[id(use)] = _reaching(index, scope, use, bindings)
    return known


def _reaching(index: ModuleIndex, scope: Scope, use: ast.Name, bindings: Sequence[Binding]) -> list[Binding]:
    events = _events(index, scope, use.id, bindings)
    if events is None:
        return list(bindings)
    position = (use.lineno, use.col_offset)
    before = [event for event in events if event.point <= position]
    after = [event for event in events if event.point > position]
    ancestors = _ancestors(index, use, scope.node)
    start = 0
    for number in range(len(before) - 1, -1, -1):
        if _always_runs_before(index, before[number], ancestors):
            start = number
            break
    else:
        if not before:
            return list(bindings)  # used before any binding here (a loop's later one, or a closure)
    reaching = before[start:]
    dominating = before[start] if reaching and _always_runs_before(index, before[start], ancestors) else None
    for loop in (node for node in ancestors if isinstance(node, _LOOPS)):
        if dominating is not None and _inside(index, dominating.statement, loop):
            break  # re-bound on every iteration before the use: nothing is carried back past it
        reaching.extend(event for event in after if _inside(index, event.statement, loop))
    return [event.binding for event in reaching]


def _events(index: ModuleIndex, scope: Scope, name: str, bindings: Sequence[Binding]) -> list[_Event] | None:
    """Every binding of `name` in the scope's body, placed; None when one cannot be placed."""
    memo = _memo(index, "_reaching_events")
    key = (id(scope.node), name)
    if key in memo:
        return memo[key]
    events: list[_Event] = []
    params = [binding for binding in bindings if isinstance(binding, ParamBinding)]
    body = getattr(scope.node, "body", None)
    if not isinstance(body, list):
        memo[key] = None
        return None
    for binding in params:
        events.append(_Event(binding, body[0], (0, 0), False))
    for statement in _statements(body):
        events.extend(_bound_by(statement, name))
    placed = _match(events, bindings)
    memo[key] = placed
    return placed


def _match(events: list[_Event], bindings: Sequence[Binding]) -> list[_Event] | None:
    """The events in source order, each holding the index's own binding object; None unless every
    binding of the index is found (an unplaced binding makes order unsafe)."""
    remaining = list(bindings)
    matched: list[_Event] = []
    for event in events:
        for number, binding in enumerate(remaining):
            if _same(event.binding, binding):
                matched.append(_Event(binding, event.statement, event.point, event.only_inside))
                del remaining[number]
                break
        else:
            return None
    if remaining:
        return None
    matched.sort(key=lambda event: event.point)
    return matched


def _same(found: Binding, recorded: Binding) -> bool:
    if isinstance(found, OpaqueBinding) or isinstance(recorded, OpaqueBinding):
        return isinstance(found, OpaqueBinding) and isinstance(recorded, OpaqueBinding)
    if isinstance(found, LoopBinding) and isinstance(recorded, LoopBinding):
        return found.iterable is recorded.iterable and found.position == recorded.position
    if isinstance(found, UnpackBinding) and isinstance(recorded, UnpackBinding):
        return found.value is recorded.value and found.position == recorded.position
    return found is recorded


def _statements(body: list[ast.stmt]) -> Iterator[ast.stmt]:
    """Every statement of a body, nested blocks included, not those of nested functions or classes."""
    stack = list(reversed(body))
    while stack:
        statement = stack.pop()
        yield statement
        if isinstance(statement, _NESTED_SCOPES):
            continue
        nested: list[ast.stmt] = []
        for field in _BLOCK_FIELDS:
            nested.extend(getattr(statement, field, None) or [])
        for handler in getattr(statement, "handlers", None) or []:
            nested.extend(handler.body)
        for case in getattr(statement, "cases", None) or []:
            nested.extend(case.body)
        stack.extend(reversed(nested))


def _bound_by(statement: ast.stmt, name: str) -> Iterator[_Event]:
    """The bindings of `name` that `statement` itself makes (not its nested blocks')."""
    end = (statement.end_lineno or statement.lineno, statement.end_col_offset or 0)
    if isinstance(statement, ast.Assign):
        for target in statement.targets:
            yield from _target_events(target, statement.value, name, statement, end)
    elif isinstance(statement, ast.AnnAssign):
        if isinstance(statement.target, ast.Name) and statement.target.id == name:
            value = statement.value if statement.value is not None else OpaqueBinding()
            yield _Event(value, statement, end, False)
    elif isinstance(statement, (ast.For, ast.AsyncFor)):
        iterable = statement.iter
        point = (iterable.end_lineno or iterable.lineno, iterable.end_col_offset or 0)
        yield from _loop_events(statement.target, iterable, name, statement, point)
    elif isinstance(statement, (ast.With, ast.AsyncWith)):
        for item in statement.items:
            if item.optional_vars is not None and _binds(item.optional_vars, name):
                yield _Event(OpaqueBinding(), statement, (item.context_expr.lineno, item.context_expr.col_offset), False)
    elif isinstance(statement, _NESTED_SCOPES):
        if statement.name == name:
            yield _Event(OpaqueBinding(), statement, end, False)
    elif isinstance(statement, (ast.Import, ast.ImportFrom)):
        for alias in statement.names:
            local = alias.asname or alias.name.split(".")[0]
            if local == name and alias.name != "*":
                yield _Event(OpaqueBinding(), statement, end, False)
    elif isinstance(statement, ast.Try) or type(statement).__name__ == "TryStar":
        for handler in statement.handlers:  # type: ignore[attr-defined]
            if handler.name == name:
                yield _Event(OpaqueBinding(), handler.body[0], (handler.lineno, handler.col_offset), True)


def _target_events(target: ast.expr, value: ast.expr, name: str, statement: ast.stmt, end: tuple[int, int]) -> Iterator[_Event]:
    """`name = value`, `a, name = value`: as the index binds an assignment's targets."""
    return _unpacked(target, name, value, lambda position: UnpackBinding(value, position), statement, end, False)


def _loop_events(target: ast.expr, iterable: ast.expr, name: str, statement: ast.stmt, point: tuple[int, int]) -> Iterator[_Event]:
    """`for name in iterable`, `for i, name in ...`: as the index binds a loop's targets."""
    whole = LoopBinding(iterable)
    return _unpacked(target, name, whole, lambda position: LoopBinding(iterable, position), statement, point, True)


def _unpacked(
    target: ast.expr,
    name: str,
    whole: Binding,
    element: Callable[[int], Binding],
    statement: ast.stmt,
    point: tuple[int, int],
    only_inside: bool,
) -> Iterator[_Event]:
    if isinstance(target, ast.Name):
        if target.id == name:
            yield _Event(whole, statement, point, only_inside)
    elif isinstance(target, (ast.Tuple, ast.List)):
        for position, item in enumerate(target.elts):
            if isinstance(item, ast.Name):
                if item.id == name:
                    yield _Event(element(position), statement, point, only_inside)
            elif _binds(item, name):
                yield _Event(OpaqueBinding(), statement, point, only_inside)
    elif isinstance(target, ast.Starred) and _binds(target.value, name):
        yield _Event(OpaqueBinding(), statement, point, only_inside)


def _binds(target: ast.expr, name: str) -> bool:
    return any(isinstance(node, ast.Name) and node.id == name for node in ast.walk(target))


def _ancestors(index: ModuleIndex, node: ast.AST, stop: ast.AST) -> list[ast.AST]:
    """The nodes enclosing `node`, innermost first, up to (not including) the scope node `stop`."""
    found = []
    current = index.parents.get(node)
    while current is not None and current is not stop:
        found.append(current)
        current = index.parents.get(current)
    return found


def _always_runs_before(index: ModuleIndex, event: _Event, ancestors: list[ast.AST]) -> bool:
    """Whether `event`'s binding runs on every path to the use whose enclosing nodes are `ancestors`."""
    if event.point == (0, 0):
        return True  # a parameter
    statement = event.statement
    if event.only_inside:
        # a loop target reaches its own body for sure (a `for` with zero iterations never runs it)
        return any(node is statement for node in ancestors) and _in_block(statement, "body", ancestors)
    parent = index.parents.get(statement)
    for node in ancestors:
        if index.parents.get(node) is parent and node is not statement:
            return _same_block(parent, statement, node)
        if node is statement:
            # the use sits inside the binding statement's own blocks (`with ... as x:` body)
            return isinstance(statement, (ast.With, ast.AsyncWith))
    return False


def _same_block(parent: ast.AST | None, first: ast.stmt, second: ast.AST) -> bool:
    """Whether `first` and `second` are statements of one block of `parent` (then `first`, being
    earlier, always runs before `second`)."""
    if parent is None:
        return False
    for field in _BLOCK_FIELDS:
        block = getattr(parent, field, None)
        if isinstance(block, list) and any(item is first for item in block):
            return any(item is second for item in block)
    return False


def _in_block(statement: ast.stmt, field: str, ancestors: list[ast.AST]) -> bool:
    block = getattr(statement, field, None) or []
    return any(item is node for node in ancestors for item in block)


def _inside(index: ModuleIndex, node: ast.AST, container: ast.AST) -> bool:
    current: ast.AST | None = node
    while current is not None:
        if current is container:
            return True
        current = index.parents.get(current)
    return False


def _memo(index: ModuleIndex, name: str) -> dict:  # type: ignore[type-arg]
    """A table kept on the module's index (it lives exactly as long as the syntax tree it is about)."""
    memo = getattr(index, name, None)
    if memo is None:
        memo = {}
        setattr(index, name, memo)
    return memo
