"""The plugin as users run it: error codes they can disable, a cache invalidated by the plugin's config,
and the mypy daemon."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from mypy import api


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


@pytest.mark.slow  # cold mypy or dmypy runs over numpy's stubs
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


@pytest.mark.slow  # cold mypy or dmypy runs over numpy's stubs
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


MALFORMED = [
    # (config file name, its text after the [mypy] part, what the error must name)
    ("mypy.ini", "[geolint-mypy]\nframe_aliases = base\n", "[geolint-mypy] frame_aliases: expected alias:frame"),
    ("mypy.ini", "[geolint-mypy]\nframe_alias = base:base_link\n", "[geolint-mypy] frame_alias: unknown setting"),
    ("setup.cfg", "[geolint-mypy]\nframe_aliases = a:b, b:a\n", "[geolint-mypy] frame_aliases: aliases form a cycle"),
    ("pyproject.toml", '[tool.geolint-mypy]\nframe_aliases = "base:base_link"\n', "[tool.geolint-mypy] frame_aliases: expected a table"),
    ("pyproject.toml", "[tool.geolint-mypy]\nframe_aliases = { base = 1 }\n", "[tool.geolint-mypy] frame_aliases: expected a table"),
    ("pyproject.toml", '[tool.geolint-mypy]\naliases = { base = "base_link" }\n', "[tool.geolint-mypy] aliases: unknown setting"),
    ("pyproject.toml", '[tool]\ngeolint-mypy = "base"\n', "[tool.geolint-mypy] geolint-mypy: expected a table"),
]


@pytest.mark.parametrize(("name", "section", "named"), MALFORMED, ids=[f"{m[0]}-{i}" for i, m in enumerate(MALFORMED)])
def test_malformed_plugin_config_is_a_clear_mypy_error(tmp_path: Path, name: str, section: str, named: str) -> None:
    (tmp_path / "snippet.py").write_text(SNIPPET)
    if name == "pyproject.toml":  # the plugin's section first: a bare [tool] table must precede [tool.mypy]
        text = section + f'[tool.mypy]\nplugins = ["geolint.mypy"]\nmypy_path = "{REPO}"\n'
    else:
        text = f"[mypy]\nplugins = geolint.mypy\nmypy_path = {REPO}\n" + section
    (tmp_path / name).write_text(text)
    result = subprocess.run(
        [sys.executable, "-m", "mypy", "--config-file", name, "--cache-dir", str(tmp_path / "c"), "snippet.py"],
        cwd=tmp_path, capture_output=True, text=True, timeout=300,
    )
    output = result.stdout + result.stderr
    assert result.returncode == 2, output
    assert "INTERNAL ERROR" not in output and "Traceback" not in output, output
    assert f"{name}: error: {named}" in result.stderr, output


@pytest.mark.slow  # cold mypy or dmypy runs over numpy's stubs
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


@pytest.mark.slow  # cold mypy or dmypy runs over numpy's stubs
def test_dmypy_run_picks_up_a_changed_plugin_config(tmp_path: Path) -> None:
    dmypy = [sys.executable, "-m", "mypy.dmypy", "--status-file", str(tmp_path / "dmypy.json")]
    env = {**os.environ, "PYTHONPATH": str(REPO)}
    run = [*dmypy, "run", "--", "--config-file", "mypy.ini", "snippet.py"]
    try:
        _write_project(tmp_path, "base:base_link")
        aliased = subprocess.run(run, cwd=tmp_path, capture_output=True, text=True, timeout=300, env=env)
        assert "[geo-frame]" in aliased.stdout, aliased.stdout + aliased.stderr
        assert "return-value" not in aliased.stdout  # "base" is "base_link"
        _write_project(tmp_path, None)
        plain = subprocess.run(run, cwd=tmp_path, capture_output=True, text=True, timeout=300, env=env)
        # The daemon started under the old aliases would repeat the first answer.
        assert "[return-value]" in plain.stdout, plain.stdout + plain.stderr
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
