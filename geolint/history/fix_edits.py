"""What a one-line edit did, when it is shaped like the fix of a geometric bug.

An edit is the text of a statement before and after a commit. Both are parsed, and the smallest
part where the two trees differ is compared: the edit is a geometric fix when that part changed in
one of the ways such fixes do, and only then (`fix_shape`):

- `reordered`: the same three or more elements in another order (quaternion components
  `[q.x, q.y, q.z, q.w]` -> `[q.w, q.x, q.y, q.z]`, an index list, a call's arguments);
- `swapped operands`: `a @ b` -> `b @ a` (also `*`, the product of quaternions and of transforms);
- `transpose for inverse`: `.T` / `transpose(...)` -> `inv(...)` / `.inverse()`, or the reverse;
- `angle unit`: a `radians`/`deg2rad`/`degrees`/`rad2deg` conversion added or removed, or
  `degrees=True` added or removed;
- `negated`: a term negated, or its negation removed;
- `extrinsics direction`: `c2w` <-> `w2c` and the like, in a name;
- `difference for relative rotation`: `q1 - q2` -> `q1 * q2.conjugate()` (or an inverse): two
  rotations compared by their relative rotation, not componentwise.

Renames, new arguments and anything else are not fixes of these classes: no shape.
"""

from __future__ import annotations

import ast
import re
from typing import Final

_CONVERSIONS: Final = frozenset({"radians", "deg2rad", "degrees", "rad2deg", "deg_to_rad", "rad_to_deg", "to_radians", "to_degrees"})
_INVERSES: Final = frozenset({"inv", "inverse", "pinv", "invert", "inverse_matrix", "invertTransform"})
_TRANSPOSES: Final = frozenset({"T", "mT", "transpose", "t", "swapaxes"})
_EXTRINSICS: Final = (("c2w", "w2c"), ("cam2world", "world2cam"), ("camera_to_world", "world_to_camera"), ("cam_to_world", "world_to_cam"))
_CONJUGATES: Final = _INVERSES | frozenset({"conjugate", "conj", "quaternion_conjugate", "quaternion_inverse", "T"})
_MIN_REORDERED: Final = 3
# the statements a fix is matched as: one line of code each
SIMPLE_STATEMENTS: Final = (ast.Assign, ast.AugAssign, ast.AnnAssign, ast.Expr, ast.Return)


def parse_statement(text: str) -> ast.stmt | None:
    """The one simple statement a line of code holds (its indentation removed), or None."""
    try:
        module = ast.parse(text.strip())
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return None
    if len(module.body) != 1 or isinstance(module.body[0], (ast.If, ast.For, ast.While, ast.With, ast.Try, ast.FunctionDef, ast.ClassDef)):
        return None
    return module.body[0]


def shape_key(node: ast.AST) -> str:
    """A statement's shape for matching: its tree without positions (so spacing, quotes and line
    breaks do not count)."""
    return ast.dump(node, annotate_fields=False, include_attributes=False)


def fix_shape(before: ast.stmt, after: ast.stmt) -> str | None:
    """The kind of geometric fix that turns `before` into `after`, or None."""
    found = _first_difference(before, after)
    if found is None:
        return None
    old, new = found
    for classify in (_reordered, _swapped_operands, _transpose_for_inverse, _angle_unit, _negated, _extrinsics_direction, _relative_rotation):
        shape = classify(old, new)
        if shape is not None:
            return shape
    return None


def _first_difference(old: ast.AST, new: ast.AST) -> tuple[ast.AST, ast.AST] | None:
    """The smallest pair of subtrees where `old` and `new` differ, when they differ in one place only."""
    if shape_key(old) == shape_key(new):
        return None
    if type(old) is not type(new):
        return old, new
    differing = []
    for name, old_value in ast.iter_fields(old):
        new_value = getattr(new, name, None)
        if isinstance(old_value, ast.AST) and isinstance(new_value, ast.AST):
            if shape_key(old_value) != shape_key(new_value):
                differing.append((old_value, new_value))
        elif isinstance(old_value, list) and isinstance(new_value, list):
            if len(old_value) != len(new_value):
                return old, new
            for old_item, new_item in zip(old_value, new_value):
                if isinstance(old_item, ast.AST) and isinstance(new_item, ast.AST):
                    if shape_key(old_item) != shape_key(new_item):
                        differing.append((old_item, new_item))
                elif old_item != new_item:
                    return old, new
        elif old_value != new_value:
            return old, new
    if len(differing) == 1:
        return _first_difference(*differing[0]) or differing[0]
    return old, new


def _elements(node: ast.AST) -> list[ast.AST] | None:
    if isinstance(node, (ast.List, ast.Tuple)):
        return list(node.elts)
    if isinstance(node, ast.Call) and not node.keywords:
        return list(node.args)
    return None


