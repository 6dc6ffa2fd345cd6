"""The fact base: what a module's values are (kind, frames) and the evidence for it, on CPython's `ast`.

`facts_for_module` builds it once per file for every rule that asks (`AstRule.needs_facts`):
one walk indexes the module (`index`), the project's naming order is learned (`conventions`),
and `model.FactBase` answers the rules' questions lazily, memoised.
"""

from __future__ import annotations

import ast

from geolint.factbase.conventions import orders_for
from geolint.factbase.index import ModuleIndex
from geolint.factbase.model import FactBase
from geolint.lint_types import Config

__all__ = ["FactBase", "ModuleIndex", "facts_for_module"]


def facts_for_module(tree: ast.Module, source: str, path: str, config: Config) -> FactBase:
    """The fact base of one module under one config."""
    index = ModuleIndex(tree, source)
    orders, mixed = orders_for(path, source, tree, config.naming.order)
    return FactBase(index, config, path, orders, order_names_mixed=mixed)
