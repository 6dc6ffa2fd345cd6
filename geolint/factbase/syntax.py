"""What an expression or statement says by its shape alone, before any fact is asked: the name a call
ends in, a literal's value, a call's positional and keyword arguments, the parts of a subscript, a
transpose, the nodes and statements below a node. Functions of `ast` nodes only; every layer of the
fact base and the rules use them."""

from __future__ import annotations

import ast
from ast import AST, AsyncFunctionDef, Attribute, BinOp, Call, ClassDef, Constant, FunctionDef, Lambda, Mult, Name, Slice, Starred, Subscript, USub, UnaryOp
import re
import sys
from typing import Final, Iterator

from geolint.factbase.index import child_nodes, statement_list_fields


def dotted_name(node: AST) -> str | None:
    """`np.linalg.norm` for that expression; None for anything but a plain dotted name."""
    parts = []
    while isinstance(node, Attribute):
        parts.append(node.attr)
        node = node.value
    if not isinstance(node, Name):
        return None
    parts.append(node.id)
    return ".".join(reversed(parts))


def last_name(node: AST) -> str | None:
    if isinstance(node, Name):
        return node.id
    if isinstance(node, Attribute):
        return node.attr
    return None


def number(node: AST | None) -> int | float | None:
    """The value of a numeric literal (with an optional unary minus), else None."""
    if isinstance(node, UnaryOp) and isinstance(node.op, USub):
        inner = number(node.operand)
        return None if inner is None else -inner
    if isinstance(node, Constant):
        value = node.value
        if type(value) is int or type(value) is float:  # not a bool
            # 1e999 is inf and a 400-digit integer overflows a float: no value to reason about.
            return value if abs(value) <= sys.float_info.max else None
    return None


def is_zero(node: AST) -> bool:
    """A value that is all zeros: `0`, `[0, 0, 0]`, `(0.0, 0.0, 0.0)`, `[0.] * 3`, `np.zeros(3)`, `np.zeros_like(t)`."""
    if isinstance(node, Constant):
        return node.value == 0
    if isinstance(node, (ast.List, ast.Tuple)):
        return bool(node.elts) and all(is_zero(element) for element in node.elts)
    if isinstance(node, BinOp) and isinstance(node.op, Mult):
        return is_zero(node.left) or is_zero(node.right)
    return isinstance(node, Call) and last_name(node.func) in ("zeros", "zeros_like")


def string(node: AST | None) -> str | None:
    return node.value if isinstance(node, Constant) and isinstance(node.value, str) else None


def positional_args(call: Call) -> list[ast.expr]:
    return [arg for arg in call.args if not isinstance(arg, Starred)]


def keyword(call: Call, name: str) -> ast.keyword | None:
    return next((kw for kw in call.keywords if kw.arg == name), None)


def subscript_parts(node: Subscript) -> list[ast.expr]:
    index = node.slice
    return list(index.elts) if isinstance(index, ast.Tuple) else [index]


def is_slice_upto(part: AST, stop: int) -> bool:
    """`:3` or `0:3` (no step)."""
    if not isinstance(part, Slice) or part.step is not None:
        return False
    if part.lower is not None and number(part.lower) != 0:
        return False
    return part.upper is not None and number(part.upper) == stop


def is_full_slice(part: AST) -> bool:
    return isinstance(part, Slice) and part.lower is None and part.upper is None and part.step is None


def is_index(part: AST, *values: int) -> bool:
    return not isinstance(part, Slice) and number(part) in values


def is_transpose(node: AST) -> bool:
    """`x.T`, `x.mT`, `x.transpose(-1, -2)` / `x.transpose(1, 2)` / `x.swapaxes(-1, -2)`."""
    if isinstance(node, Attribute) and node.attr in ("T", "mT"):
        return True
    if isinstance(node, Call) and isinstance(node.func, Attribute) and node.func.attr in ("transpose", "swapaxes", "permute"):
        values = [number(arg) for arg in node.args]
        return node.func.attr != "permute" and (values == [] and node.func.attr == "transpose" or len(values) == 2 and None not in values)
    return False


