"""The pre-commit hooks, run by the real `pre-commit try-repo` against this checkout's HEAD.

pre-commit builds the hook environment from the repository with pip (the package and the
hook's additional_dependencies, from the package index), so this test needs the index but
no other network. Two environment builds: roughly a minute together.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from geolint import api

REPO_ROOT = Path(__file__).resolve().parents[2]

BUGGY = """\
def normal_to_world(R_world_cam, t_world_cam, normal_cam):
    return R_world_cam @ normal_cam + t_world_cam
"""
CLEAN = """\
def normal_to_world(R_world_cam, normal_cam):
    return R_world_cam @ normal_cam
"""


def git(*args: str, cwd: Path) -> str:
    return subprocess.run(["git", *args], cwd=cwd, check=True, capture_output=True, text=True).stdout.strip()


@pytest.fixture(scope="module")
def head() -> str:
    try:
        return git("rev-parse", "HEAD", cwd=REPO_ROOT)
    except (subprocess.CalledProcessError, FileNotFoundError):
        pytest.skip("not a git checkout: pre-commit try-repo needs one")


def try_repo(project: Path, head: str, *files: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "pre_commit", "try-repo", str(REPO_ROOT), "--ref", head, "--color", "never", "--files", *files],
        cwd=project,
        capture_output=True,
        text=True,
        timeout=600,
    )


def test_manifest_is_valid() -> None:
    completed = subprocess.run(
        [sys.executable, "-m", "pre_commit", "validate-manifest", str(REPO_ROOT / ".pre-commit-hooks.yaml")],
        capture_output=True,
        text=True,
    )
    assert completed.returncode == 0, completed.stdout + completed.stderr


@pytest.mark.slow  # two hook environments built by pip: a minute or two
def test_hooks_fail_on_the_buggy_file_fix_it_and_pass_on_the_clean_one(tmp_path: Path, head: str) -> None:
    project = tmp_path / "project"
    project.mkdir()
    git("init", "-q", cwd=project)
    (project / "buggy.py").write_text(BUGGY, encoding="utf-8")
    (project / "clean.py").write_text(CLEAN, encoding="utf-8")
    # An excluded folder stays excluded even though pre-commit names its files.
    (project / "pyproject.toml").write_text('[tool.geolint]\nexclude = ["generated/"]\n', encoding="utf-8")
    (project / "generated").mkdir()
    (project / "generated" / "made.py").write_text(BUGGY, encoding="utf-8")
    git("add", "buggy.py", "clean.py", "pyproject.toml", "generated/made.py", cwd=project)

    both = try_repo(project, head, "buggy.py", "clean.py", "generated/made.py")
    output = both.stdout + both.stderr
    assert both.returncode == 1, output
    check_section = output.split("- hook id: geolint\n", 1)[1].split("- hook id: geolint-fix", 1)[0]
    assert re.search(r"buggy\.py:2:\d+: GEO101 ", check_section), output
    assert "clean.py" not in check_section and "made.py" not in check_section
    assert "files were modified by this hook" in output  # geolint-fix fixed buggy.py
    fixed = (project / "buggy.py").read_text(encoding="utf-8")
    assert fixed != BUGGY and [f.code for f in api.lint_text(fixed, "buggy.py")] == []
    assert (project / "clean.py").read_text(encoding="utf-8") == CLEAN
    assert (project / "generated" / "made.py").read_text(encoding="utf-8") == BUGGY

    clean = try_repo(project, head, "clean.py")
    assert clean.returncode == 0, clean.stdout + clean.stderr
    assert len(re.findall(r"^geolint.*Passed$", clean.stdout, flags=re.M)) == 2, clean.stdout
