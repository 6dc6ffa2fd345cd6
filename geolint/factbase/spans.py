"""The source text of a node with some of its inner nodes replaced (`replace_span`): how a fix is
written from the fact base's nodes, with character offsets from `ast`'s UTF-8 byte columns."""

from __future__ import annotations

from ast import AST, Attribute
from dataclasses import dataclass

from geolint.factbase.index import ModuleIndex
from geolint.source_text import split_lines


@dataclass(frozen=True)
class LastNameTarget:
    """An edit target: only the last name of a called function (`np.ones` -> its `ones`)."""

    func: AST


def last_name_target(func: AST) -> LastNameTarget:
    """An edit target for `replace_span` that replaces only a called function's last name."""
    return LastNameTarget(func)


def replace_span(index: ModuleIndex, outer: AST, edits: list[tuple[AST | LastNameTarget, str]]) -> str | None:
    """The source text of `outer` with each inner node's span replaced (for a `LastNameTarget` target,
    only the function's last name)."""
    text = index.segment(outer)
    if not text:
        return None
    base = _offset(index, outer.lineno, outer.col_offset)  # type: ignore[attr-defined]
    pieces = []
    for node, new in edits:
        if isinstance(node, LastNameTarget):
            node = node.func
            if not isinstance(node, Attribute):
                start = _offset(index, node.lineno, node.col_offset)  # type: ignore[attr-defined]
                end = _offset(index, node.end_lineno, node.end_col_offset)  # type: ignore[attr-defined,arg-type]
                if start is None or end is None or base is None:
                    return None
                pieces.append((start - base, end - base, new))
                continue
            end = _offset(index, node.end_lineno, node.end_col_offset)  # type: ignore[arg-type]
            start = None if end is None else end - len(node.attr)
        else:
            start = _offset(index, node.lineno, node.col_offset)  # type: ignore[attr-defined]
            end = _offset(index, node.end_lineno, node.end_col_offset)  # type: ignore[attr-defined,arg-type]
        if start is None or end is None or base is None:
            return None
        pieces.append((start - base, end - base, new))
    for start, end, new in sorted(pieces, reverse=True):
        if start < 0 or end > len(text):
            return None
        text = text[:start] + new + text[end:]
    return text


def _offset(index: ModuleIndex, line: int | None, byte_column: int | None) -> int | None:
    """The character offset in the module's source of an ast (line, UTF-8 byte column)."""
    if line is None or byte_column is None:
        return None
    starts = index.line_starts
    if starts is None:
        lines = split_lines(index.source)
        starts = [0]
        for text in lines:
            starts.append(starts[-1] + len(text))
        index.line_starts, index.line_texts = starts, lines
    lines = index.line_texts or []
    if not 1 <= line <= len(lines):
        return None
    text = lines[line - 1]
    column = byte_column if text.isascii() else len(text.encode("utf-8")[:byte_column].decode("utf-8", errors="replace"))
    return starts[line - 1] + column  # type: ignore[no-any-return]
