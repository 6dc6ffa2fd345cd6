"""Helpers of the numeric fact checks (tests/knowledge/test_*_facts.py): a quarter turn in a stated
component order, and what a stub states for a call, read through the knowledge base."""

from __future__ import annotations

import ast
import math

import numpy as np

from geolint.knowledge import SCALAR_FIRST, SCALAR_LAST, agreed, bind, knowledge_base

QUARTER_TURN_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
_HALF = math.sqrt(0.5)


def _quarter_turn(order: str) -> list[float]:
    """A quarter turn about z, its components in `order`."""
    components = {"w": _HALF, "x": 0.0, "y": 0.0, "z": _HALF}
    assert order in (SCALAR_FIRST, SCALAR_LAST)
    return [components[letter] for letter in order]


def _stated(qualified: str, call: str, parameter: str, field: str = "quaternion_order") -> object:
    """What the stub of `qualified` says of `parameter` (or of the return, for parameter "return") for `call`."""
    api = knowledge_base().api(qualified)
    assert api is not None, f"{qualified} is not in the knowledge base"
    node = ast.parse(call, mode="eval").body
    assert isinstance(node, ast.Call)
    bounds = bind(api, node)

    def answer(bound):  # type: ignore[no-untyped-def]
        geometry = bound.signature.returns if parameter == "return" else bound.signature.parameter(parameter).geometry
        return getattr(geometry, field) if geometry is not None else None

    stated = agreed(bounds, answer)
    assert stated is not None, f"the stub of {qualified} says nothing of {parameter} for {call}"
    return stated


def _quaternion_parts(value: object, order: str) -> dict[str, float]:
    return dict(zip(order, np.asarray(value, dtype=float).ravel()))


def _same_rotation(a: dict[str, float], b: dict[str, float]) -> bool:
    sign = 1.0 if a["w"] * b["w"] + a["x"] * b["x"] + a["y"] * b["y"] + a["z"] * b["z"] >= 0 else -1.0
    return all(abs(a[letter] - sign * b[letter]) < 1e-9 for letter in "wxyz")
