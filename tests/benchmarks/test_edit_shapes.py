"""The blind history search for fix-shaped edits (benchmarks/real_code/edit_shapes.py), on a tiny
repository made here with git, run as a subprocess the way the search is run: it never runs geolint."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.benchmarks.test_real_code_runner import commit_file, git

SEARCH = Path(__file__).resolve().parents[2] / "benchmarks" / "real_code" / "edit_shapes.py"

pytestmark = pytest.mark.skipif(shutil.which("git") is None, reason="needs git")

FIRST = """\
import numpy as np


def to_camera(points, c2w, yaw_deg):
    points_cam = points @ c2w[:3, :3] + c2w[:3, 3]
    pad = np.zeros((len(points), 1))
    R = rotation(yaw_deg)
    label = "camera frame"
    return points_cam, pad, R, label
"""


def test_fix_shaped_edits_are_candidates_and_other_edits_are_not(tmp_path: Path) -> None:
    mirror = tmp_path / "mirror"
    repo = mirror / "someone+nerf-demo"
    repo.mkdir(parents=True)
    git(repo, "init", "-q")
    commit_file(repo, FIRST, "first")
    swapped = commit_file(repo, FIRST.replace("c2w[:3, :3] + c2w[:3, 3]", "w2c[:3, :3] + w2c[:3, 3]"), "use w2c")
    text = FIRST.replace("c2w[:3, :3] + c2w[:3, 3]", "w2c[:3, :3] + w2c[:3, 3]")
    padded = commit_file(repo, text.replace("np.zeros((len(points), 1))", "np.ones((len(points), 1))"), "pad")
    converted = commit_file(repo, text.replace("np.zeros", "np.ones").replace("rotation(yaw_deg)", "rotation(np.deg2rad(yaw_deg))"), "radians")
    final = text.replace("np.zeros", "np.ones").replace("rotation(yaw_deg)", "rotation(np.deg2rad(yaw_deg))")
    reworded = commit_file(repo, final.replace('"camera frame"', '"the camera frame"'), "wording")
    (tmp_path / "manifest.toml").write_text(
        '[[repo]]\nname = "someone/nerf-demo"\nurl = "https://example.invalid/nerf-demo"\n'
        f'commit = "{reworded}"\ncategory = "nerf"\ntorch = false\n'
    )
    out = tmp_path / "candidates.json"
    result = subprocess.run(
        [sys.executable, str(SEARCH), str(mirror), "--manifest", str(tmp_path / "manifest.toml"), "--out", str(out)],
        capture_output=True, text=True, check=True,
    )  # fmt: skip
    found = {(item["commit"], tuple(item["shapes"])) for item in json.loads(out.read_text())}
    assert found == {(swapped, ("c2w/w2c",)), (padded, ("zeros/ones",)), (converted, ("degrees",))}
    assert "3 candidates to read" in result.stdout

    # commits already searched (the first 45 repositories' history, shared by a fork) are left out
    (tmp_path / "seen.txt").write_text(f"{swapped}\n{padded}\n")
    subprocess.run(
        [sys.executable, str(SEARCH), str(mirror), "--manifest", str(tmp_path / "manifest.toml"), "--out", str(out),
         "--skip-commits", str(tmp_path / "seen.txt")],
        capture_output=True, text=True, check=True,
    )  # fmt: skip
    assert [item["commit"] for item in json.loads(out.read_text())] == [converted]
