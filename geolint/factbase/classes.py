"""The classes of a module a fact is about: the class around a node, the module's top-level classes
by name, and the project class a called name is (of this module, or of a project module it imports)."""

from __future__ import annotations

import ast
from ast import AST, Attribute, ClassDef, Name
from collections import Counter
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase


def enclosing_class(facts: FactBase, node: AST) -> ClassDef | None:
    current = facts.parent(node)
    while current is not None and not isinstance(current, ClassDef):
        current = facts.parent(current)
    return current


def top_level_class(facts: FactBase, name: str) -> ClassDef | None:
    """The module's one top-level class of that name (None when there is none, or two)."""
    return top_level_classes(facts).get(name)


def top_level_classes(facts: FactBase) -> dict[str, ClassDef | None]:
    """The module's top-level classes by name; None for a name defined twice (read once per module)."""

    def find() -> dict[str, ClassDef | None]:
        classes = [node for node in facts.index.tree.body if isinstance(node, ClassDef)]
        counts = Counter(node.name for node in classes)
        return {node.name: node if counts[node.name] == 1 else None for node in classes}

    return facts.module_fact("top-level classes", find)


def called_project_class(facts: FactBase, func: ast.expr) -> tuple[FactBase, ClassDef] | None:
    """`project_class`, once per called name."""
    return facts.memoised("project class", func, lambda: project_class(facts, func))


def project_class(facts: FactBase, func: ast.expr) -> tuple[FactBase, ClassDef] | None:
    """The top-level class a called name is: of this module, or of the project module it is imported from."""
    if isinstance(func, Name):
        local = top_level_class(facts, func.id)
        if local is not None:
            return facts, local
        if func.id not in facts.index.imports:
            return None
    elif not isinstance(func, Attribute):
        return None
    if not facts.cross_module:
        return None
    found = facts.defining_module(facts.qualified_name(func) or "", facts.path)
    if found is None:
        return None
    other, name = found
    cls = top_level_class(other, name)
    return None if cls is None else (other, cls)
