"""A project module that the summaries of imported helpers parsed is not parsed again when it is
linted (the engine takes that tree), the engine leaves its own trees to nobody (few modules are
imported after they are linted), and a shared tree never stands in for other text: an unsaved
editor buffer, or a file edited on disk since."""

from __future__ import annotations

import ast
import shutil
from pathlib import Path

import pytest

from geolint import api, engine
from geolint.factbase.index import index_of_file, shared_parse

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures" / "projects"
TRANSLATED = "points @ rotation.T + translation"


@pytest.fixture
def project(tmp_path: Path) -> Path:
    root = tmp_path / "slam_helpers"
    shutil.copytree(FIXTURES / "slam_helpers", root)
    return root


def _mapping_findings(project: Path) -> set[tuple[int, str]]:
    mapping = project / "slam" / "mapping.py"
    return {(finding.line, finding.code) for finding in api.lint_text(mapping.read_text(), mapping)}


def test_the_engine_takes_the_tree_the_summaries_parsed(project: Path) -> None:
    assert {(20, "GEO101"), (21, "GEO101")} <= _mapping_findings(project)  # reads geometry.py's summaries
    geometry = project / "slam" / "geometry.py"
    text = geometry.read_text()
    api.lint_text(text, geometry)
    assert engine.cached_ast(text) is index_of_file(geometry).tree  # not parsed a second time


def test_the_engine_keeps_no_tree_of_its_own_for_importers(project: Path) -> None:
    geometry = project / "slam" / "geometry.py"
    text = geometry.read_text()
    api.lint_text(text, geometry)
    assert shared_parse(str(geometry), text) is None
    assert index_of_file(geometry).tree is not engine.cached_ast(text)  # the importer's parse, from the file
    assert {(20, "GEO101"), (21, "GEO101")} <= _mapping_findings(project)


def test_an_unsaved_buffer_never_stands_in_for_the_file(project: Path) -> None:
    geometry = project / "slam" / "geometry.py"
    buffer = geometry.read_text().replace(TRANSLATED, "points @ rotation.T")
    api.lint_text(buffer, geometry)  # an editor lints its unsaved text under the file's path
    assert (20, "GEO101") in _mapping_findings(project)  # the importer reads the file on disk


def test_a_module_edited_on_disk_is_read_again(project: Path) -> None:
    geometry = project / "slam" / "geometry.py"
    api.lint_text(geometry.read_text(), geometry)
    assert (20, "GEO101") in _mapping_findings(project)
    geometry.write_text(geometry.read_text().replace(TRANSLATED, "points @ rotation.T"))
    assert (20, "GEO101") not in _mapping_findings(project)


def test_a_lint_leaves_no_cycle_holding_its_trees(project: Path) -> None:
    # The fact bases of the linted module and of the helpers it read refer to each other through the
    # project's summaries; the engine closes them, so reference counting frees every tree at once and
    # the cycle collector (run rarely while linting) has nothing to find.
    import gc

    from geolint.factbase.model import FactBase

    gc.collect()
    gc.disable()
    gc.set_debug(gc.DEBUG_SAVEALL)
    try:
        assert {(20, "GEO101"), (21, "GEO101")} <= _mapping_findings(project)  # summaries across modules were read
        gc.collect()
        left_in_cycles = [item for item in gc.garbage if isinstance(item, (FactBase, ast.AST))]
    finally:
        gc.set_debug(0)
        gc.garbage.clear()
        gc.enable()
    assert left_in_cycles == []
