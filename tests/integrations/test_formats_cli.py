"""The CI formats on real findings: the real `geolint check --format ...` in a subprocess, over a
small project with bugs from every rule family. SARIF is validated against the vendored schema.
"""

from __future__ import annotations

import json
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import jsonschema
import pytest

from geolint import api
from tests.conftest import DECLARES_DST_FIRST

SCHEMA = json.loads((Path(__file__).parent / "data" / "sarif-schema-2.1.0.json").read_text(encoding="utf-8"))

SOURCES = {
    "perception.py": """\
def approach(T_world_base, T_base_wrist, T_object_grasp, p_cam, R_world_cam, normal_cam, t_world_cam):
    p_base = T_base_wrist @ p_cam
    T_world_grasp = T_world_base @ T_object_grasp
    normal_world = R_world_cam @ normal_cam + t_world_cam
    return p_base, T_world_grasp, normal_world
"""
    + DECLARES_DST_FIRST,
    "pkg/rotations.py": """\
from scipy.spatial.transform import Rotation


def orient(q):
    return Rotation.from_quat([q.w, q.x, q.y, q.z])


YAW = Rotation.from_euler("xyz", [0, 0, 90])
""",
    "pkg/clean.py": """\
def to_world(R_world_cam, normal_cam):
    return R_world_cam @ normal_cam
""",
}


@pytest.fixture(scope="module")
def project(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("project")
    for name, text in SOURCES.items():
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        (root / name).write_text(text, encoding="utf-8")
    return root


@pytest.fixture(scope="module")
def expected(project: Path) -> list[tuple[str, int, int, str]]:
    """(path, line, column, code) of every finding, from the API in this process."""
    found = []
    for name, text in SOURCES.items():
        found += [(name, f.line, f.column, f.code) for f in api.lint_text(text, name, api.find_config(project))]
    assert {code for *_, code in found} >= {"GEO101", "GEO201", "GEO202", "GEO301", "GEO302"}
    return sorted(found)


def check(project: Path, fmt: str) -> str:
    completed = subprocess.run(
        [sys.executable, "-m", "geolint", "check", "--no-cache", "--format", fmt, "."],
        cwd=project,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert completed.returncode == 1, completed.stderr  # findings -> exit 1, whatever the format
    return completed.stdout


def test_sarif_is_valid_and_complete(project: Path, expected: list[tuple[str, int, int, str]]) -> None:
    log = json.loads(check(project, "sarif"))
    jsonschema.Draft4Validator(SCHEMA).validate(log)
    run = log["runs"][0]
    rules = run["tool"]["driver"]["rules"]
    assert sorted(rule["id"] for rule in rules) == sorted({code for *_, code in expected})
    for rule in rules:
        assert rule["helpUri"] == api.rule_url(rule["id"])
        assert rule["shortDescription"]["text"] and rule["shortDescription"]["text"] != rule["name"]
    got = sorted(
        (
            result["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
            result["locations"][0]["physicalLocation"]["region"]["startLine"],
            result["locations"][0]["physicalLocation"]["region"]["startColumn"],
            result["ruleId"],
        )
        for result in run["results"]
    )
    assert got == expected
    assert all(rules[result["ruleIndex"]]["id"] == result["ruleId"] for result in run["results"])


def test_github_annotations_point_at_each_finding(project: Path, expected: list[tuple[str, int, int, str]]) -> None:
    lines = check(project, "github").splitlines()
    assert len(lines) == len(expected)
    for path, line, column, code in expected:
        assert any(
            entry.startswith(f"::error file={path},line={line},col={column},") and f"title={code} (" in entry
            for entry in lines
        ), (path, line, code)


def test_junit_is_xml_with_one_failure_per_finding(project: Path, expected: list[tuple[str, int, int, str]]) -> None:
    root = ET.fromstring(check(project, "junit").split("\n", 1)[1])
    failures = [
        (suite.get("name"), int(case.get("line")), case.find("failure").get("type"))
        for suite in root.iter("testsuite")
        for case in suite.iter("testcase")
    ]
    assert sorted(failures) == sorted((path, line, code) for path, line, _, code in expected)


def test_gitlab_report_has_unique_fingerprints(project: Path, expected: list[tuple[str, int, int, str]]) -> None:
    issues = json.loads(check(project, "gitlab"))
    assert sorted((i["location"]["path"], i["location"]["positions"]["begin"]["line"], i["check_name"]) for i in issues) == sorted(
        (path, line, code) for path, line, _, code in expected
    )
    assert len({issue["fingerprint"] for issue in issues}) == len(issues)
    assert all(issue["severity"] in {"info", "minor", "major", "critical", "blocker"} for issue in issues)
