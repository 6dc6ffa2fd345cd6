"""Data flow the rules ask about names, answered once per module from its index.

What a scope writes into a name (an item, an attribute, an augmented assignment) and where it
rebinds a name from its own value are tables built on first use, one pass per scope or name, so a
question about one assignment costs the same in a ten-line function as in a generated one that
rebinds its names ten thousand times.
"""

from __future__ import annotations

import ast
from ast import Name
from typing import Any

from geolint.factbase.index import ModuleIndex, Scope
from geolint.factbase.model import walk_within


def writes_into(index: ModuleIndex, scope: Scope, name: str) -> bool:
    """Whether `scope` writes into the value `name` holds: `name[:3, 3] = t`, `name += d`,
    `name[:3, 1:3] *= -1`, `name.translation = t` (or `-=`)."""
    return name in scope.subscript_stores or updates_in_place(index, scope, name)


def updates_in_place(index: ModuleIndex, scope: Scope, name: str) -> bool:
    """Whether `scope` updates the value `name` holds other than by storing into a block of it:
    `name += d`, `name[:3, 1:3] *= -1`, `name.translation = t`."""
    return name in scope.augmented or name in scope.item_augmented or name in _attribute_owners(index, scope)


def last_update_from_itself(index: ModuleIndex, scope: Scope, name: str) -> int:
    """The last line where `scope` binds `name` to a value that reads it (`T = T @ D`,
    `p_base = np.dot(p_base, R.T)`), 0 when it never does."""
    lines = _memo(index, "last_update_from_itself")
    key = (id(scope.node), name)
    line = lines.get(key)
    if line is None:
        updates = [
            value.lineno for value in scope.bindings.get(name, ()) if isinstance(value, ast.expr) and name in names_read(index, value)
        ]
        line = lines[key] = max(updates, default=0)
    return line  # type: ignore[no-any-return]


def names_read(index: ModuleIndex, value: ast.expr) -> frozenset[str]:
    """The names `value`'s parts mention (not `value` itself, nor inside nested functions)."""
    names = _memo(index, "names_read")
    found = names.get(id(value))
    if found is None:
        found = names[id(value)] = frozenset(node.id for node in walk_within(value) if isinstance(node, Name))
    return found  # type: ignore[no-any-return]


def _attribute_owners(index: ModuleIndex, scope: Scope) -> frozenset[str]:
    """The names `scope` stores attributes of (`T.translation = t`, `pose.p -= d`)."""
    owners = _memo(index, "attribute_owners")
    found = owners.get(id(scope.node))
    if found is None:
        found = owners[id(scope.node)] = frozenset(
            stored.value.id for stored, _ in scope.attribute_stores if isinstance(stored.value, Name)
        )
    return found  # type: ignore[no-any-return]


def _memo(index: ModuleIndex, name: str) -> dict[Any, Any]:
    """A table kept on the module's index (dropped with what else was derived from it, `forget_derived`)."""
    memo = index.flow.get(name)
    if memo is None:
        memo = index.flow[name] = {}
    return memo
