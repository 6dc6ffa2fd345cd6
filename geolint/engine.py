"""The lint engine: parse one file once, run every enabled rule on it, return findings.

This is the only place that turns rule reports into `Finding`s. The API, the CLI and
the language server all come through here, so the editor and CI always agree.

The pipeline for one file: decode (PEP 263 cookie, BOM) -> syntax check (GEO000, CPython's `ast`,
which reads the syntax of Python 3.10-3.13 whichever of them runs: `geolint.parsing`)
-> prefilter (each rule's `triggers`; a file no enabled rule can fire on is analysed no further)
-> every `AstRule`'s `check` on the cached `ast` tree and the file's fact base -> fixes built as
libcst transformations (`geolint.cst_fixes`; only a file with a fix is parsed with libcst)
-> configured severities -> suppression comments -> GEO900.

libcst and the rule registry are imported on first use, so a run served from the cache
never pays for them.
"""

from __future__ import annotations

import ast
import codecs
import re
import tokenize
from functools import lru_cache
from typing import TYPE_CHECKING, Iterable, Sequence

from geolint import guards, suppression
from geolint.config import enabled_codes
from geolint.lint_types import SYNTAX_ERROR, SYNTAX_ERROR_NAME, Config, Edit, Finding, Fix, Severity
from geolint.notebook import BOUNDARY as CELL_BOUNDARY, NOTEBOOK_SUFFIX
from geolint.parsing import SUPPORTED_GRAMMARS
from geolint.source_text import cached_ast, remember_tree, split_lines

if TYPE_CHECKING:
    from geolint.factbase import FactBase
    from geolint.factbase.index import ModuleIndex
    from geolint.rules.base import AstReport, AstRule

# Pseudo-rules: documented like rules, but detected here rather than by visiting the tree.
ENGINE_RULE_CODES = frozenset({SYNTAX_ERROR, guards.TOO_COMPLEX, suppression.UNUSED_SUPPRESSION})


def registered_rules() -> tuple[type[AstRule], ...]:
    from geolint.rules import all_rules

    return all_rules()


def lint_bytes(
    data: bytes,
    path: str = "<string>",
    config: Config = Config(),
    rules: Sequence[type[AstRule]] | None = None,
) -> list[Finding]:
    """Lint a file's raw bytes: honours a PEP 263 coding cookie or a BOM (UTF-8 otherwise).

    Bytes that cannot be decoded give one GEO000 finding at the offending byte, never an exception.
    """
    try:
        source, _ = decode_source(data)
    except (SyntaxError, UnicodeDecodeError, LookupError) as error:
        line, column, message = _decode_problem(data, error)
        return _only_syntax_error(path, config, rules, line, column, message)
    return lint_source(source, path, config, rules)


def _decode_problem(data: bytes, error: Exception) -> tuple[int, int, str]:
    """Where and why the bytes could not be decoded, in words a person can act on."""
    if isinstance(error, SyntaxError) and "unknown encoding" not in str(error):
        try:  # tokenize says only "invalid or missing encoding declaration": find the bad byte
            data.decode("utf-8")
        except UnicodeDecodeError as utf8_error:
            error = utf8_error
    if isinstance(error, UnicodeDecodeError):
        line, column = _byte_position(data, error.start)
        bad = data[error.start : error.start + 1].hex()
        return line, column, (
            f"cannot decode byte 0x{bad} as {error.encoding}; "
            "declare the file's encoding with a comment such as `# -*- coding: latin-1 -*-`"
        )
    return 1, 1, f"cannot decode the file: {error}"


def decode_source(data: bytes) -> tuple[str, str]:
    """The text of a Python file and the encoding it was read with (newlines kept as they are)."""
    # The first two lines as Python counts them (a CR-only file's cookie is on its first line too).
    first_two = _FIRST_TWO_LINES.match(data).group()  # type: ignore[union-attr]
    if b"coding" not in first_two and not first_two.startswith(codecs.BOM_UTF8):
        return data.decode("utf-8"), "utf-8"  # no cookie, no BOM: what tokenize would say, without asking it
    first_lines = iter(first_two.splitlines(keepends=True))
    encoding, _ = tokenize.detect_encoding(lambda: next(first_lines, b""))  # "utf-8-sig" when there is a BOM
    return data.decode(encoding), encoding


