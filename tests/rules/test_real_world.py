"""geolint over the installed sources of real geometry packages, through the real CLI.

No crash, and the findings are exactly the ones documented (with verdicts) in
docs/real-world.md, so a new false positive fails here and must be fixed in the rule.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SITE = Path(sysconfig.get_paths()["purelib"])
PACKAGES = ("pytransform3d", "spatialmath", "trimesh", "scipy/spatial", "numpy")


def documented_findings() -> set[tuple[str, int, str]]:
    text = (ROOT / "docs" / "real-world.md").read_text()
    block = re.search(r"<!-- findings:start -->(.*?)<!-- findings:end -->", text, flags=re.DOTALL)
    assert block is not None, "docs/real-world.md lost its findings markers"
    found = set()
    for line in block.group(1).strip().splitlines():
        path, number, code = line.strip().rsplit(":", 2)
        found.add((path, int(number), code))
    return found


def run_geolint(paths: list[Path]) -> set[tuple[str, int, str]]:
    missing = [path for path in paths if not path.exists()]
    if missing:
        pytest.skip(f"not installed: {missing}")
    result = subprocess.run(
        [sys.executable, "-m", "geolint", "check", "--format", "json", "--no-cache", "--select", "GEO1,GEO2,GEO3",
         *map(str, paths)],
        cwd=SITE,
        capture_output=True,
        text=True,
    )  # fmt: skip
    assert result.returncode in (0, 1), f"geolint failed (exit {result.returncode}):\n{result.stderr}"
    assert "Traceback" not in result.stderr, result.stderr
    return {
        (Path(finding["path"]).resolve().relative_to(SITE).as_posix(), finding["line"], finding["code"])
        for finding in json.loads(result.stdout)
    }


@pytest.mark.slow
def test_findings_on_real_packages_are_exactly_the_documented_ones() -> None:
    found = run_geolint([SITE / package for package in PACKAGES])
    assert found == documented_findings()


def test_pytransform3d_quickly() -> None:
    """The non-slow guard: one real geometry package, same contract."""
    found = run_geolint([SITE / "pytransform3d"])
    assert found == {item for item in documented_findings() if item[0].startswith("pytransform3d/")}
