"""The lint engine: parse one file once, run every enabled rule in one traversal, return findings.

This is the only place that turns rule `Report`s into `Finding`s. The API, the CLI and
the language server all come through here, so the editor and CI always agree.
"""

from __future__ import annotations

from typing import Iterable, Mapping, Sequence

import libcst as cst
from libcst.metadata import MetadataWrapper, PositionProvider

from geolint.lint_types import Config, Edit, Finding, Fix
from geolint.rules import Rule, RuleContext, all_rules
from geolint.rules.base import Report


def lint_source(
    source: str,
    path: str = "<string>",
    config: Config = Config(),
    rules: Sequence[type[Rule]] | None = None,
) -> list[Finding]:
    """Lint one module's text and return its findings, sorted by position."""
    rule_classes = all_rules() if rules is None else rules
    module = cst.parse_module(source)
    wrapper = MetadataWrapper(module, unsafe_skip_copy=True)
    context = RuleContext(path=path, config=config)
    instances = [rule_cls(context) for rule_cls in rule_classes]
    wrapper.visit_batched(instances)
    positions = wrapper.resolve(PositionProvider)
    findings = [
        _finding(rule, report, positions, wrapper.module, path, config)
        for rule in instances
        for report in rule.reports
    ]
    return sorted(findings, key=lambda f: (f.line, f.column, f.code))


def _finding(
    rule: Rule,
    report: Report,
    positions: Mapping[cst.CSTNode, object],
    module: cst.Module,
    path: str,
    config: Config,
) -> Finding:
    where = positions[report.node]
    start, end = where.start, where.end  # type: ignore[attr-defined]
    fix = None
    if report.replacement is not None:
        content = "" if isinstance(report.replacement, cst.RemovalSentinel) else module.code_for_node(report.replacement)
        edit = Edit(start.line, start.column + 1, end.line, end.column + 1, content)
        fix = Fix(report.applicability, (edit,), report.fix_description)
    return Finding(
        path=path,
        line=start.line,
        column=start.column + 1,
        end_line=end.line,
        end_column=end.column + 1,
        code=rule.code,
        name=rule.name,
        message=report.message,
        severity=config.severity.get(rule.code, rule.default_severity),
        fix=fix,
    )


def apply_edits(source: str, edits: Iterable[Edit]) -> str:
    """Apply non-overlapping edits to `source` (positions as in `Finding`)."""
    lines = source.splitlines(keepends=True)
    offsets = [0]
    for line in lines:
        offsets.append(offsets[-1] + len(line))

    def offset(line: int, column: int) -> int:
        return offsets[line - 1] + column - 1

    result = source
    for edit in sorted(edits, key=lambda e: (e.line, e.column), reverse=True):
        start, end = offset(edit.line, edit.column), offset(edit.end_line, edit.end_column)
        result = result[:start] + edit.content + result[end:]
    return result

