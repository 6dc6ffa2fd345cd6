"""`geolint frames`: the graph read from code, through the real CLI, against a golden DOT file,
plus the graph builder on small sources for each way a frame edge can be spelled.

To regenerate the golden file after an intended change:
`cd fixtures/frames && geolint frames . > expected.dot` (then review the diff).
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from geolint import api
from geolint.frames_graph import graph_of_source
from geolint.lint_types import Config
from tests.conftest import DECLARES_DST_FIRST

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures" / "frames"


def frames_cli(*args: str, cwd: Path = FIXTURES) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "geolint", "frames", *args], cwd=cwd, capture_output=True, text=True, timeout=120
    )


def edges(source: str, findings: bool = False) -> set[tuple[str, str, str, bool]]:
    found = api.lint_text(source, "m.py") if findings else []
    graph = graph_of_source(source, "m.py", Config(), found)
    return {(e.parent, e.child, e.label, e.mismatch) for e in graph.edges}


def test_golden_dot() -> None:
    completed = frames_cli(".")
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout == (FIXTURES / "expected.dot").read_text(encoding="utf-8")


def test_golden_has_red_edges_for_each_frame_finding() -> None:
    dot = (FIXTURES / "expected.dot").read_text(encoding="utf-8")
    red = [line for line in dot.splitlines() if "color=red" in line]
    config = api.find_config(FIXTURES)  # the fixture's pyproject.toml states its naming convention
    findings = [
        (path.name, f.line, f.code)
        for path in sorted(FIXTURES.glob("*.py"))
        for f in api.lint_text(path.read_text(encoding="utf-8"), path.name, config)
        if f.code.startswith("GEO2")
    ]
    assert findings, "the fixture must contain frame mismatches"
    assert len(red) == len(findings)
    for name, line, code in findings:
        assert any(f"{code}: " in edge and f"{name}:{line}" in edge for edge in red), (name, line, code)


def test_mermaid_and_output_file(tmp_path: Path) -> None:
    target = tmp_path / "frames.mmd"
    completed = frames_cli(".", "--format", "mermaid", "--output", str(target))
    assert completed.returncode == 0 and completed.stdout == ""
    text = target.read_text(encoding="utf-8")
    assert text.startswith("flowchart TD\n") and "linkStyle" in text and '["lidar_link"]' in text


def test_svg_or_a_clear_message_how_to_get_graphviz() -> None:
    completed = frames_cli(".", "--format", "svg")
    if shutil.which("dot") is None:
        assert completed.returncode == 2 and "apt-get install graphviz" in completed.stderr
    else:
        assert completed.returncode == 0, completed.stderr
        assert "<svg" in completed.stdout and "lidar_link" in completed.stdout


def test_missing_path_is_an_error() -> None:
    completed = frames_cli("no/such/dir")
    assert completed.returncode == 2 and "no/such/dir" in completed.stderr


def test_unwritable_output_is_an_error(tmp_path: Path) -> None:
    target = tmp_path / "missing" / "frames.dot"
    completed = frames_cli(".", "--output", str(target))
    assert completed.returncode == 2 and "cannot write" in completed.stderr and not target.exists()


def test_each_naming_convention_gives_the_same_edge() -> None:
    for name in ("T_world_cam", "world_T_cam", "world_from_cam", "cam_to_world", "cam2world"):
        assert edges(f"{name} = load()\n") == {("world", "cam", name, False)}, name
    assert edges("from pydrake.math import RigidTransform\nX_WB = load()\n") == {("w", "b", "X_WB", False)}
    assert edges("X_EQ = load()\n") == set()  # a monogram outside Drake code: a state vector as often


def test_value_names_add_frames_not_edges() -> None:
    graph = graph_of_source("p_world = get()\nnormals_cam = get()\n", "m.py")
    assert graph.edges == () and set(graph.frames) == {"world", "cam"}


def test_typed_transforms_use_the_runtime_frame_names() -> None:
    source = """\
class Base(Frame): pass
class Lidar(Frame, name="lidar_link"): pass
def mount(pose: Transform[Base, Lidar]) -> Transform["world", Base]: ...
"""
    assert edges(source) == {
        ("base", "lidar_link", "pose", False),
        ("world", "base", 'Transform["world", Base]', False),
    }


def test_frame_tree_add_calls_are_edges() -> None:
    source = """\
tree = FrameTree()
T = Transform[Map, Odom].identity()
tree.add(T)
"""
    assert ("map", "odom", "tree.add(T)", False) in edges(source)


def test_frame_findings_become_red_edges_between_the_disagreeing_frames() -> None:
    source = """\
