"""Read `[tool.geolint]` of the nearest pyproject.toml into a typed `Config`.

Every mistake in the table (an unknown key, a wrong type, a malformed rule code) raises
`ConfigError` naming the file and the key, so the CLI can exit 2 with a message people can act on.
Keys may be written in kebab-case (`per-file-ignores`) or snake_case (`per_file_ignores`).
"""

from __future__ import annotations

import os
import re
import sys
from dataclasses import fields, replace
from functools import lru_cache
from pathlib import Path
from typing import Any, Callable, Mapping

from geolint.lint_types import Config, NamingConventions, Severity

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - exercised on Python 3.10 only
    import tomli as tomllib

# A selector is a rule code or a prefix of one: "GEO", "GEO2", "GEO20", "GEO201".
SELECTOR = re.compile(r"^GEO\d{0,3}$")
FULL_CODE = re.compile(r"^GEO\d{3}$")
IDENTIFIER = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")


class ConfigError(Exception):
    """A config file that cannot be used; the message names the file and the key."""

    def __init__(self, path: Path | None, key: str | None, problem: str) -> None:
        where = str(path) if path is not None else "<config>"
        if key:
            where += f": [tool.geolint] key '{key}'"
        super().__init__(f"{where}: {problem}")
        self.path = path
        self.key = key


class UsageError(ConfigError):
    """A command-line option that cannot be used; the message names the option, not a config file."""

    def __init__(self, message: str) -> None:
        Exception.__init__(self, message)
        self.path = None
        self.key = None


def find_pyproject(start: Path) -> Path | None:
    """The nearest pyproject.toml with a `[tool.geolint]` table at or above `start`."""
    start = start.resolve()
    folder = start if start.is_dir() else start.parent
    for candidate_dir in (folder, *folder.parents):
        candidate = candidate_dir / "pyproject.toml"
        if candidate.is_file() and _has_geolint_table(candidate):
            return candidate
    return None


def nearest_pyproject(folder: Path) -> Path | None:
    """`find_pyproject` for a folder, remembered with every folder above it (a run asks for each
    folder of its files; siblings share their parents' answers). For one run: the CLI's."""
    found = _nearest_pyproject(os.path.abspath(folder))
    return Path(found) if found is not None else None


@lru_cache(maxsize=None)
def _nearest_pyproject(folder: str) -> str | None:
    candidate = os.path.join(folder, "pyproject.toml")
    if os.path.isfile(candidate) and _has_geolint_table(Path(candidate)):
        return candidate
    parent = os.path.dirname(folder)
    return None if parent == folder else _nearest_pyproject(parent)


def forget_pyprojects() -> None:
    """Forget the answers of `nearest_pyproject` (a watching run's configs may have changed)."""
    _nearest_pyproject.cache_clear()


def _has_geolint_table(pyproject: Path) -> bool:
    # A cheap text test first: most pyproject.toml files never mention geolint.
    try:
        text = pyproject.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return False
    return "tool.geolint" in text or "[tool]" in text and "geolint" in text


def find_config(start: Path) -> Config:
    """The config of the nearest pyproject.toml with a [tool.geolint] table, else the defaults."""
    pyproject = find_pyproject(start)
    return load_config(pyproject) if pyproject is not None else Config()


def load_config(pyproject: Path) -> Config:
    """Read and validate `[tool.geolint]` of one pyproject.toml (defaults when the table is absent).

    Besides the table's shape, every rule selector must name a registered rule or a prefix of one:
    a typo in `select` would otherwise turn geolint off without a word.
    """
    try:
        with open(pyproject, "rb") as stream:
            document = tomllib.load(stream)
    except OSError as error:
        raise ConfigError(pyproject, None, f"cannot read: {error.strerror or error}") from error
    except tomllib.TOMLDecodeError as error:
        raise ConfigError(pyproject, None, f"invalid TOML: {error}") from error
    table = document.get("tool", {}).get("geolint")
    if table is None:
        return Config(source=pyproject.resolve())
    if not isinstance(table, dict):
        raise ConfigError(pyproject, "tool.geolint", "must be a table")
    config = config_from_table(table, pyproject.resolve())
    _check_known_codes(table, config.source)
    return config


