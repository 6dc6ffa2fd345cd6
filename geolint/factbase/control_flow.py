"""Whether a statement or expression runs whenever its function does: no branch around it, and no
early `return` / `raise` before it. A call that reads a parameter counts as the function reading it
only then (`if degrees: return np.radians(a)` says nothing about how the function reads `a`)."""

from __future__ import annotations

import ast
from ast import (
    AST,
    AnnAssign,
    Assign,
    AsyncFor,
    AsyncFunctionDef,
    AsyncWith,
    AugAssign,
    BoolOp,
    ClassDef,
    Expr,
    For,
    FunctionDef,
    If,
    IfExp,
    Lambda,
    Match,
    Module,
    Raise,
    Return,
    Try,
    While,
    With,
)
from typing import TYPE_CHECKING, Final

from geolint.factbase.syntax import walk_within

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

_Block = FunctionDef | AsyncFunctionDef | With | AsyncWith  # a body that may be left early

# a loop's body may run no time at all, like a branch's
_BRANCHES: Final = (
    If, IfExp, Try, getattr(ast, "TryStar", Try), While, For, AsyncFor, BoolOp,
    ast.comprehension, Match, Lambda,
)  # fmt: skip


def runs_unconditionally(facts: FactBase, node: AST) -> bool:
    """No branch between `node` and its function, and no statement before it, in the function's body
    or in the body of a `with` around it, that may leave early (`if degrees: return ...`): it runs
    whenever the function does."""
    current = facts.parent(node)
    statement = node
    blocks: list[tuple[_Block, AST]] = []  # each block around `node` with its statement that holds `node`
    while current is not None and not isinstance(current, (FunctionDef, AsyncFunctionDef, Module)):
        if isinstance(current, _BRANCHES):
            return False
        if isinstance(current, (With, AsyncWith)) and statement in current.body:
            blocks.append((current, statement))  # (not in its items, which run before any exit of its body)
        statement = current
        current = facts.parent(current)
    if not isinstance(current, (FunctionDef, AsyncFunctionDef)):
        return True
    blocks.append((current, statement))
    return all(getattr(held, "lineno", 0) <= _first_early_exit(facts, block) for block, held in blocks)


_DEFINITIONS: Final = (FunctionDef, AsyncFunctionDef, ClassDef)


def _first_early_exit(facts: FactBase, block: _Block) -> int:
    """The last line of the first statement of a block's body (a function's, a `with`'s) that holds a
    `return` or `raise` under a branch or a nested block (statements after it may not run); past the
    end when there is none."""
    return facts.memoised("early-exit", block, lambda: _early_exit_line(block.body))


def _early_exit_line(body: list[ast.stmt]) -> int:
    for statement in body:
        if isinstance(statement, (Return, Raise, Expr, Assign, AugAssign, AnnAssign, *_DEFINITIONS)):
            continue  # straight-line statements (a `return` of the block itself ends it for every path alike)
        for inner in walk_within(statement):
            if isinstance(inner, (Return, Raise)):
                return statement.end_lineno or statement.lineno
    return 1 << 30
