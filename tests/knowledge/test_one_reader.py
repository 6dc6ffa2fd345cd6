"""The linter and the mypy plugin judge a call from the same line of stubs/: flip what a stub states (in a
copy read through GEOLINT_STUBS) and both layers flip with it: scipy's quaternion order, trimesh's
translating `transform_points`."""

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


def _linted_twice(tmp_path: Path, source: str, code: str, edited: Path) -> tuple[str, str]:
    """`geolint check --select code` on `source`, with the shipped stubs and with `edited`."""
    (tmp_path / "node.py").write_text(source)
    args = ["-m", "geolint", "check", "--select", code, "--no-cache", "node.py"]
    return _run(args, tmp_path, None), _run(args, tmp_path, edited)


def _checked_twice(tmp_path: Path, source: str, edited: Path) -> tuple[str, str]:
    """mypy with the plugin on `source`, with the shipped stubs and with `edited`."""
    (tmp_path / "typed.py").write_text(source)
    (tmp_path / "mypy.ini").write_text(textwrap.dedent("[mypy]\nplugins = geolint.mypy\n"))
    args = ["-m", "mypy", "--no-incremental", "--config-file", "mypy.ini", "typed.py"]
    return _run(args, tmp_path, None), _run(args, tmp_path, edited)


def test_the_linter_reads_the_stub(tmp_path: Path) -> None:
    shipped, flipped = _linted_twice(tmp_path, UNTYPED, "GEO301", _flipped_stubs(tmp_path))
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
    shipped, flipped = _checked_twice(tmp_path, TYPED, _flipped_stubs(tmp_path))
    assert "[geo-quaternion-order]" in shipped, shipped
    assert "[geo-quaternion-order]" not in flipped and "Success" in flipped, flipped


MOVING_UNTYPED = """\
import trimesh

def f(normals, T):
    return trimesh.transform_points(normals, T)
"""
MOVING_TYPED = """\
import trimesh
from geolint.typing import TransformMatrix, VectorArray

def f(normals: VectorArray, T: TransformMatrix) -> None:
    trimesh.transform_points(normals, T)
"""


def _stubs_where_transform_points_rotates_by_default(tmp_path: Path) -> Path:
    """A copy of stubs/ in which trimesh's transform_points moves a vector unless told `translate=False`."""
    copy = tmp_path / "stubs"
    shutil.copytree(stubs_folder(), copy)
    stub = copy / "trimesh" / "trimesh" / "transformations.pyi"
    text = stub.read_text()
    assert text.count("PointArray[Src]") == 1 and text.count("VectorArray[Src]") == 1
    stub.write_text(text.replace("PointArray[", "@@[").replace("VectorArray[", "PointArray[").replace("@@[", "VectorArray["))
    return copy


def test_the_linter_reads_the_moving_stub(tmp_path: Path) -> None:
    shipped, flipped = _linted_twice(tmp_path, MOVING_UNTYPED, "GEO101", _stubs_where_transform_points_rotates_by_default(tmp_path))
    assert "GEO101" in shipped, shipped
    assert "GEO101" not in flipped, flipped


@pytest.mark.slow  # two real mypy runs
@pytest.mark.skipif(not _installed("trimesh"), reason="trimesh is not installed")
def test_the_plugin_reads_the_same_moving_stub(tmp_path: Path) -> None:
    shipped, flipped = _checked_twice(tmp_path, MOVING_TYPED, _stubs_where_transform_points_rotates_by_default(tmp_path))
    assert "[geo-translation]" in shipped, shipped
    assert "[geo-translation]" not in flipped, flipped


def test_the_plugin_cache_key_follows_the_stubs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """mypy's cache is keyed by the stubs the plugin read: an edited stub re-checks every module."""
    from geolint.mypy.config import plugin_source_digest

    plugin_source_digest.cache_clear()
    shipped = plugin_source_digest()
    monkeypatch.setenv("GEOLINT_STUBS", str(_flipped_stubs(tmp_path)))
    plugin_source_digest.cache_clear()
    flipped = plugin_source_digest()
    plugin_source_digest.cache_clear()
    assert shipped != flipped
