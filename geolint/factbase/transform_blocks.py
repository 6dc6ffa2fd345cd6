"""The blocks of a 4x4 transform an expression reads: the rotation `M[:3, :3]`, the translation
`M[:3, 3]`, and the expressions that look like a translation."""

from __future__ import annotations

import ast
from ast import AST, Attribute, Constant, Name, Slice, Subscript
from typing import TYPE_CHECKING

from geolint.factbase.syntax import is_full_slice, is_index, is_slice_upto, last_name, number, subscript_parts

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase


def rotation_block_of(facts: FactBase, node: AST) -> ast.expr | None:
    """For `M[:3, :3]` (or `M[..., :3, :3]`, `M[:, :3, :3]`), the matrix M; else None."""
    if isinstance(node, Subscript):
        parts = _drop_batch(subscript_parts(node))
        if len(parts) == 2 and is_slice_upto(parts[0], 3) and is_slice_upto(parts[1], 3):
            return node.value
    return None


def translation_of(facts: FactBase, node: AST) -> ast.expr | None:
    """For `M[:3, 3]` (or `M[:3, -1]`, `M[0:3, 3]`, `M[..., :3, 3]`, `M[:, :3, 3]`, `M[..., :3, 3:]`), the
    matrix M; else None."""
    if isinstance(node, Subscript):
        parts = _drop_batch(subscript_parts(node))
        if len(parts) == 2 and is_slice_upto(parts[0], 3) and (is_index(parts[1], 3, -1) or _is_last_column(parts[1])):
            return node.value
    return None


def _is_last_column(part: AST) -> bool:
    """`3:`, `3:4`, `-1:`: the translation column kept as a column (`M[..., :3, 3:]`)."""
    if not isinstance(part, Slice) or part.step is not None or part.lower is None:
        return False
    lower, upper = number(part.lower), None if part.upper is None else number(part.upper)
    return (lower == 3 and (part.upper is None or upper == 4)) or (lower == -1 and part.upper is None)


def is_translation_like(facts: FactBase, node: AST) -> bool:
    """`t`, `trans`, `translation`, `t_world_cam`, `T[:3, 3]`, `pose.translation`, `tvec`."""
    if translation_of(facts, node) is not None:
        return True
    word = last_name(node)
    if word is None:
        return False
    if isinstance(node, Attribute) and word in ("translation", "t", "trans", "p"):
        return not facts.is_module_like(node.value)
    if not isinstance(node, Name):
        return False
    first = node.id.strip("_").split("_")[0].lower()
    return first in ("t", "trans", "translation", "tvec", "tran")


def _drop_batch(parts: list[ast.expr]) -> list[ast.expr]:
    """`M[..., :3, :3]` and `M[:, :3, :3]` index a batch of matrices like `M[:3, :3]` indexes one."""
    if len(parts) == 3 and (isinstance(parts[0], Constant) and parts[0].value is Ellipsis or is_full_slice(parts[0])):
        return parts[1:]
    return parts
