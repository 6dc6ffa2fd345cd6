"""The plugin's settings, read once from the mypy config file, and the data that keys mypy's cache.

Settings live in ``[geolint-mypy]`` (mypy.ini, setup.cfg) or ``[tool.geolint-mypy]`` (pyproject.toml):

- ``frame_aliases``: string frames that name the same frame, e.g. ``base = base_link`` makes
  ``Point["base"]`` and ``Point["base_link"]`` one type (ini: ``frame_aliases = base:base_link, cam:camera``).

`cache_key` goes to mypy's ``report_config_data``: a change of geolint's version, the plugin's own version
or these settings invalidates every cached module, so a cache never holds types analyzed under old rules.
"""

from __future__ import annotations

import configparser
import hashlib
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any, Mapping

from geolint._version import __version__

# Bump when the plugin's inference or messages change in a way cached results would not show.
PLUGIN_VERSION = "1"
SECTION = "geolint-mypy"


class PluginConfigError(ValueError):
    """A malformed [geolint-mypy] section; the message names the file."""


@dataclass(frozen=True)
class PluginConfig:
    frame_aliases: Mapping[str, str] = field(default_factory=dict)

    def canonical_frame(self, name: str) -> str:
        return self.frame_aliases.get(name, name)

    def cache_key(self) -> dict[str, Any]:
        return {
            "geolint": __version__,
            "plugin": PLUGIN_VERSION,
            "plugin_source": plugin_source_digest(),
            "frame_aliases": sorted(self.frame_aliases.items()),
        }


@lru_cache(maxsize=1)
def plugin_source_digest() -> str:
    """A digest of the plugin's own source: an edited plugin (an editable install) also invalidates the cache."""
    digest = hashlib.sha256()
    for path in sorted(Path(__file__).parent.glob("*.py")):
        digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def load(config_file: str | None) -> PluginConfig:
    if not config_file:
        return PluginConfig()
    path = Path(config_file)
    if not path.is_file():
        return PluginConfig()
    if path.suffix == ".toml":
        return _from_toml(path)
    return _from_ini(path)


def _from_toml(path: Path) -> PluginConfig:
    try:
        import tomllib
    except ImportError:  # Python 3.10
        import tomli as tomllib  # type: ignore[no-redef]
    with path.open("rb") as stream:
        data = tomllib.load(stream)
    section = data.get("tool", {}).get(SECTION, {})
    aliases = section.get("frame_aliases", {})
    if not isinstance(aliases, dict) or not all(isinstance(v, str) for v in aliases.values()):
        raise PluginConfigError(f"{path}: [tool.{SECTION}] frame_aliases must be a table of strings")
    return PluginConfig(dict(aliases))


def _from_ini(path: Path) -> PluginConfig:
    parser = configparser.ConfigParser()
    parser.read(path)
    if not parser.has_section(SECTION):
        return PluginConfig()
    raw = parser.get(SECTION, "frame_aliases", fallback="")
    aliases: dict[str, str] = {}
    for pair in filter(None, (item.strip() for item in raw.replace("\n", ",").split(","))):
        alias, sep, canonical = pair.partition(":")
        if not sep or not alias.strip() or not canonical.strip():
            raise PluginConfigError(f"{path}: [{SECTION}] frame_aliases: expected alias:frame, got {pair!r}")
        aliases[alias.strip()] = canonical.strip()
    return PluginConfig(aliases)
