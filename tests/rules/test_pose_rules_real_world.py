"""The pose rules (GEO105, GEO205, GEO206, GEO303), GEO106, GEO107, GEO207 and GEO208 add no finding on installed real code.

These rules judge the algebra itself (a rotation inverted while its translation is not, a 3x3
indexed as a 4x4, a translation in the homogeneous row, a caller's transform rewritten), so a
finding on a mature geometry library would be a false positive: the contract is zero. The
real-code corpus findings and their verdicts live in the real-code benchmark's ledger.
"""

from __future__ import annotations

import json
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

SITE = Path(sysconfig.get_paths()["purelib"])
PACKAGES = ("numpy", "scipy", "trimesh", "pytransform3d", "spatialmath", "matplotlib", "mpl_toolkits", "PIL")
CODES = "GEO105,GEO106,GEO107,GEO205,GEO206,GEO207,GEO208,GEO303"


def findings_on(paths: list[Path]) -> list[dict]:
    present = [path for path in paths if path.exists()]
    if not present:
        pytest.skip("none of the packages is installed")
    result = subprocess.run(
        [sys.executable, "-m", "geolint", "check", "--select", CODES, "--format", "json", "--no-cache", *map(str, present)],
        capture_output=True,
        text=True,
    )
    assert result.returncode in (0, 1), result.stderr
    assert "Traceback" not in result.stderr, result.stderr
    return json.loads(result.stdout)


@pytest.mark.slow
def test_no_finding_on_installed_geometry_and_numeric_packages() -> None:
    assert findings_on([SITE / package for package in PACKAGES]) == []


def test_no_finding_on_trimesh_quickly() -> None:
    """The non-slow guard: trimesh builds many 4x4 matrices by hand, some of them projective."""
    assert findings_on([SITE / "trimesh"]) == []
