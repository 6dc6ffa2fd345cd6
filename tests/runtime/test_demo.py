"""The runnable runtime demo (fixtures/runtime_demo.py) runs and shows the bug and the refusals."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import geolint

DEMO = Path(geolint.__file__).resolve().parent.parent / "fixtures" / "runtime_demo.py"


def test_runtime_demo_runs_and_shows_the_translated_normal() -> None:
    result = subprocess.run([sys.executable, str(DEMO)], capture_output=True, text=True, timeout=120, check=True)
    out = result.stdout
    assert "grasp point : Point[Base]([0.3, 0.3, 0.5])" in out
    assert "normal      : Direction[Base]([0.0, 1.0, 0.0]) length 1.00" in out
    assert "buggy normal: [0.3 1.1 0.5] length 1.24" in out
    assert "translation 5.0 m: mean normal length correct 1.000, full 4x4 5.050" in out
    for error in ("FrameMismatchError", "GeometryTypeError", "InvalidRotationError", "UnknownFrameError"):
        assert error in out
