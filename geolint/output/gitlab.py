"""`--format gitlab`: a GitLab code quality report (JSON list), shown in merge request widgets.

The fingerprint identifies a finding across pipelines. It hashes the path, the code, the message
and the occurrence number of that triple, not the line: code that moves does not make a
finding look new.
"""

from __future__ import annotations

import hashlib
import json
from collections import Counter
from pathlib import PurePath
from typing import Any, Sequence

from geolint.lint_types import Finding, Severity

_SEVERITY = {Severity.ERROR: "major", Severity.WARNING: "minor", Severity.INFO: "info", Severity.HINT: "info"}


def _fingerprint(finding: Finding, occurrence: int) -> str:
    key = "\0".join((PurePath(finding.path).as_posix(), finding.code, finding.message, str(occurrence)))
    return hashlib.md5(key.encode("utf-8"), usedforsecurity=False).hexdigest()


def _issue(finding: Finding, occurrence: int) -> dict[str, Any]:
    return {
        "type": "issue",
        "check_name": finding.code,
        "description": f"{finding.code} {finding.message}",
        "categories": ["Bug Risk"],
        "severity": _SEVERITY[Severity(finding.severity)],
        "fingerprint": _fingerprint(finding, occurrence),
        "location": {
            "path": PurePath(finding.path).as_posix(),
            "positions": {
                "begin": {"line": finding.line, "column": finding.column},
                "end": {"line": finding.end_line, "column": finding.end_column},
            },
        },
    }


def render(findings: Sequence[Finding], *, color: bool = False) -> str:
    seen: Counter[tuple[str, str, str]] = Counter()
    issues = []
    for finding in sorted(findings, key=lambda f: (f.path, f.line, f.column, f.code)):
        key = (finding.path, finding.code, finding.message)
        issues.append(_issue(finding, seen[key]))
        seen[key] += 1
    return json.dumps(issues, indent=2) + "\n"
