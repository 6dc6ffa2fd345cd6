"""The base class every lint rule derives from, and the example types rules document themselves with.

A rule is a libcst batchable visitor: the engine parses a file once and runs every
enabled rule over it in a single traversal. A rule reports with `self.report(node, ...)`;
the engine turns reports into `Finding`s (positions, severity, fix edits).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Protocol, Sequence

import libcst as cst
from libcst.metadata import PositionProvider

from geolint.lint_types import Applicability, Config, Severity


class RuleTrigger(Protocol):
    """What the engine's prefilter calls: truthy when the rule might fire on `source`."""

    def search(self, source: str, /) -> object: ...


@dataclass(frozen=True)
class Valid:
    """Code the rule must stay silent on."""

    code: str


@dataclass(frozen=True)
class Invalid:
    """Code the rule must flag; `expected_fix` is the whole module after the rule's fix."""

    code: str
    expected_fix: str | None = None


@dataclass(frozen=True)
class Report:
    """What a rule says about a node; the engine resolves positions and builds the Fix."""

    node: cst.CSTNode
    message: str
    replacement: cst.CSTNode | cst.RemovalSentinel | None = None
    applicability: Applicability = "safe"
    fix_description: str = ""


@dataclass(frozen=True)
class RuleContext:
    """What a rule may know about the file it is checking."""

    path: str
    config: Config


class Rule(cst.BatchableCSTVisitor):
    """Base class of all rules. Subclasses set the class attributes below.

    The class docstring is the rule's documentation, in ruff's sections:
    "What it does", "Why is this bad?", "Example", "Use instead", "Fix safety"
    (and, when relevant, "Options", "Known problems", "References").
    """

    code: ClassVar[str]  # e.g. "GEO101", a stable public contract
    name: ClassVar[str]  # e.g. "direction-translated", reads as the bug
    default_severity: ClassVar[Severity] = Severity.ERROR
    # A file this prefilter does not match cannot give the rule a finding, so the engine may
    # skip parsing it. None means "always run". A compiled regex works; the real rules use
    # `geolint.semantic.prefilter.Trigger`, which also reads the config (`search_with`).
    triggers: ClassVar[RuleTrigger | None] = None
    VALID: ClassVar[Sequence[Valid]] = ()
    INVALID: ClassVar[Sequence[Invalid]] = ()

    METADATA_DEPENDENCIES = (PositionProvider,)

    def __init__(self, context: RuleContext) -> None:
        super().__init__()
        self.context = context
        self.reports: list[Report] = []

    def report(
        self,
        node: cst.CSTNode,
        message: str,
        *,
        replacement: cst.CSTNode | cst.RemovalSentinel | None = None,
        applicability: Applicability = "safe",
        fix_description: str = "",
    ) -> None:
        self.reports.append(Report(node, message, replacement, applicability, fix_description))
