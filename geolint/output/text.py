"""`--format text` (the default): `path:line:col: CODE message`, then the source line and a caret,
then the evidence the finding stands on (`  = evidence: ...`) when the rule recorded any.

The first line of each finding is the grep/editor-friendly form every linter prints; a finding
whose severity is not `error` says so before its message (`GEO900 warning: ...`). The source
excerpt under it shows what was flagged; a file that cannot be read simply gets no excerpt. With
`--show-fixes`, a fixable finding also shows the lines its fix would write (`- old` / `+ new`).
"""

from __future__ import annotations

from typing import Sequence

from geolint.lint_types import Finding, Severity
from geolint.output.source import fixed_lines, line_text, location, severity_word
from geolint.terminal import BOLD, DIM, GREEN, RED, YELLOW, paint

TAB = "    "


def render(findings: Sequence[Finding], *, color: bool = False, show_fixes: bool = False) -> str:
    """Each finding as its header line plus an excerpt of the code it points at."""
    return "".join(_finding_block(finding, color, show_fixes) for finding in findings)


def severity_style(finding: Finding) -> str:
    return RED if Severity(finding.severity) is Severity.ERROR else YELLOW


def _finding_block(finding: Finding, color: bool, show_fixes: bool) -> str:
    header = (
        f"{paint(location(finding), BOLD, color=color)}: "
        f"{paint(finding.code, BOLD, severity_style(finding), color=color)} {severity_word(finding)}{finding.message}\n"
    )
    excerpt = _excerpt(finding, color)
    fix = fix_diff(finding, "  ", color) if show_fixes else ""
    return f"{header}{excerpt}{_evidence_line(finding, color)}{fix}"


def _excerpt(finding: Finding, color: bool) -> str:
    text = line_text(finding.path, finding.line)
    if text is None:
        return ""
    shown, caret = marked_line(text, finding, strip_indent=True)
    bar = paint("  | ", DIM, color=color)
    return f"{bar}{shown}\n{bar}{paint(caret, severity_style(finding), color=color)}\n"


def marked_line(text: str, finding: Finding, *, strip_indent: bool) -> tuple[str, str]:
    """A flagged line with tabs expanded, and a caret line under its flagged part (to the line's end
    when the finding spans more lines); `strip_indent` drops the line's indentation from both."""
    indent = len(text) - len(text.lstrip(" \t")) if strip_indent else 0
    body = text[indent:]
    start = max(finding.column - 1 - indent, 0)
    end = finding.end_column - 1 - indent if finding.end_line == finding.line else len(body)
    end = min(max(end, start + 1), max(len(body), start + 1))
    prefix = body[:start].replace("\t", TAB)
    marked = body[start:end].replace("\t", TAB)
    return body.replace("\t", TAB), " " * len(prefix) + "^" * max(len(marked), 1)


def _evidence_line(finding: Finding, color: bool) -> str:
    """`  = evidence: ...`: why the rule believes it, strongest first (like rustc's `= note:`)."""
    if not finding.evidence:
        return ""
    return f"{paint('  = evidence: ', DIM, color=color)}{'; '.join(finding.evidence)}\n"


def fix_diff(finding: Finding, indent: str, color: bool) -> str:
    """`help: <what the fix does>` and the lines it replaces (`-`) and writes (`+`); "" without a fix."""
    if finding.fix is None:
        return ""
    what = finding.fix.description or "apply the fix"
    unsafe = " (unsafe: --fix --unsafe-fixes)" if finding.fix.applicability != "safe" else ""
    out = [f"{indent}{paint('help:', BOLD, color=color)} {what}{unsafe}\n"]
    change = fixed_lines(finding)
    if change is not None:
        _, before, after = change
        before, after = [line.replace("\t", TAB) for line in before], [line.replace("\t", TAB) for line in after]
        # without the indentation the lines share, as the excerpt above shows its line
        common = min((len(line) - len(line.lstrip(" ")) for line in before + after if line.strip()), default=0)
        out += [f"{indent}{paint('- ' + line[common:], RED, color=color)}\n" for line in before]
        out += [f"{indent}{paint('+ ' + line[common:], GREEN, color=color)}\n" for line in after]
    return "".join(out)
