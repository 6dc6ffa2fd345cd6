"""The project's own fixes as knowledge: statement shapes its git history fixed (`mining`, with
`[tool.geolint] history = true` or `geolint check --history`) and shapes it names itself
(`known-fixes`). GEO401 reports a statement that still has one of them."""

from __future__ import annotations

import os
import threading
from functools import lru_cache

from geolint.history.fix_edits import parse_statement, shape_key
from geolint.history.mining import FixedShape, History, git, history_of
from geolint.lint_types import Config

__all__ = ["FixedShape", "History", "fixed_shapes", "forget", "history_key", "repository_of_folder"]

_lock = threading.Lock()
_heads: dict[str, str | None] = {}


@lru_cache(maxsize=4096)
def repository_of_folder(folder: str) -> str | None:
    """The work tree holding `folder`: the nearest folder with a `.git` (a folder, or a file for a
    worktree or a submodule), looked up without running git."""
    parent = os.path.dirname(folder)
    if os.path.exists(os.path.join(folder, ".git")):
        return os.path.realpath(folder)
    return None if parent == folder else repository_of_folder(parent)


def _head(root: str) -> str | None:
    with _lock:
        if root in _heads:
            return _heads[root]
    found = git(root, "rev-parse", "HEAD")
    head = found.strip() if found is not None else None
    with _lock:
        _heads[root] = head
    return head


def forget() -> None:
    """Let a long-lived process (the language server) see new commits: HEAD is asked again."""
    with _lock:
        _heads.clear()
    repository_of_folder.cache_clear()


def history_key(path: str, config: Config) -> str:
    """What a file's GEO401 findings read from its repository's history, for the findings cache."""
    if not config.history:
        return ""
    root = repository_of_folder(os.path.dirname(os.path.abspath(path)))
    head = _head(root) if root is not None else None
    return f"history:{root}:{head}:{config.history_limit}" if head is not None else ""


_mined: dict[tuple[str, str, int], dict[str, FixedShape]] = {}


def _mined_shapes(root: str, limit: int) -> dict[str, FixedShape]:
    """The repository's fixed shapes at its HEAD (asked once per process), by shape key."""
    head = _head(root)
    if head is None:
        return {}
    key = (root, head, limit)
    with _lock:
        known = _mined.get(key)
    if known is None:
        known = {shape.key: shape for shape in history_of(root, limit, head=head).shapes}
        with _lock:
            _mined[key] = known
    return known


def fixed_shapes(path: str, config: Config) -> dict[str, FixedShape]:
    """shape key -> the fix, for the file at `path`: its `known-fixes`, and with `history` on, what its
    repository's history fixed (the newest fix of a shape)."""
    found: dict[str, FixedShape] = {}
    if config.history:
        root = repository_of_folder(os.path.dirname(os.path.abspath(path)))
        if root is not None:
            found.update(_mined_shapes(root, config.history_limit))
    for before, after, reason in config.known_fixes:
        old, new = parse_statement(before), parse_statement(after)
        if old is not None and new is not None:
            found[shape_key(old)] = FixedShape(shape_key(old), "known fix", before.strip(), after.strip(), shape_key(new), "", reason, "", 0)
    return found
