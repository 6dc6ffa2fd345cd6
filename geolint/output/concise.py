"""`--output-format concise`: one line per finding, as ruff's concise format prints it:
`path:line:col: CODE [*] message`. `[*]` marks a finding `--fix` would fix (with `--unsafe-fixes`,
unsafe fixes count too); a severity other than `error` comes before the message (`warning: `).
"""

from __future__ import annotations

from typing import Sequence

from geolint.lint_types import Finding
from geolint.output.source import fixable_now, location, severity_word
from geolint.output.text import severity_style
from geolint.terminal import BOLD, CYAN, paint


def render(findings: Sequence[Finding], *, color: bool = False, unsafe_fixes: bool = False) -> str:
    return "".join(header_line(finding, color, unsafe_fixes, with_location=True) for finding in findings)


def header_line(finding: Finding, color: bool, unsafe_fixes: bool, *, with_location: bool) -> str:
    """`[path:line:col: ]CODE [*] message`, the line both concise and full begin a finding with."""
    marker = paint("[*] ", CYAN, color=color) if fixable_now(finding, unsafe_fixes) else ""
    where = f"{paint(location(finding), BOLD, color=color)}: " if with_location else ""
    code = paint(finding.code, BOLD, severity_style(finding), color=color)
    return f"{where}{code} {marker}{severity_word(finding)}{finding.message}\n"
