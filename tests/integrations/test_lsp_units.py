"""The plain functions under the language server: positions, the ignore-comment edit and the
fix-all edit. (The server itself is tested end to end in test_lsp.py.)"""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st
from lsprotocol import types
from pygls.workspace.position_codec import PositionCodec

from geolint import api
from geolint.lint_types import Edit
from geolint.lsp.actions import changed_region_edit, ignore_edit
from geolint.lsp.positions import from_lsp_position, split_lines, to_lsp_position
from tests.conftest import DECLARES_DST_FIRST

UTF16 = PositionCodec(types.PositionEncodingKind.Utf16)
UTF8 = PositionCodec(types.PositionEncodingKind.Utf8)


def apply_lsp_style(text: str, edit: Edit) -> str:
    """Apply an edit whose positions count lines the LSP way (\\n, \\r\\n, \\r only)."""
    starts = [0] + [m.end() for m in re.finditer(r"\r\n|\r|\n", text)]

    def offset(line: int, column: int) -> int:
        return starts[line - 1] + column - 1

    return text[: offset(edit.line, edit.column)] + edit.content + text[offset(edit.end_line, edit.end_column) :]


def test_positions_count_utf16_units_and_utf8_bytes() -> None:
    lines = split_lines('s = "\U0001f916é" + x\n')
    column = lines[0].index("x") + 1
    assert to_lsp_position(lines, UTF16, 1, column).character == column - 1 + 1  # the robot is 2 units
    assert to_lsp_position(lines, UTF8, 1, column).character == len(lines[0][: column - 1].encode("utf-8"))
    assert from_lsp_position(lines, UTF16, types.Position(0, column)) == (1, column)


def test_lines_split_like_lsp_not_like_splitlines() -> None:
    assert split_lines("a\x0cb\u2028c\r\nd\re") == ["a\x0cb\u2028c", "d", "e"]


def test_positions_outside_the_document_are_clamped() -> None:
    lines = split_lines("ab\ncd")
    assert to_lsp_position(lines, UTF16, 9, 9) == types.Position(1, 2)
    assert from_lsp_position(lines, UTF16, types.Position(50, 50)) == (2, 3)
    assert from_lsp_position([], UTF16, types.Position(3, 3)) == (1, 1)


def test_ignore_edit_appends_after_code_and_after_other_comments() -> None:
    source = "x = R @ n + t\ny = T @ p  # type: ignore\n"
    first = ignore_edit(source, 1, "GEO101")
    assert apply_lsp_style(source, first).splitlines()[0] == "x = R @ n + t  # geolint: ignore[GEO101]"
    second = ignore_edit(source, 2, "GEO201")
    assert apply_lsp_style(source, second).splitlines()[1] == "y = T @ p  # type: ignore  # geolint: ignore[GEO201]"


def test_ignore_edit_extends_an_existing_suppression_once() -> None:
    source = "x = R @ n + t  # geolint: ignore[GEO101]\n"
    extended = apply_lsp_style(source, ignore_edit(source, 1, "GEO203"))
    assert extended == "x = R @ n + t  # geolint: ignore[GEO101, GEO203]\n"
    assert ignore_edit(extended, 1, "GEO101") is None


def test_ignore_edit_refuses_lines_that_end_inside_a_string() -> None:
    source = 'doc = """first\nsecond"""\n'
    assert ignore_edit(source, 1, "GEO101") is None
    assert ignore_edit(source, 2, "GEO101") is not None
    assert ignore_edit(source, 7, "GEO101") is None


def test_ignore_edit_is_honoured_by_the_linter() -> None:
    source = "def f(R_world_cam, normal_cam, t_world_cam):\n    return R_world_cam @ normal_cam + t_world_cam\n"
    (finding,) = [f for f in api.lint_text(source, "m.py") if f.code == "GEO101"]
    suppressed = apply_lsp_style(source, ignore_edit(source, finding.line, "GEO101"))
    assert api.lint_text(suppressed, "m.py") == []


def test_ignore_edit_on_code_that_does_not_tokenize() -> None:
    source = "x = (R @ n + t  # note\n"
    assert apply_lsp_style(source, ignore_edit(source, 1, "GEO101")) == "x = (R @ n + t  # note  # geolint: ignore[GEO101]\n"


@settings(max_examples=400, deadline=None, derandomize=True)
@given(st.text(alphabet="ab \n\r\U0001f916", max_size=14), st.text(alphabet="ab \n\r\U0001f916", max_size=14))
def test_changed_region_edit_turns_old_into_new(old: str, new: str) -> None:
    edit = changed_region_edit(old, new)
    assert apply_lsp_style(old, edit) == new
    assert len(edit.content) <= len(new)


def test_ignore_edit_extends_a_noqa_list_instead_of_adding_a_second_directive() -> None:
    source = (
        "def f(R_world_cam, normal_cam, t_world_cam, T_world_base, p_cam):\n"
        "    a = R_world_cam @ normal_cam + t_world_cam; b = T_world_base @ p_cam  # noqa: E501, GEO101\n"
    )
    assert [f.code for f in api.lint_text(source + DECLARES_DST_FIRST, "m.py")] == ["GEO201"]
    extended = apply_lsp_style(source, ignore_edit(source, 2, "GEO201"))
    assert extended.endswith("# noqa: E501, GEO101, GEO201\n")
    assert api.lint_text(extended + DECLARES_DST_FIRST, "m.py") == []
    assert ignore_edit("x = R @ n + t  # noqa\n", 1, "GEO101") is None


def test_ignore_edit_counts_lines_like_the_linter() -> None:
    # A form feed is not a line break for Python or LSP (str.splitlines would say it is).
    source = "a = 1\x0c  # page\nx = R @ n + t\n"
    assert apply_lsp_style(source, ignore_edit(source, 2, "GEO101")).endswith("x = R @ n + t  # geolint: ignore[GEO101]\n")


def test_ignore_edit_finds_the_comment_on_a_line_that_ends_in_a_lone_cr() -> None:
    for newline in ("\n", "\r\n", "\r"):
        source = f"x = 1{newline}y = R @ n + t  # noqa: GEO201{newline}"
        edit = ignore_edit(source, 2, "GEO101")
        assert edit is not None
        assert split_lines(apply_lsp_style(source, edit))[1] == "y = R @ n + t  # noqa: GEO201, GEO101"
