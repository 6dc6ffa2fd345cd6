"""The text a finding points into, for the formats that show it (text, full) or say where it is.

Findings carry positions in the Python text geolint linted: a file's own lines, or, for text read
from stdin, the lines that came in (`remember_text`). The human formats look lines up here instead
of opening files themselves, so every format shows the same text.
"""

from __future__ import annotations

from geolint.lint_types import Finding, Severity

_given: dict[str, tuple[str, ...]] = {}


def remember_text(path: str, text: str) -> None:
    """Show `text` for findings whose path is `path` (the file is not on disk, or differs from it)."""
    from geolint.engine import split_lines

    _given[path] = tuple(split_lines(text))


def source_lines(path: str) -> tuple[str, ...]:
    """The lines (with their endings) that findings in `path` count; () when there are none."""
    given = _given.get(path)
    if given is not None:
        return given
    from geolint.engine import read_source_lines

    return read_source_lines(path)


def line_text(path: str, line: int) -> str | None:
    """Line `line` (1-based) of `path` without its ending, or None past the end or for an unreadable file."""
    lines = source_lines(path)
    if not 1 <= line <= len(lines):
        return None
    return lines[line - 1].rstrip("\r\n")


def location(finding: Finding) -> str:
    """`path:line:column`, as editors and grep read it."""
    return f"{finding.path}:{finding.line}:{finding.column}"


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
