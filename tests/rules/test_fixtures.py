"""bugbear-style fixtures: realistic files whose offending lines carry `# expect: CODE:COLUMN`.

Comment syntax: `# expect: GEO101:16` (several allowed: `# expect: GEO101:16 GEO203:5`),
on the line where the finding starts; the column is 1-based. Every fixture under `fixtures/`
named `GEO*.py` must produce exactly its annotated findings of GEO1xx-GEO3xx, the clean
fixtures none, and the demo findings from every rule family. All through the real CLI.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
from collections import Counter
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
FIXTURES = ROOT / "fixtures"
EXPECT = re.compile(r"#\s*expect:\s*((?:GEO\d{3}:\d+[\s,]*)+)")
# `fixtures/ros/<workspace>/src/<package>/...`: ROS workspaces of several packages, whose files make one
# tf tree (GEO211-GEO214 judge a node against the workspace's launch files and URDF)
ANNOTATED = sorted([*FIXTURES.glob("GEO*.py"), *(FIXTURES / "ros").rglob("GEO*.py")])
CLEAN = sorted((FIXTURES / "clean").rglob("*.py"))
DEMO = FIXTURES / "demo"


def expectations(path: Path) -> set[tuple[int, int, str]]:
    expected = set()
    for number, line in enumerate(path.read_text().splitlines(), start=1):
        match = EXPECT.search(line)
        if match:
            for item in re.findall(r"GEO\d{3}:\d+", match.group(1)):
                code, column = item.split(":")
                expected.add((number, int(column), code))
    return expected


@pytest.fixture(scope="module")
def cli_findings() -> dict[str, list[dict]]:
    """One real `geolint check --format json` run over every fixture, grouped by path."""
    paths = [str(path.relative_to(ROOT)) for path in [*ANNOTATED, *CLEAN]] + [str(DEMO.relative_to(ROOT))]
    result = subprocess.run(
        [
            sys.executable, "-m", "geolint", "check", "--format", "json", "--no-cache", "--select", "GEO1,GEO2,GEO3,GEO103",
            "--config", str(FIXTURES / "stated_naming.toml"), *paths,
        ],  # fmt: skip
        cwd=ROOT,
        capture_output=True,
        text=True,
    )
    assert result.returncode in (0, 1), result.stderr
    grouped: dict[str, list[dict]] = {}
    for finding in json.loads(result.stdout):
        grouped.setdefault(Path(finding["path"]).as_posix(), []).append(finding)
    return grouped


def test_every_rule_has_a_fixture() -> None:
    from geolint.rules import all_rules

    codes = {rule.code for rule in all_rules() if rule.code[3] in "123"}
    assert codes <= {path.stem.split("_")[0] for path in ANNOTATED}
    for path in ANNOTATED:
        # `GEO301_isaac.py`: a second fixture of GEO301, for code whose imports would change the first's meaning
        assert any(code == path.stem.split("_")[0] for _, _, code in expectations(path)), f"{path.name} expects none of its own rule"


@pytest.mark.parametrize("path", ANNOTATED, ids=lambda path: path.name)
def test_annotated_fixture(path: Path, cli_findings: dict[str, list[dict]]) -> None:
    found = {(f["line"], f["column"], f["code"]) for f in cli_findings.get(path.relative_to(ROOT).as_posix(), [])}
    assert found == expectations(path)


@pytest.mark.parametrize("path", CLEAN, ids=lambda path: path.name)
def test_clean_fixture_is_silent(path: Path, cli_findings: dict[str, list[dict]]) -> None:
    assert cli_findings.get(path.relative_to(ROOT).as_posix(), []) == []


def test_demo_shows_bugs_of_every_family(cli_findings: dict[str, list[dict]]) -> None:
    demo = [f for path, found in cli_findings.items() if path.startswith("fixtures/demo/") for f in found]
    families = Counter(f["code"][:4] for f in demo)
    assert set(families) == {"GEO1", "GEO2", "GEO3"}, families
    assert len(demo) >= 6


PROJECTS = sorted(path for path in (FIXTURES / "projects").iterdir() if path.is_dir())


@pytest.mark.parametrize("project", PROJECTS, ids=lambda path: path.name)
def test_project_fixture(project: Path) -> None:
    """A multi-module project, linted on its own (its own config and naming order): exactly its annotations."""
    result = subprocess.run(
        [sys.executable, "-m", "geolint", "check", "--format", "json", "--no-cache", "--select", "GEO1,GEO2,GEO3", "."],
        cwd=project,
        capture_output=True,
        text=True,
    )
    assert result.returncode in (0, 1), result.stderr
    found = {(Path(f["path"]).as_posix(), f["line"], f["column"], f["code"]) for f in json.loads(result.stdout)}
    expected = {
        (path.relative_to(project).as_posix(), line, column, code)
        for path in sorted(project.rglob("*.py"))
        for line, column, code in expectations(path)
    }
    assert found == expected
