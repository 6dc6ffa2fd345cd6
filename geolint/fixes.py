"""Apply rules' fixes to a module's text until nothing more can be fixed.

Guarantees, whatever the rules do:
- only fixes whose applicability is allowed (`safe`, plus `unsafe` when asked) are applied;
- overlapping fixes are never applied in the same pass (the first wins; the next pass re-lints);
- fixes are applied as libcst transformations (`geolint.cst_fixes`): each edit's node is replaced in
  the module's tree and the tree is written back, so nothing outside the fixed nodes changes;
- the result always parses: a batch that breaks the module is retried fix by fix, and a fix
  that breaks it alone (or that is no node replacement) is dropped for good;
- the result is a fixed point (re-running changes nothing), reached within `MAX_PASSES`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Collection, Sequence

from geolint.engine import lint_source
from geolint.lint_types import Config, Edit, Finding
from geolint.parsing import parse_module

if TYPE_CHECKING:
    from geolint.rules import AstRule

MAX_PASSES = 10


@dataclass(frozen=True)
class FixOutcome:
    """The fixed text, how many findings the fixes removed, and the findings that remain."""

    source: str
    fixed: int
    remaining: tuple[Finding, ...]
    fixed_codes: tuple[str, ...] = ()  # the code of each finding a fix removed (`--show-fixes` lists them)

    @property
    def changed(self) -> bool:
        return self.fixed > 0


def fixable(finding: Finding, *, unsafe: bool, only: Collection[str] | None = None) -> bool:
    """Whether `finding` has a fix we may apply (`only`: code prefixes to restrict to)."""
    if finding.fix is None or not finding.fix.edits:
        return False
    if finding.fix.applicability != "safe" and not unsafe:
        return False
    return only is None or any(finding.code.startswith(prefix) for prefix in only)


def fix_source(
    source: str,
    path: str = "<string>",
    config: Config = Config(),
    *,
    unsafe: bool = False,
    only: Collection[str] | None = None,
    rules: Sequence[type[AstRule]] | None = None,
    findings: Sequence[Finding] | None = None,
) -> FixOutcome:
    """Apply every allowed fix to `source`, pass after pass, until none is left or none applies.

    `findings` are `source`'s own with this path, config and rules, when the caller has linted it
    already (`geolint check --fix`): the first pass starts from them instead of linting again."""
    current = source
    fixed = 0
    fixed_codes: list[str] = []
    dropped: set[tuple[str, str, str]] = set()  # fixes that broke the module: (code, message, edit text)
    findings = list(findings) if findings is not None else lint_source(current, path, config, rules)
    for _ in range(MAX_PASSES):
        candidates = [
            finding
            for finding in findings
            if fixable(finding, unsafe=unsafe, only=only) and _identity(finding) not in dropped
        ]
        if not candidates:
            break
        batch = _non_overlapping(candidates)
        attempt = _applied(current, [edit for finding in batch for edit in finding.fix.edits])  # type: ignore[union-attr]
        if attempt is not None:
            current, fixed = attempt, fixed + len(batch)
            fixed_codes += [finding.code for finding in batch]
        else:  # something in the batch breaks the module: find the culprits one at a time
            for finding in batch:
                attempt = _applied(current, finding.fix.edits)  # type: ignore[union-attr]
                if attempt is not None:
                    current, fixed = attempt, fixed + 1
                    fixed_codes.append(finding.code)
                    break  # the other fixes' positions moved: re-lint before trying them
                dropped.add(_identity(finding))
        findings = lint_source(current, path, config, rules)
    return FixOutcome(current, fixed, tuple(findings), tuple(fixed_codes))


def _applied(source: str, edits: Sequence[Edit]) -> str | None:
    """`source` with `edits` applied through its libcst tree, or None when that changes nothing, an edit
    is no node replacement, or the result does not compile (libcst writes what CPython may reject,
    e.g. a literal as an assignment target)."""
    from geolint.cst_fixes import apply_edits

    attempt = apply_edits(source, edits)
    if attempt is None or attempt == source:
        return None
    try:
        parse_module(attempt)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return None
    return attempt


def parses(source: str) -> bool:
    """Whether both CPython (reading Python 3.10-3.13 syntax) and libcst accept `source` (a fix must never break a file)."""
    try:
        parse_module(source)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return False
    import libcst as cst

    try:
        cst.parse_module(source)
    except (cst.ParserSyntaxError, RecursionError):
        return False
    return True


def _identity(finding: Finding) -> tuple[str, str, str]:
    edits = finding.fix.edits if finding.fix else ()
    return (finding.code, finding.message, "\x00".join(edit.content for edit in edits))


def _non_overlapping(findings: Sequence[Finding]) -> list[Finding]:
    """A left-to-right selection of fixes whose edits touch disjoint ranges."""
    chosen: list[Finding] = []
    taken: list[tuple[tuple[int, int], tuple[int, int]]] = []
    for finding in sorted(findings, key=lambda f: (f.line, f.column)):
        spans = [((e.line, e.column), (e.end_line, e.end_column)) for e in finding.fix.edits]  # type: ignore[union-attr]
        if any(start < other_end and other_start < end for start, end in spans for other_start, other_end in taken):
            continue
        if any(start == other_start for start, _ in spans for other_start, _ in taken):
            continue  # two insertions at one place would interleave unpredictably
        chosen.append(finding)
        taken.extend(spans)
    return chosen