def _reordered(old: ast.AST, new: ast.AST) -> str | None:
    old_items, new_items = _elements(old), _elements(new)
    if old_items is None or new_items is None or len(old_items) != len(new_items) or len(old_items) < _MIN_REORDERED:
        return None
    if isinstance(old, ast.Call) and (not isinstance(new, ast.Call) or shape_key(old.func) != shape_key(new.func)):
        return None
    old_keys, new_keys = [shape_key(item) for item in old_items], [shape_key(item) for item in new_items]
    if old_keys != new_keys and sorted(old_keys) == sorted(new_keys) and len(set(old_keys)) == len(old_keys):
        return "swapped arguments" if isinstance(old, ast.Call) else "reordered"
    return None


def _swapped_operands(old: ast.AST, new: ast.AST) -> str | None:
    if isinstance(old, ast.BinOp) and isinstance(new, ast.BinOp) and type(old.op) is type(new.op) and isinstance(old.op, (ast.MatMult, ast.Mult)):
        if shape_key(old.left) == shape_key(new.right) and shape_key(old.right) == shape_key(new.left):
            return "swapped operands"
    if isinstance(old, ast.Call) and isinstance(new, ast.Call) and shape_key(old.func) == shape_key(new.func) and len(old.args) == len(new.args) == 2:
        if _last_name(old.func) in ("matmul", "dot", "compose", "quaternion_multiply", "multiply") and shape_key(old.args[0]) == shape_key(new.args[1]) and shape_key(old.args[1]) == shape_key(new.args[0]):
            return "swapped operands"
    return None


def _last_name(node: ast.AST) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return node.attr
    return None


def _wrapped_by(outer: ast.AST, inner: ast.AST, names: frozenset[str]) -> bool:
    """`outer` is `inner` with one of `names` applied: `f(inner)`, `inner.f()`, `inner.f`."""
    key = shape_key(inner)
    if isinstance(outer, ast.Call) and _last_name(outer.func) in names:
        if len(outer.args) == 1 and shape_key(outer.args[0]) == key:
            return True
        if not outer.args and isinstance(outer.func, ast.Attribute) and shape_key(outer.func.value) == key:
            return True
    return isinstance(outer, ast.Attribute) and outer.attr in names and shape_key(outer.value) == key


def _transpose_for_inverse(old: ast.AST, new: ast.AST) -> str | None:
    for first, second in ((old, new), (new, old)):
        base = _unwrapped(first, _TRANSPOSES)
        if base is not None and _wrapped_by(second, base, _INVERSES):
            return "transpose for inverse"
    return None


def _unwrapped(node: ast.AST, names: frozenset[str]) -> ast.AST | None:
    if isinstance(node, ast.Attribute) and node.attr in names:
        return node.value
    if isinstance(node, ast.Call) and _last_name(node.func) in names:
        if len(node.args) == 1:
            return node.args[0]
        if not node.args and isinstance(node.func, ast.Attribute):
            return node.func.value
    return None


def _angle_unit(old: ast.AST, new: ast.AST) -> str | None:
    if _wrapped_by(new, old, _CONVERSIONS) or _wrapped_by(old, new, _CONVERSIONS):
        return "angle unit"
    if isinstance(old, ast.Call) and isinstance(new, ast.Call) and shape_key(old.func) == shape_key(new.func):
        old_keywords = {keyword.arg for keyword in old.keywords}
        new_keywords = {keyword.arg for keyword in new.keywords}
        if old_keywords ^ new_keywords == {"degrees"}:
            return "angle unit"
    return None


def _negated(old: ast.AST, new: ast.AST) -> str | None:
    for first, second in ((old, new), (new, old)):
        if isinstance(second, ast.UnaryOp) and isinstance(second.op, ast.USub) and shape_key(second.operand) == shape_key(first):
            # a number's sign is a setting someone tuned (`mu = -6.` -> `mu = 6.`), not a term's direction
            return None if isinstance(first, ast.Constant) else "negated"
    return None


def _extrinsics_direction(old: ast.AST, new: ast.AST) -> str | None:
    old_name, new_name = _last_name(old), _last_name(new)
    if old_name is None or new_name is None or type(old) is not type(new):
        return None
    for one, other in _EXTRINSICS:
        for first, second in ((one, other), (other, one)):
            if first in old_name and re.sub(re.escape(first), second, old_name) == new_name:
                return "extrinsics direction"
    return None


def _relative_rotation(old: ast.AST, new: ast.AST) -> str | None:
    if not (isinstance(old, ast.BinOp) and isinstance(old.op, ast.Sub)):
        return None
    if isinstance(new, ast.BinOp) and isinstance(new.op, (ast.Mult, ast.MatMult)):
        operands = [new.left, new.right]
    elif isinstance(new, ast.Call) and len(new.args) == 2:
        operands = list(new.args)
    else:
        return None
    left, right = shape_key(old.left), shape_key(old.right)
    for plain, inverted in ((operands[0], operands[1]), (operands[1], operands[0])):
        if shape_key(plain) in (left, right) and any(_wrapped_by(inverted, side, _CONJUGATES) for side in (old.left, old.right) if shape_key(side) != shape_key(plain)):
            return "difference for relative rotation"
    return None
