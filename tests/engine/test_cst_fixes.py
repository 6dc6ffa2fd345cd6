"""Fixes as libcst transformations (`geolint.cst_fixes`): a replacement becomes an edit only when it is
a node libcst can put in the reported node's place, and applying edits replaces those nodes in the tree
and keeps everything else as it was."""

from __future__ import annotations

from geolint import cst_fixes, engine
from geolint.fixes import fix_source
from geolint.lint_types import Edit


def built(source: str, edit: Edit) -> Edit | None:
    (made,) = cst_fixes.build_edits(source, [edit])
    return made


def test_an_expression_replacement_is_the_edit_asked_for_and_keeps_the_parentheses_around_it() -> None:
    source = "x = (  # why\n    a + b\n) * 2\n"
    edit = Edit(2, 5, 2, 10, "2 * a")
    assert built(source, edit) == edit
    assert cst_fixes.apply_edits(source, [edit]) == "x = (  # why\n    2 * a\n) * 2\n"


def test_a_tuple_span_with_its_parentheses_is_the_tuple_node() -> None:
    # `ast` counts a tuple's parentheses as part of it, libcst as the tuple's own lpar/rpar
    source = "r = R.from_quat(((qw, qx, qy, qz)))\n"
    edit = Edit(1, 18, 1, 34, "(qx, qy, qz, qw)")
    assert built(source, edit) == edit
    assert cst_fixes.apply_edits(source, [edit]) == "r = R.from_quat(((qx, qy, qz, qw)))\n"


def test_a_multi_line_replacement_keeps_the_file_line_endings_as_given() -> None:
    source = "n_h = np.append(\r\n    normal, 1)\r\n"
    edit = Edit(1, 7, 2, 15, "np.append(\r\n    normal, 0)")
    assert built(source, edit) == edit
    assert cst_fixes.apply_edits(source, [edit]) == "n_h = np.append(\r\n    normal, 0)\r\n"


def test_no_edit_for_a_span_that_is_no_node_or_text_that_is_no_node() -> None:
    source = "x = a + b\n"
    assert built(source, Edit(1, 5, 1, 8, "c")) is None  # `a +` is no node
    assert built(source, Edit(1, 5, 1, 10, "a +")) is None  # does not parse
    assert built(source, Edit(1, 5, 1, 10, "a  # b")) is None  # a comment would not be written back as given
    assert cst_fixes.apply_edits(source, [Edit(1, 5, 1, 8, "c")]) is None


def test_a_statement_added_below_a_line_keeps_its_comment_there_and_the_file_newline() -> None:
    source = "def f(q):\r\n    t.x = q.x  # copied\r\n    return t\r\n"
    edit = built(source, Edit(2, 5, 2, 14, "t.x = q.x\n    t.w = q.w"))
    assert edit == Edit(2, 5, 2, 24, "t.x = q.x  # copied\r\n    t.w = q.w")
    fixed = "def f(q):\r\n    t.x = q.x  # copied\r\n    t.w = q.w\r\n    return t\r\n"
    assert cst_fixes.apply_edits(source, [edit]) == engine.apply_edits(source, [edit]) == fixed


def test_a_cr_only_file_keeps_its_last_line_ending() -> None:
    # libcst writes such a module back without its last "\r"; the fix must not drop it
    source = "import numpy as np\rnormal_h = np.append(normal, 1)\r"
    outcome = fix_source(source, "x.py")
    assert outcome.source == "import numpy as np\rnormal_h = np.append(normal, 0)\r" and outcome.fixed == 1


def test_a_real_rule_fix_is_built_through_libcst_and_keeps_an_inner_comment() -> None:
    source = "import numpy as np\nnormal_h = np.append(\n    normal,  # the surface normal\n    1,\n)\n"
    (finding,) = [f for f in engine.lint_source(source, "x.py") if f.code == "GEO101"]
    assert finding.fix is not None
    fixed = "import numpy as np\nnormal_h = np.append(\n    normal,  # the surface normal\n    0,\n)\n"
    assert cst_fixes.apply_edits(source, finding.fix.edits) == fixed


def test_a_fix_that_adds_a_statement_keeps_a_comment_on_the_line_it_annotates() -> None:
    # GEO306 copies the missing component after the last copied one; as a text edit over the node's
    # span it put the new statement before the line's comment, and the comment ended on the new line
    source = (
        "from geometry_msgs.msg import Pose\ndef f(rotation):\n    pose = Pose()\n    pose.orientation.x = rotation.x\n"
        "    pose.orientation.y = rotation.y\n    pose.orientation.z = rotation.z  # the source's z\n    return pose\n"
    )
    outcome = fix_source(source, "x.py", unsafe=True)
    assert outcome.source == source.replace(
        "  # the source's z\n", "  # the source's z\n    pose.orientation.w = rotation.w\n"
    ) and outcome.fixed == 1
