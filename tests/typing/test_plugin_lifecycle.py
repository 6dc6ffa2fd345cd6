"""The plugin as users run it: error codes they can disable, a cache invalidated by the plugin's config,
and the mypy daemon."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from mypy import api

from geolint.mypy.config import PluginConfigError

REPO = Path(__file__).resolve().parents[2]

SNIPPET = '''
from geolint import Point, Transform

def f(T: Transform["world", "camera"], p: Point["base"]) -> Point["base_link"]:
    T @ p
    return p
'''


def _write_project(root: Path, aliases: str | None) -> Path:
    (root / "snippet.py").write_text(SNIPPET)
    section = f"\n[geolint-mypy]\nframe_aliases = {aliases}\n" if aliases else ""
    config = root / "mypy.ini"
    config.write_text(
        f"[mypy]\nplugins = geolint.mypy\nmypy_path = {REPO}\nshow_error_codes = True\n"
        f"[mypy-geolint.*]\nfollow_imports = silent\n{section}"
    )
    return config


def test_error_code_can_be_disabled(tmp_path: Path) -> None:
    config = _write_project(tmp_path, None)
    cache = str(tmp_path / "cache")
    base = ["--config-file", str(config), "--cache-dir", cache, str(tmp_path / "snippet.py")]
    enabled, _, _ = api.run(base)
    disabled, _, _ = api.run(["--disable-error-code", "geo-frame", *base])
    assert "[geo-frame]" in enabled
    assert "[geo-frame]" not in disabled
    # the unrelated return-value error stays: disabling one code silences only it
    assert "[return-value]" in disabled


def test_changed_plugin_config_invalidates_the_cache(tmp_path: Path) -> None:
    cache = str(tmp_path / "cache")
    snippet = str(tmp_path / "snippet.py")
    config = _write_project(tmp_path, "base:base_link")
    aliased, _, _ = api.run(["--config-file", str(config), "--cache-dir", cache, snippet])
    assert "return-value" not in aliased  # "base" is "base_link"
    config = _write_project(tmp_path, None)
    plain, _, _ = api.run(["--config-file", str(config), "--cache-dir", cache, snippet])
    # A cache reused across the config change would repeat the first answer.
    assert "[return-value]" in plain


def test_bad_plugin_config_names_the_file(tmp_path: Path) -> None:
    config = _write_project(tmp_path, "base")
    with pytest.raises(PluginConfigError, match=r"mypy\.ini.*frame_aliases.*'base'"):
        api.run(["--config-file", str(config), "--cache-dir", str(tmp_path / "c"), str(tmp_path / "snippet.py")])


def test_dmypy_runs_the_plugin(tmp_path: Path) -> None:
    config = _write_project(tmp_path, None)
    dmypy = [sys.executable, "-m", "mypy.dmypy", "--status-file", str(tmp_path / "dmypy.json")]
    env = {**os.environ, "PYTHONPATH": str(REPO)}
    try:
        result = subprocess.run(
            [*dmypy, "run", "--", "--config-file", str(config), "snippet.py"],
            cwd=tmp_path, capture_output=True, text=True, timeout=300, env=env,
        )
        assert "[geo-frame]" in result.stdout, result.stdout + result.stderr
        assert 'Transform["world" <- "camera"] applied to Point["base"]' in result.stdout
        # fine-grained re-checks after edits: the fix silences it, a new string-frame bug is found
        check = [*dmypy, "check", "snippet.py"]
        (tmp_path / "snippet.py").write_text(SNIPPET.replace('p: Point["base"]', 'p: Point["camera"]'))
        fixed = subprocess.run(check, cwd=tmp_path, capture_output=True, text=True, timeout=120, env=env)
        assert "geo-frame" not in fixed.stdout and "name-defined" not in fixed.stdout, fixed.stdout + fixed.stderr
        (tmp_path / "snippet.py").write_text(SNIPPET.replace('p: Point["base"]', 'p: Point["odom"]'))
        broken = subprocess.run(check, cwd=tmp_path, capture_output=True, text=True, timeout=120, env=env)
        assert 'applied to Point["odom"]' in broken.stdout, broken.stdout + broken.stderr
        assert "name-defined" not in broken.stdout, broken.stdout
    finally:
        subprocess.run([*dmypy, "stop"], cwd=tmp_path, capture_output=True, timeout=60, env=env)


def test_frame_aliases_from_pyproject(tmp_path: Path) -> None:
    (tmp_path / "snippet.py").write_text(SNIPPET)
    pyproject = tmp_path / "pyproject.toml"
    pyproject.write_text(
        f'[tool.mypy]\nplugins = ["geolint.mypy"]\nmypy_path = "{REPO}"\nshow_error_codes = true\n'
        '[[tool.mypy.overrides]]\nmodule = "geolint.*"\nfollow_imports = "silent"\n'
        '[tool.geolint-mypy]\nframe_aliases = { base = "base_link" }\n'
    )
    cache = str(tmp_path / "c")
    stdout, _, _ = api.run(["--config-file", str(pyproject), "--cache-dir", cache, str(tmp_path / "snippet.py")])
    assert "[geo-frame]" in stdout  # the plugin ran
    assert "return-value" not in stdout  # and "base" is "base_link"
