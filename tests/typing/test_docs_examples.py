"""The examples of docs/typing.md (the README's "Static checking, three ways") run, and mypy with the plugin
reports exactly the errors their comments announce (``# error: ...  [code]``) and nothing else."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest
from mypy import api

REPO = Path(__file__).resolve().parents[2]
DOC = REPO / "docs" / "typing.md"
CONFIG = Path(__file__).parent / "mypy.ini"
ANNOUNCED = re.compile(r"#\s*error: .*\[(?P<code>[a-z-]+)\]\s*$")


def python_blocks() -> list[str]:
    return re.findall(r"```python\n(.*?)```", DOC.read_text(), flags=re.S)


def _announced_codes(block: str) -> dict[int, str]:
    """line (1-based) -> code, for an ``# error:`` comment on that line or on the comment line right after it."""
    lines = block.splitlines()
    announced: dict[int, str] = {}
    for number, text in enumerate(lines, start=1):
        match = ANNOUNCED.search(text)
        if match:
            target = number - 1 if text.lstrip().startswith("#") else number
            announced[target] = match["code"]
    return announced


def test_docs_have_the_three_ways() -> None:
    assert len(python_blocks()) >= 3


@pytest.mark.parametrize("index", range(len(python_blocks())))
def test_example_runs(index: int, tmp_path: Path) -> None:
    script = tmp_path / f"example_{index}.py"
    script.write_text(python_blocks()[index])
    result = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, cwd=REPO, timeout=120)
    assert result.returncode == 0, result.stderr


def test_examples_report_what_they_announce(tmp_path: Path) -> None:
    files = []
    for index, block in enumerate(python_blocks()):
        path = tmp_path / f"doc_example_{index}.py"
        path.write_text(block)
        files.append(path)
    arguments = ["--config-file", str(CONFIG), "--cache-dir", str(tmp_path / "cache"), *map(str, files)]
    stdout, stderr, _ = api.run(arguments)
    for path, block in zip(files, python_blocks()):
        reported = {
            (int(m["line"]), m["code"])
            for m in re.finditer(rf"{re.escape(path.name)}:(?P<line>\d+): error: .*\[(?P<code>[a-z-]+)\]", stdout)
        }
        expected = set(_announced_codes(block).items())
        assert reported == expected, f"{path.name}\n{stdout}{stderr}"


ALIASED = """
from geolint import Point, Transform

def f(T: Transform["world", "camera"], p: Point["cam"], lidar: Point["lidar"]) -> Point["base_link"]:
    T @ lidar
    return Point["base"]([0.0, 0.0, 0.0])
"""


def config_blocks() -> list[tuple[str, str]]:
    return re.findall(r"```(ini|toml)\n(.*?)```", DOC.read_text(), flags=re.S)


def test_docs_show_each_config_form() -> None:
    assert sorted({language for language, _ in config_blocks()}) == ["ini", "toml"]


@pytest.mark.slow  # a cold mypy run per snippet
@pytest.mark.parametrize("index", range(len(config_blocks())))
def test_config_snippet_works_when_copied(index: int, tmp_path: Path) -> None:
    """The snippet as written (plus where to find geolint in this checkout): the plugin runs and the aliases apply."""
    language, text = config_blocks()[index]
    (tmp_path / "example.py").write_text(ALIASED)
    if language == "toml":
        config = tmp_path / "pyproject.toml"
        config.write_text(text.replace("[tool.mypy]\n", f'[tool.mypy]\nmypy_path = "{REPO}"\n', 1))
    else:
        config = tmp_path / "mypy.ini"
        config.write_text(text.replace("[mypy]\n", f"[mypy]\nmypy_path = {REPO}\n", 1))
    result = subprocess.run(
        [sys.executable, "-m", "mypy", "--config-file", config.name, "--no-incremental", "example.py"],
        cwd=tmp_path, capture_output=True, text=True, timeout=300,
    )
    assert 'applied to Point["lidar"]' in result.stdout, result.stdout + result.stderr
    # "cam" is "camera" and "base" is "base_link" through the snippet's aliases: no other error in the example
    # (geolint itself is read from this checkout as source here, so its own files may show notes of their own)
    assert result.stdout.count("example.py:") == 1, result.stdout
