"""Read the frames and transforms out of Python code, for `geolint frames`.

Where a frame graph comes from, in one file:

- names in the naming conventions the linter knows (`T_world_cam`, `world_T_cam`, `X_WB`,
  `cam_to_world`, ...: `geolint.semantic.names.frames_of_name`) give an edge dst -> src, and
  value names (`p_world`, `normals_cam`) give a frame;
- typed annotations `Transform[Dst, Src]` (and `Transform[...]` used as a constructor) give an
  edge; frame classes (`class World(Frame)`, `class BaseLink(Frame, name="base_link")`) are read
  by the name the runtime gives them;
- `FrameTree.add(T)` calls give an edge labelled with the call, as the runtime tree would hold it;
- the linter's GEO2xx findings (frame mismatches) give red edges between the two frames that
  disagree (the pair the rule recorded in `Finding.frames`), labelled with the code and file:line.

`T_a_b` names are read in the project's naming order, as the linter learns it (`naming` in the
config, else the project's `from_frame=`/`to_frame=` declarations and compositions); where both
orders stay open they are drawn dst-first, and where the project declares both they are not drawn.

Frame names are lower-cased, as `frames_of_name` gives them, so `Transform[World, Cam]` and
`T_world_cam` draw one edge between the same two frames.
"""

from __future__ import annotations

import ast
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterable, Sequence

from geolint.lint_types import Config, Finding
from geolint.parsing import parse_module
from geolint.render import FrameEdge, FrameGraph
from geolint.factbase import tf_workspace, typed
from geolint.factbase.conventions import naming_config, orders_for
from geolint.factbase.model import DST_FIRST, SRC_FIRST
from geolint.factbase.tf_statements import LookedUp, Published, settled
from geolint.semantic.names import NameFrames, frames_of_name, order_dependent, same_frame

MISMATCH_PREFIX = "GEO2"
_LINE_BREAKS = re.compile(r"\r\n|\r|\n")
_LABEL_WIDTH = 48
_INVERSE_CALLS = frozenset({"inv", "inverse", "pinv"})
_PRODUCT_CALLS = frozenset({"dot", "matmul"})


