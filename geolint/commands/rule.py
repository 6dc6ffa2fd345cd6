"""`geolint rule CODE`: print one rule's documentation (from its docstring)."""

from __future__ import annotations

import argparse
import sys

from geolint.cli import EXIT_ERROR, EXIT_OK


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("code", metavar="CODE", help="a rule code such as GEO101, or a rule name such as direction-translated")


def run(args: argparse.Namespace) -> int:
    from geolint.api import rule_url
    from geolint.docs import rule_doc
    from geolint.rules import all_rules, rule_by_code

    rule = rule_by_code(args.code) or next((r for r in all_rules() if r.name == args.code.lower()), None)
    if rule is None:
        codes = ", ".join(r.code for r in all_rules())
        sys.stderr.write(f"geolint: error: unknown rule {args.code!r}; known rules: {codes}\n")
        return EXIT_ERROR
    sys.stdout.write(f"# {rule.code} {rule.name}\n\n{rule_doc(rule)}\n\nSee also: {rule_url(rule.code)}\n")
    return EXIT_OK
