"""`geolint check --watch`: check, then check again whenever a file or a config changes.

Changes are found by polling: every half second the Python files, notebooks, `pyproject.toml` and
`.gitignore` files under the paths (and each `pyproject.toml` above them) are stat'ed, and a run
starts when a modification time or a size differs, or a file came or went. The standard library
only; no event API is needed. Each run happens in a forked child, so it starts from a process that
has linted nothing: no file read or config found by an earlier run can be remembered wrongly.
Where there is no fork (Windows), runs happen in this process with the read caches cleared.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path
from typing import Callable

from geolint.cli import EXIT_ERROR, EXIT_OK

POLL_SECONDS = 0.5
WATCHED_NAMES = ("pyproject.toml", ".gitignore")
WATCHED_SUFFIXES = (".py", ".pyi", ".ipynb")

Snapshot = dict[str, tuple[int, int]]


def watch(args: argparse.Namespace, check_once: Callable[[argparse.Namespace], int]) -> int:
    """Run `check_once(args)` now and after every change, until Ctrl-C (then exit 0)."""
    paths = [Path(path) for path in (args.paths or [Path(".")])]
    _say("Starting geolint in watch mode (Ctrl-C stops)...")
    try:
        while True:
            before = snapshot(paths, args.config)
            _clear_terminal()
            _run(args, check_once)
            _say(f"[{time.strftime('%H:%M:%S')}] Watching for file changes.")
            while snapshot(paths, args.config) == before:
                time.sleep(POLL_SECONDS)
            _say("File change detected...")
    except KeyboardInterrupt:
        return EXIT_OK


def snapshot(paths: list[Path], config: Path | None) -> Snapshot:
    """(modification time, size) of every watched file under `paths`, and of the configs above them."""
    from geolint.files import DEFAULT_EXCLUDES

    skipped = {name for name in DEFAULT_EXCLUDES if "*" not in name}
    found: Snapshot = {}

    def note(path: str) -> None:
        try:
            stat = os.stat(path)
        except OSError:
            return
        found[path] = (stat.st_mtime_ns, stat.st_size)

    for path in paths:
        absolute = Path(os.path.abspath(path))
        for folder in (absolute if absolute.is_dir() else absolute.parent, *absolute.parents):
            note(str(folder / "pyproject.toml"))
        if not absolute.is_dir():
            note(str(absolute))
            continue
        for top, folders, names in os.walk(absolute):
            folders[:] = [name for name in folders if name not in skipped and not name.endswith(".egg-info")]
            for name in names:
                if name.endswith(WATCHED_SUFFIXES) or name in WATCHED_NAMES:
                    note(os.path.join(top, name))
    if config is not None:
        note(str(config))
    return found


def _run(args: argparse.Namespace, check_once: Callable[[argparse.Namespace], int]) -> int:
    """One check, in a forked child where there is fork."""
    sys.stdout.flush()
    sys.stderr.flush()
    if not hasattr(os, "fork"):
        _forget_reads()
        return check_once(args)
    child = os.fork()
    if child == 0:  # the child: check, flush, and leave without running the parent's exit handlers
        code = EXIT_ERROR
        try:
            code = check_once(args)
        except KeyboardInterrupt:
            code = EXIT_OK
        finally:
            for stream in (sys.stdout, sys.stderr):
                try:
                    stream.flush()
                except (OSError, ValueError):
                    pass
            os._exit(code)
    _, status = os.waitpid(child, 0)
    return os.waitstatus_to_exitcode(status)


def _forget_reads() -> None:
    """Clear what an in-process run remembers of files and configs (no fork to start clean)."""
    from geolint.config import forget_pyprojects
    from geolint.engine import read_source_lines

    forget_pyprojects()
    read_source_lines.cache_clear()


def _clear_terminal() -> None:
    if sys.stdout.isatty():
        sys.stdout.write("\x1b[2J\x1b[H")
        sys.stdout.flush()


def _say(message: str) -> None:
    sys.stderr.write(message + "\n")
    sys.stderr.flush()
