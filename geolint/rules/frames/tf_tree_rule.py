"""The base of the rules on the project's tf tree (GEO211-GEO214): the module's own tf statements,
and the graph of its whole project with them (`geolint.factbase.tf_workspace`)."""

from __future__ import annotations

import os
import re
from typing import ClassVar, Final

from geolint.factbase.model import FactBase
from geolint.factbase.project_files import is_test_module
from geolint.factbase.tf_statements import Place, Published, PythonStatement, python_statements, settled
from geolint.factbase.tf_workspace import TfGraph, frames_of_statements, graph_of, project_graph, project_of
from geolint.knowledge import knowledge_base
from geolint.rules.base import RuleTrigger
from geolint.rules.fact_rule import FactRule

# REP 105's chain: each frame is the parent of the next (earth -> map -> odom -> base_link)
REP105_CHAIN: Final = ("earth", "map", "odom", "base_link")


def reverses_rep105(edge: Published) -> bool:
    """Whether a publication puts a frame of REP 105's chain above one that the chain puts above it."""
    if edge.parent not in REP105_CHAIN or edge.child not in REP105_CHAIN:
        return False
    return REP105_CHAIN.index(edge.parent) > REP105_CHAIN.index(edge.child)


class _TfText:
    """A module names one of the knowledge base's tf calls or launched executables (a cheap gate: one
    `in` test per name, which scans faster than an alternation with no first character)."""

    def __init__(self) -> None:
        self._names: tuple[str, ...] | None = None

    @property
    def pattern(self) -> str:
        return "|".join(re.escape(name) for name in self._known())

    def _known(self) -> tuple[str, ...]:
        if self._names is None:
            self._names = tuple(knowledge_base().tf_names())
        return self._names

    def search(self, source: str, /) -> bool:
        return any(name in source for name in self._known())

    def search_with(self, source: str, config: object, /) -> bool:
        return self.search(source)


TF_TEXT: Final = _TfText()


class ModuleTfTree:
    """The module's tf statements and its project's graph, computed once for every rule that asks."""

    def __init__(self, facts: FactBase) -> None:
        # a file on disk is judged with its project (its places named as the project's files are); a
        # snippet (an example, standard input) alone
        on_disk = os.path.isfile(facts.path)
        statements = python_statements(facts, os.path.realpath(facts.path) if on_disk else facts.path)
        own = frames_of_statements(statements)
        self.graph: TfGraph = project_graph(facts.path, own) if on_disk and statements else graph_of([own])
        # a frame that is the default of a parameter the project's launch files set is unknown here too
        self.statements: list[PythonStatement] = [
            PythonStatement(settled(found.statement, self.graph.overridden), found.call) for found in statements
        ]
        self.root = project_of(facts.path) if on_disk else None
        self._path, self._own = facts.path, own
        # a test sets up the tree it needs (a stand-in `base_link -> map`): not the robot's
        self.is_test = is_test_module(os.path.relpath(facts.path, self.root) if self.root is not None else facts.path)
        self._whole: TfGraph | None = self.graph if self.statements or self.root is None else None

    def whole_graph(self) -> TfGraph:
        """The project's graph even when this module states nothing about tf itself (a camera driver
        that only stamps its images)."""
        if self._whole is None:
            self._whole = project_graph(self._path, self._own)
        return self._whole

    def where(self, place: Place) -> str:
        """`path:line` for a message: the path relative to the working folder when it is inside it, else
        to the project (never a path of this machine)."""
        path = place.path
        if os.path.isabs(path):
            relative = os.path.relpath(path)
            if relative.startswith("..") and self.root is not None:
                relative = os.path.relpath(path, self.root)
            path = relative if not relative.startswith("..") else os.path.basename(path)
        return f"{path}:{place.line}"


class TfTreeRule(FactRule):
    """A rule on the tf statements of the module, judged against the project's whole tree."""

    triggers: ClassVar[RuleTrigger | None] = TF_TEXT

    def run(self) -> None:
        tree = self.facts.shared(ModuleTfTree)
        if tree.statements and not tree.is_test:
            self.check_tree(tree)

    def check_tree(self, tree: ModuleTfTree) -> None:
        raise NotImplementedError
