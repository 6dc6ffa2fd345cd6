"""`geolint rule CODE` / `geolint rule --all`: print rules' documentation (from their docstrings)."""

from __future__ import annotations

import argparse
import json
import sys

from geolint.cli import EXIT_ERROR, EXIT_OK


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("code", nargs="?", metavar="CODE", help="a rule code such as GEO101, or a rule name such as direction-translated")
    parser.add_argument("--all", action="store_true", help="print every rule's documentation")
    parser.add_argument("--output-format", "--format", dest="format", choices=("text", "json"), default="text", help="output format (default: text)")


def run(args: argparse.Namespace) -> int:
    from geolint.rules import all_rules, rule_by_code

    if args.all == (args.code is not None):
        sys.stderr.write("geolint: error: name one rule (geolint rule GEO101) or ask for --all\n")
        return EXIT_ERROR
    if args.all:
        rules = list(all_rules())
    else:
        rule = rule_by_code(args.code) or next((r for r in all_rules() if r.name == args.code.lower()), None)
        if rule is None:
            codes = ", ".join(r.code for r in all_rules())
            sys.stderr.write(f"geolint: error: unknown rule {args.code!r}; known rules: {codes}\n")
            return EXIT_ERROR
        rules = [rule]
    if args.format == "json":
        shown = [_as_json(rule) for rule in rules]
        sys.stdout.write(json.dumps(shown if args.all else shown[0], indent=2, ensure_ascii=False) + "\n")
    else:
        sys.stdout.write("\n".join(_as_text(rule) for rule in rules))
    return EXIT_OK


def _as_text(rule) -> str:
    from geolint.api import rule_url
    from geolint.docs import rule_doc

    return f"# {rule.code} {rule.name}\n\n{rule_doc(rule)}\n\nSee also: {rule_url(rule.code)}\n"


def _as_json(rule) -> dict[str, object]:
    """The fields of ruff's `rule --output-format json`, as geolint has them."""
    from geolint.api import rule_url
    from geolint.docs import is_fixable, rule_doc, rule_summary

    return {
        "code": rule.code,
        "name": rule.name,
        "summary": rule_summary(rule),
        "fixable": is_fixable(rule),
        "opt_in": rule.opt_in,
        "explanation": rule_doc(rule),
        "url": rule_url(rule.code),
    }
