"""Which component of which quaternion an expression is: `q[3]`, `q[..., 3]`, `float(q[3])` is (q, 3);
`[q[1], q[2], q[3], q[0]]` is q's components 1, 2, 3, 0; `[a, b, c, d]` spells four components."""

from __future__ import annotations

import ast
from ast import AST, Call, Constant, Name, Starred, Subscript
from typing import TYPE_CHECKING

from geolint.factbase.syntax import is_full_slice, last_name, number, subscript_parts

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase


def component_index(node: ast.expr) -> tuple[ast.expr, int] | None:
    """`q[3]`, `q[:, 3]`, `q[..., 3]`, `float(q[3])`: (q, 3) for an integer last index after full slices only."""
    node = unwrapped_scalar(node)
    if not isinstance(node, Subscript):
        return None
    parts = subscript_parts(node)
    if not parts:
        return None  # `x[()]`
    *leading, last = parts
    if not all(is_full_slice(part) or is_ellipsis(part) for part in leading):
        return None
    value = number(last)
    if not isinstance(value, int) or isinstance(value, bool) or not -4 <= value <= 3:
        return None
    return node.value, value % 4


def spelled_components(facts: FactBase, node: ast.expr) -> list[ast.expr] | None:
    """The four elements of `[a, b, c, d]`, `(a, b, c, d)` or `np.array([a, b, c, d])`."""
    if isinstance(node, Call) and last_name(node.func) in ("array", "asarray", "tensor", "as_tensor") and len(node.args) == 1:
        if facts.is_array_call(node.func, "array", "asarray", "tensor", "as_tensor"):
            node = node.args[0]
    if isinstance(node, (ast.List, ast.Tuple)) and len(node.elts) == 4 and not any(isinstance(e, Starred) for e in node.elts):
        return list(node.elts)
    return None


def unwrapped_scalar(node: ast.expr) -> ast.expr:
    """`float(q[3])` -> `q[3]`: the builtin conversion keeps the component's value."""
    if (
        isinstance(node, Call) and isinstance(node.func, Name) and node.func.id == "float"
        and len(node.args) == 1 and not node.keywords
    ):
        return node.args[0]
    return node


def same_base(facts: FactBase, elements: list[ast.expr]) -> tuple[ast.expr, list[int]] | None:
    """`[q[1], q[2], q[3], q[0]]` -> (q, [1, 2, 3, 0]): integer components of one base expression."""
    found = [component_index(element) for element in elements]
    if any(item is None for item in found):
        return None
    bases = {ast.dump(item[0]) for item in found}  # type: ignore[index]
    if len(bases) != 1:
        return None
    return found[0][0], [item[1] for item in found]  # type: ignore[index]


def is_ellipsis(node: AST) -> bool:
    return isinstance(node, Constant) and node.value is Ellipsis
