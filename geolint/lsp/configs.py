"""The `[tool.geolint]` config for each open document, read through the API like the CLI reads it.

Configs are cached per folder. On every use the cache checks the modification time of each
pyproject.toml that could apply (from the folder up to the one in use, or up to the root when
none is), so an edited, created or deleted config is noticed even when the editor does not watch
files. `generation` counts changes of any cached config's value: the server compares it with the
last one it acted on, so a notification that changes nothing costs nothing.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

from geolint.api import find_config
from geolint.lint_types import Config

CONFIG_FILE = "pyproject.toml"

Stamp = tuple[tuple[str, int | None], ...]


def _stamp(folder: Path, config: Config | None) -> Stamp:
    """The modification time (None: absent) of each pyproject.toml from `folder` up to the config's."""
    last = config.source.parent if config is not None and config.source is not None else None
    stamps: list[tuple[str, int | None]] = []
    for directory in (folder, *folder.parents):
        candidate = directory / CONFIG_FILE
        try:
            stamps.append((str(candidate), os.stat(candidate).st_mtime_ns))
        except OSError:
            stamps.append((str(candidate), None))
        if last is not None and directory == last:
            break
    return tuple(stamps)


@dataclass(frozen=True)
class _Cached:
    config: Config | None  # None: the file is broken (the error is in `error`)
    error: Exception | None
    stamp: Stamp


class ConfigCache:
    """Config lookups by folder, re-read when a pyproject.toml that could apply changes."""

    def __init__(self) -> None:
        self._by_folder: dict[Path, _Cached] = {}
        self.generation = 0

    def _read(self, folder: Path) -> _Cached:
        try:
            config: Config | None = find_config(folder)
            error = None
        except Exception as problem:  # a broken pyproject.toml: the caller reports it
            config, error = None, problem
        return _Cached(config, error, _stamp(folder, config))

    def _store(self, folder: Path, fresh: _Cached) -> None:
        old = self._by_folder.get(folder)
        if old is not None and (old.config != fresh.config or repr(old.error) != repr(fresh.error)):
            self.generation += 1
        self._by_folder[folder] = fresh

    def config_for(self, folder: Path) -> Config:
        """The config for files in `folder`; raises what `find_config` raises on a bad file."""
        folder = folder.resolve()
        cached = self._by_folder.get(folder)
        if cached is None or _stamp(folder, cached.config) != cached.stamp:
            cached = self._read(folder)
            self._store(folder, cached)
        if cached.error is not None:
            raise cached.error
        assert cached.config is not None
        return cached.config

    def check(self) -> None:
        """Re-read every cached folder whose files changed (by modification time)."""
        for folder, cached in list(self._by_folder.items()):
            if _stamp(folder, cached.config) != cached.stamp:
                self._store(folder, self._read(folder))

    def reload(self) -> None:
        """Re-read every cached folder (the editor says a pyproject.toml changed)."""
        for folder in list(self._by_folder):
            self._store(folder, self._read(folder))
