"""The server's copy of each open document, kept in LSP's line terms.

LSP breaks lines at `\\n`, `\\r\\n` and `\\r` only. pygls' own document splits with
`str.splitlines`, which also breaks at form feeds, `\\v`, `\\x1c`-`\\x1e`, `\\x85`, U+2028 and
U+2029, so one such character in a comment shifts every later incremental edit and the buffer
silently diverges from the editor's. Here lines come from `engine.split_lines` (the linter's own
rule) and each change is applied by character offset, clamped the way the LSP spec says:
a line past the end means the end of the document, a character past the end of a line means the
end of that line (never into its line break), and a position inside a UTF-16 surrogate pair
moves to the end of that character.
"""

from __future__ import annotations

import bisect
import re
from dataclasses import replace
from typing import Optional, Sequence

from lsprotocol import types
from pygls.workspace import TextDocument, Workspace
from pygls.workspace.position_codec import PositionCodec

from geolint.engine import split_lines
from geolint.lint_types import Edit, Finding

_LINE_BREAK = re.compile(r"\r\n|\r|\n")


def line_starts(source: str) -> list[int]:
    """The offset where each LSP line of `source` starts (a trailing break opens a last, empty line)."""
    return [0, *(match.end() for match in _LINE_BREAK.finditer(source))]


def _content_end(source: str, start: int, next_start: int) -> int:
    """The end of a line's text, before its line break."""
    end = next_start
    if end > start and source[end - 1] == "\n":
        end -= 1
    if end > start and source[end - 1] == "\r":
        end -= 1
    return end


def offset_at(source: str, starts: Sequence[int], codec: PositionCodec, position: types.Position) -> int:
    """The character offset of an LSP position (in the codec's units), clamped into the document."""
    if position.line < 0:
        return 0
    if position.line >= len(starts):
        return len(source)
    start = starts[position.line]
    next_start = starts[position.line + 1] if position.line + 1 < len(starts) else len(source)
    end = _content_end(source, start, next_start)
    units = 0
    offset = start
    while offset < end and units < position.character:
        units += codec.client_num_units(source[offset])
        offset += 1
    return offset


class LspTextDocument(TextDocument):
    """pygls' TextDocument with LSP's line breaks for its lines and its incremental edits."""

    @property
    def lines(self) -> Sequence[str]:
        return tuple(split_lines(self.source))

    def _apply_incremental_change(self, change: types.TextDocumentContentChangePartial) -> None:
        source = self.source
        starts = line_starts(source)
        start = offset_at(source, starts, self.position_codec, change.range.start)
        end = offset_at(source, starts, self.position_codec, change.range.end)
        if end < start:  # a reversed range: take it as the span it names
            start, end = end, start
        self._source = source[:start] + change.text + source[end:]


class LspWorkspace(Workspace):
    """A pygls Workspace whose documents are `LspTextDocument`s."""

    @classmethod
    def like(cls, workspace: Workspace) -> "LspWorkspace":
        """A new, empty workspace with the settings pygls chose for `workspace` at initialize."""
        return cls(
            workspace.root_uri,
            workspace._sync_kind,
            list(workspace.folders.values()),
            workspace.position_encoding,
        )

    def _create_text_document(
        self,
        doc_uri: str,
        source: Optional[str] = None,
        version: Optional[int] = None,
        language_id: Optional[str] = None,
    ) -> TextDocument:
        return LspTextDocument(
            doc_uri,
            source=source,
            version=version,
            language_id=language_id,
            sync_kind=self._sync_kind,
            position_codec=self.position_codec,
        )


def _common_prefix(old: str, new: str) -> int:
    """Length of the common prefix, by bisection on slices (fast on large texts)."""
    low, high = 0, min(len(old), len(new))
    while low < high:
        middle = (low + high + 1) // 2
        if old[low:middle] == new[low:middle]:
            low = middle
        else:
            high = middle - 1
    return low


def _common_suffix(old: str, new: str, limit: int) -> int:
    low, high = 0, limit
    while low < high:
        middle = (low + high + 1) // 2
        if old[len(old) - middle : len(old) - low] == new[len(new) - middle : len(new) - low]:
            low = middle
        else:
            high = middle - 1
    return low


class TextChange:
    """How an older text of a document became the current one, as one changed span.

    Lets results computed for the older text be used on the current one: a position before the
    span stays, one after it moves with the text, and anything inside it is gone.
    """

    def __init__(self, old: str, new: str) -> None:
        self.old, self.new = old, new
        self.prefix = _common_prefix(old, new)
        limit = min(len(old), len(new)) - self.prefix
        self.suffix = _common_suffix(old, new, limit)
        self._old_starts = line_starts(old)
        self._new_starts = line_starts(new)

    def _old_offset(self, line: int, column: int) -> int:
        if line - 1 >= len(self._old_starts):
            return len(self.old)
        start = self._old_starts[max(line - 1, 0)]
        following = self._old_starts[line] if line < len(self._old_starts) else len(self.old)
        return min(start + max(column - 1, 0), _content_end(self.old, start, following))

    def _new_position(self, offset: int) -> tuple[int, int]:
        line = bisect.bisect_right(self._new_starts, offset)
        return line, offset - self._new_starts[line - 1] + 1

    def move_span(self, line: int, column: int, end_line: int, end_column: int) -> tuple[int, int, int, int] | None:
        """A (line, column, end_line, end_column) of the old text in the new one; None if it was edited."""
        start = self._old_offset(line, column)
        end = self._old_offset(end_line, end_column)
        if end <= self.prefix:
            return line, column, end_line, end_column
        changed_end = len(self.old) - self.suffix
        if start < changed_end:
            return None
        shift = len(self.new) - len(self.old)
        return (*self._new_position(start + shift), *self._new_position(end + shift))

    def move_finding(self, finding: Finding) -> Finding | None:
        """The finding placed in the new text (its fix dropped if the change touched one of its edits)."""
        moved = self.move_span(finding.line, finding.column, finding.end_line, finding.end_column)
        if moved is None:
            return None
        fix = finding.fix
        if fix is not None:
            edits = []
            for edit in fix.edits:
                span = self.move_span(edit.line, edit.column, edit.end_line, edit.end_column)
                if span is None:
                    fix = None
                    break
                edits.append(Edit(*span, edit.content))
            else:
                fix = replace(fix, edits=tuple(edits))
        line, column, end_line, end_column = moved
        return replace(finding, line=line, column=column, end_line=end_line, end_column=end_column, fix=fix)