def transposed_value(node: AST) -> ast.expr | None:
    """For `x.T` (and the torch spellings), x."""
    if is_transpose(node):
        return node.value if isinstance(node, Attribute) else node.func.value  # type: ignore[attr-defined,no-any-return]
    return None


def is_scalar_annotation(annotation: ast.expr) -> bool:
    text = ast.unparse(annotation)
    words = set(re.split(r"[\s|\[\],]+", text)) - {""}
    scalar = {"int", "float", "str", "bool", "SupportsIndex", "None", "Optional", "typing.Optional", "Literal"}
    return bool(words) and words <= scalar | {word for word in words if word.startswith(("'", '"'))}


def flat_literal(node: ast.expr) -> list[ast.expr]:
    """The elements of a literal tuple/list, nested ones flattened in order (`((0, 0), (0, 1))`)."""
    if not isinstance(node, (ast.Tuple, ast.List)):
        return [node]
    return [element for item in node.elts for element in flat_literal(item)]


def einsum_operands(subscripts: ast.expr, first: ast.expr, second: ast.expr) -> tuple[ast.expr, ast.expr] | None:
    """(matrix, operand) for an `einsum` that is the matrix acting on the operand, as `matrix @ operand`
    does: the matrix's last index is summed against one index of the operand, which the output
    replaces by the matrix's row index (`"ij,jk->ik"`, `"bij,bj->bi"`, `"ik,...k->...i"`, and
    `"bij,bkj->bki"` on rows). Any other contraction (a transpose acting, a trace) is None."""
    text = string(subscripts)
    if text is None or text.count("->") != 1:
        return None
    inputs, output = text.replace(" ", "").split("->")
    parts = inputs.split(",")
    if len(parts) != 2:
        return None
    for matrix, operand, (matrix_node, operand_node) in ((parts[0], parts[1], (first, second)), (parts[1], parts[0], (second, first))):
        letters = matrix.replace("...", "")
        if len(letters) < 2 or len(set(letters)) != len(letters):
            continue
        row, summed = letters[-2], letters[-1]
        batch = matrix[: -2]
        if operand.count(summed) != 1 or row in operand or operand.replace(summed, row) != output:
            continue
        if all(letter in output for letter in batch.replace("...", "")):
            return matrix_node, operand_node
    return None


def walk_within(node: AST, stop_at_functions: bool = True) -> Iterator[AST]:
    """The nodes below `node` (iteratively), not entering nested functions when asked (leaves such as
    `Load` and operators left out)."""
    stack = child_nodes(node)
    while stack:
        current = stack.pop()
        yield current
        if stop_at_functions and type(current) in _SCOPE_NODES:
            continue
        stack.extend(child_nodes(current))


_SCOPE_NODES: Final = frozenset({FunctionDef, AsyncFunctionDef, Lambda, ClassDef})


_DEFINITIONS: Final = (FunctionDef, AsyncFunctionDef, ClassDef)


def statements_under(node: AST, into_definitions: bool = True) -> list[AST]:
    """The statements below `node` (and the `except` handlers and `match` cases that hold some),
    found through statement lists only, never walking an expression; with `into_definitions` False,
    not those of the functions and classes defined inside."""
    found: list[AST] = []
    stack: list[AST] = list(getattr(node, "body", []))
    while stack:
        statement = stack.pop()
        found.append(statement)
        if not into_definitions and isinstance(statement, _DEFINITIONS):
            continue
        for field in statement_list_fields(statement):
            stack.extend(getattr(statement, field))
    return found


def components_of_one_array(elements: list[ast.expr]) -> ast.expr | None:
    """For `[x[0], x[1], x[2]]` or `[x.x, x.y, x.z]` (a ROS Vector3 or Point, a PyKDL Vector), the
    expression x; else None."""
    bases = []
    for position, element in enumerate(elements):
        if isinstance(element, Subscript) and is_index(element.slice, position):
            bases.append(element.value)
        elif isinstance(element, Attribute) and element.attr == "xyz"[position]:
            bases.append(element.value)
        else:
            return None
    codes = {ast.dump(base) for base in bases}
    return bases[0] if len(codes) == 1 else None
