"""`--format junit`: JUnit XML, which most CI systems (GitLab, Jenkins, Azure, CircleCI) show as test results.

Each file with findings is a `<testsuite>`, each finding a failed `<testcase>`. With no findings
there is one passing test case, so a CI that requires at least one test stays green.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from itertools import groupby
from typing import Sequence

from geolint.lint_types import Finding


def _testcase(parent: ET.Element, finding: Finding) -> None:
    case = ET.SubElement(
        parent,
        "testcase",
        name=f"{finding.code} at {finding.line}:{finding.column}",
        classname=finding.path,
        file=finding.path,
        line=str(finding.line),
    )
    failure = ET.SubElement(case, "failure", message=f"{finding.code} {finding.message}", type=finding.code)
    failure.text = f"{finding.path}:{finding.line}:{finding.column}: {finding.code} [{finding.name}] {finding.message}"


def render(findings: Sequence[Finding], *, color: bool = False) -> str:
    root = ET.Element("testsuites", name="geolint", tests=str(max(len(findings), 1)), failures=str(len(findings)))
    if not findings:
        suite = ET.SubElement(root, "testsuite", name="geolint", tests="1", failures="0", errors="0", skipped="0")
        ET.SubElement(suite, "testcase", name="no findings", classname="geolint")
    by_path = groupby(sorted(findings, key=lambda f: (f.path, f.line, f.column, f.code)), key=lambda f: f.path)
    for path, group in by_path:
        file_findings = list(group)
        count = str(len(file_findings))
        suite = ET.SubElement(root, "testsuite", name=path, tests=count, failures=count, errors="0", skipped="0")
        for finding in file_findings:
            _testcase(suite, finding)
    ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"
