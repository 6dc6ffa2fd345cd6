"""Suppression comments: `# geolint: ignore[GEO101]` and `# noqa: GEO101`, and what they cover.

- At the end of a line, a directive covers findings that start on that line.
- On a line of its own, it covers the next statement, all of its lines (for a compound statement
  such as `for` or `def`, its header only). If the next line of code starts no statement (the
  comment sits inside a bracketed expression), it covers that line only.
- `# geolint: ignore` and a bare `# noqa` (as in ruff and flake8) cover every code.
- `# noqa` codes that are not geolint's (E501, F401) belong to other tools and are left alone.

Directives that suppress nothing, or name codes that do not exist, become GEO900 findings.
"""

from __future__ import annotations

import ast
import io
import re
import tokenize
from dataclasses import dataclass, field
from typing import Collection, Iterable, Sequence

from geolint.lint_types import Finding, Severity
from geolint.source_text import cached_ast, split_lines

UNUSED_SUPPRESSION = "GEO900"
UNUSED_SUPPRESSION_NAME = "unused-suppression"

# `# geolint: ignore` or `# geolint: ignore[GEO101, GEO2...]`, anywhere in a comment.
GEOLINT_DIRECTIVE = re.compile(r"#\s*geolint\s*:\s*ignore\b(?:\[(?P<codes>[^\]]*)\])?", re.IGNORECASE)
# `# noqa` or `# noqa: GEO101, E501` (flake8 syntax; the colon is required before codes).
# A code is letters, a digit, then letters or digits: a typo such as `GEO1O1` stays one code.
NOQA_DIRECTIVE = re.compile(
    r"#\s*noqa(?::\s*(?P<codes>[A-Za-z]+[0-9][A-Za-z0-9]*(?:[,\s]+[A-Za-z]+[0-9][A-Za-z0-9]*)*))?", re.IGNORECASE
)
GEO_CODE = re.compile(r"^GEO\d", re.IGNORECASE)  # ours: GEO then a digit (misspelt codes included)
CODE_SPLIT = re.compile(r"[,\s]+")


@dataclass
class Directive:
    """One suppression comment: where it is, what it names, which lines it covers, what it used."""

    kind: str  # "geolint" or "noqa"
    line: int  # 1-based line of the comment
    column: int  # 1-based column where the directive starts
    end_column: int  # exclusive
    codes: tuple[str, ...] | None  # None: every code; upper-cased for matching
    own_line: bool
    written: tuple[str, ...] = ()  # the codes as the comment spells them, for messages
    first_line: int = 0
    last_line: int = 0
    used_codes: set[str] = field(default_factory=set)
    used: bool = False

    def covers(self, finding: Finding) -> bool:
        if not self.first_line <= finding.line <= self.last_line:
            return False
        return self.codes is None or finding.code in self.codes


# A line that may hold a directive: a `#` followed later by one of the two keywords.
CANDIDATE_LINE = re.compile(r"#[^\r\n]*?(?:geolint|noqa)", re.IGNORECASE)


def may_have_directives(source: str) -> bool:
    """A cheap test that lets the engine skip looking for directives in most files."""
    # `CANDIDATE_LINE` tries its keywords after every `#`; first, in C, whether the text holds either
    # in any case at all (`geol`: `re.IGNORECASE` also matches `i` to `ı` and `İ`, which `lower`
    # leaves or turns into two characters), which most files do not
    lowered = source.lower()
    if "noqa" not in lowered and "geol" not in lowered:
        return False
    return CANDIDATE_LINE.search(source) is not None


def parse_directives(source: str) -> list[Directive]:
    """Every suppression directive in real comments (never inside strings).

    Tokenizing a whole file in pure Python is slow, so only the lines that may hold a directive
    are tokenized, each on its own; the module's `ast` says which of them lie inside a
    multi-line string. Without an `ast` (a file CPython cannot parse) the whole file is tokenized.
    """
    if not may_have_directives(source):
        return []
    try:
        tree = cached_ast(source)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        directives = _directives_by_tokenizing_everything(source)
    else:
        directives = _directives_on_candidate_lines(split_lines(source), tree)
    if any(d.own_line for d in directives):
        _assign_own_line_spans(source, directives)
    for directive in directives:
        if not directive.own_line:
            directive.first_line = directive.last_line = directive.line
    return directives


