"""The text of a ROS frame id when the code fixes it: a literal, a module constant, or a string built
from them (`"/" + "map"`, `"%s/%s" % ("", "gps")`, `"{}/{}".format(...)`, an f-string of constants).

Only exact values: a name counts when one definition certainly reaches it, and anything read at run
time (a parameter, `rospy.get_param`, an attribute) leaves the value unknown (None).
"""

from __future__ import annotations

from typing import Final

import ast
from ast import (
    Add,
    Attribute,
    BinOp,
    Call,
    Constant,
    FormattedValue,
    JoinedStr,
    Mod,
    Name,
)

from geolint.factbase.index import ModuleIndex, module_constant
from geolint.factbase.reaching import resolve, scope_of

_MAX_DEPTH: Final = 6
_MAX_LENGTH: Final = 256  # frame ids are short; nothing longer is built here


def frame_string(node: ast.expr, index: ModuleIndex, depth: int = _MAX_DEPTH) -> str | None:
    """The string `node` certainly evaluates to, or None."""
    if depth <= 0:
        return None
    if isinstance(node, Constant):
        return node.value if isinstance(node.value, str) else None
    if isinstance(node, Name):
        return _string_of_name(node, index, depth)
    if isinstance(node, BinOp):
        return _string_of_operation(node, index, depth)
    if isinstance(node, Call) and isinstance(node.func, Attribute) and node.func.attr == "format" and not node.keywords:
        template = frame_string(node.func.value, index, depth - 1)
        values = [frame_string(arg, index, depth - 1) for arg in node.args]
        if template is None or None in values:
            return None
        return _formatted(lambda: template.format(*values))
    if isinstance(node, JoinedStr):
        return _string_of_f_string(node, index, depth)
    return None


def _string_of_name(node: Name, index: ModuleIndex, depth: int) -> str | None:
    """The string of the one definition that reaches `node` (or of the module constant it reads)."""
    resolved = resolve(index, node)
    value: ast.expr | None = resolved if isinstance(resolved, ast.expr) else None
    if isinstance(value, Name):  # unknown here: a global the reading scope does not rebind?
        value = None if value.id in scope_of(index, value).bindings else module_constant(index, value.id)
    return frame_string(value, index, depth - 1) if value is not None and not isinstance(value, Name) else None


def _string_of_operation(node: BinOp, index: ModuleIndex, depth: int) -> str | None:
    """`"/" + "map"`, `"%s/%s" % ("", "gps")`."""
    if isinstance(node.op, Add):
        left, right = frame_string(node.left, index, depth - 1), frame_string(node.right, index, depth - 1)
        return _short(left + right) if left is not None and right is not None else None
    if isinstance(node.op, Mod):
        template = frame_string(node.left, index, depth - 1)
        parts = node.right.elts if isinstance(node.right, ast.Tuple) else [node.right]
        values = [frame_string(part, index, depth - 1) for part in parts]
        if template is None or None in values:
            return None
        return _formatted(lambda: template % tuple(values))
    return None


def _string_of_f_string(node: JoinedStr, index: ModuleIndex, depth: int) -> str | None:
    """`f"{prefix}/map"` of constants, each formatted plainly (`!s` at most, no format spec)."""
    pieces = []
    for piece in node.values:
        if isinstance(piece, FormattedValue):
            if piece.conversion not in (-1, ord("s")) or piece.format_spec is not None:
                return None
            piece = piece.value  # type: ignore[assignment]
        text = frame_string(piece, index, depth - 1)
        if text is None:
            return None
        pieces.append(text)
    return _short("".join(pieces))


def _formatted(render: object) -> str | None:
    try:
        text = render()  # type: ignore[operator]
    except (TypeError, ValueError, KeyError, IndexError):
        return None
    return _short(text) if isinstance(text, str) else None


def _short(text: str) -> str | None:
    return text if len(text) <= _MAX_LENGTH else None
