"""GEO210 on keys and keywords (`{"location": ...}`, `eye=`), and through helpers that only relabel
the axes of a world-to-camera translation. A plain `location` / `position` needs data evidence."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from geolint.engine import lint_source
from geolint.lint_types import Config
from geolint.rules.frames.geo210_camera_center_from_translation import CameraCenterFromTranslation

BOP = (
    "import numpy as np\n"
    "def to_blender(p):\n    return [p[0], -p[2], p[1]]\n"
    "def scaled(p):\n    return [p[0] * 0.01, p[1] * 0.01, p[2] * 0.01]\n"
    "def f(sc, cams, image, marker):\n"
    "    T = np.eye(4)\n"
    "    T[:3, :3] = np.array(sc['cam_R_w2c']).reshape(3, 3)\n"
    "    T[:3, 3] = np.array(sc['cam_t_w2c'])\n"
)


def findings(body: str) -> list[int]:
    source = BOP + "".join(f"    {line}\n" for line in body.splitlines())
    found = lint_source(source, "example.py", Config(), rules=[CameraCenterFromTranslation])
    return [finding.line for finding in found if finding.code == "GEO210"]


@pytest.mark.parametrize(
    "body",
    [
        "cams.append({'location': list(T[:3, 3])})",
        "cams.append({'position': T[:3, 3].tolist()})",
        "pos = to_blender(list(T[:3, 3]))\ncams.append({'location': pos})",  # through an axis relabelling
        "cams.add(location=to_blender(T[:3, 3]))",
        "cams.append({'camera_position': image.tvec})",  # a camera name: COLMAP's attribute is enough
        "cams.look_at(eye=image.tvec)",
    ],
)
def test_a_world_to_camera_translation_stored_as_a_position(body: str) -> None:
    assert len(findings(body)) == 1


@pytest.mark.parametrize(
    "body",
    [
        "cams.append({'location': list(np.linalg.inv(T)[:3, 3])})",  # the camera-to-world translation
        "cams.append({'translation': list(T[:3, 3])})",  # extrinsics stored as extrinsics
        "cams.append({'location': scaled(T[:3, 3])})",  # a helper doing arithmetic: the chain ends
        "cams.append({'position': marker.tvec})",  # OpenCV's tvec under a plain key: the marker in the camera
        "W2C = np.linalg.inv(T)\ncams.append({'position': W2C[:3, 3]})",  # only a (wrong) name says w2c
    ],
)
def test_silent(body: str) -> None:
    assert findings(body) == []


def test_static_method_of_an_imported_project_class(tmp_path: Path) -> None:
    """`Utility.to_blender(p)`, a static method of a class in another module of the project."""
    (tmp_path / ".git").mkdir()
    package = tmp_path / "pkg"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "utility.py").write_text(
        "class Utility:\n    @staticmethod\n    def to_blender(point, axes):\n"
        "        out = []\n        for i, axis in enumerate(axes):\n            out.append(point[i])\n"
        "            if axis.startswith('-'):\n                out[-1] *= -1\n        return out\n"
    )
    (package / "loader.py").write_text(
        "import numpy as np\nfrom pkg.utility import Utility\n"
        "def load(sc, cams, axes):\n    T = np.eye(4)\n    T[:3, :3] = np.array(sc['cam_R_w2c']).reshape(3, 3)\n"
        "    T[:3, 3] = np.array(sc['cam_t_w2c'])\n    pos = Utility.to_blender(list(T[:3, 3]), axes)\n"
        "    cams.append({'location': pos})\n"
    )
    result = subprocess.run(
        [sys.executable, "-m", "geolint", "check", "--no-cache", "--select", "GEO210", "pkg/loader.py"],
        cwd=tmp_path, capture_output=True, text=True,
    )  # fmt: skip
    assert "loader.py:8:" in result.stdout and "GEO210" in result.stdout, result.stdout + result.stderr