_FIRST_TWO_LINES = re.compile(rb"[^\r\n]*(?:\r\n|\r|\n)?[^\r\n]*(?:\r\n|\r|\n)?")


def encode_source(text: str, encoding: str) -> bytes:
    """The bytes to write back for text read by `decode_source` ("utf-8-sig" keeps the BOM)."""
    return text.encode(encoding)


@guards.too_deep_becomes_a_finding
def lint_source(
    source: str,
    path: str = "<string>",
    config: Config = Config(),
    rules: Sequence[type[AstRule]] | None = None,
) -> list[Finding]:
    """Lint one module's text and return its findings, sorted by position.

    `rules` defaults to every registered rule; the config's select/ignore/per-file-ignores
    then decide which of them run. Never raises for bad code (a syntax error is GEO000);
    an exception from a rule propagates, so callers can report it as an internal error.
    """
    candidates = registered_rules() if rules is None else tuple(rules)
    on = set(enabled_codes(config, path, tuple(rule.code for rule in candidates)))
    on -= {rule.code for rule in candidates if rule.opt_in and rule.code not in config.select}
    visitors = [rule for rule in candidates if rule.code in on and rule.code not in ENGINE_RULE_CODES]

    taken: ModuleIndex | None = None
    active = [rule for rule in visitors if _may_fire(rule, source, config)]
    # Parsing is the cost every file would pay: a file no enabled rule can read is parsed only when the
    # syntax check, the complexity check or an unused-suppression verdict asks for it.
    checked = SYNTAX_ERROR in on or guards.TOO_COMPLEX in on or bool(active) or (
        suppression.UNUSED_SUPPRESSION in on and suppression.may_have_directives(source)
    )
    if checked:
        taken = _reuse_shared_parse(path, source)
        # size and CPython's parser before any analysis; the nesting depth below, before any analysis
        # and before libcst's parser (measured on the fact base's walk when an AstRule runs)
        limit = guards.exceeded_limit(source, config, measure_depth=False)
        if limit is not None:
            return guards.limit_finding(path, config, limit)
        guards.make_room_for_recursion(config)
        syntax_error = _syntax_error(source)
        if syntax_error is not None:
            cells = _lint_parseable_cells(source, path, config, rules) if path.endswith(NOTEBOOK_SUFFIX) else None
            if cells is not None:
                return cells
            line, column, message = syntax_error
            return _only_syntax_error(path, config, rules, line, column, f"syntax error for {SUPPORTED_GRAMMARS}: {message}")
        limit = _depth_limit(source, config, bool(active), guards.TOO_COMPLEX in on or (
            suppression.UNUSED_SUPPRESSION in on and suppression.may_have_directives(source)
        ))
        if limit is not None:
            return guards.limit_finding(path, config, limit)
    findings: list[Finding] = []
    if active:
        findings += _run_ast_rules(source, path, config, active)
    if taken is not None:
        taken.forget_derived()  # the shared index stays as an importer found it

    if suppression.may_have_directives(source):
        directives = suppression.parse_directives(source)
        findings = suppression.apply_suppressions(findings, directives)
        if suppression.UNUSED_SUPPRESSION in on and directives:
            known = {rule.code for rule in registered_rules()}
            findings += suppression.unused_suppression_findings(
                directives,
                path,
                known_codes=known,
                enabled_codes=on,
                severity=_severity_of(suppression.UNUSED_SUPPRESSION, config, Severity.WARNING),
            )
    return sorted(findings, key=finding_order)


def _lint_parseable_cells(source: str, path: str, config: Config, rules: Sequence[type[AstRule]] | None) -> list[Finding] | None:
    """A notebook's cells, joined, that do not parse: IPython compiles each cell alone, so a cell that
    does not parse (a pasted table, a doctest) is one GEO000 and the other cells are linted, with the
    broken ones blanked line for line. None when the joined text is no notebook's or still does not parse."""
    lines = source.splitlines(keepends=True)
    starts = [number for number, line in enumerate(lines) if line == CELL_BOUNDARY]
    if not starts:
        return None
    kept = list(lines)
    findings: list[Finding] = []
    for position, start in enumerate(starts):
        end = starts[position + 1] if position + 1 < len(starts) else len(lines)
        error = _syntax_error("".join(lines[start + 1 : end]))
        if error is not None:
            line, column, message = error
            findings += _only_syntax_error(path, config, rules, start + 1 + line, column, f"syntax error for {SUPPORTED_GRAMMARS}: {message}")
            kept[start + 1 : end] = ["\n"] * (end - start - 1)
    blanked = "".join(kept)
    if blanked == source or _syntax_error(blanked) is not None:
        return None
    return sorted(findings + lint_source(blanked, path, config, rules), key=finding_order)


