"""A scope that rebinds its names many times (generated code, long scripts) costs the linter time
linear in its size: measured as the number of Python function calls a lint makes, which, unlike
time, does not depend on the machine."""

from __future__ import annotations

import sys

from geolint.api import lint_text


def rebinding_function(rounds: int) -> str:
    """A function that rebinds four names `rounds` times (the frames of each stated by its name)."""
    lines = ["import numpy as np", "", "", "def step(T_world_cam, p_cam, origin):"]
    for _ in range(rounds):
        lines += [
            "    p_world = T_world_cam @ p_cam",
            "    v = p_world - origin",
            "    T_world_cam = T_world_cam @ np.eye(4)",
            "    p_cam = v + origin",
        ]
    lines.append("    return p_world, v")
    return "\n".join(lines) + "\n"


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
