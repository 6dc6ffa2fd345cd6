"""What a terminal gets that a pipe or a CI log does not: colour and a progress bar.

Colour only when the stream is a TTY and `NO_COLOR` is unset (https://no-color.org) and the
terminal is not "dumb". The progress bar only on an interactive stderr, never in CI (`CI` set).
"""

from __future__ import annotations

import os
import sys
import time
from typing import TextIO

RESET = "\x1b[0m"
BOLD = "\x1b[1m"
RED = "\x1b[31m"
GREEN = "\x1b[32m"
YELLOW = "\x1b[33m"
CYAN = "\x1b[36m"
DIM = "\x1b[2m"


def use_color(stream: TextIO) -> bool:
    """Whether to colour output written to `stream`."""
    if os.environ.get("NO_COLOR"):
        return False
    if os.environ.get("TERM") == "dumb":
        return False
    return _isatty(stream)


def show_progress(stream: TextIO) -> bool:
    """Whether a progress bar may be drawn on `stream` (an interactive terminal outside CI)."""
    return _isatty(stream) and not os.environ.get("CI") and os.environ.get("TERM") != "dumb"


def paint(text: str, *styles: str, color: bool) -> str:
    return "".join(styles) + text + RESET if color and styles else text


def _isatty(stream: TextIO) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):
        return False


class ProgressBar:
    """A one-line `[#####.....] 120/480 files` bar on stderr, redrawn at most ten times a second."""

    WIDTH = 30

    def __init__(self, stream: TextIO = sys.stderr, *, enabled: bool = True) -> None:
        self.stream = stream
        self.enabled = enabled
        self._last_draw = 0.0
        self._drawn = False

    def update(self, done: int, total: int) -> None:
        if not self.enabled or total < 2:
            return
        now = time.monotonic()
        if done < total and now - self._last_draw < 0.1:
            return
        self._last_draw = now
        filled = self.WIDTH * done // total
        self.stream.write(f"\r[{'#' * filled}{'.' * (self.WIDTH - filled)}] {done}/{total} files")
        self.stream.flush()
        self._drawn = True

    def close(self) -> None:
        if self._drawn:
            self.stream.write("\r\x1b[2K")
            self.stream.flush()
            self._drawn = False