def _depth_limit(source: str, config: Config, analysed: bool, verdict_needed: bool) -> guards.LimitExceeded | None:
    """Whether the tree of `source` (which parses) is nested past `max-nesting-depth`.

    When an AstRule runs, the fact base's walk of the tree measures it (one walk for both); otherwise
    the guards walk it, but only when something would still read the file or GEO001 is on (a file
    no rule reads and GEO001 ignores gets no finding either way).
    """
    limit = config.max_nesting_depth
    if analysed:
        from geolint.factbase import module_index

        index = module_index(cached_ast(source), source, limit)
        return guards.past_depth_limit(index.too_deep_at, limit) if index.too_deep else None
    return guards.too_deep(cached_ast(source), limit) if verdict_needed else None


def _reuse_shared_parse(path: str, source: str) -> ModuleIndex | None:
    """Take the tree (and index) of this very text when the process parsed it already (a project
    module another linted module imports): the syntax check and the fact base then find them.

    The engine does not leave its own trees for later importers: few are imported after they are
    linted, and kept trees crowd the imported modules' trees out of the shared budget and are freed
    long after, out of the processor's caches (3.8% more time, compiled, on 40 realcode repositories)."""
    from geolint.factbase import index as index_module, remember_index

    shared = index_module.shared_parse(path, source)
    if shared is not None:
        tree, index = shared
        remember_tree(source, tree)
        if index is not None:
            remember_index(index)
        return index
    return None


def _may_fire(rule: type[AstRule], source: str, config: Config) -> bool:
    """The prefilter: whether the rule's trigger matches (a trigger that can read the config is given it)."""
    trigger = rule.triggers
    if trigger is None:
        return True
    search_with = getattr(trigger, "search_with", None)
    return bool(search_with(source, config) if search_with is not None else trigger.search(source))


def _run_ast_rules(source: str, path: str, config: Config, rule_classes: Sequence[type[AstRule]]) -> list[Finding]:
    """Every AstRule's `check` on the cached `ast` of `source`, sharing one fact base; reports become findings."""
    from geolint.rules.base import RuleContext

    tree = cached_ast(source)
    facts = _facts_for(tree, source, path, config, rule_classes)
    context = RuleContext(path=path, config=config, source=source, facts=facts)
    instances = [rule_cls(context) for rule_cls in rule_classes]
    try:
        for rule in instances:
            rule.check(tree)
    finally:
        if facts is not None:
            facts.project.close()
            facts.close()
    if not any(rule.reports for rule in instances):
        return []
    columns = _CharacterColumns(source)
    findings = [_ast_finding(rule, report, columns, path, config) for rule in instances for report in rule.reports]
    return _with_fixes(source, findings, [report for rule in instances for report in rule.reports])


def _with_fixes(source: str, findings: list[Finding], reports: Sequence[AstReport]) -> list[Finding]:
    """Each finding whose report has a replacement, with the fix that replaces its node in the module's
    libcst tree (`geolint.cst_fixes`); libcst parses only a file with such a finding."""
    wanted = [index for index, report in enumerate(reports) if report.replacement is not None]
    if not wanted:
        return findings
    from dataclasses import replace

    from geolint.cst_fixes import build_edits

    requests = []
    for index in wanted:
        finding, replacement = findings[index], reports[index].replacement
        requests.append(Edit(finding.line, finding.column, finding.end_line, finding.end_column, replacement))  # type: ignore[arg-type]
    for index, edit in zip(wanted, build_edits(source, requests)):
        if edit is not None:
            report = reports[index]
            findings[index] = replace(findings[index], fix=Fix(report.applicability, (edit,), report.fix_description))
    return findings


def _facts_for(
    tree: ast.Module, source: str, path: str, config: Config, rule_classes: Sequence[type[AstRule]]
) -> FactBase | None:
    """The file's fact base, built once for all rules that ask for it (`needs_facts`); None otherwise."""
    if not any(getattr(rule, "needs_facts", False) for rule in rule_classes):
        return None
    from geolint.factbase import facts_for_module

    return facts_for_module(tree, source, path, config)


