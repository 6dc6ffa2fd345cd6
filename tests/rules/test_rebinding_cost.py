"""A scope that rebinds its names many times (generated code, long scripts) costs the linter time
linear in its size: measured as the number of Python function calls a lint makes, which, unlike
time, does not depend on the machine."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

from geolint.api import lint_text

_SPEC = importlib.util.spec_from_file_location("bench_rebinding", Path(__file__).resolve().parents[2] / "benchmarks" / "bench_rebinding.py")
assert _SPEC is not None and _SPEC.loader is not None
_BENCHMARK = importlib.util.module_from_spec(_SPEC)
_SPEC.loader.exec_module(_BENCHMARK)


def rebinding_function(rounds: int) -> str:
    """The benchmark's generated function (benchmarks/bench_rebinding.py), rebinding four names `rounds` times."""
    return _BENCHMARK.rebinding_function(4 * rounds)


def calls_to_lint(source: str) -> int:
    """How many Python functions run while every rule lints `source`."""
    lint_text("x = 1\n")  # imports and tables built once, outside the count
    count = 0

    def on_event(frame: object, event: str, argument: object) -> None:
        nonlocal count
        if event == "call":
            count += 1

    sys.setprofile(on_event)
    try:
        lint_text(source, "generated.py")
    finally:
        sys.setprofile(None)
    return count


def test_ten_times_the_rebindings_cost_at_most_ten_times_the_work():
    # 100 rounds is past the rebindings that reaching definitions keep order for (every binding
    # then reaches every use): the case that cost the square of the rebindings
    small, large = calls_to_lint(rebinding_function(100)), calls_to_lint(rebinding_function(1000))
    assert large < 11 * small, (small, large)
