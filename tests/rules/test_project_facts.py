"""Whole-project evidence: the naming order learned from declarations, helper summaries across
modules, and the findings cache re-linting a module when a helper it imports changes."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

from geolint import api
from geolint.config import config_from_table
from geolint.lint_types import Config
from geolint.factbase.conventions import Votes, votes_of_source
from geolint.factbase.model import DST_FIRST, SRC_FIRST

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures" / "projects"


def test_declarations_decide_the_order() -> None:
    src_first = 'T_obj_world = RigidTransform(R, t, from_frame="obj", to_frame="world")\n'
    dst_first = 'T_stp_obj = RigidTransform(R, t, from_frame="obj", to_frame="stp")\n'
    assert votes_of_source(src_first).orders() == (SRC_FIRST,)
    assert votes_of_source(dst_first).orders() == (DST_FIRST,)
    both = votes_of_source(src_first + dst_first)
    assert both.mixed and both.orders() == (DST_FIRST, SRC_FIRST)


def test_compositions_decide_when_nothing_is_declared() -> None:
    assert votes_of_source("T_world_tool = T_world_base @ T_base_tool\n").orders() == (DST_FIRST,)
    assert votes_of_source("T_grasp_world = T_obj_world * T_grasp_obj\n").orders() == (SRC_FIRST,)
    assert Votes().orders() == (DST_FIRST, SRC_FIRST)  # no evidence: both readings stay open


def test_only_declarations_state_the_convention() -> None:
    src_first = 'T_obj_world = RigidTransform(R, t, from_frame="obj", to_frame="world")\n'
    dst_first = 'T_stp_obj = RigidTransform(R, t, from_frame="obj", to_frame="stp")\n'
    assert votes_of_source(src_first).stated and votes_of_source(dst_first).stated
    assert not votes_of_source(src_first + dst_first).stated  # both orders: mixed
    # compositions choose the reading, but a project's own compositions do not make its names evidence
    composed = votes_of_source("T_world_tool = T_world_base @ T_base_tool\n" * 5)
    assert composed.orders() == (DST_FIRST,) and not composed.stated
    assert not Votes().stated


NAMES_ONLY = "def f(T_world_cam, p_base, T_world_base, T_cam_tool):\n    return T_world_cam @ p_base, T_world_base @ T_cam_tool\n"


def _frame_codes(source: str, config: Config = Config()) -> list[str]:
    return [f.code for f in api.lint_text(source, "m.py", config) if f.code.startswith("GEO2")]


def test_names_on_both_sides_are_reported_only_where_the_convention_is_stated() -> None:
    # unstated (no config, no declaration; compositions alone do not state it): names are too weak
    assert _frame_codes(NAMES_ONLY) == []
    assert _frame_codes(NAMES_ONLY + "T_world_tool = T_world_base @ T_base_tool\n" * 5) == []
    # stated by the config, in either order
    assert _frame_codes(NAMES_ONLY, config_from_table({"naming": "dst-first"}, None)) == ["GEO201", "GEO202"]
    assert _frame_codes(NAMES_ONLY, config_from_table({"naming": "src-first"}, None)) == ["GEO201", "GEO202"]
    # stated by a declaration bound to a `T_a_b` name, in one order only
    declared = 'T_world_base = RigidTransform(R, t, from_frame="base", to_frame="world")\n'
    assert _frame_codes(NAMES_ONLY + declared) == ["GEO201", "GEO202"]
    mixed = declared + 'T_obj_world = RigidTransform(R, t, from_frame="obj", to_frame="world")\n'
    assert _frame_codes("def f(p_base):\n    return cam2world @ p_base\n" + mixed) == []


def test_a_declared_side_is_evidence_enough_without_a_stated_convention() -> None:
    source = (
        "def f(buffer, stamp, p_base, T_base_tool):\n"
        "    lookup = buffer.lookup_transform('world', 'cam', stamp)\n"
        "    return lookup @ p_base, lookup @ T_base_tool\n"
    )
    found = [f for f in api.lint_text(source, "m.py") if f.code.startswith("GEO2")]
    assert [f.code for f in found] == ["GEO201", "GEO202"]
    assert all(any("lookup_transform" in reason for reason in f.evidence) for f in found)


def test_a_declaration_in_one_module_states_the_convention_for_the_whole_project(tmp_path: Path) -> None:
    def frame_codes() -> list[str]:  # the real CLI: a fresh process reads the project's declarations afresh
        completed = subprocess.run(
            [sys.executable, "-m", "geolint", "check", "--no-cache", "--format", "json", "."],
            cwd=tmp_path, capture_output=True, text=True, timeout=120,
        )  # fmt: skip
        return sorted(f["code"] for f in json.loads(completed.stdout) if f["code"].startswith("GEO2"))

    (tmp_path / "setup.py").write_text("")
    (tmp_path / "poses.py").write_text('T_world_base = RigidTransform(R, t, from_frame="base", to_frame="world")\n')
    (tmp_path / "planner.py").write_text(NAMES_ONLY)
    assert frame_codes() == ["GEO201", "GEO202"]
    (tmp_path / "poses.py").write_text("T_world_base = load()\n")
    assert frame_codes() == []


def _findings(root: Path) -> list:
    return [f for result in api.lint_paths([root], cache_dir=root / ".cache") for f in result.findings]


def test_a_helper_edit_relints_its_importers(tmp_path: Path) -> None:
    project = tmp_path / "slam_helpers"
    shutil.copytree(FIXTURES / "slam_helpers", project)
    before = {(Path(f.path).name, f.line, f.code) for f in _findings(project)}
    assert ("mapping.py", 20, "GEO101") in before
    helper = project / "slam" / "geometry.py"
    helper.write_text(helper.read_text().replace("points @ rotation.T + translation", "points @ rotation.T"))
    stats: dict[str, int] = {}
    after = [f for result in api.lint_paths([project], cache_dir=project / ".cache", stats=stats) for f in result.findings]
    assert ("mapping.py", 20, "GEO101") not in {(Path(f.path).name, f.line, f.code) for f in after}
    assert stats["linted"] >= 2  # the helper and the module that imports it


def test_a_package_no_project_folder_holds_has_no_summary(tmp_path: Path) -> None:
    """Calls into packages outside the project (`gym.make`, `time.sleep`) are ruled out by the run's
    folder listings before any argument is looked at; the project's own packages still are read."""
    import ast

    from geolint.factbase import facts_for_module
    from geolint.factbase.project_files import folder_listings, may_be_project_module
    from geolint.lint_types import Config

    (tmp_path / "pyproject.toml").write_text("[project]\nname = 'demo'\n")
    (tmp_path / "geom").mkdir()
    (tmp_path / "geom" / "__init__.py").write_text("")
    (tmp_path / "geom" / "ops.py").write_text("def apply_pose(T, x):\n    return T[:3, :3] @ x + T[:3, 3]\n")
    (tmp_path / "helpers.py").write_text("def scale(x):\n    return 2 * x\n")
    main = tmp_path / "main.py"
    source = "import gym, time\nfrom geom.ops import apply_pose\nimport helpers\ngym.make(n)\ntime.sleep(n)\napply_pose(T, n)\nhelpers.scale(n)\n"
    main.write_text(source)
    tree = ast.parse(source)
    calls = [node for node in ast.walk(tree) if isinstance(node, ast.Call)]
    calls.sort(key=lambda call: call.lineno)
    with folder_listings():
        assert not may_be_project_module("gym", str(main)) and may_be_project_module("geom", str(main))
        assert may_be_project_module("helpers", str(main))  # a module file beside the importer
        facts = facts_for_module(tree, source, str(main), Config())
        assert [facts.may_have_summary(call) for call in calls] == [False, False, True, True]
    assert may_be_project_module("gym", str(tmp_path / "other.py"))  # no listing: nothing is ruled out
