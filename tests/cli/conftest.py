"""Helpers for the CLI tests: run the real `geolint` command in a subprocess.

`run_geolint` starts `python -m geolint`-equivalent processes with the stand-in rules of
`sample_rules.py` registered (the launcher imports them, then calls `geolint.cli.main`), so the
tests do not depend on what the real rules flag. `run_module` runs plain `python -m geolint`.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
LAUNCHER = "import sys, sample_rules; from geolint.cli import main; sys.exit(main(sys.argv[1:]))"


def _env(extra: dict[str, str] | None, cache_dir: Path | None) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "CI", "FORCE_COLOR")}
    env["PYTHONPATH"] = os.pathsep.join([str(HERE), env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    if cache_dir is not None:
        env["GEOLINT_CACHE_DIR"] = str(cache_dir)
    env.update(extra or {})
    return env


def launch_geolint(*args: str) -> list[str]:
    """The command line that runs `geolint ARGS` with the sample rules registered."""
    return [sys.executable, "-c", LAUNCHER, *args]


def cli_env(env: dict[str, str] | None = None, cache_dir: Path | None = None) -> dict[str, str]:
    """The environment the CLI tests run geolint in (no colour settings of the caller's, sample rules importable)."""
    return _env(env, cache_dir)


def run_geolint(
    *args: str, cwd: Path, env: dict[str, str] | None = None, cache_dir: Path | None = None, input: str | None = None
) -> subprocess.CompletedProcess[str]:
    """`geolint ARGS` with the sample rules registered, in `cwd` (`input` is its stdin)."""
    return subprocess.run(
        launch_geolint(*args),
        cwd=cwd,
        env=_env(env, cache_dir),
        capture_output=True,
        text=True,
        timeout=120,
        input=input,
    )


def run_module(
    *args: str, cwd: Path, env: dict[str, str] | None = None, cache_dir: Path | None = None, input: str | None = None
) -> subprocess.CompletedProcess[str]:
    """`python -m geolint ARGS` exactly as a user runs it (only the real rules)."""
    return subprocess.run(
        [sys.executable, "-m", "geolint", *args],
        cwd=cwd,
        env=_env(env, cache_dir),
        capture_output=True,
        text=True,
        timeout=120,
        input=input,
    )


class Runner:
    """Runs the CLI in one project folder with one private cache dir (fixtures `cli` / `cli_real`)."""

    def __init__(self, function, project: Path, cache_dir: Path) -> None:
        self.function = function
        self.project = project
        self.cache_dir = cache_dir

    def __call__(self, *args: str, env: dict[str, str] | None = None, cwd: Path | None = None, input: str | None = None):
        return self.function(*args, cwd=cwd or self.project, env=env, cache_dir=self.cache_dir, input=input)

    def write(self, name: str, text: str, encoding: str = "utf-8") -> Path:
        """Write a file under the project (folders made as needed)."""
        path = self.project / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(text.encode(encoding))
        return path


@pytest.fixture
def cli(project: Path, cache_dir: Path) -> Runner:
    """`geolint` with the stand-in rules of sample_rules.py registered."""
    return Runner(run_geolint, project, cache_dir)


@pytest.fixture
def cli_real(project: Path, cache_dir: Path) -> Runner:
    """`python -m geolint` with only the real rules."""
    return Runner(run_module, project, cache_dir)


@pytest.fixture
def project(tmp_path: Path) -> Path:
    """An empty project folder with its own cache dir (so tests never share a cache)."""
    root = tmp_path / "project"
    root.mkdir()
    return root


@pytest.fixture
def cache_dir(tmp_path: Path) -> Path:
    return tmp_path / "cache"
