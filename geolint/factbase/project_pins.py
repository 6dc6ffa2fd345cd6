"""The versions a project allows for its dependencies, read from what it declares: requirements files,
pyproject.toml (PEP 621 and Poetry), setup.py's `install_requires` literal, and lock files (uv.lock,
poetry.lock, Pipfile.lock), which say the exact version.

A stub fact marked `@versions(">=0.7")` holds for a project only when every version its declarations
allow is in that range (`Pins.allow_only`); a project that pins nothing, or allows versions on both
sides, gets no versioned fact at all: the linter stays silent rather than guess.
"""

from __future__ import annotations

import ast
import hashlib
import json
import re
import sys
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from collections.abc import Iterable
from typing import Any, Final

from packaging.requirements import InvalidRequirement, Requirement
from packaging.specifiers import InvalidSpecifier, Specifier, SpecifierSet
from packaging.utils import canonicalize_name
from packaging.version import InvalidVersion, Version

from geolint.factbase.project_files import project_root

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - exercised by the lowest supported Python
    import tomli as tomllib

_REQUIREMENT_FILES: Final = ("requirements*.txt", "requirements/*.txt", "requirements*.in")
_TOML_LOCKS: Final = ("uv.lock", "poetry.lock")  # and Pipfile.lock, which is JSON
_MAX_BYTES: Final = 2_000_000  # a declaration file larger than this is not one a person wrote


@dataclass(frozen=True)
class _Bound:
    version: Version
    inclusive: bool


@dataclass
class Pins:
    """What one project allows: distribution (canonical name) -> the specifiers it is declared with, and
    the exact version a lock file names."""

    specifiers: dict[str, SpecifierSet] = field(default_factory=dict)
    locked: dict[str, Version] = field(default_factory=dict)

    def allow_only(self, distribution: str, specifier: str) -> bool:
        """Whether every version the project allows for `distribution` satisfies `specifier` (PEP 440)."""
        try:
            wanted = SpecifierSet(specifier)
        except InvalidSpecifier:
            return False
        name = canonicalize_name(distribution)
        locked = self.locked.get(name)
        if locked is not None:
            return wanted.contains(locked, prereleases=True)
        allowed = self.specifiers.get(name)
        if allowed is None:
            return False
        exact = _exact(allowed)
        if exact is not None:
            return wanted.contains(exact, prereleases=True)
        return _within(_interval(allowed), wanted)


def pins_for(path: str) -> Pins:
    """The pins of the project around `path` (none outside a project)."""
    root = project_root(path)
    return _read_pins(str(root)) if root is not None else Pins()


def pins_key(path: str) -> str:
    """What the project's declarations say, for the findings cache ('' when it declares nothing)."""
    root = project_root(path)
    return _key(str(root)) if root is not None else ""


@lru_cache(maxsize=256)
def _key(root: str) -> str:
    pins = _read_pins(root)
    if not pins.specifiers and not pins.locked:
        return ""
    text = repr((sorted((name, str(spec)) for name, spec in pins.specifiers.items()), sorted((n, str(v)) for n, v in pins.locked.items())))
    return hashlib.blake2b(text.encode(), digest_size=8).hexdigest()


@lru_cache(maxsize=256)
def _read_pins(root: str) -> Pins:
    folder = Path(root)
    pins = Pins()
    requirements: list[str] = []
    for pattern in _REQUIREMENT_FILES:
        for path in sorted(folder.glob(pattern)):
            requirements.extend(_requirement_lines(_text(path)))
    pyproject = _toml(folder / "pyproject.toml")
    requirements.extend(_pep621(pyproject))
    requirements.extend(_poetry(pyproject))
    requirements.extend(_install_requires(_text(folder / "setup.py")))
    for line in requirements:
        _add_requirement(pins, line)
    _read_locks(folder, pins)
    return pins


def _text(path: Path) -> str:
    try:
        if path.stat().st_size > _MAX_BYTES:
            return ""
        return path.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return ""


def _toml(path: Path) -> dict[str, Any]:
    try:
        return tomllib.loads(_text(path))
    except tomllib.TOMLDecodeError:
        return {}


def _requirement_lines(text: str) -> Iterable[str]:
    for line in text.splitlines():
        line = line.split(" #", 1)[0].strip()
        if line and not line.startswith(("#", "-", "git+", "http:", "https:", "file:")):
            yield line


def _pep621(pyproject: dict[str, Any]) -> list[str]:
    project = pyproject.get("project")
    if not isinstance(project, dict):
        return []
    found = [item for item in project.get("dependencies", []) if isinstance(item, str)]
    optional = project.get("optional-dependencies", {})
    if isinstance(optional, dict):
        found += [item for group in optional.values() if isinstance(group, list) for item in group if isinstance(item, str)]
    return found


_CARET: Final = re.compile(r"^\^(\d+)(?:\.(\d+))?(?:\.(\d+))?$")


def _poetry(pyproject: dict[str, Any]) -> list[str]:
    """`[tool.poetry.dependencies]` as requirement strings (`^0.6.2` is `>=0.6.2,<0.7`)."""
    poetry = pyproject.get("tool", {}).get("poetry", {}) if isinstance(pyproject.get("tool"), dict) else {}
    found = []
    for name, constraint in (poetry.get("dependencies", {}) if isinstance(poetry, dict) else {}).items():
        version = constraint.get("version") if isinstance(constraint, dict) else constraint
        if not isinstance(version, str) or name == "python":
            continue
        caret = _CARET.match(version.strip())
        if caret is not None:
            parts = [int(part) for part in caret.groups() if part is not None]
            first = next((index for index, part in enumerate(parts) if part), len(parts) - 1)
            upper = [*parts[:first], parts[first] + 1]
            version = f">={'.'.join(map(str, parts))},<{'.'.join(map(str, upper))}"
        elif version.strip() == "*":
            continue
        elif version.strip()[:1].isdigit():
            version = f"=={version.strip()}"
        found.append(f"{name}{version}")
    return found


