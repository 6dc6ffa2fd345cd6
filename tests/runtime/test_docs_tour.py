"""The tour in docs/runtime.md (also the README's) runs, and its commented results are what it prints."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

import geolint
from geolint import FrameMismatchError

DOC = Path(geolint.__file__).resolve().parent.parent / "docs" / "runtime.md"


def test_the_tour_runs_as_documented(capsys: pytest.CaptureFixture[str]) -> None:
    block = re.search(r"## Tour\n\n```python\n(.*?)```", DOC.read_text(), re.S)
    assert block, "docs/runtime.md lost its tour"
    source = block.group(1)
    namespace: dict[str, object] = {}
    results: dict[str, object] = {}
    for node in ast.parse(source).body:
        segment = ast.get_source_segment(source, node) or ""
        following = source.splitlines()[node.end_lineno] if node.end_lineno < len(source.splitlines()) else ""  # type: ignore[operator]
        if "# FrameMismatchError" in following:
            with pytest.raises(FrameMismatchError, match=re.escape(following.split("FrameMismatchError: ")[1])):
                exec(compile(ast.Module([node], []), "tour", "exec"), namespace)
            continue
        if isinstance(node, ast.Expr):
            results[segment] = eval(compile(ast.Expression(node.value), "tour", "eval"), namespace)
        else:
            exec(compile(ast.Module([node], []), "tour", "exec"), namespace)
    assert repr(results["T_world_tool @ Point[Tool]([0.2, 0, 0])"]) == "Point[World]([0.3, 0.3, 0.5])"
    assert repr(results["T_world_tool @ Direction[Tool]([1, 0, 0])"]) == "Direction[World]([0.0, 1.0, 0.0])"
    assert results["cloud.normal_lengths().max()"] == pytest.approx(1.0, abs=1e-12)
    assert repr(results["tree.transform(Point[Camera]([0, 0, 1]), to=World)"]) == "Point[World]([0.3, 0.1, 1.55])"
    assert '"World" -> "Tool"' in capsys.readouterr().out
