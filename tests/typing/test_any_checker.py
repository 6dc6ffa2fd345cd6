"""Without the plugin, `geolint.typing` still works in plain mypy and in pyright (basedpyright): the lines
marked ``# expect-error`` are rejected by both, every other line is accepted."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from mypy import api

HERE = Path(__file__).parent
REPO = HERE.parent.parent
CASE = HERE / "any_checker" / "arrays_any_checker.py"


def expected_lines() -> set[int]:
    return {n for n, text in enumerate(CASE.read_text().splitlines(), start=1) if "# expect-error" in text}


def test_plain_mypy_without_plugin(tmp_path: Path) -> None:
    config = tmp_path / "mypy.ini"
    config.write_text(f"[mypy]\nmypy_path = {REPO}\n[mypy-geolint.*]\nfollow_imports = silent\n")
    stdout, stderr, _ = api.run(["--config-file", str(config), "--cache-dir", str(tmp_path / "c"), str(CASE)])
    reported = {int(line.split(":")[1]) for line in stdout.splitlines() if ": error:" in line}
    assert reported == expected_lines(), stdout + stderr


def test_pyright(tmp_path: Path) -> None:
    (tmp_path / "pyrightconfig.json").write_text(
        json.dumps({"extraPaths": [str(REPO)], "typeCheckingMode": "standard", "pythonVersion": "3.11"})
    )
    case = tmp_path / CASE.name
    case.write_text(CASE.read_text())
    pyright = Path(sys.executable).with_name("basedpyright")
    result = subprocess.run(
        [str(pyright), "--outputjson", "--pythonpath", sys.executable, str(case)],
        capture_output=True, text=True, cwd=tmp_path, timeout=300,
    )
    diagnostics = json.loads(result.stdout)["generalDiagnostics"]
    reported = {d["range"]["start"]["line"] + 1 for d in diagnostics if d["severity"] == "error"}
    assert reported == expected_lines(), result.stdout[-3000:]