def config_from_table(table: Mapping[str, Any], source: Path | None) -> Config:
    """Build a `Config` from an already-parsed `[tool.geolint]` table."""
    values: dict[str, Any] = {}
    for raw_key, raw_value in table.items():
        key = raw_key.replace("-", "_")
        reader = _READERS.get(key)
        if reader is None:
            raise ConfigError(source, raw_key, f"unknown key{_did_you_mean(key, _READERS)}")
        values[key] = reader(raw_value, source, raw_key)
    if "extend_select" in values:  # as ruff's: added to `select` (or to the default, every rule)
        values["select"] = values.get("select", Config.select) + values.pop("extend_select")
    return Config(**values, source=source)


def with_overrides(
    config: Config,
    *,
    select: tuple[str, ...] | None = None,
    extend_select: tuple[str, ...] = (),
    extend_ignore: tuple[str, ...] = (),
) -> Config:
    """The config with command-line `--select` (replaces), `--extend-select` and `--ignore` (add to) applied.

    A malformed or unknown selector raises `UsageError` naming the option: the mistake is on the command line.
    """
    for option, selectors in (("--select", select or ()), ("--extend-select", extend_select), ("--ignore", extend_ignore)):
        for selector in selectors:
            if not SELECTOR.match(selector):
                raise UsageError(f"{option}: invalid rule selector {selector!r} (expected e.g. GEO, GEO2, GEO201)")
            if not _selects_a_rule(selector):
                raise UsageError(f"{option}: {_unknown(selector)}")
    return replace(
        config,
        select=(select if select is not None else config.select) + extend_select,
        ignore=config.ignore + extend_ignore,
    )


def parse_selector_list(text: str) -> tuple[str, ...]:
    """Split a comma-separated command-line list of selectors ("GEO1, GEO201")."""
    return tuple(part.strip().upper() for part in text.split(",") if part.strip())


# --- one reader per key ------------------------------------------------------------------


def _string_list(value: Any, source: Path | None, key: str) -> tuple[str, ...]:
    if not isinstance(value, list) or not all(isinstance(item, str) for item in value):
        raise ConfigError(source, key, f"must be a list of strings, got {_describe(value)}")
    return tuple(value)


def _selectors(value: Any, source: Path | None, key: str) -> tuple[str, ...]:
    selectors = _string_list(value, source, key)
    for selector in selectors:
        if not SELECTOR.match(selector):
            raise ConfigError(source, key, f"invalid rule selector {selector!r} (expected e.g. GEO, GEO2, GEO201)")
    return selectors


def _identifiers(value: Any, source: Path | None, key: str) -> tuple[str, ...]:
    names = _string_list(value, source, key)
    for name in names:
        if not IDENTIFIER.match(name):
            raise ConfigError(source, key, f"{name!r} is not a Python identifier")
    return names


def _per_file_ignores(value: Any, source: Path | None, key: str) -> dict[str, tuple[str, ...]]:
    if not isinstance(value, dict):
        raise ConfigError(source, key, f"must be a table of glob = [codes], got {_describe(value)}")
    return {pattern: _selectors(codes, source, f"{key}.{pattern}") for pattern, codes in value.items()}


NAMING_ORDERS = ("auto", "dst-first", "src-first")


