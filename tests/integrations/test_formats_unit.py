"""The CI output formats on hand-built findings: escaping, schema validity, grouping, fingerprints.

`test_formats_cli.py` runs the same formats through the real `geolint check` on real findings.
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import jsonschema
import pytest

from geolint.lint_types import Edit, Finding, Fix, Severity
from geolint.output import render

SCHEMA = json.loads((Path(__file__).parent / "data" / "sarif-schema-2.1.0.json").read_text(encoding="utf-8"))


def finding(code: str = "GEO101", line: int = 3, message: str = "normal moved by a 4x4, use R", **kw: object) -> Finding:
    values: dict = dict(
        path="pkg/robot.py", line=line, column=5, end_line=line, end_column=17, code=code,
        name="direction-translated", message=message, severity=Severity.ERROR, fix=None,
    )
    values.update(kw)
    return Finding(**values)


FIXABLE = finding(
    "GEO301", 8, "quaternion order", severity=Severity.WARNING, name="quat-order",
    fix=Fix("safe", (Edit(8, 5, 8, 17, "q[[3, 0, 1, 2]]"),), "reorder to xyzw"),
)


def test_github_escapes_commas_colons_and_newlines_in_properties_and_message() -> None:
    odd = finding(path="dir,x/a:b.py", message="line one\nline two 100%")
    (line,) = render([odd], "github").splitlines()
    assert line.startswith("::error file=dir%2Cx/a%3Ab.py,line=3,col=5,endLine=3,endColumn=17,")
    assert "title=GEO101 (direction-translated)::" in line
    assert line.endswith("::GEO101 line one%0Aline two 100%25")


def test_github_maps_severities_to_annotation_levels() -> None:
    lines = render([finding(), FIXABLE, finding(severity=Severity.INFO)], "github").splitlines()
    assert [line.split(" ")[0] for line in lines] == ["::error", "::warning", "::notice"]


def test_sarif_validates_and_has_one_rule_per_code() -> None:
    findings = [finding(line=3), finding(line=9), FIXABLE, finding(path="/abs/other.py")]
    log = json.loads(render(findings, "sarif"))
    jsonschema.Draft4Validator(SCHEMA).validate(log)
    run = log["runs"][0]
    assert [rule["id"] for rule in run["tool"]["driver"]["rules"]] == ["GEO101", "GEO301"]
    assert all(rule["helpUri"].endswith(rule["id"].lower()) for rule in run["tool"]["driver"]["rules"])
    assert len(run["results"]) == 4
    for result in run["results"]:
        assert run["tool"]["driver"]["rules"][result["ruleIndex"]]["id"] == result["ruleId"]
    region = run["results"][1]["locations"][0]["physicalLocation"]["region"]
    assert region == {"startLine": 9, "startColumn": 5, "endLine": 9, "endColumn": 17}
    assert run["results"][3]["locations"][0]["physicalLocation"]["artifactLocation"] == {"uri": "file:///abs/other.py"}
    (fix,) = run["results"][2]["fixes"]
    assert fix["artifactChanges"][0]["replacements"][0]["insertedContent"]["text"] == "q[[3, 0, 1, 2]]"


def test_sarif_with_no_findings_is_still_a_valid_log() -> None:
    log = json.loads(render([], "sarif"))
    jsonschema.Draft4Validator(SCHEMA).validate(log)
    assert log["runs"][0]["results"] == []


def test_schema_rejects_a_broken_log() -> None:
    # Guards the guard: the vendored schema really constrains results.
    log = json.loads(render([finding()], "sarif"))
    log["runs"][0]["results"][0]["level"] = "fatal"
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.Draft4Validator(SCHEMA).validate(log)


def test_junit_groups_by_file_and_fails_each_finding() -> None:
    xml = render([finding(), FIXABLE, finding(path="b.py")], "junit")
    root = ET.fromstring(xml.split("\n", 1)[1])
    suites = {suite.get("name"): suite for suite in root.iter("testsuite")}
    assert set(suites) == {"pkg/robot.py", "b.py"}
    assert suites["pkg/robot.py"].get("failures") == "2"
    failure_types = [case.find("failure").get("type") for case in suites["pkg/robot.py"].iter("testcase")]
    assert failure_types == ["GEO101", "GEO301"]
    assert root.get("failures") == "3"


def test_junit_without_findings_has_one_passing_case() -> None:
    root = ET.fromstring(render([], "junit").split("\n", 1)[1])
    cases = list(root.iter("testcase"))
    assert len(cases) == 1 and cases[0].find("failure") is None


def test_gitlab_fingerprint_ignores_line_but_separates_duplicates() -> None:
    here = json.loads(render([finding(line=3)], "gitlab"))
    moved = json.loads(render([finding(line=30)], "gitlab"))
    assert here[0]["fingerprint"] == moved[0]["fingerprint"]
    twice = json.loads(render([finding(line=3), finding(line=7)], "gitlab"))
    assert len({issue["fingerprint"] for issue in twice}) == 2
    other = json.loads(render([finding(message="another")], "gitlab"))
    assert other[0]["fingerprint"] != here[0]["fingerprint"]
    assert here[0]["location"] == {"path": "pkg/robot.py", "positions": {"begin": {"line": 3, "column": 5}, "end": {"line": 3, "column": 17}}}
    assert here[0]["severity"] == "major" and here[0]["check_name"] == "GEO101"
