"""Every typing case and typed fixture through the real mypy with the geolint plugin: positive and negative
cases live side by side in the files (see `expectations`)."""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

import pytest

HERE = Path(__file__).parent
CASES = sorted((HERE / "cases").glob("*.py"))
FIXTURES = HERE.parent.parent / "fixtures" / "typed"
BUG_FIXTURES = sorted((FIXTURES / "bugs").glob("*.py"))
CLEAN_FIXTURES = sorted((FIXTURES / "clean").glob("*.py"))


# Cases whose expected reveals spell numpy's own array types, which numpy 2.3 changed.
NUMPY_SPELLED_CASES = frozenset({"arrays.py", "bridge_and_third_party.py"})


def _numpy_below(major: int, minor: int) -> bool:
    import numpy

    return tuple(int(part) for part in numpy.__version__.split(".")[:2]) < (major, minor)


def test_mypy_did_not_crash(checked: tuple[str, str, int]) -> None:
    stdout, stderr, status = checked
    assert "INTERNAL ERROR" not in stdout + stderr, stdout + stderr
    assert status in (0, 1), stdout + stderr


@pytest.mark.parametrize("path", CASES + BUG_FIXTURES + CLEAN_FIXTURES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_expectations_hold(path: Path, checked: tuple[str, str, int], expectations: ModuleType) -> None:
    if path.name in NUMPY_SPELLED_CASES and _numpy_below(2, 3):
        pytest.skip("the revealed array types are spelled as numpy >= 2.3 spells them (Python 3.10 gets numpy 2.2)")
    reported = expectations.parse_mypy_output(checked[0]).get(path.name, [])
    problems = expectations.mismatches(path, reported)
    assert not problems, "\n".join(problems)


def test_bug_fixtures_expect_errors_and_clean_fixtures_expect_none(expectations: ModuleType) -> None:
    expected_in = expectations.expected_in
    assert BUG_FIXTURES and CLEAN_FIXTURES
    for path in BUG_FIXTURES:
        assert any(kind == "E" for marks in expected_in(path).values() for kind, _ in marks), path
    for path in CLEAN_FIXTURES:
        assert not any(kind == "E" for marks in expected_in(path).values() for kind, _ in marks), path


def test_every_error_code_is_exercised() -> None:
    text = "\n".join(path.read_text() for path in CASES + BUG_FIXTURES)
    for code in ("geo-frame", "geo-kind", "geo-translation"):
        assert f"# E: {code}" in text
