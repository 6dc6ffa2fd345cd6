"""Which component of which quaternion an expression is: `q[3]`, `q[..., 3]`, `float(q[3])` is (q, 3);
`[q[1], q[2], q[3], q[0]]` is q's components 1, 2, 3, 0; `[a, b, c, d]` spells four components."""

from __future__ import annotations

import ast
from ast import AST, Attribute, Call, Constant, Name, Slice, Starred, Subscript
from typing import TYPE_CHECKING, Final

from geolint.factbase.syntax import is_full_slice, last_name, number, string, subscript_parts

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

COMPONENTS: Final = "wxyz"  # a quaternion's component letters, scalar first


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


def component_name(value: ast.expr) -> tuple[str, str] | None:
    """The quaternion component a value names, with what it belongs to: `q.w` and `q["w"]` (w, q),
    `qw`, `q_w`, `quat_w`, `ori_w` (w, the prefix), a bare `w` (w, "")."""
    if isinstance(value, Attribute) and value.attr in COMPONENTS:
        return value.attr, ast.dump(value.value)
    if isinstance(value, Subscript):
        key = string(value.slice)
        if key is not None and key in COMPONENTS and len(key) == 1:
            return key, ast.dump(value.value)
    if not isinstance(value, Name):
        return None
    lowered = value.id.lower()
    if lowered in COMPONENTS and len(lowered) == 1:
        return lowered, ""
    for prefix in ("q", "q_", "quat_", "quat", "rot_", "orientation_", "ori_"):
        rest = lowered[len(prefix) :]
        if lowered.startswith(prefix) and len(rest) == 1 and rest in COMPONENTS:
            return rest, prefix
    return None


def named_order(values: list[ast.expr]) -> str | None:
    """'wxyz' for `[q.w, q.x, q.y, q.z]` (components of one object, or names like qw/q_w/w), each
    component once; any of the 24 orders."""
    components = [component_name(value) for value in values]
    if any(component is None for component in components):
        return None
    letters = "".join(component[0] for component in components)  # type: ignore[index]
    owners = {component[1] for component in components}  # type: ignore[index]
    if sorted(letters) != sorted(COMPONENTS) or len(owners) != 1:
        return None
    return letters


def order_dependent_part(node: Subscript) -> str | None:
    """`x[:, 1:]` / `x[..., :3]`: 'vector' (the vector part of one order); `x[..., 0]` / `x[:, 3]`: 'scalar'."""
    parts = subscript_parts(node)
    if len(parts) < 2 or not all(isinstance(part, Slice) and part.lower is part.upper is part.step is None or (isinstance(part, Constant) and part.value is Ellipsis) for part in parts[:-1]):
        return None  # a lone `q[0]` may be a row of a stack: only indexing after leading `:` / `...` is judged
    last = parts[-1]
    if isinstance(last, Slice) and last.step is None:
        bounds = (number(last.lower) if last.lower is not None else 0, number(last.upper) if last.upper is not None else 4)
        if bounds in ((1, 4), (0, 3), (0, -1)):
            return "vector"
        if bounds in ((0, 1), (3, 4), (-1, 4)):
            return "scalar"
        return None
    value = number(last)
    return "scalar" if value in (0, 3, -1) and not isinstance(value, bool) else None


def literal_components(facts: FactBase, node: ast.expr) -> list[float] | None:
    """`[0, 0, 0, 1]`, `(0., 0., 0., 1.)`, `np.array([...])`, `torch.tensor([...])`: four literal numbers."""
    elements = spelled_components(facts, node)
    if elements is None:
        return None
    values = [number(element) for element in elements]
    return None if any(value is None or isinstance(value, bool) for value in values) else values  # type: ignore[return-value]
