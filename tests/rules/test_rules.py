"""Every registered rule's VALID and INVALID examples, run through the real engine.

Adding a rule adds its cases here automatically (fixit's generic test builder): VALID code
must give no finding of the rule; INVALID code exactly one, with the `message` and `range` an
example pins; a fix must reproduce `expected_fix` (as a text edit and as libcst's transformation
alike), parse, and be idempotent; the rule's prefilter must let every INVALID through.
"""

from __future__ import annotations

import ast
from dataclasses import replace

import pytest

from geolint.config import config_from_table
from geolint.engine import ENGINE_RULE_CODES, apply_edits, lint_source
from geolint.lint_types import Config
from geolint import cst_fixes
from geolint.rules import AstRule, Invalid, Valid, all_rules

CASES = [
    pytest.param(rule, example, id=f"{rule.code}-{kind}-{index}")
    for rule in all_rules()
    for kind, examples in (("valid", rule.VALID), ("invalid", rule.INVALID))
    for index, example in enumerate(examples)
]


def findings_of(rule: type[AstRule], source: str, config: Config = Config()):
    return [finding for finding in lint_source(source, "example.py", config, rules=[rule]) if finding.code == rule.code]


def example_config(rule: type[AstRule], example: Valid | Invalid) -> Config:
    """The example's `[tool.geolint]` table; an opt-in rule is selected by its code."""
    table = dict(example.options or {})
    if rule.opt_in:
        table["select"] = [rule.code]
    return config_from_table(table, None) if table else Config()


@pytest.mark.parametrize(("rule", "example"), CASES)
def test_example(rule: type[AstRule], example: Valid | Invalid) -> None:
    config = example_config(rule, example)
    found = findings_of(rule, example.code, config)
    if isinstance(example, Valid):
        assert found == [], f"{rule.code} flagged VALID code:\n{example.code}\n{found}"
        return
    assert len(found) == 1, f"{rule.code} should flag exactly once:\n{example.code}\n{found}"
    finding = found[0]
    assert finding.name == rule.name
    assert 1 <= finding.line <= finding.end_line
    if example.message is not None:
        assert finding.message == example.message
    if example.range is not None:
        assert (finding.line, finding.column, finding.end_line, finding.end_column) == example.range
    if rule.triggers is not None and rule.code not in ENGINE_RULE_CODES:  # GEO000/GEO900 run in the engine
        assert rule.triggers.search(example.code), f"{rule.code}'s prefilter would skip its own INVALID example"
    if example.expected_fix is not None:
        assert finding.fix is not None, f"{rule.code} offers no fix for:\n{example.code}"
        fixed = apply_edits(example.code, finding.fix.edits)
        assert fixed == example.expected_fix
    if finding.fix is not None:
        fixed = apply_edits(example.code, finding.fix.edits)
        # the edit an editor applies as text is what replacing the node in the libcst tree gives
        assert cst_fixes.apply_edits(example.code, finding.fix.edits) == fixed
        ast.parse(fixed)  # a fix always produces code that parses
        again = [f for f in findings_of(rule, fixed, config) if f.fix is not None]
        refixed = apply_edits(fixed, [edit for f in again for edit in f.fix.edits])
        assert refixed == fixed, f"{rule.code}'s fix is not idempotent:\n{fixed}\n->\n{refixed}"


@pytest.mark.parametrize("rule", all_rules(), ids=lambda rule: rule.code)
def test_rule_has_examples_both_ways(rule: type[AstRule]) -> None:
    assert rule.VALID, f"{rule.code} has no VALID examples"
    assert rule.INVALID, f"{rule.code} has no INVALID examples"


@pytest.mark.parametrize("rule", all_rules(), ids=lambda rule: rule.code)
def test_rule_pins_a_message_and_a_range(rule: type[AstRule]) -> None:
    # fixit's `expected_message` and `range`: what a finding says and where, not only that it fires
    assert any(example.message is not None and example.range is not None for example in rule.INVALID), (
        f"{rule.code} has no INVALID example with both `message=` and `range=`"
    )


def test_a_wrong_pinned_message_or_range_fails() -> None:
    rule = next(rule for rule in all_rules() if rule.code == "GEO101")
    pinned = next(example for example in rule.INVALID if example.message is not None and example.range is not None)
    line, column, end_line, end_column = pinned.range  # type: ignore[misc]
    for wrong in (
        replace(pinned, message=pinned.message + "!"),  # type: ignore[operator]
        replace(pinned, range=(line, column + 1, end_line, end_column)),
        replace(pinned, range=(line, column, end_line, end_column - 1)),
    ):
        with pytest.raises(AssertionError):
            test_example(rule, wrong)


SAFE_FIXES = {"GEO101", "GEO301", "GEO302"}  # the fixes issue 3 lists as safe


@pytest.mark.parametrize("rule", [r for r in all_rules() if r.code[3] in "123"], ids=lambda rule: rule.code)
def test_only_listed_fixes_are_safe(rule: type[AstRule]) -> None:
    for example in rule.INVALID:
        for finding in findings_of(rule, example.code, example_config(rule, example)):
            if finding.fix is not None and finding.fix.applicability == "safe":
                assert rule.code in SAFE_FIXES, f"{rule.code} marks a fix safe that issue 3 does not list"
