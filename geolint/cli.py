"""The `geolint` command line: a thin adapter that dispatches to one module per subcommand.

Each subcommand lives in `geolint/commands/<name>.py` and exposes
`add_arguments(parser)` and `run(args) -> int`. Modules are imported only when their
subcommand runs, so `geolint check` never pays for the language server's imports.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys
from typing import NoReturn, Sequence

from geolint._build import is_compiled
from geolint._version import __version__

# subcommand -> one-line help; the module is geolint.commands.<subcommand with - as _>
SUBCOMMANDS = {
    "check": "lint files for geometric type errors",
    "rule": "print one rule's documentation",
    "rules": "list every rule",
    "lsp": "run the language server over stdio",
    "frames": "draw the frames and transforms found in code",
}

EXIT_OK, EXIT_FINDINGS, EXIT_ERROR = 0, 1, 2

# The distribution's name on the package index (the import package and the command are `geolint`).
DISTRIBUTION = "geolint-robotics"
# Optional modules -> the extra that installs them.
EXTRA_OF_MODULE = {"pygls": "lsp", "lsprotocol": "lsp", "mypy": "mypy", "scipy": "scipy"}


def missing_extra_message(command: str, error: ImportError) -> str | None:
    """What to install when `error` is an optional dependency's absence, else None.

    The extra's own requirements, read from the installed distribution, install wherever geolint came
    from; `DISTRIBUTION[extra]` would need the package index, where geolint is not published yet.
    """
    module = (getattr(error, "name", None) or "").split(".")[0]
    extra = EXTRA_OF_MODULE.get(module)
    if extra is None:
        return None
    requirements = " ".join(f"'{requirement}'" for requirement in requirements_of_extra(extra))
    install = f"pip install {requirements}" if requirements else f"pip install '.[{extra}]' in a checkout of geolint"
    return f"geolint {command} needs the `{extra}` extra ({module} is not installed): {install}"


def requirements_of_extra(extra: str) -> list[str]:
    """The requirements the installed distribution lists for `extra` (`pygls>=2.0`), markers dropped."""
    from importlib.metadata import PackageNotFoundError, requires

    try:
        listed = requires(DISTRIBUTION) or []
    except PackageNotFoundError:
        return []
    found = []
    for line in listed:
        requirement, _, marker = line.partition(";")
        if f'extra == "{extra}"' in marker.replace("'", '"'):
            found.append(requirement.strip().replace(" ", ""))
    return found


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="geolint", description="Catch geometric type errors in Python code.")
    parser.add_argument("--version", action="version", version=f"geolint {__version__}{' (compiled)' if is_compiled() else ''}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name, help_text in SUBCOMMANDS.items():
        sub = subparsers.add_parser(name, help=help_text, description=help_text)
        sub.set_defaults(command_module=f"geolint.commands.{name.replace('-', '_')}")
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = build_parser()
    # Parse the subcommand first, then let its module add its own arguments.
    known, _ = parser.parse_known_args(argv[:1] if argv and not argv[0].startswith("-") else argv)
    if getattr(known, "command", None) is None:
        parser.print_help(sys.stderr)
        return EXIT_ERROR
    module = importlib.import_module(known.command_module)
    sub = argparse.ArgumentParser(prog=f"geolint {known.command}", description=SUBCOMMANDS[known.command])
    module.add_arguments(sub)
    try:
        args = sub.parse_args(argv[1:])
    except SystemExit as exit_:  # argparse exits 2 on usage errors, as we want
        return int(exit_.code or 0)
    try:
        return int(module.run(args))
    except ImportError as error:
        message = missing_extra_message(known.command, error)
        if message is None:
            raise
        print(f"geolint: error: {message}", file=sys.stderr)
        return EXIT_ERROR
    except BrokenPipeError:  # `geolint rules | head`: the reader left; stop quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return EXIT_FINDINGS


def main_and_exit() -> NoReturn:
    """The `geolint` command: `main`, then an exit that skips tearing down what the run built (as
    mypy's `hard_exit` does). Freeing a cold run's syntax trees, indexes and caches object by object
    at interpreter exit took about a second of a 15 s run; output and logs are flushed first, and
    nothing else is left to do (the findings cache is saved inside the run)."""
    code = main()
    logging = sys.modules.get("logging")  # imported by the language server only: not worth importing here
    if logging is not None:
        logging.shutdown()
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (BrokenPipeError, OSError, ValueError):  # a reader that left, or a closed stream
            pass
    os._exit(code)


if __name__ == "__main__":
    main_and_exit()
