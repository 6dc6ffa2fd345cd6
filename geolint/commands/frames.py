"""`geolint frames PATH`: draw the frames and transforms found in code, mismatches in red."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from geolint.render import RENDERERS, GraphvizNotFound

EXIT_OK, EXIT_ERROR = 0, 2


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("paths", nargs="*", type=Path, default=[Path(".")], metavar="PATH", help="files or folders (default: .)")
    parser.add_argument(
        "--format", choices=sorted(RENDERERS), default="dot", help="Graphviz DOT (default), JSON, Mermaid, or SVG (needs graphviz)"
    )
    parser.add_argument("--output", "-o", type=Path, metavar="FILE", help="write here instead of standard output")


def run(args: argparse.Namespace) -> int:
    missing = [str(path) for path in args.paths if not path.exists()]
    if missing:
        print(f"geolint frames: no such file or folder: {', '.join(missing)}", file=sys.stderr)
        return EXIT_ERROR
    from geolint.frames_graph import graph_of_paths

    try:
        graph = graph_of_paths(args.paths)
        text = RENDERERS[args.format](graph)
    except GraphvizNotFound as error:
        print(f"geolint frames: {error}", file=sys.stderr)
        return EXIT_ERROR
    except Exception as error:  # config errors and the like: one clear line, exit 2 like `check`
        print(f"geolint frames: {error}", file=sys.stderr)
        return EXIT_ERROR
    if args.output is None:
        sys.stdout.write(text)
    else:
        try:
            args.output.write_text(text, encoding="utf-8")
        except OSError as error:
            print(f"geolint frames: cannot write {args.output}: {error.strerror or error}", file=sys.stderr)
            return EXIT_ERROR
    return EXIT_OK