def _naming(value: Any, source: Path | None, key: str) -> NamingConventions:
    # `naming = "src-first"` sets the order of `T_a_b` names; a table switches conventions (and may set `order`)
    if isinstance(value, str):
        value = {"order": value}
    if not isinstance(value, dict):
        raise ConfigError(source, key, f"must be \"auto\", \"dst-first\", \"src-first\" or a table of switches, got {_describe(value)}")
    known = {field.name for field in fields(NamingConventions)}
    switches: dict[str, Any] = {}
    for raw_name, switch in value.items():
        name = raw_name.replace("-", "_")
        if name == "order":
            if switch not in NAMING_ORDERS:
                raise ConfigError(source, f"{key}.order" if raw_name == "order" else key, f"must be one of {', '.join(NAMING_ORDERS)}, got {_describe(switch)}")
            switches[name] = switch
            continue
        if name not in known:
            raise ConfigError(source, f"{key}.{raw_name}", f"unknown naming convention{_did_you_mean(name, known)}")
        if not isinstance(switch, bool):
            raise ConfigError(source, f"{key}.{raw_name}", f"must be true or false, got {_describe(switch)}")
        switches[name] = switch
    return NamingConventions(**switches)


def _frame_aliases(value: Any, source: Path | None, key: str) -> dict[str, str]:
    if not isinstance(value, dict):
        raise ConfigError(source, key, f"must be a table of alias = \"frame\", got {_describe(value)}")
    for alias, frame in value.items():
        if not isinstance(frame, str) or not IDENTIFIER.match(frame) or not IDENTIFIER.match(alias):
            raise ConfigError(source, f"{key}.{alias}", f"must map a frame name to a frame name, got {_describe(frame)}")
    return dict(value)


def _severity(value: Any, source: Path | None, key: str) -> dict[str, Severity]:
    if not isinstance(value, dict):
        raise ConfigError(source, key, f"must be a table of CODE = \"error\"|\"warning\"|\"info\"|\"hint\", got {_describe(value)}")
    levels = {level.value: level for level in Severity}
    result: dict[str, Severity] = {}
    for code, level in value.items():
        if not FULL_CODE.match(code):
            raise ConfigError(source, f"{key}.{code}", "must be a full rule code such as GEO101")
        if level not in levels:
            raise ConfigError(source, f"{key}.{code}", f"must be one of {', '.join(levels)}, got {_describe(level)}")
        result[code] = levels[level]
    return result


def _positive_int(value: Any, source: Path | None, key: str) -> int:
    if not isinstance(value, int) or isinstance(value, bool) or value < 1:
        raise ConfigError(source, key, f"must be a positive integer, got {_describe(value)}")
    return value


def _boolean(value: Any, source: Path | None, key: str) -> bool:
    if not isinstance(value, bool):
        raise ConfigError(source, key, f"must be true or false, got {_describe(value)}")
    return value


def _known_fixes(value: Any, source: Path | None, key: str) -> tuple[tuple[str, str, str], ...]:
    """`[{ before = "...", after = "...", reason = "..." }, ...]`: each a statement of one line that parses."""
    from geolint.history.fix_edits import parse_statement

    if not isinstance(value, list):
        raise ConfigError(source, key, f"must be a list of tables with `before` and `after`, got {_describe(value)}")
    found = []
    for position, item in enumerate(value):
        where = f"{key}[{position}]"
        if not isinstance(item, dict) or set(item) - {"before", "after", "reason"} or not {"before", "after"} <= set(item):
            raise ConfigError(source, where, "must be a table with `before`, `after` and an optional `reason`")
        if not all(isinstance(text, str) for text in item.values()):
            raise ConfigError(source, where, "`before`, `after` and `reason` must be strings")
        for part in ("before", "after"):
            if parse_statement(item[part]) is None:
                raise ConfigError(source, f"{where}.{part}", f"must be one Python statement on one line, got {item[part]!r}")
        found.append((item["before"], item["after"], item.get("reason", "")))
    return tuple(found)


_READERS: dict[str, Callable[[Any, Path | None, str], Any]] = {
    "select": _selectors,
    "extend_select": _selectors,
    "ignore": _selectors,
    "per_file_ignores": _per_file_ignores,
    "exclude": _string_list,
    "extend_exclude": _string_list,
    "naming": _naming,
    "frame_aliases": _frame_aliases,
    "extra_direction_names": _identifiers,
    "extra_point_names": _identifiers,
    "severity": _severity,
    "max_file_size": _positive_int,
    "max_nesting_depth": _positive_int,
    "history": _boolean,
    "history_limit": _positive_int,
    "known_fixes": _known_fixes,
}


