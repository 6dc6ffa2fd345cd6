"""`geolint rules`: list every rule (code, name, whether it can fix, one-line summary)."""

from __future__ import annotations

import argparse
import json
import sys

from geolint.cli import EXIT_OK


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--format", choices=("text", "json"), default="text", help="output format (default: text)")


def run(args: argparse.Namespace) -> int:
    from geolint.docs import is_fixable, rule_summary
    from geolint.rules import all_rules

    rows = [(r.code, r.name, is_fixable(r), rule_summary(r)) for r in all_rules()]
    if args.format == "json":
        table = [{"code": c, "name": n, "fixable": f, "summary": s} for c, n, f, s in rows]
        sys.stdout.write(json.dumps(table, indent=2) + "\n")
        return EXIT_OK
    name_width = max((len(n) for _, n, _, _ in rows), default=4)
    sys.stdout.write(f"{'CODE':<7} {'NAME':<{name_width}} FIX  SUMMARY\n")
    for code, name, fixable, summary in rows:
        sys.stdout.write(f"{code:<7} {name:<{name_width}} {'yes' if fixable else '   '}  {summary}\n")
    return EXIT_OK
