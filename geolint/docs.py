"""Rule documentation, taken from the rules' docstrings (never written twice).

`geolint rule CODE` prints `rule_doc`, `geolint rules` lists `rule_summary`, and
`docs/rules.md` is `rules_markdown()` (regenerate with `python -m geolint.docs > docs/rules.md`;
a test fails when the committed file is out of date).
"""

from __future__ import annotations

import inspect
import re
from typing import TYPE_CHECKING, Sequence

if TYPE_CHECKING:
    from geolint.rules.base import RuleAttributes

SECTION = re.compile(r"^##\s+(?P<title>.+?)\s*$", re.MULTILINE)


def rule_doc(rule: type[RuleAttributes]) -> str:
    """The rule's documentation (its docstring, dedented)."""
    return inspect.cleandoc(rule.__doc__ or "").strip()


def doc_sections(rule: type[RuleAttributes]) -> dict[str, str]:
    """Section title -> body, from the rule's `## Title` markdown headings."""
    doc = rule_doc(rule)
    matches = list(SECTION.finditer(doc))
    return {
        match.group("title"): doc[match.end() : matches[i + 1].start() if i + 1 < len(matches) else len(doc)].strip()
        for i, match in enumerate(matches)
    }


def rule_summary(rule: type[RuleAttributes]) -> str:
    """One line: the first sentence of "What it does"."""
    body = doc_sections(rule).get("What it does") or rule_doc(rule)
    flat = " ".join(body.split())
    sentence = re.split(r"(?<=[.!?])\s", flat, maxsplit=1)[0]
    return sentence


def is_fixable(rule: type[RuleAttributes]) -> bool:
    """Whether the rule offers fixes (it documents at least one with an INVALID example)."""
    return any(example.expected_fix is not None for example in rule.INVALID)


def rules_markdown(rules: Sequence[type[RuleAttributes]] | None = None) -> str:
    """The whole `docs/rules.md` page."""
    if rules is None:
        from geolint.rules import all_rules

        return rules_markdown(all_rules())
    out = [
        "# geolint rules",
        "",
        "<!-- Generated from the rules' docstrings by `python -m geolint.docs > docs/rules.md`; do not edit. -->",
        "",
        "| Code | Name | Fixable | What it does |",
        "| --- | --- | --- | --- |",
    ]
    for rule in rules:
        opt_in = " (opt-in)" if rule.opt_in else ""
        out.append(f"| [{rule.code}](#{rule.code.lower()}) | {rule.name}{opt_in} | {'yes' if is_fixable(rule) else ''} | {rule_summary(rule)} |")
    for rule in rules:
        body = SECTION.sub(lambda m: f"### {m.group('title')}", rule_doc(rule))
        heading = f"## {rule.code} {rule.name}" + (" (opt-in)" if rule.opt_in else "")
        out += ["", f'<a id="{rule.code.lower()}"></a>', "", heading, "", body]
        if rule.opt_in:
            out += ["", f"This rule is opt-in: it runs only when `{rule.code}` itself is selected."]
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    import sys

    sys.stdout.write(rules_markdown())
