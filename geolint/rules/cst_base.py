"""The libcst rule base: a batchable visitor the engine runs in one libcst traversal.

Only rules not yet ported to `AstRule` use it; importing this module imports libcst.
"""

from __future__ import annotations

from dataclasses import dataclass

import libcst as cst
from libcst.metadata import PositionProvider

from geolint.lint_types import Applicability
from geolint.rules.base import RuleAttributes, RuleContext


@dataclass(frozen=True)
class Report:
    """What a rule says about a node; the engine resolves positions and builds the Fix."""

    node: cst.CSTNode
    message: str
    replacement: cst.CSTNode | cst.RemovalSentinel | None = None
    applicability: Applicability = "safe"
    fix_description: str = ""


class Rule(RuleAttributes, cst.BatchableCSTVisitor):
    """A rule on libcst: a batchable visitor the engine runs in one traversal with the other `Rule`s."""

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

