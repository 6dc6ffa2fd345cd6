"""The fact base: what a module's values are (kind, frames) and the evidence for it, on CPython's `ast`.

`facts_for_module` builds it once per file for every rule that asks (`AstRule.needs_facts`):
one walk indexes the module (`index`), the project's naming order is learned (`conventions`),
and `model.FactBase` answers the rules' questions lazily, memoised.
"""

from __future__ import annotations

import ast
import threading
from dataclasses import replace

from geolint.factbase.conventions import learned_aliases, naming_config, orders_for
from geolint.factbase.index import ModuleIndex
from geolint.factbase.model import FactBase
from geolint.lint_types import Config

__all__ = ["FactBase", "ModuleIndex", "facts_for_module", "index_of", "module_index"]

# The last module indexed, per thread: the engine, the fact base and the rules that walk the tree
# all ask about the same module in a row, and one walk serves them all.
_last_index = threading.local()


def module_index(tree: ast.Module, source: str, depth_limit: int | None = None) -> ModuleIndex:
    """The index of `tree` (whose text is `source`), walked once for everyone who asks."""
    cached: ModuleIndex | None = getattr(_last_index, "value", None)
    # (a shared parse's index holds an equal text, read by another decoder: same tree, same text)
    if cached is not None and cached.tree is tree and (cached.source is source or cached.source == source) and not cached.too_deep:
        if depth_limit is None or cached.depth_limit == depth_limit:  # measured against the same limit
            return cached
    index = ModuleIndex(tree, source, depth_limit)
    _last_index.value = index
    return index


def remember_index(index: ModuleIndex) -> None:
    """Make `index` the one `module_index` and `index_of` find for its tree (a shared parse)."""
    _last_index.value = index


def last_index(tree: ast.Module) -> ModuleIndex | None:
    """The index last built, when it is `tree`'s."""
    cached: ModuleIndex | None = getattr(_last_index, "value", None)
    return cached if cached is not None and cached.tree is tree else None


def index_of(tree: ast.Module) -> ModuleIndex:
    """The index of `tree` for code that holds only the tree (the last one built, else a new one)."""
    cached: ModuleIndex | None = getattr(_last_index, "value", None)
    if cached is not None and cached.tree is tree and not cached.too_deep:
        return cached
    index = ModuleIndex(tree, "")
    _last_index.value = index
    return index


def facts_for_module(tree: ast.Module, source: str, path: str, config: Config) -> FactBase:
    """The fact base of one module under one config."""
    index = module_index(tree, source)
    reading = orders_for(path, source, tree, config.naming.order)
    config = naming_config(config, reading)
    aliases = learned_aliases(tree, source, reading.orders)
    if aliases and not aliases.keys() & {key.lower() for key in config.frame_aliases}:
        config = replace(config, frame_aliases={**aliases, **config.frame_aliases})
    return FactBase(index, config, path, reading.orders, order_names_mixed=reading.mixed, names_stated=reading.stated)
