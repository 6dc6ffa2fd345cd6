"""Whole-project evidence: the naming order learned from declarations, helper summaries across
modules, and the findings cache re-linting a module when a helper it imports changes."""

from __future__ import annotations

import shutil
from pathlib import Path

from geolint import api
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