def _directives_on_candidate_lines(lines: Sequence[str], tree: ast.AST) -> list[Directive]:
    rows = [index + 1 for index, line in enumerate(lines) if "#" in line and CANDIDATE_LINE.search(line)]
    if not rows:
        return []
    # Multi-line strings near the candidate lines, as (first row, first byte column, last row, end byte column).
    spans = [span for row in rows for span in _multiline_strings_around(tree, row)]
    directives: list[Directive] = []
    for row in rows:
        line = lines[row - 1].rstrip("\r\n")
        encoded = line.encode("utf-8")
        start_byte, end_byte = 0, len(encoded)
        inside = False
        for first, first_col, last, last_col in spans:
            if first < row < last:
                inside = True
                break
            if row == last and last_col is not None:
                start_byte = max(start_byte, last_col)
            if row == first:
                end_byte = min(end_byte, first_col)
        if inside or start_byte >= end_byte:
            continue
        prefix = encoded[:start_byte].decode("utf-8", "replace")
        segment = encoded[start_byte:end_byte].decode("utf-8", "replace")
        code_before = start_byte > 0 and bool(prefix.strip())
        for token in _tokens(segment):
            if token.type == tokenize.COMMENT:
                directive = _directive(token.string, row, len(prefix) + token.start[1], code_before)
                if directive is not None:
                    directives.append(directive)
                break  # a comment runs to the end of the line
            if token.type not in (tokenize.NL, tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT, tokenize.ENDMARKER):
                code_before = True
    return directives


_BODY_FIELDS = frozenset({"body", "orelse", "finalbody", "handlers", "cases"})


def _multiline_strings_around(tree: ast.AST, row: int) -> list[tuple[int, int, int, int]]:
    """Multi-line string literals in the innermost statement that spans `row`.

    Descends through statement bodies only (cheap), then walks the expressions of that one
    statement (for a compound statement, its header only), instead of the whole module.
    """
    node: ast.AST = tree
    while True:
        inner: ast.AST | None = None
        for field in _BODY_FIELDS:
            for child in getattr(node, field, None) or ():
                if isinstance(child, ast.ExceptHandler) or (hasattr(ast, "match_case") and isinstance(child, ast.match_case)):
                    candidates = getattr(child, "body", ())
                    first = getattr(child, "lineno", None) or (candidates[0].lineno if candidates else 0)
                    last = candidates[-1].end_lineno if candidates else first
                    if first <= row <= (last or first):
                        inner = child
                        break
                elif isinstance(child, ast.stmt) and child.lineno <= row <= (child.end_lineno or child.lineno):
                    inner = child
                    break
            if inner is not None:
                break
        if inner is None:
            break
        node = inner
    if node is tree:
        return []
    header = [getattr(node, name) for name in node._fields if name not in _BODY_FIELDS]
    found = []
    for part in header:
        for value in part if isinstance(part, list) else [part]:
            if not isinstance(value, ast.AST):
                continue
            for item in ast.walk(value):
                if (
                    isinstance(item, (ast.Constant, ast.JoinedStr))
                    and item.end_lineno is not None
                    and item.end_lineno > item.lineno
                    and (isinstance(item, ast.JoinedStr) or isinstance(item.value, (str, bytes)))
                ):
                    found.append((item.lineno, item.col_offset, item.end_lineno, item.end_col_offset or 0))
    return found


def _tokens(segment: str) -> list[tokenize.TokenInfo]:
    """The tokens of one line on its own (an unclosed bracket ends it early, which is fine here)."""
    found: list[tokenize.TokenInfo] = []
    try:
        for token in tokenize.generate_tokens(io.StringIO(segment.lstrip(" \t") + "\n").readline):
            found.append(token._replace(start=(token.start[0], token.start[1] + len(segment) - len(segment.lstrip(" \t")))))
    except (tokenize.TokenError, SyntaxError, IndentationError):
        pass
    return found


