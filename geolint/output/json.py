"""`--format json`: one JSON array, one object per finding with exactly the keys
`path`, `line`, `column`, `end_line`, `end_column` (1-based; end exclusive), `code`, `name`,
`message`, `severity`, `fix` (null, or `{"applicability": "safe"|"unsafe", "edits": [...]}` where
each edit is `{"line", "column", "end_line", "end_column", "content"}`), and, only when the rule
states why, `evidence` (a list of strings, strongest first), and, only for a frame mismatch,
`frames` (`[expected, found]`: the frame the operation needs and the one it got), and, only in a
notebook, `cell` (its 1-based number among all cells; lines are then counted within the cell,
as ruff's JSON does). `[]` when clean.
"""

from __future__ import annotations

import json
from typing import Any, Sequence

from geolint.lint_types import Finding, Severity
from geolint.output.source import in_cell


def finding_as_json(finding: Finding) -> dict[str, Any]:
    finding, cell = in_cell(finding)
    fix = finding.fix
    shown = {
        "path": finding.path,
        "line": finding.line,
        "column": finding.column,
        "end_line": finding.end_line,
        "end_column": finding.end_column,
        "code": finding.code,
        "name": finding.name,
        "message": finding.message,
        "severity": Severity(finding.severity).value,
        "fix": None
        if fix is None
        else {
            "applicability": fix.applicability,
            "edits": [
                {
                    "line": edit.line,
                    "column": edit.column,
                    "end_line": edit.end_line,
                    "end_column": edit.end_column,
                    "content": edit.content,
                }
                for edit in fix.edits
            ],
        },
    }
    if cell is not None:
        shown["cell"] = cell
    if finding.evidence:
        shown["evidence"] = list(finding.evidence)
    if finding.frames is not None:
        shown["frames"] = list(finding.frames)
    return shown


def render(findings: Sequence[Finding], *, color: bool = False) -> str:
    """The findings as one JSON array (colour never applies)."""
    return json.dumps([finding_as_json(finding) for finding in findings], indent=2, ensure_ascii=False) + "\n"
