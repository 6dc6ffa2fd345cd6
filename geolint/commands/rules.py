"""`geolint rules`: list every rule (code, name, whether it can fix, one-line summary)."""

from __future__ import annotations

import argparse
import json
import os
import shutil
import sys
import textwrap

from geolint.cli import EXIT_OK


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--format", choices=("text", "json"), default="text", help="output format (default: text)")


def run(args: argparse.Namespace) -> int:
    from geolint.docs import is_fixable, rule_summary
    from geolint.rules import all_rules

    rules = all_rules()
    if args.format == "json":
        table = [
            {"code": r.code, "name": r.name, "fixable": is_fixable(r), "opt_in": r.opt_in, "summary": rule_summary(r)}
            for r in rules
        ]
        sys.stdout.write(json.dumps(table, indent=2) + "\n")
        return EXIT_OK
    rows = [(r.code, r.name, is_fixable(r), rule_summary(r) + (f" (opt-in: select {r.code})" if r.opt_in else "")) for r in rules]
    name_width = max((len(n) for _, n, _, _ in rows), default=4)
    indent = 7 + 1 + name_width + 1 + 3 + 2
    width = _terminal_width()
    if width - indent < 30:  # too narrow for a column: the summary goes under its row
        for code, name, fixable, summary in rows:
            sys.stdout.write(f"{code} {name}{' (fix)' if fixable else ''}\n")
            sys.stdout.writelines(f"    {line}\n" for line in textwrap.wrap(summary, max(width - 4, 16), break_on_hyphens=False))
    else:
        sys.stdout.write(f"{'CODE':<7} {'NAME':<{name_width}} FIX  SUMMARY\n")
        for code, name, fixable, summary in rows:
            first, *rest = textwrap.wrap(summary, width - indent, break_on_hyphens=False)
            sys.stdout.write(f"{code:<7} {name:<{name_width}} {'yes' if fixable else '   '}  {first}\n")
            sys.stdout.writelines(" " * indent + line + "\n" for line in rest)
    footer = textwrap.wrap("`geolint rule CODE` prints one rule's documentation.", max(width, 16))
    sys.stdout.write("\n" + "".join(line + "\n" for line in footer))
    return EXIT_OK


PIPE_WIDTH = 100  # for a pipe or a file: the width of a wide terminal, not one line per rule


def _terminal_width() -> int:
    """The width to wrap summaries to: `COLUMNS`, else the terminal's, else PIPE_WIDTH."""
    if not os.environ.get("COLUMNS") and not sys.stdout.isatty():
        return PIPE_WIDTH
    return shutil.get_terminal_size().columns
