"""Code actions: the fix of a finding (QuickFix), "ignore GEOxxx for this line", and fix-all.

Everything here works on geolint positions and plain text; `server.py` turns the results
into LSP edits in the client's position encoding.
"""

from __future__ import annotations

import io
import tokenize
from dataclasses import dataclass

from geolint.lint_types import Edit
from geolint.lsp.positions import split_lines
from geolint.suppression import CODE_SPLIT, GEOLINT_DIRECTIVE, NOQA_DIRECTIVE

FIX_ALL_KIND = "source.fixAll.geolint"

# The suppression comments `geolint check` honours, read with the engine's own patterns.
_DIRECTIVES = (GEOLINT_DIRECTIVE, NOQA_DIRECTIVE)


@dataclass(frozen=True)
class _LineComments:
    comments: tuple[tuple[int, str], ...]  # (0-based column, text) of each comment on the line
    ends_in_string: bool  # the line break is inside a (triple-quoted) string: no comment can go there


def _comments_on_line(source: str, line: int) -> _LineComments:
    """Comments on 1-based `line`, from the tokenizer; a regex guess when the code does not tokenize."""
    try:
        comments = []
        ends_in_string = False
        # newline=None: lines end at \r and \r\n too, so token line numbers are LSP's.
        for token in tokenize.generate_tokens(io.StringIO(source, newline=None).readline):
            if token.type == tokenize.COMMENT and token.start[0] == line:
                comments.append((token.start[1], token.string))
            elif token.type == tokenize.STRING and token.start[0] <= line < token.end[0]:
                ends_in_string = True
            elif token.start[0] > line:
                break
        return _LineComments(tuple(comments), ends_in_string)
    except (tokenize.TokenError, SyntaxError, IndentationError):
        lines = split_lines(source)
        text = lines[line - 1] if line - 1 < len(lines) else ""
        hash_at = text.find("#")
        return _LineComments(((hash_at, text[hash_at:]),) if hash_at >= 0 else (), False)


def ignore_edit(source: str, line: int, code: str) -> Edit | None:
    """The edit that makes `geolint` ignore `code` on 1-based `line`; None if there is nothing to do.

    Extends an existing `# geolint: ignore[...]` or `# noqa: ...` list (geolint reads one
    directive per comment, so a second one in the same comment would not count), or else appends
    `# geolint: ignore[CODE]` at the end of the line, after any other comment such as `# type: ignore`.
    """
    lines = split_lines(source)
    if not 1 <= line <= len(lines):
        return None
    text = lines[line - 1]
    found = _comments_on_line(source, line)
    if found.ends_in_string:
        return None
    for column, comment in found.comments:
        for pattern in _DIRECTIVES:
            match = pattern.search(comment)
            if match is None:
                continue
            if match.group("codes") is None:
                return None  # a bare `# noqa` or `# geolint: ignore` already covers every code
            codes = [c for c in CODE_SPLIT.split(match.group("codes").strip()) if c]
            if code in codes:
                return None
            start = column + match.start("codes")
            end = column + match.end("codes")
            return Edit(line, start + 1, line, end + 1, ", ".join([*codes, code]))
    content_end = len(text.rstrip())
    return Edit(line, content_end + 1, line, len(text) + 1, f"  # geolint: ignore[{code}]")


def _position(text: str, offset: int) -> tuple[int, int]:
    """The 1-based (line, column) of a character offset, with LSP's line breaks."""
    before = text[:offset]
    line_start = max(before.rfind("\n"), before.rfind("\r")) + 1
    line = before.count("\n") + before.count("\r") - before.count("\r\n") + 1
    return line, offset - line_start + 1


def changed_region_edit(old: str, new: str) -> Edit:
    """The single edit that turns `old` into `new`, spanning only the changed middle."""
    prefix = 0
    limit = min(len(old), len(new))
    while prefix < limit and old[prefix] == new[prefix]:
        prefix += 1
    suffix = 0
    while suffix < limit - prefix and old[len(old) - 1 - suffix] == new[len(new) - 1 - suffix]:
        suffix += 1
    # Never split a \r\n pair: an edit ending between them would leave a stray \r.
    if 0 < prefix < len(old) and old[prefix - 1] == "\r" and old[prefix] == "\n":
        prefix -= 1
    end = len(old) - suffix
    if 0 < end < len(old) and old[end - 1] == "\r" and old[end] == "\n":
        suffix -= 1
    line, column = _position(old, prefix)
    end_line, end_column = _position(old, len(old) - suffix)
    return Edit(line, column, end_line, end_column, new[prefix : len(new) - suffix])
