"""The shared frame-graph renderer: DOT, Mermaid and SVG output of hand-built graphs."""

from __future__ import annotations

import shutil

import pytest

from geolint.render import (
    FrameEdge,
    FrameGraph,
    GraphvizNotFound,
    render_dot,
    render_mermaid,
    render_svg,
)

GRAPH = FrameGraph(
    edges=(
        FrameEdge("world", "base", "T_world_base", location="robot.py:3"),
        FrameEdge("base", "cam", "T_base_cam", location="robot.py:4"),
        FrameEdge("world", "cam", "T_world_base @ T_cam_x", mismatch=True, location="robot.py:9"),
    ),
    frames=("map",),
)


def test_dot_has_every_frame_and_edge_with_red_mismatch() -> None:
    dot = render_dot(GRAPH)
    assert dot.startswith('digraph "frames" {')
    for frame in ("world", "base", "cam", "map"):
        assert f'  "{frame}";' in dot
    assert '"world" -> "base" [label="T_world_base\\nrobot.py:3"];' in dot
    mismatch = next(line for line in dot.splitlines() if "robot.py:9" in line)
    assert "color=red" in mismatch and '"world" -> "cam"' in mismatch
    assert "color=red" not in next(line for line in dot.splitlines() if "robot.py:4" in line)


def test_dot_is_independent_of_edge_order_and_drops_duplicates() -> None:
    shuffled = FrameGraph(edges=tuple(reversed(GRAPH.edges)) + GRAPH.edges[:1], frames=GRAPH.frames)
    assert render_dot(shuffled) == render_dot(GRAPH)


def test_dot_escapes_quotes_and_backslashes() -> None:
    dot = render_dot(FrameGraph(edges=(FrameEdge('a"b', "c\\d", "x"),)))
    assert '"a\\"b" -> "c\\\\d"' in dot


def test_mermaid_uses_safe_ids_and_styles_mismatches_red() -> None:
    mermaid = render_mermaid(GRAPH)
    lines = mermaid.splitlines()
    assert lines[0] == "flowchart TD"
    ids = {line.split("[")[0].strip(): line.split('"')[1] for line in lines if '["' in line}
    assert sorted(ids.values()) == ["base", "cam", "map", "world"]
    edge_lines = [line for line in lines if "-->" in line]
    assert len(edge_lines) == 3
    red_index = next(i for i, line in enumerate(edge_lines) if "robot.py:9" in line)
    assert lines[-1].startswith(f"  linkStyle {red_index} stroke:red")


def test_mermaid_escapes_label_quotes() -> None:
    mermaid = render_mermaid(FrameGraph(edges=(FrameEdge("a", "b", 'say "hi"'),)))
    assert '"say #quot;hi#quot;"' in mermaid


def test_svg_without_graphviz_says_how_to_get_it(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("PATH", "")
    with pytest.raises(GraphvizNotFound, match="apt-get install graphviz"):
        render_svg(GRAPH)


@pytest.mark.skipif(shutil.which("dot") is None, reason="Graphviz `dot` is not installed")
def test_svg_with_graphviz_draws_the_frames() -> None:
    svg = render_svg(GRAPH)
    assert "<svg" in svg and "T_world_base" in svg and "world" in svg
