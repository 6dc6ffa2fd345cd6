"""`--format github`: GitHub Actions workflow commands, which the runner turns into annotations
on the pull request's diff (`::error file=...,line=...,col=...,endLine=...,endColumn=...,title=...::message`).
"""

from __future__ import annotations

from typing import Sequence

from geolint.lint_types import Finding, Severity

# GitHub has three annotation levels; info and hint both become a notice.
_COMMAND = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice", Severity.HINT: "notice"}


def _escape_data(text: str) -> str:
    # The escapes the Actions runner decodes (actions/toolkit, command.ts).
    return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _escape_property(text: str) -> str:
    return _escape_data(text).replace(":", "%3A").replace(",", "%2C")


def _command(finding: Finding) -> str:
    properties = {
        "file": finding.path,
        "line": finding.line,
        "col": finding.column,
        "endLine": finding.end_line,
        "endColumn": finding.end_column,
        "title": f"{finding.code} ({finding.name})",
    }
    joined = ",".join(f"{key}={_escape_property(str(value))}" for key, value in properties.items())
    return f"::{_COMMAND[Severity(finding.severity)]} {joined}::{_escape_data(f'{finding.code} {finding.message}')}"


def render(findings: Sequence[Finding], *, color: bool = False) -> str:
    """One workflow command per finding (colour never applies: the runner parses these lines)."""
    return "".join(_command(finding) + "\n" for finding in findings)
