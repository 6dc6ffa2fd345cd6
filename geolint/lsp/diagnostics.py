"""Findings as LSP diagnostics: rule code, a link to the rule's docs, source "geolint", configured severity."""

from __future__ import annotations

import re
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


_AT_LINE = re.compile(r"\bat line (\d+)\b")


def evidence_information(
    finding: Finding, uri: str, lines: Sequence[str], codec: PositionCodec
) -> list[types.DiagnosticRelatedInformation] | None:
    """Why the rule believes it, as related information: an item that names a line ("from_frame=
    'obj' at line 12") points there, the others at the finding itself."""
    if not finding.evidence:
        return None
    related = []
    for item in finding.evidence:
        stated = _AT_LINE.search(item)
        line = int(stated.group(1)) if stated else 0
        if 1 <= line <= len(lines):
            where = to_lsp_range(lines, codec, line, 1, line, len(lines[line - 1].rstrip("\r\n")) + 1)
        else:
            where = finding_range(finding, lines, codec)
        related.append(types.DiagnosticRelatedInformation(location=types.Location(uri=uri, range=where), message=item))
    return related


def to_diagnostic(finding: Finding, lines: Sequence[str], codec: PositionCodec, uri: str | None = None) -> types.Diagnostic:
    return types.Diagnostic(
        range=finding_range(finding, lines, codec),
        message=finding.message,
        severity=_SEVERITY[Severity(finding.severity)],
        code=finding.code,
        code_description=types.CodeDescription(href=rule_url(finding.code)),
        source=SOURCE,
        # Lets a client (or our code-action handler) tell fixable findings apart without re-linting.
        data={"name": finding.name, "fixable": finding.fix is not None},
        related_information=evidence_information(finding, uri, lines, codec) if uri is not None else None,
    )
