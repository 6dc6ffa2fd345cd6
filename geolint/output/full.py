"""`--output-format full`: each finding as ruff's full format shows one. A header
(`CODE [*] message`), the location (` --> path:line:col`), the flagged lines with two lines of
context in a line-number gutter and carets under the flagged code, the evidence, the fix
(`help:` and the lines it removes `-` and writes `+`), and the rule's documentation link.
"""

from __future__ import annotations

from typing import Sequence

from geolint.lint_types import Finding
from geolint.output.concise import header_line
from geolint.output.source import cell_lines, fixed_lines, location, source_lines
from geolint.output.text import TAB, marked_line, severity_style
from geolint.terminal import BOLD, DIM, GREEN, RED, paint

CONTEXT = 2  # lines shown before and after the flagged ones
MOST_FLAGGED = 8  # a longer span shows its first and last lines, with `...` between


def render(findings: Sequence[Finding], *, color: bool = False, unsafe_fixes: bool = False) -> str:
    return "".join(_block(finding, color, unsafe_fixes) + "\n" for finding in findings)


def _block(finding: Finding, color: bool, unsafe_fixes: bool) -> str:
    lines = source_lines(finding.path)
    block_first, block_last, offset = cell_lines(finding.path, finding.line)  # a notebook's cell, else the file
    last_flagged = min(max(finding.end_line, finding.line), block_last)
    first_shown = max(finding.line - CONTEXT, block_first)
    last_shown = min(last_flagged + CONTEXT, block_last)
    width = len(str(max(last_shown, finding.line) - offset))
    bar = paint(" " * width + " |", DIM, color=color)
    out = [header_line(finding, color, unsafe_fixes, with_location=False)]
    out.append(f"{' ' * width}{paint('-->', DIM, color=color)} {location(finding)}\n")
    if 1 <= finding.line <= len(lines):
        out.append(bar + "\n")
        out += _excerpt(finding, lines, first_shown, last_flagged, last_shown, width, offset, color)
        out.append(bar + "\n")
    if finding.evidence:
        out.append(f"{' ' * width} {paint('= evidence:', DIM, color=color)} {'; '.join(finding.evidence)}\n")
    out += _fix(finding, width, offset, color)
    from geolint.api import rule_url

    out.append(f"{' ' * width} {paint('= docs:', DIM, color=color)} {rule_url(finding.code)}\n")
    return "".join(out)


def _excerpt(
    finding: Finding, lines: tuple[str, ...], first: int, last_flagged: int, last: int, width: int, offset: int, color: bool
) -> list[str]:
    def row(number: int, text: str) -> str:
        return f"{paint(f'{number - offset:>{width}} |', DIM, color=color)} {text}".rstrip() + "\n"

    def carets(caret: str) -> str:
        return f"{paint(' ' * width + ' |', DIM, color=color)} {paint(caret, severity_style(finding), color=color)}\n"

    out = []
    flagged = range(finding.line, last_flagged + 1)
    elided = len(flagged) > MOST_FLAGGED
    for number in range(first, last + 1):
        if elided and finding.line + MOST_FLAGGED // 2 <= number <= last_flagged - MOST_FLAGGED // 2:
            if number == finding.line + MOST_FLAGGED // 2:
                out.append(f"{paint(' ' * width + ' |', DIM, color=color)} ...\n")
            continue
        text = lines[number - 1].rstrip("\r\n")
        shown, caret = marked_line(text, finding, strip_indent=False)
        out.append(row(number, shown))
        if number == finding.line:
            out.append(carets(caret))
        elif number in flagged and number == last_flagged:  # the end of a span: up to its last column
            body = shown.lstrip(" ")
            end = len(text[: max(finding.end_column - 1, 0)].replace("\t", TAB))
            out.append(carets(" " * (len(shown) - len(body)) + "^" * max(end - (len(shown) - len(body)), 1)))
    return out


def _fix(finding: Finding, width: int, offset: int, color: bool) -> list[str]:
    if finding.fix is None:
        return []
    what = finding.fix.description or "apply the fix"
    out = [f"{paint('help:', BOLD, color=color)} {what}\n"]
    change = fixed_lines(finding)
    if change is not None:
        first, before, after = change
        bar = paint(" " * width + " |", DIM, color=color)
        out.append(bar + "\n")
        out += [f"{' ' * width} {paint('- ' + line.replace(chr(9), TAB), RED, color=color)}\n" for line in before]
        out += [
            f"{paint(f'{first + index - offset:>{width}}', DIM, color=color)} {paint('+ ' + line.replace(chr(9), TAB), GREEN, color=color)}\n"
            for index, line in enumerate(after)
        ]
        out.append(bar + "\n")
    if finding.fix.applicability != "safe":
        out.append(f"{' ' * width} {paint('= note:', DIM, color=color)} an unsafe fix, applied only with --fix --unsafe-fixes\n")
    return out
