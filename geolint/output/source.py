"""The text a finding points into, for the formats that show it (text, full) or say where it is.

Findings carry positions in the Python text geolint linted: a file's own lines, or, for text read
from stdin, the lines that came in (`remember_text`). The human formats look lines up here instead
of opening files themselves, so every format shows the same text.
"""

from __future__ import annotations

from dataclasses import replace

from geolint.lint_types import Finding, Severity
from geolint.notebook import cell_position, notebook_of

_given: dict[str, tuple[str, ...]] = {}


def remember_text(path: str, text: str) -> None:
    """Show `text` for findings whose path is `path` (the file is not on disk, or differs from it)."""
    from geolint.engine import split_lines

    _given[path] = tuple(split_lines(text))


def forget_text(path: str) -> None:
    _given.pop(path, None)


def source_lines(path: str) -> tuple[str, ...]:
    """The lines (with their endings) that findings in `path` count; () when there are none.
    For a notebook: the Python of its code cells, as it was linted (geolint.notebook)."""
    given = _given.get(path)
    if given is not None:
        return given
    notebook = notebook_of(path)
    if notebook is not None:
        from geolint.engine import split_lines

        _given[path] = tuple(split_lines(notebook.python))
        return _given[path]
    from geolint.engine import read_source_lines

    return read_source_lines(path)


def cell_lines(path: str, line: int) -> tuple[int, int, int]:
    """The first and last lines of the block that holds `line` (a notebook's cell, else the whole
    file), and what to subtract from a line to number it within the block (0 for a file)."""
    notebook = notebook_of(path)
    cell = notebook.cell_at(line) if notebook is not None else None
    if cell is None:
        return 1, len(source_lines(path)), 0
    return cell.first_line, cell.first_line + len(cell.python) - 1, cell.first_line - 1


def line_text(path: str, line: int) -> str | None:
    """Line `line` (1-based) of `path` without its ending, or None past the end or for an unreadable file."""
    lines = source_lines(path)
    if not 1 <= line <= len(lines):
        return None
    return lines[line - 1].rstrip("\r\n")


def location(finding: Finding) -> str:
    """`path:line:column`, as editors and grep read it; `path:cell N:line:column` in a notebook (as ruff)."""
    shown, cell = in_cell(finding)
    where = f"cell {cell}:" if cell is not None else ""
    return f"{finding.path}:{where}{shown.line}:{shown.column}"


def in_cell(finding: Finding) -> tuple[Finding, int | None]:
    """The finding with its lines (and its fix's) counted within its notebook cell, and the cell's
    number; the finding itself and None for a Python file."""
    position = cell_position(finding.path, finding.line)
    if position is None:
        return finding, None
    cell, line = position
    offset = finding.line - line
    fix = finding.fix
    if fix is not None:
        edits = tuple(replace(edit, line=edit.line - offset, end_line=edit.end_line - offset) for edit in fix.edits)
        fix = replace(fix, edits=edits)
    return replace(finding, line=line, end_line=max(finding.end_line - offset, line), fix=fix), cell


def fixable_now(finding: Finding, unsafe_fixes: bool) -> bool:
    """Whether `--fix` (with `--unsafe-fixes` when `unsafe_fixes`) would apply this finding's fix."""
    return finding.fix is not None and (finding.fix.applicability == "safe" or unsafe_fixes)


def fixed_lines(finding: Finding) -> tuple[int, list[str], list[str]] | None:
    """The first line a fix touches, the lines it replaces and the lines it writes (without endings)."""
    if finding.fix is None or not finding.fix.edits:
        return None
    from geolint.engine import apply_edits, split_lines

    lines = source_lines(finding.path)
    first = min(edit.line for edit in finding.fix.edits)
    last = max(edit.end_line for edit in finding.fix.edits)
    if not lines or last > len(lines):
        return None
    fixed = split_lines(apply_edits("".join(lines), finding.fix.edits))
    kept_after = len(lines) - last
    before = [line.rstrip("\r\n") for line in lines[first - 1 : last]]
    after = [line.rstrip("\r\n") for line in fixed[first - 1 : len(fixed) - kept_after]]
    return first, before, after


def plural(count: int, noun: str) -> str:
    return f"{count} {noun}{'s' * (count != 1)}"


def severity_word(finding: Finding) -> str:
    """`warning: ` (or `info: `, `hint: `) before a message; nothing for an error, the usual case."""
    severity = Severity(finding.severity)
    return "" if severity is Severity.ERROR else f"{severity.value}: "