def _install_requires(text: str) -> list[str]:
    """The string literals of `install_requires=[...]` in setup.py (read, never run)."""
    if "install_requires" not in text:
        return []
    try:
        tree = ast.parse(text)
    except (SyntaxError, ValueError):
        return []
    return [
        element.value
        for node in ast.walk(tree)
        if isinstance(node, ast.keyword) and node.arg == "install_requires" and isinstance(node.value, (ast.List, ast.Tuple))
        for element in node.value.elts
        if isinstance(element, ast.Constant) and isinstance(element.value, str)
    ]


def _add_requirement(pins: Pins, line: str) -> None:
    try:
        requirement = Requirement(line)
    except InvalidRequirement:
        return
    name = canonicalize_name(requirement.name)
    pins.specifiers[name] = pins.specifiers.get(name, SpecifierSet()) & requirement.specifier


def _read_locks(folder: Path, pins: Pins) -> None:
    for name in _TOML_LOCKS:
        packages = _toml(folder / name).get("package", [])
        for package in packages if isinstance(packages, list) else []:
            if isinstance(package, dict):
                _lock(pins, package.get("name"), package.get("version"))
    try:
        pipfile = json.loads(_text(folder / "Pipfile.lock") or "{}")
    except ValueError:
        pipfile = {}
    for section in ("default", "develop"):
        entries = pipfile.get(section, {}) if isinstance(pipfile, dict) else {}
        for name, entry in entries.items() if isinstance(entries, dict) else ():
            version = entry.get("version", "") if isinstance(entry, dict) else ""
            _lock(pins, name, version.removeprefix("==") if isinstance(version, str) else None)


def _lock(pins: Pins, name: object, version: object) -> None:
    if not isinstance(name, str) or not isinstance(version, str):
        return
    try:
        pins.locked[canonicalize_name(name)] = Version(version)
    except InvalidVersion:
        return


def _exact(allowed: SpecifierSet) -> Version | None:
    for specifier in allowed:
        if specifier.operator in ("==", "===") and "*" not in specifier.version:
            try:
                return Version(specifier.version)
            except InvalidVersion:
                return None
    return None


def _interval(allowed: SpecifierSet) -> tuple[_Bound | None, _Bound | None]:
    """The smallest interval holding every version `allowed` admits: (lower, upper), None for unbounded."""
    lower: _Bound | None = None
    upper: _Bound | None = None
    for specifier in allowed:
        for bound, is_lower in _bounds(specifier):
            if is_lower:
                lower = bound if lower is None or _tighter_lower(bound, lower) else lower
            else:
                upper = bound if upper is None or _tighter_upper(bound, upper) else upper
    return lower, upper


def _bounds(specifier: Specifier) -> list[tuple[_Bound, bool]]:
    """(bound, is it a lower one) for one specifier; `!=` bounds nothing."""
    text = specifier.version
    try:
        if specifier.operator == "==" and text.endswith(".*"):
            base = Version(text[:-2])
            return [(_Bound(base, True), True), (_Bound(_next_release(base.release, len(base.release)), False), False)]
        version = Version(text)
    except InvalidVersion:
        return []
    operator = specifier.operator
    if operator in (">=", ">"):
        return [(_Bound(version, operator == ">="), True)]
    if operator in ("<=", "<"):
        return [(_Bound(version, operator == "<="), False)]
    if operator == "~=":
        return [(_Bound(version, True), True), (_Bound(_next_release(version.release, len(version.release) - 1), False), False)]
    if operator in ("==", "==="):
        return [(_Bound(version, True), True), (_Bound(version, True), False)]
    return []


def _next_release(release: tuple[int, ...], length: int) -> Version:
    """The first release after every `release[:length].*` (`1.4` of `~=1.4.5` -> 1.5)."""
    kept = list(release[: max(length, 1)])
    kept[-1] += 1
    return Version(".".join(map(str, kept)))


def _tighter_lower(candidate: _Bound, current: _Bound) -> bool:
    return candidate.version > current.version or (candidate.version == current.version and not candidate.inclusive)


def _tighter_upper(candidate: _Bound, current: _Bound) -> bool:
    return candidate.version < current.version or (candidate.version == current.version and not candidate.inclusive)


def _within(allowed: tuple[_Bound | None, _Bound | None], wanted: SpecifierSet) -> bool:
    """Whether the interval `allowed` lies inside every specifier of `wanted`."""
    lower, upper = allowed
    for specifier in wanted:
        for bound, is_lower in _bounds(specifier):
            if is_lower and (lower is None or lower.version < bound.version or (lower.version == bound.version and lower.inclusive and not bound.inclusive)):
                return False
            if not is_lower and (upper is None or upper.version > bound.version or (upper.version == bound.version and upper.inclusive and not bound.inclusive)):
                return False
        if specifier.operator == "!=":
            return False  # an excluded version inside the interval cannot be ruled out here
    return True