class _CharacterColumns:
    """Turns `ast`'s UTF-8 byte offsets within a line into the character columns findings use."""

    def __init__(self, source: str) -> None:
        self._lines = split_lines(source)

    def column(self, line: int, byte_offset: int) -> int:
        """The 0-based character column of `byte_offset` on 1-based `line`."""
        if not 1 <= line <= len(self._lines):
            return byte_offset
        text = self._lines[line - 1]
        if text.isascii():
            return byte_offset
        return len(text.encode("utf-8")[:byte_offset].decode("utf-8", errors="replace"))


def _ast_finding(rule: AstRule, report: AstReport, columns: _CharacterColumns, path: str, config: Config) -> Finding:
    node = report.node
    line = getattr(node, "lineno", 1) or 1
    end_line = getattr(node, "end_lineno", None) or line
    column = columns.column(line, getattr(node, "col_offset", 0) or 0)
    end_offset = getattr(node, "end_col_offset", None)
    end_column = column + 1 if end_offset is None else columns.column(end_line, end_offset)
    return Finding(
        path=path,
        line=line,
        column=column + 1,
        end_line=end_line,
        end_column=end_column + 1,
        code=rule.code,
        name=rule.name,
        message=report.message,
        severity=_severity_of(rule.code, config, rule.default_severity),
        evidence=report.evidence,
        frames=report.frames,
    )


def finding_order(finding: Finding) -> tuple[int, int, str, int, int, str]:
    return (finding.line, finding.column, finding.code, finding.end_line, finding.end_column, finding.message)


def _severity_of(code: str, config: Config, default: Severity) -> Severity:
    return config.severity.get(code, default)


def _syntax_error(source: str) -> tuple[int, int, str] | None:
    """(line, column, message) of CPython's first syntax error, or None when the module compiles."""
    try:
        cached_ast(source)
    except SyntaxError as error:
        return (error.lineno or 1, max(error.offset or 1, 1), error.msg or "invalid syntax")
    except (ValueError, MemoryError, RecursionError) as error:  # null bytes, absurd nesting
        return (1, 1, str(error) or type(error).__name__)
    return None


def _only_syntax_error(
    path: str, config: Config, rules: Sequence[type[AstRule]] | None, line: int, column: int, message: str
) -> list[Finding]:
    candidates = (SYNTAX_ERROR,) if rules is None else tuple(rule.code for rule in rules)
    if SYNTAX_ERROR not in candidates or not enabled_codes(config, path, (SYNTAX_ERROR,)):
        return []
    return [
        Finding(
            path=path,
            line=line,
            column=column,
            end_line=line,
            end_column=column + 1,
            code=SYNTAX_ERROR,
            name=SYNTAX_ERROR_NAME,
            message=message,
            severity=_severity_of(SYNTAX_ERROR, config, Severity.ERROR),
        )
    ]


def _byte_position(data: bytes, offset: int) -> tuple[int, int]:
    line_start = data.rfind(b"\n", 0, offset) + 1
    return data.count(b"\n", 0, offset) + 1, offset - line_start + 1


@lru_cache(maxsize=256)
def read_source_lines(path: str) -> tuple[str, ...]:
    """The lines of the Python file at `path` (as `split_lines` gives them); () when it cannot be read.

    Remembered for the last files asked for: the text output and the baseline both look up
    the line each finding starts on, many findings to a file.
    """
    try:
        with open(path, "rb") as stream:
            text, _ = decode_source(stream.read())
    except (OSError, SyntaxError, UnicodeDecodeError, LookupError):
        return ()
    return tuple(split_lines(text))


def apply_edits(source: str, edits: Iterable[Edit]) -> str:
    """Apply non-overlapping edits to `source` (positions as in `Finding`)."""
    lines = split_lines(source)
    offsets = [0]
    for line in lines:
        offsets.append(offsets[-1] + len(line))

    def offset(line: int, column: int) -> int:
        if line > len(lines):  # an edit at the very end of a file without a final newline
            return offsets[-1] + column - 1
        return offsets[line - 1] + column - 1

    result = source
    for edit in sorted(edits, key=lambda e: (e.line, e.column), reverse=True):
        start, end = offset(edit.line, edit.column), offset(edit.end_line, edit.end_column)
        result = result[:start] + edit.content + result[end:]
    return result