@dataclass
class _FileReader(ast.NodeVisitor):
    """One pass over one module's AST, collecting edges and frames."""

    source: str
    path: str
    config: Config
    frame_classes: dict[str, str] = field(default_factory=dict)
    typed: dict[str, NameFrames] = field(default_factory=dict)  # variable -> frames from its annotation
    trees: set[str] = field(default_factory=set)  # variables holding a FrameTree
    edges: dict[tuple[str, str, str], FrameEdge] = field(default_factory=dict)
    frames: set[str] = field(default_factory=set)
    claimed: set[int] = field(default_factory=set)  # Transform[...] nodes already drawn under a better label
    # the project's reading of `T_a_b` (as the linter learns it): both orders open draws dst-first
    orders: tuple[str, ...] = (DST_FIRST,)
    order_names_mixed: bool = False  # both orders declared: a `T_a_b` name alone is no edge
    lines: list[str] = field(default_factory=list)  # the source's lines, split on first use

    # ---- frames of names, types and expressions ------------------------------------------------

    def _canon(self, frame: str) -> str:
        frame = frame.lower()
        aliases = {key.lower(): value.lower() for key, value in self.config.frame_aliases.items()}
        return aliases.get(frame, frame)

    def name_frames(self, name: str) -> NameFrames | None:
        """A name's frames in the project's naming order (`T_obj_world` maps obj into world in a src-first project)."""
        stated = frames_of_name(name, self.config)
        if stated is None or not stated.is_operator or not order_dependent(name):
            return stated
        if self.order_names_mixed:
            return None
        return stated.inverted() if self.orders == (SRC_FIRST,) else stated

    def transform_type(self, node: ast.AST | None) -> NameFrames | None:
        """Frames of `Transform[Dst, Src]` (or `geolint.Transform[...]`); None for anything else."""
        if not isinstance(node, ast.Subscript) or _name_of(node.value) != "Transform":
            return None
        frames = typed.typed_frames(node, self.frame_classes)
        if frames is None or frames.dst is None or frames.src is None:
            return None
        return NameFrames(dst=self._canon(frames.dst), src=self._canon(frames.src), operator="transform")

    def frames_of(self, node: ast.AST | None) -> NameFrames | None:
        """What frames an expression is in, from its names, types and the algebra around them."""
        if isinstance(node, (ast.Name, ast.Attribute)):
            name = node.id if isinstance(node, ast.Name) else node.attr
            if isinstance(node, ast.Attribute) and node.attr == "T":  # transpose: meant as the inverse
                inner = self.frames_of(node.value)
                return inner.inverted() if inner is not None and inner.is_operator else None
            if name in self.typed:
                return self.typed[name]
            return self.name_frames(name)
        if isinstance(node, ast.Subscript):
            return self.transform_type(node)
        if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.MatMult, ast.Mult)):
            return _product(self.frames_of(node.left), self.frames_of(node.right))
        if isinstance(node, ast.Call):
            callee = _name_of(node.func)
            if callee in _INVERSE_CALLS:
                operand = node.func.value if isinstance(node.func, ast.Attribute) and not node.args else None
                inner = self.frames_of(operand if operand is not None else (node.args[0] if node.args else None))
                return inner.inverted() if inner is not None and inner.is_operator else None
            pair = _product_operands(node)
            if pair is not None:
                return _product(self.frames_of(pair[0]), self.frames_of(pair[1]))
            if isinstance(node.func, ast.Attribute):  # Transform[A, B].from_matrix(...)
                return self.transform_type(node.func.value)
        return None

    def mismatch(self, node: ast.AST) -> tuple[str, str] | None:
        """The two frames a node wrongly takes to be the same, if it does."""
        if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.MatMult, ast.Mult)):
            return _inner_mismatch(self.frames_of(node.left), self.frames_of(node.right))
        if isinstance(node, ast.Call):
            pair = _product_operands(node)
            if pair is not None:
                return _inner_mismatch(self.frames_of(pair[0]), self.frames_of(pair[1]))
        if isinstance(node, ast.Attribute) and node.attr == "T":
            inner = self.frames_of(node.value)
            if inner is not None and inner.operator == "transform" and inner.dst and inner.src:
                return inner.src, inner.dst  # the drawn "inverse" that a transpose is not
        if isinstance(node, (ast.Assign, ast.AnnAssign)) and node.value is not None:
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            value = self.frames_of(node.value)
            for target in targets:
                found = _assign_mismatch(self.frames_of(target), value)
                if found is not None:
                    return found
        return None

    # ---- collecting ------------------------------------------------------------------------------

    def location(self, node: ast.AST) -> str:
        return f"{self.path}:{getattr(node, 'lineno', 0)}"

    def add_edge(self, frames: NameFrames | None, label: str, node: ast.AST) -> None:
        if frames is None:
            return
        if frames.is_operator:
            assert frames.dst is not None and frames.src is not None
            key = (frames.dst, frames.src, label)
            self.edges.setdefault(key, FrameEdge(frames.dst, frames.src, label, location=self.location(node)))
        elif frames.frame is not None:
            self.frames.add(frames.frame)

    def collect_frame_classes(self, module: ast.Module) -> None:
        self.frame_classes = typed.frame_classes(module)

    def claim_types(self, node: ast.AST) -> None:
        self.claimed.update(id(inner) for inner in ast.walk(node) if isinstance(inner, ast.Subscript))

    def visit_Name(self, node: ast.Name) -> None:
        self.add_edge(self.name_frames(node.id), node.id, node)

    def visit_Attribute(self, node: ast.Attribute) -> None:
        self.add_edge(self.name_frames(node.attr), node.attr, node)
        self.generic_visit(node)

    def visit_arg(self, node: ast.arg) -> None:
        typed = self.transform_type(node.annotation)
        if typed is not None:
            self.typed[node.arg] = typed
            self.add_edge(typed, node.arg, node)
        else:
            self.add_edge(self.name_frames(node.arg), node.arg, node)

    def visit_AnnAssign(self, node: ast.AnnAssign) -> None:
        typed = self.transform_type(node.annotation)
        if typed is not None and isinstance(node.target, ast.Name):
            self.typed[node.target.id] = typed
            self.add_edge(typed, node.target.id, node)
            if node.value is not None:
                self.claim_types(node.value)
        if _name_of(node.annotation) == "FrameTree" and isinstance(node.target, ast.Name):
            self.trees.add(node.target.id)
        # Not the annotation itself: its Transform[...] is this variable's edge, drawn above.
        self.visit(node.target)
        if node.value is not None:
            self.visit(node.value)

    def visit_Assign(self, node: ast.Assign) -> None:
        if isinstance(node.value, ast.Call) and _name_of(node.value.func) == "FrameTree":
            self.trees.update(target.id for target in node.targets if isinstance(target, ast.Name))
        typed = self._constructed_type(node.value)
        if typed is not None:  # `T = Transform[World, Cam].from_matrix(M)`: the edge is called T
            for target in node.targets:
                if isinstance(target, ast.Name):
                    self.typed[target.id] = typed
                    self.add_edge(typed, target.id, node)
            self.claim_types(node.value)
        self.generic_visit(node)

    def _constructed_type(self, node: ast.AST) -> NameFrames | None:
        while isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
            node = node.func.value
        if isinstance(node, ast.Call):
            node = node.func
        return self.transform_type(node)

    def visit_Subscript(self, node: ast.Subscript) -> None:
        typed = self.transform_type(node)
        if typed is not None and id(node) not in self.claimed:
            self.add_edge(typed, _segment(self.source, node), node)
        self.generic_visit(node)

    def visit_Call(self, node: ast.Call) -> None:
        func = node.func
        if (
            isinstance(func, ast.Attribute)
            and func.attr == "add"
            and node.args
            and (_name_of(func.value) in self.trees or "tree" in (_name_of(func.value) or "").lower())
        ):
            frames = self.frames_of(node.args[0])
            if frames is not None and frames.is_operator:
                self.add_edge(frames, _segment(self.source, node), node)
                self.claim_types(node.args[0])
        self.generic_visit(node)

    # ---- findings ------------------------------------------------------------------------------

    def _span(self, node: ast.AST) -> tuple[int, int, int, int]:
        """A node's span as findings give it: 1-based character columns, end exclusive."""
        start, end = getattr(node, "lineno", 0), getattr(node, "end_lineno", 0) or 0
        return (
            start,
            self._characters(start, getattr(node, "col_offset", 0)) + 1,
            end,
            self._characters(end, getattr(node, "end_col_offset", 0) or 0) + 1,
        )

    def _characters(self, line: int, byte_offset: int) -> int:
        if not self.lines:
            self.lines = _LINE_BREAKS.split(self.source)  # the lines `ast` counts (not at form feeds)
        text = self.lines[line - 1] if 0 < line <= len(self.lines) else ""
        return byte_offset if text.isascii() else len(text.encode("utf-8")[:byte_offset].decode("utf-8", errors="replace"))

    def add_mismatches(self, module: ast.Module, findings: Iterable[Finding]) -> None:
        nodes = [node for node in ast.walk(module) if isinstance(node, (ast.expr, ast.stmt))]
        for finding in findings:
            if not finding.code.startswith(MISMATCH_PREFIX):
                continue
            inside = [
                node
                for node in nodes
                if node.lineno >= finding.line and (node.end_lineno or node.lineno) <= finding.end_line
            ]
            enclosing = [
                node
                for node in nodes
                if isinstance(node, ast.stmt) and node.lineno <= finding.line <= (node.end_lineno or node.lineno)
            ]
            # Smallest candidates first: the flagged expression, then the statement around it.
            ordered = sorted(inside, key=_extent) + sorted(enclosing, key=_extent)
            flagged = [node for node in inside if self._span(node) == (finding.line, finding.column, finding.end_line, finding.end_column)]
            if finding.frames is not None and flagged:
                ordered = flagged[:1]  # the rule recorded the frames that differ: label the flagged expression
            for node in ordered:
                pair = finding.frames or self.mismatch(node)
                if pair is None:
                    continue
                pair = (self._canon(pair[0]), self._canon(pair[1]))
                label = f"{finding.code}: {_segment(self.source, node)}"
                edge = FrameEdge(pair[0], pair[1], label, mismatch=True, location=f"{self.path}:{finding.line}")
                self.edges.setdefault((pair[0], pair[1], label), edge)
                break


