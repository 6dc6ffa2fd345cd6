"""One shared mypy run over every typing case and the typed fixtures (mypy is the slow part: run it once)."""

from __future__ import annotations

import importlib.util
import os
import sys
from pathlib import Path
from types import ModuleType

import pytest
from mypy import api

HERE = Path(__file__).parent
REPO = HERE.parent.parent
CONFIG = HERE / "mypy.ini"
CASES = sorted((HERE / "cases").glob("*.py"))
FIXTURES = REPO / "fixtures" / "typed"
BUG_FIXTURES = sorted((FIXTURES / "bugs").glob("*.py"))
CLEAN_FIXTURES = sorted((FIXTURES / "clean").glob("*.py"))


@pytest.fixture(scope="session")
def mypy_cache(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("mypy_cache")


@pytest.fixture(scope="session")
def checked(mypy_cache: Path) -> tuple[str, str, int]:
    """stdout, stderr, exit status of mypy with the plugin over all cases and fixtures."""
    files = [str(path) for path in [*CASES, *BUG_FIXTURES, *CLEAN_FIXTURES]]
    # run_lowest_mypy.sh runs mypy from a bare venv and points it at an interpreter that has numpy & co.
    python = os.environ.get("GEOLINT_TYPING_PYTHON")
    interpreter = ["--python-executable", python] if python else []
    return api.run(["--config-file", str(CONFIG), "--cache-dir", str(mypy_cache), *interpreter, *files])


@pytest.fixture(scope="session")
def expectations() -> ModuleType:
    """The `expectations` helper module (loaded by path: test folders are not packages here)."""
    spec = importlib.util.spec_from_file_location("geolint_typing_expectations", HERE / "expectations.py")
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up while the class is built
    spec.loader.exec_module(module)
    return module
