"""The `[tool.geolint]` config for each open document, read through the API like the CLI reads it.

Configs are cached per folder and re-read when the pyproject.toml they came from changes on disk
(checked by modification time on every lint) or when the client reports a changed pyproject.toml.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

from geolint.api import find_config
from geolint.lint_types import Config


@dataclass(frozen=True)
class _Cached:
    config: Config
    stamp: float | None  # mtime of config.source when read


def _stamp(config: Config) -> float | None:
    if config.source is None:
        return None
    try:
        return os.stat(config.source).st_mtime_ns
    except OSError:
        return None


class ConfigCache:
    """Config lookups by folder, re-read when the file they came from changes."""

    def __init__(self) -> None:
        self._by_folder: dict[Path, _Cached] = {}

    def clear(self) -> None:
        self._by_folder.clear()

    def config_for(self, folder: Path) -> Config:
        """The config that applies to files in `folder`; raises what `find_config` raises on a bad file."""
        cached = self._by_folder.get(folder)
        if cached is not None and _stamp(cached.config) == cached.stamp:
            return cached.config
        config = find_config(folder)
        self._by_folder[folder] = _Cached(config, _stamp(config))
        return config