def _name_of(node: ast.AST | None) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return node.attr
    return None


def _product_operands(call: ast.Call) -> tuple[ast.expr, ast.expr] | None:
    """`np.dot(a, b)`, `np.matmul(a, b)` -> (a, b); `a.dot(b)` -> (a, b)."""
    callee = _name_of(call.func)
    if callee not in _PRODUCT_CALLS:
        return None
    if len(call.args) == 2:
        return call.args[0], call.args[1]
    if len(call.args) == 1 and isinstance(call.func, ast.Attribute) and _name_of(call.func.value) not in {"np", "numpy"}:
        return call.func.value, call.args[0]
    return None


def _product(left: NameFrames | None, right: NameFrames | None) -> NameFrames | None:
    if left is None or right is None or not left.is_operator:
        return None
    if right.is_operator:
        return NameFrames(dst=left.dst, src=right.src, operator=left.operator)
    return NameFrames(frame=left.dst) if right.frame is not None else None


def _inner_mismatch(left: NameFrames | None, right: NameFrames | None) -> tuple[str, str] | None:
    if left is None or right is None or not left.is_operator or left.src is None:
        return None
    other = right.dst if right.is_operator else right.frame
    if same_frame(left.src, other) is False:
        assert other is not None
        return left.src, other
    return None