def _directives_by_tokenizing_everything(source: str) -> list[Directive]:
    directives: list[Directive] = []
    lines_with_code: set[int] = set()
    try:
        for token in tokenize.generate_tokens(io.StringIO(source).readline):
            if token.type == tokenize.COMMENT:
                directive = _directive(token.string, token.start[0], token.start[1], token.start[0] in lines_with_code)
                if directive is not None:
                    directives.append(directive)
            elif token.type not in (tokenize.NL, tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT, tokenize.ENDMARKER):
                for row in range(token.start[0], token.end[0] + 1):
                    lines_with_code.add(row)
    except (tokenize.TokenError, SyntaxError, IndentationError):
        pass  # keep what was found before the error; the engine reports the syntax error itself
    return directives


def _directive(comment: str, line: int, column: int, after_code: bool) -> Directive | None:
    match = GEOLINT_DIRECTIVE.search(comment)
    kind = "geolint"
    if match is None:
        match = NOQA_DIRECTIVE.search(comment)
        kind = "noqa"
    if match is None:
        return None
    raw = match.group("codes")
    written: tuple[str, ...] = ()
    if raw is None:
        codes = None
    else:
        written = tuple(code for code in CODE_SPLIT.split(raw.strip()) if code)
        if kind == "noqa":
            written = tuple(code for code in written if GEO_CODE.match(code))
            if not written:
                return None  # only other tools' codes: not ours to judge
        codes = tuple(code.upper() for code in written)
    return Directive(
        kind=kind,
        line=line,
        column=column + match.start() + 1,
        end_column=column + match.end() + 1,
        codes=codes,
        own_line=not after_code,
        written=written,
    )


def _assign_own_line_spans(source: str, directives: Sequence[Directive]) -> None:
    lines = split_lines(source)
    spans = _statement_spans(source)
    for directive in directives:
        if not directive.own_line:
            continue
        next_line = _next_code_line(lines, directive.line)
        directive.first_line = next_line
        directive.last_line = spans.get(next_line, next_line)


def _next_code_line(lines: Sequence[str], after: int) -> int:
    for index in range(after, len(lines)):  # `after` is 1-based, so this starts on the next line
        stripped = lines[index].strip()
        if stripped and not stripped.startswith("#"):
            return index + 1
    return after  # nothing follows: the directive covers nothing (and will be reported unused)


def _statement_spans(source: str) -> dict[int, int]:
    """Start line -> last line covered, for every statement (compound statements: their header)."""
    try:
        tree = cached_ast(source)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return {}
    spans: dict[int, int] = {}
    for node in ast.walk(tree):
        if not isinstance(node, ast.stmt):
            continue
        decorators: list[ast.expr] = getattr(node, "decorator_list", [])
        start = min([node.lineno, *(decorator.lineno for decorator in decorators)])
        body = getattr(node, "body", None)
        if isinstance(body, list) and body and isinstance(body[0], ast.stmt):
            end = max(node.lineno, body[0].lineno - 1)
        else:
            end = node.end_lineno or node.lineno
        spans[start] = max(spans.get(start, start), end)
    return spans


def apply_suppressions(
    findings: Iterable[Finding],
    directives: Sequence[Directive],
) -> list[Finding]:
    """The findings no directive covers; marks on each directive what it was used for."""
    kept: list[Finding] = []
    for finding in findings:
        covering = [d for d in directives if d.covers(finding)]
        if not covering:
            kept.append(finding)
            continue
        for directive in covering:
            directive.used = True
            directive.used_codes.add(finding.code)
    return kept


