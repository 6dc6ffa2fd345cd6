"""`geolint lsp`: run the language server over stdin/stdout (editors start it; see docs/editors.md)."""

from __future__ import annotations

import argparse
import logging
import sys


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--stdio", action="store_true", help="talk LSP over stdin/stdout (the default and only transport)")
    parser.add_argument("--log-file", metavar="FILE", help="write the server's log to FILE (stdout carries the protocol)")
    parser.add_argument("--verbose", action="store_true", help="log debug messages")


def run(args: argparse.Namespace) -> int:
    from geolint.lsp.server import server  # without the `lsp` extra, the CLI names the extra to install
    level = logging.DEBUG if args.verbose else logging.WARNING
    if args.log_file:
        logging.basicConfig(filename=args.log_file, level=level)
    else:  # stderr: stdout is the protocol channel
        logging.basicConfig(stream=sys.stderr, level=level)
    server.start_io()
    return 0
