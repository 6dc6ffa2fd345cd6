"""The linter and the mypy plugin judge a call from the same line of stubs/: flip the order a stub states
(in a copy read through GEOLINT_STUBS) and both layers flip with it."""

from __future__ import annotations

import importlib.metadata
import os
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from geolint.knowledge import stubs_folder

UNTYPED = """\
from scipy.spatial.transform import Rotation

def f(q_wxyz):
    return Rotation.from_quat(q_wxyz)
"""
TYPED = """\
from scipy.spatial.transform import Rotation
from geolint.typing import QuaternionWXYZ

def f(q: QuaternionWXYZ) -> None:
    Rotation.from_quat(q)
"""


def _flipped_stubs(tmp_path: Path) -> Path:
    """A copy of stubs/ in which scipy's from_quat reads w, x, y, z by default."""
    copy = tmp_path / "stubs"
    shutil.copytree(stubs_folder(), copy)
    stub = copy / "scipy" / "scipy" / "spatial" / "transform" / "_rotation.pyi"
    text = stub.read_text()
    first = "quat: Annotated[QuaternionXYZW, STACKED], *, scalar_first: Literal[False]"
    second = "quat: Annotated[QuaternionWXYZ, STACKED], *, scalar_first: Literal[True]"
    assert first in text and second in text
    stub.write_text(text.replace(first, "@@1").replace(second, "@@2").replace("@@1", first.replace("XYZW", "WXYZ")).replace("@@2", second.replace("WXYZ", "XYZW")))
    return copy


def _run(args: list[str], cwd: Path, stubs: Path | None) -> str:
    env = {**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parents[2])}
    env.pop("GEOLINT_STUBS", None)
    if stubs is not None:
        env["GEOLINT_STUBS"] = str(stubs)
    done = subprocess.run([sys.executable, *args], cwd=cwd, capture_output=True, text=True, env=env, timeout=600)
    return done.stdout + done.stderr


def test_the_linter_reads_the_stub(tmp_path: Path) -> None:
    (tmp_path / "node.py").write_text(UNTYPED)
    shipped = _run(["-m", "geolint", "check", "--select", "GEO301", "--no-cache", "node.py"], tmp_path, None)
    flipped = _run(["-m", "geolint", "check", "--select", "GEO301", "--no-cache", "node.py"], tmp_path, _flipped_stubs(tmp_path))
    assert "GEO301" in shipped, shipped
    assert "GEO301" not in flipped, flipped


def _installed(distribution: str) -> bool:
    try:
        importlib.metadata.distribution(distribution)
    except importlib.metadata.PackageNotFoundError:
        return False
    return True


@pytest.mark.slow  # two real mypy runs
@pytest.mark.skipif(not _installed("scipy-stubs"), reason="scipy-stubs is not installed")
def test_the_plugin_reads_the_same_stub(tmp_path: Path) -> None:
    (tmp_path / "typed.py").write_text(TYPED)
    (tmp_path / "mypy.ini").write_text(textwrap.dedent("[mypy]\nplugins = geolint.mypy\n"))
    args = ["-m", "mypy", "--no-incremental", "--config-file", "mypy.ini", "typed.py"]
    shipped = _run(args, tmp_path, None)
    flipped = _run(args, tmp_path, _flipped_stubs(tmp_path))
    assert "[geo-quaternion-order]" in shipped, shipped
    assert "[geo-quaternion-order]" not in flipped and "Success" in flipped, flipped
