"""Function summaries: what a helper does to its parameters and returns, so call sites anywhere in the
project know (`to_homogeneous(x)` appends w = 1 to x; `apply_pose(T, x)` rotates and translates x;
`load_normals()` returns directions; `heading(v)` returns radians; `rot_z(theta)` reads radians).

A summary belongs to one family, one question about a function, and a family is computed only when a
rule or a fact asks it (`FactBase.summary_of(call, FAMILY)`): the kind a helper returns and the w it
appends (`kind_summaries`), whether it translates a parameter (`kind_summaries.TRANSLATION`), the
angle units it returns and reads (`angle_units.ANGLE_UNITS`), the quaternion orders it returns and
reads (`quaternion_orders.QUATERNIONS`). Running GEO101 alone computes no angle or quaternion summary.

Summaries compose: a helper that calls another project helper (in its own module or in one it
imports, through aliases and relative imports, and through a package `__init__` that re-exports it)
gets the callee's effect. `ProjectSummaries` computes them lazily for one linted module, each in a
fresh scratch fact base (so a value computed under a provisional summary is never kept), and
iterates recursion and import cycles to a fixpoint: a cycle's first pass reads the summaries still
being computed as unknown, and the cycle's head is recomputed until its summary stops changing
(at most `_MAX_ROUNDS` passes; a cycle that does not settle stays unknown). Which project file an
import names, and the digest the findings cache keys a file by, are `project_files`' answers.
"""

from __future__ import annotations

import ast
from ast import AsyncFunctionDef, Call, FunctionDef
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Final, Generic, TYPE_CHECKING, TypeVar

from geolint.factbase.index import ParamBinding, index_of_file  # no cycle: the index imports no fact base module

if TYPE_CHECKING:
    from geolint.factbase.index import ModuleIndex, Scope
    from geolint.factbase.model import FactBase


@dataclass
class Summary:
    """What all summaries share: the function's positional parameters, and whether the summary is still
    being computed (on a cycle's first pass: its `return`s constrain nothing yet)."""

    parameters: tuple[str, ...] = ()
    pending: bool = False


_S = TypeVar("_S", bound=Summary)
Function = FunctionDef | AsyncFunctionDef


class SummaryFamily(Generic[_S]):
    """One question summaries answer about every function: `summarize(facts, function, parameters)`
    computes it (in a scratch fact base of the function's module); `make(parameters=..., pending=...)`
    is its summary type; `bound` drops `self` from a method's summary."""

    def __init__(self, tag: str, make: Callable[..., _S], summarize: Callable[[FactBase, Function, tuple[str, ...]], _S], bound: Callable[[_S], _S]) -> None:
        self.tag = tag
        self.make = make
        self.summarize = summarize
        self.bound = bound
        _FAMILIES[tag] = self


_FAMILIES: Final[dict[str, SummaryFamily]] = {}  # type: ignore[type-arg]


def family_of(tag: str) -> SummaryFamily:  # type: ignore[type-arg]
    """The family registered under `tag` (the fact base's memo keys a call's summary by it)."""
    return _FAMILIES[tag]


def shifted(mapping: dict) -> dict:  # type: ignore[type-arg]
    """A mapping keyed by parameter index, as a method's call `self.method(a, b)` sees it: `self` dropped."""
    return {index - 1: value for index, value in mapping.items() if index > 0}


def summarize(facts: FactBase, function: Function, family: SummaryFamily[_S]) -> _S:
    """The `family` summary of a function of `facts`' module (helpers it calls answer through theirs)."""
    params = tuple(arg.arg for arg in (*function.args.posonlyargs, *function.args.args))
    return family.summarize(facts, function, params)


def only_bound_as_parameter(scope: Scope, name: str) -> bool:
    """A parameter never rebound in its function (so what a callee does to it, it does to the argument)."""
    bound = scope.bindings.get(name, [])
    return len(bound) == 1 and isinstance(bound[0], ParamBinding) and name not in scope.augmented


def plain_parameters(scope: Scope, params: tuple[str, ...]) -> set[str]:
    """The parameters never rebound in their function (`only_bound_as_parameter`)."""
    return {name for name in params if only_bound_as_parameter(scope, name)}


def settled_returns(facts: FactBase, scope: Scope, family: SummaryFamily) -> list[ast.expr]:  # type: ignore[type-arg]
    """The function's `return` values, but `return f(...)` of a `family` summary not known yet on a
    cycle's first pass, which says nothing either way (the cycle's later passes see what the other
    `return`s agree on)."""
    return [value for value in scope.returns if not _pending(facts, value, family)]


def _pending(facts: FactBase, value: ast.expr, family: SummaryFamily) -> bool:  # type: ignore[type-arg]
    if not isinstance(value, Call) or not facts.may_have_summary(value):
        return False
    summary = facts.summary_of(value, family)
    return summary is not None and summary.pending


_ARROW: Final = " -> "
_SHOWN_HOPS: Final = 5  # a longer chain of helpers is shown as its first hops, "...", and its end


def chain(helper: str, rest: str | None) -> str:
    """`helper -> rest`, with at most `_SHOWN_HOPS` hops spelled out (chains nest one helper at a
    time, so an unbounded text would grow with the square of the chain's length)."""
    hops = [helper, *rest.split(_ARROW)] if rest else [helper]
    if len(hops) > _SHOWN_HOPS:
        hops = [*hops[: _SHOWN_HOPS - 2], "...", hops[-1]]
    return _ARROW.join(hops)


