"""Rule documentation, taken from the rules' docstrings (never written twice).

`geolint rule CODE` prints `rule_doc`, `geolint rules` lists `rule_summary`, and
`docs/rules.md` is `rules_markdown()` (regenerate with `python -m geolint.docs > docs/rules.md`;
a test fails when the committed file is out of date).
"""

from __future__ import annotations

import ast
import inspect
import re
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Sequence

if TYPE_CHECKING:
    from geolint.rules.base import RuleAttributes

SECTION = re.compile(r"^##\s+(?P<title>.+?)\s*$", re.MULTILINE)


def rule_doc(rule: type[RuleAttributes]) -> str:
    """The rule's documentation (its docstring, dedented), with the shared section on naming
    conventions for the rules that read names as frames."""
    doc = inspect.cleandoc(_docstring(rule)).strip()
    if rule.documents_naming:
        from geolint.rules.fact_rule import NAMING_OPTIONS

        doc = f"{doc}\n\n{NAMING_OPTIONS}"
    return doc


def _docstring(rule: type[RuleAttributes]) -> str:
    """The class docstring; for a class compiled by mypyc (which does not keep it), read from the
    module's source file, which the compiled build ships beside the extension."""
    module_file = getattr(sys.modules.get(rule.__module__), "__file__", None) or ""
    if module_file.endswith(".py"):
        return rule.__doc__ or ""
    source = Path(module_file).with_name(f"{rule.__module__.rpartition('.')[2]}.py")
    try:
        tree = ast.parse(source.read_text(encoding="utf-8"))
    except (OSError, SyntaxError, ValueError):
        return ""
    for node in ast.walk(tree):
        if isinstance(node, ast.ClassDef) and node.name == rule.__name__:
            return ast.get_docstring(node, clean=False) or ""
    return ""


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