def _check_known_codes(table: Mapping[str, Any], source: Path | None) -> None:
    """Raise `ConfigError` for a selector (or severity code) that names no registered rule (as ruff does)."""
    for raw_key, value in table.items():
        key = raw_key.replace("-", "_")
        if key in ("select", "extend_select", "ignore"):
            named = [(raw_key, selector) for selector in value]
        elif key == "per_file_ignores":
            named = [(f"{raw_key}.{pattern}", selector) for pattern, codes in value.items() for selector in codes]
        elif key == "severity":
            named = [(f"{raw_key}.{code}", code) for code in value]
        else:
            continue
        for where, selector in named:
            if not _selects_a_rule(selector):
                raise ConfigError(source, where, _unknown(selector))


def _known_codes() -> tuple[str, ...]:
    from geolint.rules import all_rules  # the registry, imported only once a selector is checked

    return tuple(rule.code for rule in all_rules())


def _selects_a_rule(selector: str) -> bool:
    return any(code.startswith(selector) for code in _known_codes())


def _unknown(selector: str) -> str:
    import difflib

    close = difflib.get_close_matches(selector, _known_codes(), n=1)
    hint = f"did you mean {close[0]}? " if close else ""
    return f"unknown rule selector {selector!r}: no rule code starts with it ({hint}`geolint rules` lists them)"


def _describe(value: Any) -> str:
    return f"{type(value).__name__} {value!r}"


def _did_you_mean(name: str, candidates: Any) -> str:
    import difflib

    close = difflib.get_close_matches(name, list(candidates), n=1)
    return f" (did you mean '{close[0].replace('_', '-')}'?)" if close else ""


# --- which rules a config enables ----------------------------------------------------------


def config_root(config: Config) -> Path:
    """The folder that relative patterns (excludes, per-file-ignores) are anchored to."""
    return config.source.parent if config.source is not None else Path.cwd()


def is_selected(code: str, selectors: tuple[str, ...], ignores: tuple[str, ...]) -> bool:
    """Whether `code` is on: the most specific (longest) matching selector decides, ignore wins ties."""
    best_select = max((len(s) for s in selectors if code.startswith(s)), default=-1)
    best_ignore = max((len(s) for s in ignores if code.startswith(s)), default=-1)
    return best_select >= 0 and best_select > best_ignore


def ignored_for_path(config: Config, path: str) -> tuple[str, ...]:
    """The `per-file-ignores` selectors whose glob matches `path` (relative to the config root)."""
    if not config.per_file_ignores:
        return ()
    relative = _relative_posix(path, config_root(config))
    name = relative.rsplit("/", 1)[-1]
    found: list[str] = []
    for pattern, codes in config.per_file_ignores.items():
        if _glob_matches(pattern, relative) or ("/" not in pattern and _glob_matches(pattern, name)):
            found.extend(codes)
    return tuple(found)


def enabled_codes(config: Config, path: str, codes: tuple[str, ...]) -> tuple[str, ...]:
    """The subset of `codes` this config turns on for the file at `path`."""
    return _selected_codes(codes, config.select, config.ignore + ignored_for_path(config, path))


@lru_cache(maxsize=1024)
def _selected_codes(codes: tuple[str, ...], selectors: tuple[str, ...], ignores: tuple[str, ...]) -> tuple[str, ...]:
    return tuple(code for code in codes if is_selected(code, selectors, ignores))  # asked once per file: cached


def _relative_posix(path: str, root: Path) -> str:
    import os

    absolute = os.path.abspath(path)
    relative = os.path.relpath(absolute, root) if absolute.startswith(str(root) + os.sep) else path
    return relative.replace(os.sep, "/")


def _glob_matches(pattern: str, relative: str) -> bool:
    return _compiled_glob(pattern).match_file(relative)


@lru_cache(maxsize=256)
def _compiled_glob(pattern: str):  # -> pathspec.GitIgnoreSpec
    import pathspec

    return pathspec.GitIgnoreSpec.from_lines([pattern])