def _assign_mismatch(target: NameFrames | None, value: NameFrames | None) -> tuple[str, str] | None:
    if target is None or value is None:
        return None
    if target.frame is not None and value.frame is not None and same_frame(target.frame, value.frame) is False:
        return target.frame, value.frame
    if target.is_operator and value.is_operator:
        for wanted, got in ((target.dst, value.dst), (target.src, value.src)):
            if same_frame(wanted, got) is False:
                assert wanted is not None and got is not None
                return wanted, got
    return None


def _extent(node: ast.AST) -> tuple[int, int, int]:
    lines = (getattr(node, "end_lineno", 0) or 0) - getattr(node, "lineno", 0)
    width = (getattr(node, "end_col_offset", 0) or 0) - getattr(node, "col_offset", 0)
    return lines, width if lines == 0 else 0, getattr(node, "col_offset", 0)


def _segment(source: str, node: ast.AST) -> str:
    text = " ".join((ast.get_source_segment(source, node) or "").split())
    return text if len(text) <= _LABEL_WIDTH else text[: _LABEL_WIDTH - 1] + "…"


def graph_of_source(
    source: str, path: str, config: Config = Config(), findings: Sequence[Finding] = (), location: str | None = None
) -> FrameGraph:
    """The frame graph of one module's text; `findings` (its lint findings) add the red edges.

    `T_a_b` names are read in the order the linter uses for the file at `location` (default
    `path`): the config's `naming`, else what the project declares. Code that does not parse
    gives an empty graph (the linter reports it as GEO000).
    """
    try:
        module = parse_module(source)
    except (SyntaxError, ValueError):
        return FrameGraph()
    reading = orders_for(location or path, source, module, config.naming.order)
    reader = _FileReader(source, path, naming_config(config, reading), orders=reading.orders, order_names_mixed=reading.mixed)
    reader.collect_frame_classes(module)
    reader.visit(module)
    reader.add_mismatches(module, findings)
    return FrameGraph(edges=tuple(reader.edges.values()), frames=tuple(sorted(reader.frames)))


