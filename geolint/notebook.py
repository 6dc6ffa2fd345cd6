"""Jupyter notebooks (`.ipynb`): their code cells linted as one module, findings shown by cell.

The code cells are joined into one Python text, each after a boundary comment line, so a name
defined in one cell is known in the next, as in the kernel. IPython syntax that is not Python
(`%matplotlib inline`, `!pip install`, `x = !ls`, `obj?`, a `%%bash` cell) is replaced, line for
line, by text that is (`pass`, `x = None`, blank lines), so positions never move.

Findings keep positions in that joined text (the cache, the baseline and `--fix` all work on it);
the output formats show them by cell (`lab.ipynb:cell 3:2:5`, ruff's form: cells counted from 1
among all cells, markdown ones included, lines and columns within the cell). A fix is written back
only into the `source` of the cells it changed, and only when every replaced IPython line is still
where it was; the rest of the notebook (outputs, metadata, key order, indentation) is kept.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from functools import lru_cache
from json.decoder import scanstring  # type: ignore[attr-defined]  # the decoder's own string scanner; typeshed leaves it out
from typing import Any

from geolint.lint_types import SYNTAX_ERROR, SYNTAX_ERROR_NAME, Config, Finding, Severity

NOTEBOOK_SUFFIX = ".ipynb"
# Starts each code cell in the joined text: a comment, so no analysis sees it.
BOUNDARY = "# ---- notebook cell (geolint) ----\n"
# Cell magics whose body is Python (IPython runs it); any other `%%` cell is not linted.
PYTHON_CELL_MAGICS = frozenset({"time", "timeit", "capture", "prun", "debug", "python", "python3"})
_SHELL_ASSIGNMENT = re.compile(r"^(\s*[A-Za-z_][\w.]*(?:\s*,\s*[A-Za-z_][\w.]*)*\s*=\s*)[!%]")
_HELP = re.compile(r"^\s*(\?\??[\w.]|[\w.\[\]()]+\?\??\s*$)")


class NotebookError(ValueError):
    """The file is not a Jupyter notebook geolint can read."""


def is_notebook(path: object) -> bool:
    return str(path).endswith(NOTEBOOK_SUFFIX)


def unreadable_notebook(path: str, config: Config, error: NotebookError) -> list[Finding]:
    """What a `.ipynb` that is not a notebook (empty, a Git LFS pointer, broken JSON) gives: one
    GEO000 finding at 1:1, as a file that does not parse does (ruff's `invalid-syntax`)."""
    from geolint.config import enabled_codes

    if not enabled_codes(config, path, (SYNTAX_ERROR,)):
        return []
    severity = config.severity.get(SYNTAX_ERROR, Severity.ERROR)
    return [Finding(path, 1, 1, 1, 2, SYNTAX_ERROR, SYNTAX_ERROR_NAME, str(error), severity)]


@dataclass(frozen=True)
class Cell:
    number: int  # 1-based, among all cells
    first_line: int  # the line of the joined text where the cell's first line is
    lines: tuple[str, ...]  # the cell's lines as written (with their endings)
    python: tuple[str, ...]  # the same lines as the Python that is linted
    ends_with_newline: bool


@dataclass(frozen=True)
class Notebook:
    document: dict[str, Any]
    cells: tuple[Cell, ...]  # the code cells

    @property
    def python(self) -> str:
        """The text geolint lints: every code cell's Python after a boundary line."""
        return "".join(BOUNDARY + "".join(cell.python) for cell in self.cells)

    def cell_at(self, line: int) -> Cell | None:
        """The code cell holding line `line` of the joined text (None on a boundary line)."""
        for cell in reversed(self.cells):
            if line >= cell.first_line:
                return cell if line < cell.first_line + len(cell.python) else None
        return None


def read_notebook(data: bytes) -> Notebook:
    try:
        document = json.loads(data.decode("utf-8-sig"))
    except (UnicodeDecodeError, ValueError) as error:
        raise NotebookError(f"not a Jupyter notebook: {error}") from error
    if not isinstance(document, dict) or not isinstance(document.get("cells"), list):
        raise NotebookError("not a Jupyter notebook: no list of cells")
    cells = []
    line = 1
    for number, cell in enumerate(document["cells"], start=1):
        if not isinstance(cell, dict) or cell.get("cell_type") != "code":
            continue
        text = _cell_text(cell.get("source", ""))
        lines = tuple(text.splitlines(keepends=True))
        ends = text.endswith("\n")
        if lines and not ends:  # the joined text gives every cell a last newline
            lines = (*lines[:-1], lines[-1] + "\n")
        line += 1  # the boundary
        cells.append(Cell(number, line, lines, tuple(_as_python(lines)), ends))
        line += len(lines)
    return Notebook(document, tuple(cells))


def _cell_text(source: Any) -> str:
    if isinstance(source, list) and all(isinstance(part, str) for part in source):
        return "".join(source)
    if isinstance(source, str):
        return source
    raise NotebookError("not a Jupyter notebook: a cell's source is neither text nor a list of lines")


def _as_python(lines: tuple[str, ...]) -> list[str]:
    """The cell's lines with IPython's own syntax replaced, one line for one line."""
    if lines and lines[0].startswith("%%"):
        magic = lines[0][2:].split(maxsplit=1)[0] if lines[0][2:].strip() else ""
        if magic not in PYTHON_CELL_MAGICS:
            return ["\n"] * len(lines)  # %%bash, %%html, %%writefile: not Python
        return ["\n", *_as_python(lines[1:])]
    python = []
    continued = False  # a `!cmd \` or `%magic \` line continues on the next one, which is not Python either
    for line in lines:
        stripped = line.lstrip(" \t")
        indent = line[: len(line) - len(stripped)]
        if continued:
            python.append("\n")
            continued = line.rstrip("\r\n").endswith("\\")
        elif _is_magic(stripped) or _HELP.match(line):
            python.append(f"{indent}pass\n" if indent else "\n")
            continued = _is_magic(stripped) and line.rstrip("\r\n").endswith("\\")
        elif _SHELL_ASSIGNMENT.match(line):
            python.append(_SHELL_ASSIGNMENT.match(line).group(1) + "None\n")  # type: ignore[union-attr]
        else:
            python.append(line)
    return python


def _is_magic(stripped: str) -> bool:
    """`%time f()`, `%%bash`, `!ls`; not a continued `% b` (modulo) or `!= b`, which are Python."""
    if stripped.startswith("%"):
        return len(stripped) > 1 and (stripped[1].isalpha() or stripped[1] == "%")
    return stripped.startswith("!") and not stripped.startswith("!=")


@lru_cache(maxsize=64)
def _read_file(path: str) -> Notebook | None:
    try:
        with open(path, "rb") as stream:
            return read_notebook(stream.read())
    except (OSError, NotebookError):
        return None


_given: dict[str, Notebook] = {}


def remember_notebook(path: str, notebook: Notebook) -> None:
    """Show findings of `path` by the cells of `notebook` (a notebook read from stdin)."""
    _given[path] = notebook


def forget_notebooks() -> None:
    """Read notebooks from disk again (one was rewritten)."""
    _read_file.cache_clear()


def notebook_of(path: str) -> Notebook | None:
    """The notebook a finding's path names (read once), or None for a Python file."""
    if not is_notebook(path):
        return None
    return _given.get(path) or _read_file(path)


def cell_position(path: str, line: int) -> tuple[int, int] | None:
    """(cell number, line within the cell) of a joined-text line of a notebook; None for a Python file."""
    notebook = notebook_of(path)
    if notebook is None:
        return None
    cell = notebook.cell_at(line)
    if cell is None:  # a boundary line (a file-wide finding at 1:1): the start of the cell after it
        cell = next((cell for cell in notebook.cells if cell.first_line > line), None)
        return (cell.number, 1) if cell is not None else None
    return cell.number, line - cell.first_line + 1


def write_back(data: bytes, fixed_python: str) -> bytes:
    """The notebook's bytes with its code cells' sources replaced by the fixed joined text.

    Only the `source` values of the cells that changed are rewritten, in place and in the layout
    their arrays had; every other byte stays. Raises `NotebookError` when the fixed text cannot be
    split into the same cells, or when a replaced IPython line moved or changed (its original
    could not be put back safely).
    """
    notebook = read_notebook(data)
    parts = fixed_python.split(BOUNDARY)
    if parts[0] != "" or len(parts) - 1 != len(notebook.cells):
        raise NotebookError("a fix moved a cell boundary; the notebook was left unchanged")
    new_sources: dict[int, str | list[str]] = {}
    for cell, fixed in zip(notebook.cells, parts[1:]):
        new_lines = fixed.splitlines(keepends=True)
        if list(cell.python) == new_lines:
            continue
        replaced = [index for index, (line, python) in enumerate(zip(cell.lines, cell.python)) if line != python]
        if replaced:
            if len(new_lines) != len(cell.lines) or any(new_lines[index] != cell.python[index] for index in replaced):
                raise NotebookError(f"a fix in cell {cell.number} would move its IPython lines; the notebook was left unchanged")
            for index in replaced:
                new_lines[index] = cell.lines[index]
        text = "".join(new_lines)
        if not cell.ends_with_newline and text.endswith("\n"):
            text = text[:-1]
        old = notebook.document["cells"][cell.number - 1].get("source")
        new_sources[cell.number - 1] = text.splitlines(keepends=True) if isinstance(old, list) else text
    if not new_sources:
        return data
    bom = b"\xef\xbb\xbf" if data.startswith(b"\xef\xbb\xbf") else b""
    raw = data[len(bom):].decode("utf-8")
    spans = _source_spans(raw)
    out, at = [], 0
    for index in sorted(new_sources):
        begin, end = spans[index]
        out += [raw[at:begin], _json_like(new_sources[index], raw[begin:end], raw)]
        at = end
    written = "".join(out) + raw[at:]
    expected = notebook.document
    for index, source in new_sources.items():
        expected["cells"][index]["source"] = source
    if json.loads(written) != expected:  # never write what would read back differently
        raise NotebookError("the fixed notebook did not read back as intended; it was left unchanged")
    return bom + written.encode("utf-8")


def _source_spans(raw: str) -> dict[int, tuple[int, int]]:
    """Where, in the notebook's JSON text, each cell's `source` value starts and ends (by cell index)."""
    decoder = json.JSONDecoder()
    whitespace = re.compile(r"[ \t\n\r]*")

    def skip(at: int) -> int:
        return whitespace.match(raw, at).end()  # type: ignore[union-attr]

    def members(at: int):
        """(key, start of value, end of value) of the object at `at`; the object's end last."""
        at = skip(at) + 1  # past "{"
        while True:
            at = skip(at)
            if raw[at] == "}":
                yield None, at + 1, at + 1
                return
            key, at = scanstring(raw, at + 1)
            begin = skip(skip(at) + 1)  # past ":"
            _, end = decoder.raw_decode(raw, begin)
            yield key, begin, end
            at = skip(end)
            if raw[at] == ",":
                at += 1

    spans: dict[int, tuple[int, int]] = {}
    for key, begin, _ in members(0):
        if key != "cells":
            continue
        at, index = skip(begin + 1), 0  # past "["
        while raw[at] != "]":
            for cell_key, value_begin, value_end in members(at):
                if cell_key == "source":
                    spans[index] = (value_begin, value_end)
                at = value_end
            at = skip(at)
            if raw[at] == ",":
                at = skip(at + 1)
            index += 1
        break
    return spans


def _json_like(value: str | list[str], old: str, raw: str) -> str:
    """`value` as JSON in the place of the `old` value, keeping its layout: in an array with as many
    lines as before, only the lines that changed are rewritten; else one line an item, indented as
    the old array's items were (or on one line, if it was)."""
    ascii_only = raw.isascii() and "\\u" in raw
    if isinstance(value, list) and old.startswith("["):
        items = _string_spans(old)
        if items is not None and len(items) == len(value):
            out, at = [], 0
            for (begin, end, text), line in zip(items, value):
                if text != line:
                    out += [old[at:begin], json.dumps(line, ensure_ascii=ascii_only)]
                    at = end
            return "".join(out) + old[at:]
    if isinstance(value, str) or "\n" not in old or not value:
        return json.dumps(value, ensure_ascii=ascii_only)
    item_indent = re.match(r"\[\s*?\n([ \t]*)", old)
    closing_indent = re.search(r"\n([ \t]*)\]$", old)
    inner = item_indent.group(1) if item_indent else ""
    outer = closing_indent.group(1) if closing_indent else ""
    items_text = (",\n" + inner).join(json.dumps(line, ensure_ascii=ascii_only) for line in value)
    return f"[\n{inner}{items_text}\n{outer}]"


def _string_spans(array: str) -> list[tuple[int, int, str]] | None:
    """(start, end, value) of each string in a JSON array of strings; None if it holds anything else."""
    spans: list[tuple[int, int, str]] = []
    at = 1
    while True:
        at = re.compile(r"[ \t\n\r,]*").match(array, at).end()  # type: ignore[union-attr]
        if array[at] == "]":
            return spans
        if array[at] != '"':
            return None
        text, end = scanstring(array, at + 1)
        spans.append((at, end, text))
        at = end
