"""Positions between geolint (1-based line, 1-based code-point column) and LSP (0-based, in the
client's negotiated encoding: UTF-16 code units unless the client asked for UTF-8 or UTF-32).

Lines are split the way LSP splits them (\\n, \\r\\n, \\r), not with `str.splitlines`, which also
breaks on form feeds and U+2028 and would shift every position after one.
"""

from __future__ import annotations

from typing import Sequence

from lsprotocol import types
from pygls.workspace.position_codec import PositionCodec

from geolint import engine


def split_lines(source: str) -> list[str]:
    """The lines of `source` without their line breaks (a trailing break gives a last empty line).

    The linter's `engine.split_lines` (which keeps the breaks and has no empty last line) is the rule.
    """
    lines = [line.rstrip("\r\n") for line in engine.split_lines(source)]
    if not source or source.endswith(("\n", "\r")):
        lines.append("")
    return lines


def to_lsp_position(lines: Sequence[str], codec: PositionCodec, line: int, column: int) -> types.Position:
    """A geolint (line, column) as an LSP Position; positions past the end are clamped to it."""
    line_index = min(max(line - 1, 0), max(len(lines) - 1, 0))
    if line - 1 >= len(lines):  # just past the last line: end of the document
        text = lines[-1] if lines else ""
        return types.Position(line=line_index, character=codec.client_num_units(text))
    text = lines[line_index] if lines else ""
    return types.Position(line=line_index, character=codec.client_num_units(text[: max(column - 1, 0)]))


def to_lsp_range(
    lines: Sequence[str], codec: PositionCodec, line: int, column: int, end_line: int, end_column: int
) -> types.Range:
    return types.Range(
        start=to_lsp_position(lines, codec, line, column),
        end=to_lsp_position(lines, codec, end_line, end_column),
    )


def from_lsp_position(lines: Sequence[str], codec: PositionCodec, position: types.Position) -> tuple[int, int]:
    """An LSP Position as a geolint (line, column), clamped into the document."""
    if not lines:
        return 1, 1
    line_index = min(max(position.line, 0), len(lines) - 1)
    text = lines[line_index]
    units = 0
    for index, char in enumerate(text):
        if units >= position.character:
            return line_index + 1, index + 1
        units += codec.client_num_units(char)
    return line_index + 1, len(text) + 1
