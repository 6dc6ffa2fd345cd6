"""The shipped knowledge base: every library folder reads, every entry cites its source, and the stubs
are valid Python in which every name is defined (checked by ruff, a real linter)."""

from __future__ import annotations

import importlib.util
import subprocess
import sys

import pytest

from geolint.knowledge import knowledge_base, stubs_folder
from geolint.knowledge.reader import read_library


def test_every_library_reads_and_has_its_metadata() -> None:
    folders = [path for path in sorted(stubs_folder().iterdir()) if path.is_dir()]
    assert folders, "stubs/ holds no library"
    for folder in folders:
        library = read_library(folder)
        assert library.packages, f"{folder.name}: METADATA.toml names no import package"
        assert library.checked, f"{folder.name}: METADATA.toml says no version the facts were checked against"
        assert library.upstream, f"{folder.name}: METADATA.toml says where the library's source is"
        assert library.apis or library.aliases, f"{folder.name}: no API and no re-export"


def test_every_entry_cites_its_source() -> None:
    uncited = [api.qualified_name for api in knowledge_base().apis() if not api.source]
    assert not uncited, f"entries without a `Source:` line (on the function or its class): {uncited}"


def test_every_stub_is_valid_python_with_every_name_defined() -> None:
    if importlib.util.find_spec("ruff") is None:
        pytest.skip("ruff is not installed")
    done = subprocess.run(
        [sys.executable, "-m", "ruff", "check", "--no-cache", "--isolated", "--select", "F,E9", str(stubs_folder())], capture_output=True, text=True
    )
    assert done.returncode == 0, done.stdout + done.stderr


def test_stubs_compile_under_this_interpreter() -> None:
    for stub in stubs_folder().rglob("*.pyi"):
        compile(stub.read_text(encoding="utf-8"), str(stub), "exec")
    assert sys.version_info >= (3, 10)


def test_the_committed_library_list_is_current() -> None:
    from pathlib import Path

    from geolint.knowledge.catalog import catalog_markdown

    committed = (Path(__file__).resolve().parents[2] / "docs" / "libraries.md").read_text(encoding="utf-8")
    assert committed == catalog_markdown(), "docs/libraries.md is stale: run `python -m geolint.knowledge.catalog > docs/libraries.md`"
