"""`--format text` (the default): `path:line:col: CODE message`, then the source line and a caret,
then the evidence the finding stands on (`  = evidence: ...`) when the rule recorded any.

The first line of each finding is the grep/editor-friendly form every linter prints; the
source excerpt under it shows what was flagged. Source lines are read from the findings'
paths; a file that cannot be read simply gets no excerpt.
"""

from __future__ import annotations

from typing import Sequence

from geolint.lint_types import Finding, Severity
from geolint.terminal import BOLD, CYAN, DIM, RED, YELLOW, paint

TAB = "    "


def render(findings: Sequence[Finding], *, color: bool = False) -> str:
    """Each finding as its header line plus an excerpt of the code it points at."""
    return "".join(_finding_block(finding, color) for finding in findings)


def _finding_block(finding: Finding, color: bool) -> str:
    severity_style = RED if Severity(finding.severity) is Severity.ERROR else YELLOW
    header = (
        f"{paint(finding.path, BOLD, color=color)}:{finding.line}:{finding.column}: "
        f"{paint(finding.code, BOLD, severity_style, color=color)} {finding.message}\n"
    )
    line_text = _source_line(finding.path, finding.line)
    if line_text is None:
        return header + _evidence_line(finding, color)
    stripped = line_text.lstrip(" \t")
    indent = len(line_text) - len(stripped)
    start = max(finding.column - 1 - indent, 0)
    end = finding.end_column - 1 - indent if finding.end_line == finding.line else len(stripped)
    end = min(max(end, start + 1), max(len(stripped), start + 1))
    shown = stripped.replace("\t", TAB)
    prefix = stripped[:start].replace("\t", TAB)
    marked = stripped[start:end].replace("\t", TAB)
    caret = " " * len(prefix) + "^" * max(len(marked), 1)
    excerpt = f"{paint('  | ', DIM, color=color)}{shown}\n{paint('  | ', DIM, color=color)}{paint(caret, CYAN if not color else severity_style, color=color)}\n"
    return f"{header}{excerpt}{_evidence_line(finding, color)}"


def _evidence_line(finding: Finding, color: bool) -> str:
    """`  = evidence: ...`: why the rule believes it, strongest first (like rustc's `= note:`)."""
    if not finding.evidence:
        return ""
    return f"{paint('  = evidence: ', DIM, color=color)}{'; '.join(finding.evidence)}\n"


def _source_line(path: str, line: int) -> str | None:
    from geolint.engine import read_source_lines

    lines = read_source_lines(path)
    if not 1 <= line <= len(lines):
        return None
    return lines[line - 1].rstrip("\r\n")
