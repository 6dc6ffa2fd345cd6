"""Memoised, cycle-safe evaluation of one fact per AST node (a kind, a quaternion order, a unit...).

Facts are computed by following values back through assignments, so evaluation can meet itself
(`x = x + v`) or run deep; both give None, which every caller reads as "no evidence".
"""

from __future__ import annotations

from typing import Callable, Generic, Hashable, TypeVar

_T = TypeVar("_T")


class NodeMemo(Generic[_T]):
    """One fact per key (usually `id(node)`), computed once; None on a cycle or past `max_depth`."""

    def __init__(self, max_depth: int) -> None:
        self.max_depth = max_depth
        self._values: dict[Hashable, _T | None] = {}
        self._active: set[Hashable] = set()

    def get(self, key: Hashable, compute: Callable[[], _T | None]) -> _T | None:
        if key in self._values:
            return self._values[key]
        if key in self._active or len(self._active) > self.max_depth:
            return None  # a cycle or runaway depth: no evidence
        self._active.add(key)
        try:
            value = compute()
        finally:
            self._active.discard(key)
        self._values[key] = value
        return value
