"""The text of a ROS frame id when the code fixes it: a literal, a module constant, or a string built
from them (`"/" + "map"`, `"%s/%s" % ("", "gps")`, `"{}/{}".format(...)`, an f-string of constants).

Only exact values: a name counts when one definition certainly reaches it, and anything read at run
time (a parameter, `rospy.get_param`, an attribute) leaves the value unknown (None).
"""

from __future__ import annotations

import ast
from ast import (
    Add,
    Assign,
    Attribute,
    BinOp,
    Call,
    Constant,
    FormattedValue,
    JoinedStr,
    Mod,
    Name,
)
from typing import Final

from geolint.factbase.index import ModuleIndex, module_constant
from geolint.factbase.reaching import (
    resolve,
    runs_before,
    scope_of,
    single_definition,
    statement_of,
)

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


class StampedFrames:
    """Every `<name>.header.frame_id = ...` and `<name>.child_frame_id = ...` of a module, read in one
    pass: what frame a message or a `TransformStamped` held by a local name was stamped with before a
    call (`frame_before`)."""

    def __init__(self, index: ModuleIndex) -> None:
        self.index = index
        # (scope id, owner name, attribute path) -> [(position, value)] in source order
        self.stores: dict[tuple[int, str, tuple[str, ...]], list[tuple[tuple[int, int], ast.expr]]] = {}
        # (attribute, attribute path) -> values, for a message kept on `self` (`self.t.header.frame_id = ...`)
        self.self_stores: dict[tuple[str, tuple[str, ...]], list[ast.expr]] = {}
        for node in index.nodes(Assign):
            assert isinstance(node, Assign)
            if len(node.targets) != 1:
                continue
            owner, path = _owner_and_path(node.targets[0])
            if owner == "self" and len(path) > 1 and path[1:] in STAMP_PATHS:
                self.self_stores.setdefault((path[0], path[1:]), []).append(node.value)
            if owner is None or path not in STAMP_PATHS:
                continue
            key = (id(scope_of(index, node)), owner, path)
            self.stores.setdefault(key, []).append(((node.lineno, node.col_offset), node.value))

    def frame_of_attribute(self, attribute: str, path: tuple[str, ...]) -> ast.expr | None:
        """The value every `self.<attribute>.<path> = value` of the module sets, when there is one store
        (a message built once in `__init__` and sent from a callback)."""
        values = self.self_stores.get((attribute, path), [])
        return values[0] if len(values) == 1 else None

    def frame_before(self, owner: Name, call: ast.AST, path: tuple[str, ...]) -> ast.expr | None:
        """The value of the last `owner.<path> = value` before `call` in its function, set on the object
        `owner` holds at the call (a second `v = Vector3Stamped()` starts a message with no frame) by a
        statement that runs whenever the call does."""
        definition = single_definition(self.index, owner)
        if definition is None:
            return None
        scope = scope_of(self.index, call)
        position = (getattr(call, "lineno", 0), getattr(call, "col_offset", 0))
        found = None
        for point, value in self.stores.get((id(scope), owner.id, path), ()):
            if definition.point <= point < position:
                found = value
        if found is None:
            return None
        assignment = statement_of(self.index, found)
        return found if assignment is not None and runs_before(self.index, assignment, call) else None


PARENT_PATH: Final = ("header", "frame_id")
CHILD_PATH: Final = ("child_frame_id",)
STAMP_PATHS: Final = frozenset({PARENT_PATH, CHILD_PATH})


def _owner_and_path(node: ast.expr) -> tuple[str | None, tuple[str, ...]]:
    """`("t", ("header", "frame_id"))` for `t.header.frame_id`."""
    parts: list[str] = []
    while isinstance(node, Attribute):
        parts.append(node.attr)
        node = node.value
    return (node.id, tuple(reversed(parts))) if isinstance(node, Name) and parts else (None, ())
