"""`--format sarif`: a SARIF 2.1.0 log, the format GitHub code scanning and other CI dashboards import.

One `reportingDescriptor` per rule code that has findings (with its docs link as `helpUri`),
one result per finding with a region, and the fix edits as SARIF `fixes`. Columns are counted
in Unicode code points, as geolint counts them, and the run says so (`columnKind`).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Sequence

from geolint._version import __version__
from geolint.api import rule_url
from geolint.docs import rule_doc
from geolint.lint_types import Finding, Severity

SCHEMA_URI = "https://json.schemastore.org/sarif-2.1.0.json"
INFORMATION_URI = "https://github.com/geolint/geolint"

_LEVEL = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note", Severity.HINT: "note"}


def _artifact_uri(path: str) -> dict[str, str]:
    as_path = Path(path)
    if as_path.is_absolute():
        return {"uri": as_path.as_uri()}
    # Relative paths are relative to where `geolint check` ran: the checkout root in CI.
    return {"uri": as_path.as_posix(), "uriBaseId": "%SRCROOT%"}


def _rule_summary(code: str, fallback: str) -> str:
    """The first line of the rule's documentation, or `fallback` for codes with no rule class."""
    try:
        from geolint.rules import rule_by_code

        rule = rule_by_code(code)
    except Exception:  # a broken rule module must not stop the report from being written
        rule = None
    doc = rule_doc(rule) if rule is not None else ""
    return doc.splitlines()[0].strip() if doc else fallback


def _descriptor(finding: Finding) -> dict[str, Any]:
    return {
        "id": finding.code,
        "name": finding.name,
        "shortDescription": {"text": _rule_summary(finding.code, finding.name)},
        "helpUri": rule_url(finding.code),
        "help": {"text": f"See {rule_url(finding.code)}"},
        "defaultConfiguration": {"level": _LEVEL[Severity(finding.severity)]},
    }


def _fix_description(finding: Finding) -> str:
    assert finding.fix is not None
    text = finding.fix.description or f"fix {finding.code}"
    return f"{text} (unsafe: may change behaviour)" if finding.fix.applicability == "unsafe" else text


def _result(finding: Finding, rule_index: int) -> dict[str, Any]:
    location = {"artifactLocation": _artifact_uri(finding.path)}
    result: dict[str, Any] = {
        "ruleId": finding.code,
        "ruleIndex": rule_index,
        "level": _LEVEL[Severity(finding.severity)],
        "message": {"text": finding.message},
        "locations": [
            {
                "physicalLocation": {
                    **location,
                    "region": {
                        "startLine": finding.line,
                        "startColumn": finding.column,
                        "endLine": finding.end_line,
                        "endColumn": finding.end_column,
                    },
                }
            }
        ],
    }
    if finding.fix is not None and finding.fix.edits:
        result["fixes"] = [
            {
                "description": {"text": _fix_description(finding)},
                "artifactChanges": [
                    {
                        **location,
                        "replacements": [
                            {
                                "deletedRegion": {
                                    "startLine": edit.line,
                                    "startColumn": edit.column,
                                    "endLine": edit.end_line,
                                    "endColumn": edit.end_column,
                                },
                                "insertedContent": {"text": edit.content},
                            }
                            for edit in finding.fix.edits
                        ],
                    }
                ],
            }
        ]
    return result


def sarif_log(findings: Sequence[Finding]) -> dict[str, Any]:
    """The SARIF log as a JSON-ready dict (one run of the geolint tool)."""
    rule_index: dict[str, int] = {}
    descriptors: list[dict[str, Any]] = []
    for finding in sorted(findings, key=lambda f: f.code):
        if finding.code not in rule_index:
            rule_index[finding.code] = len(descriptors)
            descriptors.append(_descriptor(finding))
    return {
        "$schema": SCHEMA_URI,
        "version": "2.1.0",
        "runs": [
            {
                "tool": {
                    "driver": {
                        "name": "geolint",
                        "version": __version__,
                        "semanticVersion": __version__,
                        "informationUri": INFORMATION_URI,
                        "rules": descriptors,
                    }
                },
                "columnKind": "unicodeCodePoints",
                "results": [_result(finding, rule_index[finding.code]) for finding in findings],
            }
        ],
    }


def render(findings: Sequence[Finding], *, color: bool = False) -> str:
    return json.dumps(sarif_log(findings), indent=2) + "\n"
