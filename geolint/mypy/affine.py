"""Affine combinations of point arrays: ``(a + b) / 2``, ``0.5 * (a + b)``, ``0.25 * a + 0.75 * b``.

``a + b`` alone has no geometric meaning (``geo-kind``), but divided by 2 it is the midpoint. An operator hook
sees one operation at a time and cannot look at the expression around it, so the typing trick has two halves:

1. right after parsing (the same pre-pass that protects string frames), every arithmetic expression whose terms
   carry literal weights is read as ``sum(w_i * x_i)`` and remembered, with each of its sub-expressions, by node
   identity (the checker later sees the very same node objects);
2. while checking, an operation inside such an expression asks `geolint.algebra.affine_combination` about its
   own terms (already checked, their types known): point weights summing to 1 give a point, to 0 a vector. An
   inner step such as ``a + b`` is given a provisional point type and no error; the outermost expression reports
   weights that sum to anything else.

Only annotated arrays: the runtime's ``Point`` refuses ``+`` and ``*`` outright, so there the error stays.
"""

from __future__ import annotations

from dataclasses import dataclass

from mypy.nodes import Context, Expression, FloatExpr, IntExpr, OpExpr, UnaryExpr

Term = tuple[Expression, float]


@dataclass(frozen=True)
class Combination:
    node: Expression  # kept so its identity stays unique while it is registered
    terms: tuple[Term, ...]
    outermost: bool


_COMBINATIONS: dict[int, Combination] = {}
_BY_FILE: dict[str, list[int]] = {}


def forget(path: str) -> None:
    """Drop what was registered for `path` (a module parsed again, e.g. by the mypy daemon)."""
    for key in _BY_FILE.pop(path, []):
        _COMBINATIONS.pop(key, None)


def register(node: Expression, path: str) -> None:
    """Remember `node` and its sub-expressions if `node` is an outermost weighted combination (see module doc)."""
    if id(node) in _COMBINATIONS or not isinstance(node, (OpExpr, UnaryExpr)):
        return
    terms = _linear_terms(node)
    if len(terms) < 2:
        return  # one scaled term (pts * 1e-3, a unit conversion) is not a combination
    if all(abs(weight) == 1.0 for _, weight in terms):
        return  # a plain sum or difference: the ordinary rules judge it (a + b is an error, a - b a vector)
    keys = _BY_FILE.setdefault(path, [])
    for inner in _inner_steps(node):
        _COMBINATIONS[id(inner)] = Combination(inner, tuple(_linear_terms(inner)), outermost=inner is node)
        keys.append(id(inner))


def at(context: Context) -> Combination | None:
    """The combination `context` (an operator expression being checked) belongs to, if any."""
    found = _COMBINATIONS.get(id(context))
    return found if found is not None and found.node is context else None


def _number(expr: Expression) -> float | None:
    if isinstance(expr, (IntExpr, FloatExpr)):
        return float(expr.value)
    if isinstance(expr, UnaryExpr) and expr.op == "-" and isinstance(expr.expr, (IntExpr, FloatExpr)):
        return -float(expr.expr.value)
    return None


def _linear_terms(expr: Expression) -> list[Term]:
    """``expr`` as weighted terms: ``(a + b) / 2`` is ``[(a, 0.5), (b, 0.5)]``; anything else is one term."""
    if isinstance(expr, OpExpr):
        if expr.op in ("+", "-"):
            sign = 1.0 if expr.op == "+" else -1.0
            return _linear_terms(expr.left) + [(term, sign * weight) for term, weight in _linear_terms(expr.right)]
        if expr.op == "*":
            for factor, other in ((expr.left, expr.right), (expr.right, expr.left)):
                number = _number(factor)
                if number is not None and _number(other) is None:
                    return [(term, number * weight) for term, weight in _linear_terms(other)]
        if expr.op == "/":
            divisor = _number(expr.right)
            if divisor and _number(expr.left) is None:
                return [(term, weight / divisor) for term, weight in _linear_terms(expr.left)]
    if isinstance(expr, UnaryExpr) and expr.op == "-" and _number(expr) is None:
        return [(term, -weight) for term, weight in _linear_terms(expr.expr)]
    return [(expr, 1.0)]


def _inner_steps(expr: Expression) -> list[Expression]:
    """`expr` and every arithmetic step `_linear_terms` looked through to find its terms."""
    steps: list[Expression] = [expr]
    if isinstance(expr, OpExpr) and expr.op in ("+", "-", "*", "/"):
        terms = {id(term) for term, _ in _linear_terms(expr)}
        for child in (expr.left, expr.right):
            if id(child) not in terms and _number(child) is None:
                steps.extend(_inner_steps(child))
    elif isinstance(expr, UnaryExpr) and expr.op == "-":
        if id(expr.expr) not in {id(term) for term, _ in _linear_terms(expr)}:
            steps.extend(_inner_steps(expr.expr))
    return steps