def unused_suppression_findings(
    directives: Sequence[Directive],
    path: str,
    *,
    known_codes: Collection[str],
    enabled_codes: Collection[str],
    severity: Severity,
) -> list[Finding]:
    """GEO900 findings: directives that suppressed nothing, and codes that do not exist.

    A code whose rule is off for this file (not selected) is not called unused: with the rule off
    we cannot know whether it would have fired. A bare `# noqa` is left to the tools that share it.
    """
    findings: list[Finding] = []
    for directive in directives:
        problems: list[str] = []
        if directive.codes is None:
            if directive.kind == "geolint" and not directive.used:
                problems.append("unused blanket suppression `# geolint: ignore`")
        else:
            spelled = dict(zip(directive.codes, directive.written))
            unknown = [spelled.get(code, code) for code in directive.codes if code not in known_codes]
            unused = [
                code
                for code in directive.codes
                if code in known_codes and code in enabled_codes and code not in directive.used_codes
            ]
            if unknown:
                problems.append(f"unknown rule code{'s' if len(unknown) > 1 else ''} {', '.join(unknown)} in suppression")
            if unused:
                problems.append(f"unused suppression of {', '.join(unused)}")
        if problems:
            findings.append(
                Finding(
                    path=path,
                    line=directive.line,
                    column=directive.column,
                    end_line=directive.line,
                    end_column=directive.end_column,
                    code=UNUSED_SUPPRESSION,
                    name=UNUSED_SUPPRESSION_NAME,
                    message="; ".join(problems),
                    severity=severity,
                )
            )
    return findings


def add_suppressions(source: str, findings: Sequence[Finding]) -> str:
    """`source` with a `# geolint: ignore[...]` comment for every finding (what `--add-noqa` does).

    The comment goes at the end of the finding's first line, extending a geolint directive that is
    already there; where a comment cannot go (the line ends inside a string or after a backslash),
    it goes on its own line above the statement instead, with the statement's indentation.
    """
    lines = split_lines(source)
    if not findings or not lines:
        return source
    line_ends, existing = _comment_sites(source)
    codes_at_end: dict[int, set[str]] = {}
    codes_above: dict[int, set[str]] = {}
    for finding in findings:
        if finding.line in line_ends:
            codes_at_end.setdefault(finding.line, set()).add(finding.code)
        else:
            codes_above.setdefault(_statement_start(source, finding.line), set()).add(finding.code)

    for row, codes in codes_at_end.items():
        text = lines[row - 1]
        body = text.rstrip("\r\n")
        ending = text[len(body) :]
        directive = existing.get(row)
        if directive is not None and directive.codes is not None:
            merged = sorted(set(directive.codes) | codes)
            start, end = directive.column - 1, directive.end_column - 1
            body = body[:start] + f"# geolint: ignore[{', '.join(merged)}]" + body[end:]
        else:
            body = body.rstrip() + f"  # geolint: ignore[{', '.join(sorted(codes))}]"
        lines[row - 1] = body + ending
    newline = "\r\n" if "\r\n" in source else "\n"
    for row in sorted(codes_above, reverse=True):
        statement_line = lines[row - 1]
        indent = statement_line[: len(statement_line) - len(statement_line.lstrip(" \t"))]
        lines.insert(row - 1, f"{indent}# geolint: ignore[{', '.join(sorted(codes_above[row]))}]{newline}")
    return "".join(lines)


def _comment_sites(source: str) -> tuple[set[int], dict[int, Directive]]:
    """Lines where a trailing comment may be added, and the geolint directives already on lines."""
    line_ends: set[int] = set()
    try:
        for token in tokenize.generate_tokens(io.StringIO(source).readline):
            if token.type in (tokenize.NEWLINE, tokenize.NL) and token.start[0] == token.end[0]:
                line_ends.add(token.start[0])
    except (tokenize.TokenError, SyntaxError):
        pass
    existing = {d.line: d for d in parse_directives(source) if d.kind == "geolint" and not d.own_line}
    return line_ends, existing


def _statement_start(source: str, line: int) -> int:
    """The first line of the innermost statement that covers `line` (the line itself if none)."""
    try:
        tree = cached_ast(source)  # called once per finding: parse the text once
    except (SyntaxError, ValueError):
        return line
    best = line
    best_size: int | None = None
    for node in ast.walk(tree):
        if isinstance(node, ast.stmt) and node.lineno <= line <= (node.end_lineno or node.lineno):
            size = (node.end_lineno or node.lineno) - node.lineno
            if best_size is None or size < best_size:
                best, best_size = node.lineno, size
    return best
