"""The base class lint rules derive from, and the example types rules document themselves with.

An `AstRule` runs on CPython's `ast` (the fast C parser) and the file's fact base: the engine calls
`check(tree)` once per file; the rule reports with `self.report(node, message, replacement=...)`,
where a replacement is the new source text of exactly the node's span.

The engine turns reports into `Finding`s (positions, severity), and a replacement into a fix that
replaces the node in the module's libcst tree (`geolint.cst_fixes`).
"""

from __future__ import annotations

import ast
from dataclasses import dataclass
from typing import Any, ClassVar, Mapping, Protocol, Sequence

from geolint.lint_types import Applicability, Config, Severity

class RuleTrigger(Protocol):
    """What the engine's prefilter calls: truthy when the rule might fire on `source`."""

    def search(self, source: str, /) -> object: ...


@dataclass(frozen=True)
class Valid:
    """Code the rule must stay silent on; `options` is the `[tool.geolint]` table it is linted with."""

    code: str
    options: Mapping[str, object] | None = None


@dataclass(frozen=True)
class Invalid:
    """Code the rule must flag exactly once (fixit's `Invalid`).

    `expected_fix` is the whole module after the rule's fix; `options` is the `[tool.geolint]` table it
    is linted with. `message` pins the finding's exact message, and `range` where it is reported:
    `(line, column, end_line, end_column)` of the reported node as the CLI prints them (lines and
    columns count from 1; the end column is just past the node's last character). Every rule pins
    both on at least one example, so a message or a caret cannot drift unnoticed.
    """

    code: str
    expected_fix: str | None = None
    options: Mapping[str, object] | None = None
    message: str | None = None
    range: tuple[int, int, int, int] | None = None


@dataclass(frozen=True)
class AstReport:
    """What an `AstRule` says about an `ast` node; `replacement` is the new text of the node's whole span.

    `evidence` says why, strongest first (e.g. "T_world_cam: from_frame='cam' at line 12");
    `frames` is a frame mismatch's (expected, found) pair, for the frames graph and the JSON.
    """

    node: ast.AST
    message: str
    replacement: str | None = None
    applicability: Applicability = "safe"
    fix_description: str = ""
    evidence: tuple[str, ...] = ()
    frames: tuple[str, str] | None = None


@dataclass(frozen=True)
class RuleContext:
    """What a rule may know about the file it is checking.

    `source` is the module's text; `facts` the file's fact base (what the analysis knows about its
    values), built once per file and shared by every rule; None when no enabled rule needs it.
    """

    path: str
    config: Config
    source: str = ""
    facts: Any = None


class RuleAttributes:
    """The class attributes every rule sets (what the registry, the engine and the docs read).

    The class docstring is the rule's documentation, in ruff's sections:
    "What it does", "Why is this bad?", "Example", "Use instead", "Fix safety"
    (and, when relevant, "Options", "Known problems", "References").
    """

    code: ClassVar[str]  # e.g. "GEO101", a stable public contract
    name: ClassVar[str]  # e.g. "direction-translated", reads as the bug
    default_severity: ClassVar[Severity] = Severity.ERROR
    # Off unless its exact code is selected (`--select GEO103`, `select = ["GEO", "GEO103"]`), like
    # bugbear's opinionated B9 warnings: for rules whose evidence is too weak to be on by default.
    opt_in: ClassVar[bool] = False
    # A file this prefilter does not match cannot give the rule a finding, so the engine may
    # skip parsing it. None means "always run". A compiled regex works; the real rules use
    # `geolint.factbase.vocabulary.Gate`, which also reads the config (`search_with`).
    triggers: ClassVar[RuleTrigger | None] = None
    VALID: ClassVar[Sequence[Valid]] = ()
    INVALID: ClassVar[Sequence[Invalid]] = ()
    # Frame rules that read names as frames share one `## Options` section on naming conventions,
    # which the documentation appends (`geolint.rules.fact_rule.NAMING_OPTIONS`).
    documents_naming: ClassVar[bool] = False


class AstRule(RuleAttributes):
    """A rule on CPython's `ast`: `check(tree)` is called once per file and reports through `report`."""

    def __init__(self, context: RuleContext) -> None:
        self.context = context
        self.reports: list[AstReport] = []

    def check(self, tree: ast.Module) -> None:
        """Inspect the module and `report` what is wrong (the engine calls this once per file)."""
        raise NotImplementedError

    def report(
        self,
        node: ast.AST,
        message: str,
        *,
        replacement: str | None = None,
        applicability: Applicability = "safe",
        fix_description: str = "",
        evidence: Sequence[str] = (),
        frames: tuple[str, str] | None = None,
    ) -> None:
        self.reports.append(AstReport(node, message, replacement, applicability, fix_description, tuple(evidence), frames))
