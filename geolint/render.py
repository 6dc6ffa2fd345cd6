"""The one renderer of frame graphs: Graphviz DOT, Mermaid, and SVG (through the `dot` binary).

`geolint frames` (graphs read from code) and the runtime `FrameTree.to_dot()` both build a
`FrameGraph` and hand it here, so a picture of the frames looks the same wherever it comes from.

An edge points from the parent frame to the child frame: `T_world_cam` (which maps points in
`cam` to `world`) is the edge world -> cam. A `mismatch` edge is a use the linter found wrong
(a GEO2xx finding); it is drawn red and dashed, labelled with its `location` ("file:line").

Output is deterministic (frames and edges sorted), so it can be compared with a golden file.
"""

from __future__ import annotations

import json
import shutil
import subprocess
from dataclasses import dataclass

MISMATCH_COLOR = "red"
LOOKUP_COLOR = "gray40"

GRAPHVIZ_MISSING = (
    "SVG output needs the Graphviz `dot` program, which was not found on PATH. "
    "Install it (Debian/Ubuntu: `apt-get install graphviz`; macOS: `brew install graphviz`; "
    "conda: `conda install graphviz`), or use `--format dot` / `--format mermaid` and render elsewhere."
)


class GraphvizNotFound(RuntimeError):
    """Raised by `render_svg` when the Graphviz `dot` binary is not installed."""


@dataclass(frozen=True)
class FrameEdge:
    """A transform between two frames: `parent` is the destination frame, `child` the source frame.

    `label` is what the edge is called in the code (e.g. "T_world_cam"); `location` is
    "file:line" where it was seen (may be empty); `mismatch` marks a wrong use, drawn red.
    `lookup` marks a transform the code asks tf for (target -> source) rather than one it
    publishes, drawn dotted.
    """

    parent: str
    child: str
    label: str = ""
    mismatch: bool = False
    location: str = ""
    lookup: bool = False


@dataclass(frozen=True)
class FrameGraph:
    """Frames and the transforms between them. `frames` may list frames that have no edge."""

    edges: tuple[FrameEdge, ...] = ()
    frames: tuple[str, ...] = ()
    name: str = "frames"

    def all_frames(self) -> tuple[str, ...]:
        """Every frame named by `frames` or by an edge, sorted."""
        named = set(self.frames)
        for edge in self.edges:
            named.update((edge.parent, edge.child))
        return tuple(sorted(named))

    def sorted_edges(self) -> tuple[FrameEdge, ...]:
        """Edges without duplicates, in a stable order (correct uses before mismatches)."""
        unique = set(self.edges)
        return tuple(sorted(unique, key=lambda e: (e.mismatch, e.parent, e.child, e.label, e.location)))


def _edge_caption(edge: FrameEdge) -> str:
    return "\n".join(part for part in (edge.label, edge.location) if part)


# ---- Graphviz DOT ------------------------------------------------------------------------------


def _dot_quote(text: str) -> str:
    escaped = text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n")
    return f'"{escaped}"'


def render_dot(graph: FrameGraph) -> str:
    """The graph as a Graphviz `digraph` (parent -> child, mismatches red)."""
    lines = [
        f"digraph {_dot_quote(graph.name)} {{",
        "  rankdir=TB;",
        '  node [shape=ellipse, fontname="Helvetica"];',
        '  edge [fontname="Helvetica", fontsize=10];',
    ]
    lines.extend(f"  {_dot_quote(frame)};" for frame in graph.all_frames())
    for edge in graph.sorted_edges():
        attributes = []
        caption = _edge_caption(edge)
        if caption:
            attributes.append(f"label={_dot_quote(caption)}")
        if edge.mismatch:
            # Dashed as well as red, so the mismatch reads without colour too.
            attributes += [f"color={MISMATCH_COLOR}", f"fontcolor={MISMATCH_COLOR}", "penwidth=2", "style=dashed"]
        elif edge.lookup:
            attributes += [f"color={LOOKUP_COLOR}", f"fontcolor={LOOKUP_COLOR}", "style=dotted"]
        suffix = f" [{', '.join(attributes)}]" if attributes else ""
        lines.append(f"  {_dot_quote(edge.parent)} -> {_dot_quote(edge.child)}{suffix};")
    lines.append("}")
    return "\n".join(lines) + "\n"


# ---- Mermaid -----------------------------------------------------------------------------------


def _mermaid_text(text: str) -> str:
    # Mermaid labels are double-quoted; it understands HTML entities and <br/> for line breaks.
    return (
        text.replace("&", "#amp;").replace('"', "#quot;").replace("<", "#lt;").replace(">", "#gt;")
    ).replace("\n", "<br/>")


def render_mermaid(graph: FrameGraph) -> str:
    """The graph as a Mermaid `flowchart` (frames get safe ids; names are shown as labels)."""
    frames = graph.all_frames()
    node_id = {frame: f"f{index}" for index, frame in enumerate(frames)}
    lines = ["flowchart TD"]
    lines.extend(f'  {node_id[frame]}["{_mermaid_text(frame)}"]' for frame in frames)
    red_links = []
    for index, edge in enumerate(graph.sorted_edges()):
        caption = _edge_caption(edge)
        link = "-.->" if edge.lookup and not edge.mismatch else "-->"
        arrow = f'{link}|"{_mermaid_text(caption)}"|' if caption else link
        lines.append(f"  {node_id[edge.parent]} {arrow} {node_id[edge.child]}")
        if edge.mismatch:
            red_links.append(str(index))
    if red_links:
        lines.append(f"  linkStyle {','.join(red_links)} stroke:{MISMATCH_COLOR},stroke-width:2px,stroke-dasharray:5 3,color:{MISMATCH_COLOR}")
    return "\n".join(lines) + "\n"


# ---- SVG ---------------------------------------------------------------------------------------


def render_svg(graph: FrameGraph, *, timeout: float = 60.0) -> str:
    """The graph as SVG, laid out by the Graphviz `dot` binary; `GraphvizNotFound` if it is missing."""
    dot = shutil.which("dot")
    if dot is None:
        raise GraphvizNotFound(GRAPHVIZ_MISSING)
    completed = subprocess.run(
        [dot, "-Tsvg"], input=render_dot(graph), capture_output=True, text=True, timeout=timeout, check=False
    )
    if completed.returncode != 0:
        raise RuntimeError(f"graphviz `dot` failed (exit {completed.returncode}): {completed.stderr.strip()}")
    return completed.stdout


def render_json(graph: FrameGraph) -> str:
    """The graph as data: its frames, and each edge with what the drawings show of it."""
    edges = [
        {"parent": edge.parent, "child": edge.child, "label": edge.label, "location": edge.location, "mismatch": edge.mismatch, "lookup": edge.lookup}
        for edge in graph.sorted_edges()
    ]
    return json.dumps({"name": graph.name, "frames": list(graph.all_frames()), "edges": edges}, indent=2) + "\n"


RENDERERS = {"dot": render_dot, "json": render_json, "mermaid": render_mermaid, "svg": render_svg}
