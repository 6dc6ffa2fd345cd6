"""The real-code benchmark runner on a tiny repository made here with git (no download).

Runs benchmarks/real_code/run.py as a subprocess, the way the benchmark is run: ledger matching by
the flagged expression survives a line shift, new and gone findings are counted, and --history
finds a commit that fixed a bug.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

RUNNER = Path(__file__).resolve().parents[2] / "benchmarks" / "real_code" / "run.py"

pytestmark = pytest.mark.skipif(shutil.which("git") is None, reason="needs git")

BUGGY = """\
import numpy as np


def grasp_in_world(T_world_base, T_cam_tool, p_cam):
    T_world_tool = T_world_base @ T_cam_tool
    return T_world_tool


def world_base(R, t):
    from autolab_core import RigidTransform

    # a declaration bound to a `T_a_b` name: the project states its order, so names are evidence
    T_world_base = RigidTransform(R, t, from_frame="base", to_frame="world")
    return T_world_base
"""

FIXED = BUGGY.replace("T_world_base @ T_cam_tool", "T_world_base @ T_base_cam @ T_cam_tool").replace(
    "T_world_base, T_cam_tool", "T_world_base, T_base_cam, T_cam_tool"
)


def git(repo: Path, *arguments: str) -> str:
    return subprocess.run(
        ["git", "-C", str(repo), "-c", "user.name=t", "-c", "user.email=t@t", *arguments],
        check=True,
        capture_output=True,
        text=True,
    ).stdout


def commit_file(repo: Path, text: str, message: str) -> str:
    (repo / "planner.py").write_text(text)
    git(repo, "add", "planner.py")
    git(repo, "commit", "-q", "-m", message)
    return git(repo, "rev-parse", "HEAD").strip()


@pytest.fixture
def mirror(tmp_path: Path) -> Path:
    mirror = tmp_path / "mirror"
    repo = mirror / "someone+grasp-demo"
    repo.mkdir(parents=True)
    git(repo, "init", "-q")
    commit = commit_file(repo, BUGGY, "first")
    (tmp_path / "manifest.toml").write_text(
        f'[[repo]]\nname = "someone/grasp-demo"\nurl = "https://example.invalid/grasp-demo"\n'
        f'commit = "{commit}"\ncategory = "grasping"\ntorch = false\n'
    )
    return mirror


def run(tmp_path: Path, mirror: Path, *extra: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, str(RUNNER), str(mirror), "--manifest", str(tmp_path / "manifest.toml"),
         "--ledger", str(tmp_path / "ledger.toml"), "--jobs", "1", *extra],
        capture_output=True,
        text=True,
        timeout=300,
    )


def counts(output: str) -> dict[str, int]:
    """The per-repository row: files, lines, findings, TP, FP, unclear, new, gone."""
    row = next(line for line in output.splitlines() if line.startswith("someone/grasp-demo"))
    numbers = [int(n) for n in row.split()[1:9]]
    return dict(zip(["files", "lines", "findings", "TP", "FP", "unclear", "new", "gone"], numbers))


def set_verdict(ledger: Path, verdict: str) -> None:
    text = ledger.read_text()
    ledger.write_text(re.sub(r'verdict = "[^"]*"', f'verdict = "{verdict}"', text))


def test_ledger_matches_after_a_line_shift_and_counts_new_and_gone(tmp_path: Path, mirror: Path) -> None:
    first = run(tmp_path, mirror, "--record-new")
    assert first.returncode == 0, first.stderr
    assert counts(first.stdout)["new"] == 1
    ledger = tmp_path / "ledger.toml"
    assert 'code = "GEO202"' in ledger.read_text()
    set_verdict(ledger, "TP")

    # Three lines inserted above: the finding moves from line 5 to line 8 and still matches.
    shifted = BUGGY.replace("import numpy as np\n", "import numpy as np\nimport os\nimport sys\n\n", 1)
    (mirror / "someone+grasp-demo" / "planner.py").write_text(shifted)
    second = run(tmp_path, mirror)
    assert second.returncode == 0, second.stderr
    assert counts(second.stdout) | {"lines": 0} == {
        "files": 1, "lines": 0, "findings": 1, "TP": 1, "FP": 0, "unclear": 0, "new": 0, "gone": 0
    }
    assert "precision TP / (TP + FP) = 1 / 1 = 100.0 %" in second.stdout

    # A different composition bug appears and the recorded one is fixed: one new, one gone.
    other = FIXED + "\n\ndef other(T_world_base, T_cam_gripper):\n    T_world_gripper = T_world_base @ T_cam_gripper\n    return T_world_gripper\n"
    (mirror / "someone+grasp-demo" / "planner.py").write_text(other)
    third = run(tmp_path, mirror)
    assert third.returncode == 0, third.stderr
    row = counts(third.stdout)
    assert (row["findings"], row["TP"], row["new"], row["gone"]) == (1, 0, 1, 1)
    assert "NEW someone/grasp-demo:planner.py:" in third.stdout
    assert "GONE someone/grasp-demo:planner.py:5: GEO202 (TP)" in third.stdout


def test_history_mode_finds_the_commit_that_fixed_a_bug(tmp_path: Path, mirror: Path) -> None:
    repo = mirror / "someone+grasp-demo"
    fix = commit_file(repo, FIXED, "compose through the base frame")
    # A later commit that touches geometry but fixes nothing must not be a candidate.
    commit_file(repo, FIXED.replace("return T_world_tool", "return T_world_tool.copy()"), "copy")
    done = run(tmp_path, mirror, "--history", "--candidates-out", str(tmp_path / "candidates.json"))
    assert done.returncode == 0, done.stderr
    assert f"candidate someone/grasp-demo@{fix[:10]} planner.py:5 GEO202" in done.stdout
    assert "1 finding(s) removed by a commit" in done.stdout

    # Recorded as a historical bug (wrongly marked missed), it is re-checked at the commit before the fix.
    (tmp_path / "ledger.toml").write_text(
        f'[[history]]\nrepo = "someone/grasp-demo"\nfix_commit = "{fix}"\npath = "planner.py"\nline = 5\n'
        'bug_class = "frames (GEO202)"\ncaught = false\nhow_found = "lint-diff"\nreason = "planted"\n'
        'issue = ""\nexpr_hash = ""\n'
    )
    checked = run(tmp_path, mirror, "--history", "--history-limit", "0", "--record-new")
    assert checked.returncode == 0, checked.stderr
    assert "CAUGHT" in checked.stdout and "(ledger says missed)" in checked.stdout
    assert "caught at the pre-fix commit: 1 / 1 = 100 %" in checked.stdout
    assert "caught = true" in (tmp_path / "ledger.toml").read_text()


def test_history_rows_are_linted_with_the_sibling_modules_of_their_commit(tmp_path: Path, mirror: Path) -> None:
    """A bug seen only through a helper of another module (its summary translates its argument) is caught,
    as the real CLI catches it in an exported tree: the helper is read as it was before the fix."""
    repo = mirror / "someone+grasp-demo"
    (repo / "posekit.py").write_text("def apply_pose(T, x):\n    return T[:3, :3] @ x + T[:3, 3]\n")
    git(repo, "add", "posekit.py")
    caller = "from posekit import apply_pose\n\n\ndef mesh_in_world(T, mesh):\n    return apply_pose(T, mesh.vertices), apply_pose(T, mesh.face_normals)\n"
    commit_file(repo, caller, "normals")
    fix = commit_file(repo, caller.replace("apply_pose(T, mesh.face_normals)", "T[:3, :3] @ mesh.face_normals.T"), "rotate only")
    git(repo, "rm", "-q", "posekit.py")  # the helper is gone after the fix: only the pre-fix tree has it
    git(repo, "commit", "-q", "-m", "drop the helper")
    (tmp_path / "ledger.toml").write_text(
        f'[[history]]\nrepo = "someone/grasp-demo"\nfix_commit = "{fix}"\npath = "planner.py"\nline = 5\n'
        'bug_class = "direction translated (GEO101)"\ncaught = false\nhow_found = "planted"\nreason = "planted"\n'
        'issue = ""\nexpr_hash = ""\n'
    )
    checked = run(tmp_path, mirror, "--history", "--history-limit", "0")
    assert checked.returncode == 0, checked.stderr
    assert "GEO101 `apply_pose` rotates and translates" in checked.stdout
    assert "caught at the pre-fix commit: 1 / 1 = 100 %" in checked.stdout


def test_a_missing_checkout_is_an_error_not_a_crash(tmp_path: Path, mirror: Path) -> None:
    shutil.rmtree(mirror / "someone+grasp-demo")
    done = run(tmp_path, mirror)
    assert done.returncode == 2
    assert "someone/grasp-demo: no checkout at" in done.stderr


def test_reformatting_does_not_change_the_expression_key() -> None:
    import importlib.util

    spec = importlib.util.spec_from_file_location("real_code_run", RUNNER)
    assert spec is not None and spec.loader is not None
    runner = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = runner  # dataclasses look their module up there
    spec.loader.exec_module(runner)
    before = ["T = RigidTransform(R, from_frame='obj', to_frame='world')"]
    after = ["T = RigidTransform(", "    R,", '    from_frame="obj",', '    to_frame="world",', ")"]
    old = runner.normalised_expression(before, 1, 5, 1, len(before[0]) + 1)
    new = runner.normalised_expression(after, 1, 5, 5, 2)
    assert old == new == 'RigidTransform(R,from_frame="obj",to_frame="world")'
    # A real change of the expression still changes the key.
    assert runner.normalised_expression(["T = RigidTransform(R, from_frame='world')"], 1, 5, 1, 42) != old


def test_checkouts_are_made_from_mirrors_at_the_pinned_commit(tmp_path):
    """checkouts.py: a clone per manifest row with its history, at the manifest's commit (not the
    mirror's newest); a row without a mirror is reported and the others are still made."""
    mirror = tmp_path / "mirrors" / "lab+planner" / "repo"
    mirror.mkdir(parents=True)
    git(mirror, "init", "-q")
    pinned = commit_file(mirror, BUGGY, "buggy")
    commit_file(mirror, FIXED, "fixed")
    manifest = tmp_path / "manifest.toml"
    row = 'name = "{}"\nurl = "https://example.invalid"\ncommit = "{}"\ncategory = "grasping"\ntorch = false\n'
    manifest.write_text("[[repo]]\n" + row.format("lab/planner", pinned) + "\n[[repo]]\n" + row.format("lab/absent", pinned))
    done = subprocess.run(
        [sys.executable, str(RUNNER.with_name("checkouts.py")), str(tmp_path / "mirrors"), str(tmp_path / "out"), "--manifest", str(manifest)],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 1 and "FAILED lab/absent: no mirror" in done.stderr
    checkout = tmp_path / "out" / "lab+planner"
    assert git(checkout, "rev-parse", "HEAD").strip() == pinned
    assert (checkout / "planner.py").read_text() == BUGGY
    assert len(git(checkout, "log", "--all", "--oneline").splitlines()) == 2  # the fix is still in reach of --history