def agreed(found: list, field: str) -> list | None:  # type: ignore[type-arg]
    """`found` when every `return` has a fact and all agree on `field`, else None."""
    if not found or any(fact is None for fact in found) or len({getattr(fact, field) for fact in found}) != 1:
        return None
    return found


# --- composition: summaries of one linted module's helpers, to a fixpoint ------------------------

_MAX_SUMMARY_DEPTH: Final = 12  # helpers calling helpers this deep; deeper calls are unknown
_MAX_ROUNDS: Final = 4  # passes over a recursion or import cycle before it is given up as unknown
_BUDGET: Final = 3000  # summaries of one family computed for one linted module (each costs about its function's size)
_NO_CUT: Final = 1 << 30


class ProjectSummaries:
    """The summaries one linted module reads, computed on demand and kept for its lint only (so a
    long-running process never serves a summary computed against an older version of a module).

    Each summary is computed in a scratch fact base of its module. A call that reaches a summary
    still being computed (recursion, an import cycle) reads its provisional value (unknown on the
    first pass) and marks every summary computed since as provisional; the first summary of the
    cycle is recomputed until it stops changing, and only then kept. `fact_base` builds the fact
    base of another project module (the class `FactBase`, passed in: this module is below it).
    """

    def __init__(self, config, fact_base: Callable[..., FactBase]) -> None:  # type: ignore[no-untyped-def]
        self.config = config
        self._fact_base = fact_base
        self._final: dict[tuple[str, int, int], Summary | None] = {}
        self._provisional: dict[tuple[str, int, int], Summary] = {}
        self._positions: dict[tuple[str, int, int], int] = {}
        self._lowest_cut: list[int] = []  # per frame of the stack: the lowest frame a cycle reached
        self._modules: dict[str, FactBase | None] = {}
        self.computed = 0  # summaries computed, of every family
        self._computed_of: dict[str, int] = {}  # the same, per family: each family has its own budget

    def adopt(self, facts: FactBase) -> None:
        """The linted module itself: other modules that import it read its in-memory text."""
        if facts.path and os.path.isfile(facts.path):
            self._modules.setdefault(os.path.abspath(facts.path), facts)

    def close(self) -> None:
        """Forget the fact bases and summaries read for this lint. They refer back to this object, and
        the cycle would keep every module's syntax tree alive until the cycle collector ran."""
        for facts in self._modules.values():
            if facts is not None:
                facts.close()
        self._modules.clear()
        self._final.clear()
        self._provisional.clear()

    def facts_of(self, file: Path) -> FactBase | None:
        """The fact base of another project module (its parse and index are shared by the process)."""
        key = os.path.abspath(file)
        if key not in self._modules:
            index = _module_index_of_file(file)
            self._modules[key] = None if index is None else self._fact_base(index, self.config, key, project=self)
        return self._modules[key]

    def computed_families(self) -> set[str]:
        """The tags of the families this lint has computed a summary of."""
        return set(self._computed_of)

    def summary(self, facts: FactBase, function: Function, family: SummaryFamily[_S]) -> _S | None:
        tag = family.tag
        key = (tag, id(facts.index), id(function))
        if key in self._final:
            return self._final[key]  # type: ignore[return-value]
        position = self._positions.get(key)
        if position is not None:  # recursion or an import cycle: read what is known so far
            self._lowest_cut[-1] = min(self._lowest_cut[-1], position)
            return self._provisional.get(key) or family.make(pending=True)  # type: ignore[return-value]
        if len(self._lowest_cut) >= _MAX_SUMMARY_DEPTH or self._computed_of.get(tag, 0) >= _BUDGET:
            if self._lowest_cut:
                self._lowest_cut[-1] = -1  # cut short: nothing computed from here on is kept
            return None
        position = len(self._lowest_cut)
        self._positions[key] = position
        self._lowest_cut.append(_NO_CUT)
        rounds = 0
        try:
            while True:
                self.computed += 1
                self._computed_of[tag] = self._computed_of.get(tag, 0) + 1
                scratch = facts.scratch()
                try:
                    result: _S | None = summarize(scratch, function, family)
                finally:
                    scratch.close()
                lowest = self._lowest_cut[position]
                if lowest == _NO_CUT:
                    self._final[key] = result
                    return result
                if lowest < position:  # part of a cycle through a summary below: provisional
                    if position:
                        self._lowest_cut[position - 1] = min(self._lowest_cut[position - 1], lowest)
                    return result
                # the head of a cycle: again, with this pass's summary, until it settles
                if rounds and result == self._provisional.get(key):
                    break
                rounds += 1
                if rounds >= _MAX_ROUNDS:
                    result = None
                    break
                self._provisional[key] = result  # type: ignore[assignment]
                self._lowest_cut[position] = _NO_CUT
            self._provisional.pop(key, None)
            self._final[key] = result
            return result
        finally:
            del self._positions[key]
            self._lowest_cut.pop()


def _module_index_of_file(file: Path) -> ModuleIndex | None:
    """The parse and index of a project module, shared by every lint of the process (and with the
    engine, when the module is linted too): they depend on the file's text alone, unlike its summaries."""
    return index_of_file(file)
