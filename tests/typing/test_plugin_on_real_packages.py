"""The plugin never crashes mypy: mypy with the plugin over the installed sources of numpy and pytransform3d
(their own type errors are theirs; an INTERNAL ERROR or a traceback would be ours)."""

from __future__ import annotations

from pathlib import Path

import pytest
from mypy import api

REPO = Path(__file__).resolve().parents[2]


@pytest.mark.slow
@pytest.mark.parametrize("package", ["pytransform3d", "numpy"])
def test_mypy_with_plugin_over_installed_package(package: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    config = tmp_path / "mypy.ini"
    config.write_text(f"[mypy]\nplugins = geolint.mypy\nmypy_path = {REPO}\n")
    monkeypatch.chdir(tmp_path)  # not site-packages: its top-level modules would shadow mypy's own
    stdout, stderr, status = api.run(
        ["--config-file", str(config), "--cache-dir", str(tmp_path / "cache"), "--ignore-missing-imports",
         "-p", package]
    )
    assert "INTERNAL ERROR" not in stdout + stderr, (stdout + stderr)[-4000:]
    assert "Traceback" not in stderr, stderr[-4000:]
    assert status in (0, 1), (stdout + stderr)[-4000:]
    assert f"site-packages/{package}/" in stdout or status == 0  # it really checked the package
