"""Findings as LSP diagnostics: rule code, a link to the rule's docs, source "geolint", configured severity."""

from __future__ import annotations

from typing import Sequence

from lsprotocol import types
from pygls.workspace.position_codec import PositionCodec

from geolint.api import rule_url
from geolint.lint_types import Finding, Severity
from geolint.lsp.positions import to_lsp_range

SOURCE = "geolint"

_SEVERITY = {
    Severity.ERROR: types.DiagnosticSeverity.Error,
    Severity.WARNING: types.DiagnosticSeverity.Warning,
    Severity.INFO: types.DiagnosticSeverity.Information,
    Severity.HINT: types.DiagnosticSeverity.Hint,
}


def finding_range(finding: Finding, lines: Sequence[str], codec: PositionCodec) -> types.Range:
    return to_lsp_range(lines, codec, finding.line, finding.column, finding.end_line, finding.end_column)


def to_diagnostic(finding: Finding, lines: Sequence[str], codec: PositionCodec) -> types.Diagnostic:
    return types.Diagnostic(
        range=finding_range(finding, lines, codec),
        message=finding.message,
        severity=_SEVERITY[Severity(finding.severity)],
        code=finding.code,
        code_description=types.CodeDescription(href=rule_url(finding.code)),
        source=SOURCE,
        # Lets a client (or our code-action handler) tell fixable findings apart without re-linting.
        data={"name": finding.name, "fixable": finding.fix is not None},
    )
