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
import sys
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any, Mapping

from geolint._version import __version__
from geolint.knowledge import stubs_folder

# Bump when the plugin's inference or messages change in a way cached results would not show.
PLUGIN_VERSION = "1"
SECTION = "geolint-mypy"


class PluginConfigError(ValueError):
    """A malformed [geolint-mypy] / [tool.geolint-mypy] section; the message names the file, section and key."""

    def __init__(self, path: Path, section: str, key: str, problem: str) -> None:
        super().__init__(f"{path}: error: [{section}] {key}: {problem}")


KNOWN_KEYS = ("frame_aliases",)


@dataclass(frozen=True)
class PluginConfig:
    frame_aliases: Mapping[str, str] = field(default_factory=dict)

    def canonical_frame(self, name: str) -> str:
        return self.frame_aliases.get(name, name)

    def version_tag(self) -> str:
        """geolint's version with a digest of the plugin and these settings (see plugin._expose_settings_to_daemon)."""
        digest = hashlib.sha256(repr(sorted(self.cache_key().items())).encode()).hexdigest()[:12]
        return f"{__version__}+{digest}"

    def cache_key(self) -> dict[str, Any]:
        return {
            "geolint": __version__,
            "plugin": PLUGIN_VERSION,
            "plugin_source": plugin_source_digest(),
            "frame_aliases": sorted(self.frame_aliases.items()),
        }


@lru_cache(maxsize=1)
def plugin_source_digest() -> str:
    """A digest of the plugin's own source and of the knowledge base it reads (`stubs/`, or the folder
    GEOLINT_STUBS names): an edited plugin or stub also invalidates the cache."""
    digest = hashlib.sha256()
    knowledge = Path(__file__).parent.parent / "knowledge"
    stubs = stubs_folder()
    for path in [*sorted(Path(__file__).parent.glob("*.py")), *sorted(knowledge.glob("*.py")), *sorted(stubs.rglob("*.py*")), *sorted(stubs.rglob("*.toml"))]:
        digest.update(str(path.relative_to(stubs) if path.is_relative_to(stubs) else path.name).encode())
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
    if sys.version_info >= (3, 11):
        import tomllib
    else:
        import tomli as tomllib
    with path.open("rb") as stream:
        data = tomllib.load(stream)  # mypy has parsed this file already: a syntax error never gets here
    section_name = f"tool.{SECTION}"
    tool = data.get("tool", {})
    section = tool.get(SECTION, {}) if isinstance(tool, dict) else {}
    if not isinstance(section, dict):
        raise PluginConfigError(path, section_name, SECTION, f"expected a table, got {section!r}")
    _reject_unknown_keys(path, section_name, section)
    aliases = section.get("frame_aliases", {})
    if not isinstance(aliases, dict) or not all(isinstance(value, str) for value in aliases.values()):
        example = '{ base = "base_link" }'
        raise PluginConfigError(
            path, section_name, "frame_aliases", f"expected a table of frame names such as {example}, got {aliases!r}"
        )
    return PluginConfig(_resolved(path, section_name, aliases))


def _from_ini(path: Path) -> PluginConfig:
    parser = configparser.ConfigParser(inline_comment_prefixes=("#", ";"), interpolation=None)
    try:
        parser.read(path)
    except configparser.Error as error:  # mypy reads the same file with the same parser: rarely reached
        raise PluginConfigError(path, SECTION, "(file)", str(error).splitlines()[0]) from None
    if not parser.has_section(SECTION):
        return PluginConfig()
    _reject_unknown_keys(path, SECTION, dict(parser.items(SECTION)))
    raw = parser.get(SECTION, "frame_aliases", fallback="")
    aliases: dict[str, str] = {}
    for pair in filter(None, (item.strip() for item in raw.replace("\n", ",").split(","))):
        alias, sep, canonical = pair.partition(":")
        if not sep or not alias.strip() or not canonical.strip():
            raise PluginConfigError(
                path, SECTION, "frame_aliases", f"expected alias:frame pairs such as base:base_link, got {pair!r}"
            )
        aliases[alias.strip()] = canonical.strip()
    return PluginConfig(_resolved(path, SECTION, aliases))


def _reject_unknown_keys(path: Path, section: str, values: Mapping[str, object]) -> None:
    for key in values:
        if key not in KNOWN_KEYS:
            known = ", ".join(KNOWN_KEYS)
            raise PluginConfigError(path, section, key, f"unknown setting (known: {known})")


def _resolved(path: Path, section: str, aliases: Mapping[str, str]) -> dict[str, str]:
    """Aliases followed to the frame they end at (``base -> base_link -> base_footprint``); a cycle is an error."""
    resolved: dict[str, str] = {}
    for alias in aliases:
        seen = [alias]
        target = aliases[alias]
        while target in aliases and target != alias:
            if target in seen:
                break
            seen.append(target)
            target = aliases[target]
        if target in seen or target == alias:
            cycle = " -> ".join([*seen, target])
            raise PluginConfigError(path, section, "frame_aliases", f"aliases form a cycle: {cycle}")
        resolved[alias] = target
    return resolved