def merge(graphs: Iterable[FrameGraph], name: str = "frames") -> FrameGraph:
    """One graph with every frame and edge of `graphs`.

    A transform spelled the same way in many files is drawn once, at its first location;
    every mismatch is kept, since each one is a separate bug.
    """
    edges: dict[tuple[str, str, str, str], FrameEdge] = {}
    frames: set[str] = set()
    for graph in graphs:
        for edge in graph.edges:
            place = edge.location if edge.mismatch else ""
            edges.setdefault((edge.parent, edge.child, edge.label, place), edge)
        frames.update(graph.frames)
    return FrameGraph(edges=tuple(edges.values()), frames=tuple(sorted(frames)), name=name)


def graph_of_paths(paths: Sequence[Path], config: Config | None = None) -> FrameGraph:
    """The frame graph of files and folders, with the linter's GEO2xx findings as red edges.

    Files are found and linted through `geolint.api.lint_paths`, exactly as `geolint check` finds
    them; the config is the one `geolint check` would use (the nearest `[tool.geolint]`).
    """
    from geolint import api

    if config is None:
        config = api.find_config(Path(paths[0]) if paths else Path.cwd())
    graphs = []
    projects: set[str] = set()
    stating: dict[str, set[str]] = {}  # project -> its files that state tf facts
    for result in api.lint_paths(paths, config):
        location = getattr(result, "location", None) or Path(result.path)
        try:
            source = Path(location).read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError):
            continue  # the linter has already said what is wrong with it
        graph = graph_of_source(source, result.path, config, result.findings, str(location))
        root = tf_workspace.project_of(str(location))
        projects.add(root)
        if os.path.realpath(location) in stating.setdefault(root, _stating_files(root)):
            # a ROS node's tf calls say what it publishes and looks up: its variable names
            # (`laser_to_base = buffer.lookup_transform(...)`) would draw the same edges again, guessed
            graph = FrameGraph(edges=tuple(edge for edge in graph.edges if edge.mismatch), frames=graph.frames)
        graphs.append(graph)
    graphs += [tf_tree_graph(root) for root in sorted(projects)]
    return merge(graphs)


def _stating_files(root: str) -> set[str]:
    return {file for file, _ in tf_workspace.project_frames(root)}


def tf_tree_graph(root: str) -> FrameGraph:
    """The tf tree a project states (`geolint.factbase.tf_workspace`): what its nodes and launch files
    publish and its URDF joins, as edges parent -> child labelled with how; what its nodes look up as
    dotted edges target -> source. A frame that is a parameter's default is drawn when nothing in the
    project sets the parameter, and the label names it."""
    files = tf_workspace.project_frames(root)
    overridden = tf_workspace.graph_of(frames for _, frames in files).overridden
    edges = []
    for file, frames in files:
        shown = _shown_path(file, root)
        for edge in (settled(published, overridden) for published in frames.published):
            if edge.parent is not None and edge.child is not None:
                edges.append(FrameEdge(edge.parent, edge.child, _label(edge), location=f"{shown}:{edge.place.line}"))
        for lookup in (settled(looked_up, overridden) for looked_up in frames.looked_up):
            if lookup.target is not None and lookup.source is not None:
                edges.append(FrameEdge(lookup.target, lookup.source, _label(lookup), location=f"{shown}:{lookup.place.line}", lookup=True))
    return FrameGraph(edges=tuple(edges))


def _label(statement: Published | LookedUp) -> str:
    """How a statement is made, with the parameters whose defaults gave its frames."""
    if not statement.parameters:
        return statement.how
    return f"{statement.how} (defaults of {', '.join(parameter for _, parameter in statement.parameters)})"


def _shown_path(file: str, root: str) -> str:
    """A project file as the drawing names it: relative to the working folder when inside it, else to the project."""
    relative = os.path.relpath(file)
    return relative if not relative.startswith("..") else os.path.relpath(file, root)
