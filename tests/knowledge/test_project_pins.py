"""The versions a project declares for its dependencies, and the versioned stub facts they let the
linter use: a fact holds only when every version the project allows is in its range."""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from geolint.factbase.project_pins import pins_for


def _project(tmp_path: Path, files: dict[str, str]) -> str:
    for name, text in files.items():
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text))
    (tmp_path / "setup.cfg").touch()  # a project marker
    module = tmp_path / "node.py"
    module.touch()
    return str(module)


@pytest.mark.parametrize(
    ("files", "holds", "fails"),
    [
        ({"requirements.txt": "torch\nkornia==0.6.12  # pinned for the old checkpoints\n"}, ["<0.7"], [">=0.7"]),
        ({"requirements.txt": "kornia>=0.7.1,<0.9\n"}, [">=0.7"], ["<0.7", ">=0.8"]),
        ({"requirements/base.txt": "kornia~=0.6.2\n"}, ["<0.7", ">=0.6"], [">=0.7", "<0.6.5"]),
        ({"pyproject.toml": '[project]\nname = "x"\ndependencies = ["kornia>=0.7"]\n'}, [">=0.7"], ["<0.7"]),
        ({"pyproject.toml": '[project]\nname = "x"\n[project.optional-dependencies]\nvision = ["Kornia<0.7"]\n'}, ["<0.7"], [">=0.7"]),
        ({"pyproject.toml": '[tool.poetry.dependencies]\npython = "^3.10"\nkornia = "^0.6.2"\n'}, ["<0.7"], [">=0.7"]),
        ({"setup.py": "from setuptools import setup\nsetup(name='x', install_requires=['kornia==0.7.0'])\n"}, [">=0.7"], ["<0.7"]),
        ({"requirements.txt": "kornia\n"}, [], [">=0.7", "<0.7"]),  # any version: nothing holds for certain
        ({"requirements.txt": "kornia!=0.6.5\n"}, [], [">=0.7", "<0.7"]),
        ({}, [], [">=0.7", "<0.7"]),
    ],
)
def test_a_versioned_fact_holds_only_when_every_allowed_version_satisfies_it(
    tmp_path: Path, files: dict[str, str], holds: list[str], fails: list[str]
) -> None:
    pins = pins_for(_project(tmp_path, files))
    assert [spec for spec in holds if pins.allow_only("kornia", spec)] == holds
    assert [spec for spec in fails if pins.allow_only("kornia", spec)] == []


def test_a_lock_file_names_the_exact_version(tmp_path: Path) -> None:
    lock = '[[package]]\nname = "kornia"\nversion = "0.6.12"\n'
    pins = pins_for(_project(tmp_path, {"requirements.txt": "kornia>=0.5\n", "uv.lock": lock}))
    assert pins.allow_only("kornia", "<0.7") and not pins.allow_only("kornia", ">=0.7")
    pipfile = json.dumps({"default": {"kornia": {"version": "==0.7.2"}}})
    other = tmp_path / "other"
    other.mkdir()
    pins = pins_for(_project(other, {"Pipfile.lock": pipfile}))
    assert pins.allow_only("kornia", ">=0.7")


def test_broken_declarations_say_nothing_and_break_nothing(tmp_path: Path) -> None:
    pins = pins_for(_project(tmp_path, {"pyproject.toml": "[project\n", "requirements.txt": "kornia===\n", "setup.py": "setup(install_requires=[\n"}))
    assert not pins.allow_only("kornia", ">=0.7") and not pins.allow_only("kornia", "<0.7")


UNTYPED = """\
from kornia.geometry import quaternion_to_rotation_matrix
from scipy.spatial.transform import Rotation


def grasp_matrix(R_grasp):
    q = Rotation.from_matrix(R_grasp).as_quat()
    return quaternion_to_rotation_matrix(q)
"""


@pytest.mark.parametrize(("requirements", "flagged"), [("kornia==0.9.0\n", True), ("kornia<0.7\n", False), ("kornia\n", False), ("", False)])
def test_the_linter_uses_the_fact_the_project_s_pins_select(tmp_path: Path, requirements: str, flagged: bool) -> None:
    """kornia reads (w, x, y, z) from 0.7 on and (x, y, z, w) before; scipy's `as_quat` returns x, y, z, w."""
    _project(tmp_path, {"requirements.txt": requirements, "grasp.py": UNTYPED})
    done = subprocess.run(
        [sys.executable, "-m", "geolint", "check", "--select", "GEO301", "--output-format", "json", "grasp.py"],
        cwd=tmp_path, capture_output=True, text=True, timeout=300, check=False,
    )  # fmt: skip
    findings = json.loads(done.stdout)
    assert [finding["line"] for finding in findings] == ([7] if flagged else []), done.stdout + done.stderr


def test_a_changed_pin_is_not_served_from_the_findings_cache(tmp_path: Path) -> None:
    _project(tmp_path, {"requirements.txt": "kornia<0.7\n", "grasp.py": UNTYPED})
    args = [sys.executable, "-m", "geolint", "check", "--select", "GEO301", "--output-format", "json", "grasp.py"]
    first = subprocess.run(args, cwd=tmp_path, capture_output=True, text=True, timeout=300, check=False)
    assert json.loads(first.stdout) == []
    (tmp_path / "requirements.txt").write_text("kornia>=0.7\n")
    second = subprocess.run(args, cwd=tmp_path, capture_output=True, text=True, timeout=300, check=False)
    assert [finding["line"] for finding in json.loads(second.stdout)] == [7]
