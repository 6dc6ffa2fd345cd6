"""Where a function moves its points: the first product or `transform_points` call on a point, and
what it returns untouched (GEO104's normals left behind, which GEO107 leaves to it)."""

from __future__ import annotations

import ast
from ast import AST, Attribute, Call, Name, Return
from typing import TYPE_CHECKING, Mapping, Sequence

from geolint.algebra import Kind
from geolint.factbase.index import ParamBinding
from geolint.factbase.fact_types import GEOMETRIC
from geolint.factbase.syntax import last_name, transposed_value, walk_within

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase


def first_point_transform(
    facts: FactBase, root: AST, body_only: bool = False, parameters: Mapping[str, Sequence[object]] | None = None
) -> tuple[AST, str] | None:
    """The first (in source order) product or `transform_points` call on a point inside `root`, with
    the point's text. `parameters` (a scope's bindings): only a point that is a parameter of it counts."""
    nodes = [root] if not body_only else []
    nodes += sorted(walk_within(root), key=lambda n: (getattr(n, "lineno", 0), getattr(n, "col_offset", 0)))
    for node in nodes:
        product = facts.matmul(node)
        if product is not None:
            for value, matrix in ((product.left, product.right), (product.right, product.left)):
                points = _point(facts, value, parameters)
                if points is not None and facts.kind_of(matrix) not in GEOMETRIC:
                    return node, points
        if isinstance(node, Call) and last_name(node.func) == "transform_points" and node.args:
            points = _point(facts, node.args[0], parameters)
            if points is not None:
                return node, points
    return None


def _point(facts: FactBase, node: AST, parameters: Mapping[str, Sequence[object]] | None) -> str | None:
    """The text of `node` when it is a point (through `.T` and `np.asarray(...)`)."""
    while isinstance(node, (Attribute, Call)):
        inner = transposed_value(node)
        if inner is not None:
            node = inner
        elif isinstance(node, Call) and last_name(node.func) in ("asarray", "array") and node.args:
            node = node.args[0]
        else:
            break
    if facts.kind_of(node) != Kind.POINT:
        return None
    if parameters is not None:
        if not isinstance(node, Name):
            return None
        bindings = parameters.get(node.id, [])
        if not bindings or not all(isinstance(binding, ParamBinding) for binding in bindings):
            return None
    return facts.code_of(node)


def returned_names(returns: list[ast.expr]) -> set[str]:
    """The names a function returns, alone or as elements of a returned tuple or list."""
    names: set[str] = set()
    for value in returns:
        elements = value.elts if isinstance(value, (ast.Tuple, ast.List)) else [value]
        for element in elements:
            if isinstance(element, Name):
                names.add(element.id)
    return names


def read_outside_returns(function: AST, name: str) -> bool:
    """Whether `name` is read anywhere in the function's body other than directly in a `return`."""
    stack = list(getattr(function, "body", []))
    while stack:
        node = stack.pop()
        if isinstance(node, Return):
            continue
        if isinstance(node, Name) and node.id == name:
            return True
        stack.extend(ast.iter_child_nodes(node))
    return False