def f(T_world_cam, p_base, T_world_base, T_cam_tool):
    p = T_world_cam @ p_base
    T = T_world_base @ T_cam_tool
""" + DECLARES_DST_FIRST
    red = {(parent, child) for parent, child, _, mismatch in edges(source, findings=True) if mismatch}
    assert red == {("cam", "base"), ("base", "cam")}


def test_a_src_first_project_is_drawn_in_its_own_order_with_the_rules_frames(tmp_path: Path) -> None:
    """autolab_core style: `T_obj_world` maps obj into world, as the project declares. The edges
    and the red edges follow the order the linter learned, and the red edges are the frames
    the findings recorded (read in dst-first order, the names would give other pairs)."""
    (tmp_path / "setup.py").write_text("")
    (tmp_path / "grasp.py").write_text(
        "from autolab_core import RigidTransform\n"
        "\n"
        "def place(R, t, T_gripper_cam, p_base):\n"
        '    T_cam_world = RigidTransform(R, t, from_frame="cam", to_frame="world")\n'
        "    T_gripper_world = T_gripper_cam @ T_cam_world\n"
        "    p_world = T_cam_world @ p_base\n"
        "    return T_gripper_world, p_world\n"
    )
    results = api.lint_paths([tmp_path / "grasp.py"], Config(), use_cache=False)
    recorded = sorted((f.code, f.frames) for result in results for f in result.findings)
    assert recorded == [("GEO201", ("cam", "base")), ("GEO202", ("gripper", "world"))]
    completed = frames_cli(".", cwd=tmp_path)
    assert completed.returncode == 0, completed.stderr
    drawn = completed.stdout
    assert '"world" -> "cam" [label="T_cam_world' in drawn  # world <- cam: maps cam into world
    assert '"cam" -> "gripper" [label="T_gripper_cam' in drawn
    assert '"cam" -> "base" [label="GEO201: T_cam_world @ p_base' in drawn
    assert '"gripper" -> "world" [label="GEO202: T_gripper_cam @ T_cam_world' in drawn
    assert '"cam" -> "world" [label="T_cam_world' not in drawn


def test_a_project_that_declares_both_orders_draws_no_edge_for_order_names(tmp_path: Path) -> None:
    (tmp_path / "setup.py").write_text("")
    (tmp_path / "m.py").write_text(
        "from autolab_core import RigidTransform\n"
        'T_obj_world = RigidTransform(R, t, from_frame="obj", to_frame="world")\n'
        'T_world_cam = RigidTransform(R, t, from_frame="cam", to_frame="world")\n'
        "world_T_base = load()\n"
    )
    drawn = frames_cli(".", cwd=tmp_path).stdout
    assert "T_obj_world" not in drawn and "T_world_cam" not in drawn
    assert '"world" -> "base" [label="world_T_base' in drawn  # not an order-dependent name


def test_code_that_does_not_parse_gives_an_empty_graph() -> None:
    graph = graph_of_source("def f(:\n", "m.py")
    assert graph.edges == () and graph.frames == ()


def test_the_same_transform_in_many_files_is_drawn_once(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text('[tool.geolint]\nnaming = "dst-first"\n', encoding="utf-8")
    for name in ("a.py", "b.py"):
        (tmp_path / name).write_text("def f(T_world_cam, p_base):\n    return T_world_cam @ p_base\n", encoding="utf-8")
    completed = frames_cli(".", cwd=tmp_path)
    assert completed.returncode == 0, completed.stderr
    lines = completed.stdout.splitlines()
    assert len([line for line in lines if '"world" -> "cam"' in line]) == 1
    assert len([line for line in lines if "color=red" in line]) == 2  # one bug in each file


def test_a_bad_config_is_a_clear_error(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text('[tool.geolint]\nframe-aliasez = {cam = "camera"}\n', encoding="utf-8")
    (tmp_path / "a.py").write_text("T_world_cam = load()\n", encoding="utf-8")
    completed = frames_cli(".", cwd=tmp_path)
    assert completed.returncode == 2
    assert "pyproject.toml" in completed.stderr and "frame-aliasez" in completed.stderr


def test_frame_aliases_from_the_config_merge_frames(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text('[tool.geolint]\nframe-aliases = {cam = "camera"}\n', encoding="utf-8")
    (tmp_path / "a.py").write_text("T_world_cam = load()\nT_camera_tool = load()\n", encoding="utf-8")
    completed = frames_cli(".", cwd=tmp_path)
    assert completed.returncode == 0, completed.stderr
    assert '"world" -> "camera"' in completed.stdout and '"cam"' not in completed.stdout
