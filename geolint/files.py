"""Find the Python files to lint under the paths given on the command line.

Folders are walked with `.gitignore`-style excludes: the config's `exclude` (which replaces the
defaults below) and `extend-exclude` (which adds to them), plus every `.gitignore` file met on the
way. Patterns are anchored at the config root (the folder of pyproject.toml, else the cwd). A file
or folder named explicitly is always linted, unless `force_exclude` is set (what pre-commit hooks
want, since pre-commit passes every staged file by name): a named folder that sits in an excluded
one (`geolint check .venv/lib/python3.11/site-packages/numpy`) is walked as its own root, so the
excludes still apply to what is below it.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Callable, Iterable, Sequence

from geolint.config import config_root
from geolint.lint_types import Config

if TYPE_CHECKING:
    from geolint.cache import DiscoveryCache

# Folders nobody wants linted (tools' caches, virtualenvs, build output).
DEFAULT_EXCLUDES = (
    ".bzr", ".direnv", ".eggs", ".git", ".hg", ".svn", ".mypy_cache", ".nox", ".pytest_cache",
    ".ruff_cache", ".geolint_cache", ".tox", ".venv", "venv", "__pypackages__", "__pycache__",
    "_build", "buck-out", "build", "dist", "node_modules", "*.egg-info",
)  # fmt: skip
PYTHON_SUFFIXES = (".py", ".pyi", ".ipynb")  # notebooks: their code cells (geolint.notebook)


class DiscoveryError(Exception):
    """A path given on the command line that does not exist or cannot be read."""


@dataclass(frozen=True)
class SourceFile:
    """A file to lint: where it is on disk, and how to show it (as given or relative to the cwd)."""

    path: Path
    display: str
    resolved: Path | None = None  # `path.resolve()`, when discovery knew it already

    def real_path(self) -> Path:
        return self.resolved if self.resolved is not None else self.path.resolve()


@lru_cache(maxsize=64)
def _spec(patterns: tuple[str, ...]):  # -> pathspec.GitIgnoreSpec
    import pathspec

    return pathspec.GitIgnoreSpec.from_lines(patterns)


def exclude_patterns(config: Config) -> tuple[str, ...]:
    """The effective exclude patterns: `exclude` (or the defaults) plus `extend-exclude`."""
    base = config.exclude if config.exclude else DEFAULT_EXCLUDES
    return tuple(base) + tuple(config.extend_exclude)


def discover(
    paths: Sequence[Path], config: Config, *, force_exclude: bool = False, cache: DiscoveryCache | None = None
) -> list[SourceFile]:
    """Every file to lint under `paths`, without duplicates, sorted by display path.

    With a `cache`, an earlier run's answer is reused while every folder it listed and every
    `.gitignore` it read are unchanged (a warm run then lists no folder at all).
    """
    root = config_root(config).resolve()
    patterns = exclude_patterns(config)
    # (a named folder that is a link asks another question once the link points elsewhere)
    question = (os.getcwd(), str(root), patterns, force_exclude, tuple((str(path), os.path.realpath(path)) for path in paths))
    if cache is not None and not all(path.is_dir() for path in paths):
        cache = None  # files named one by one (pre-commit's way) need no listing, and their lists vary
    # (a named folder that still is one, each listed folder with its mtime unchanged: the same files)
    if cache is not None:
        stored = cache.load(question)
        if stored is not None:
            return [SourceFile(Path(path), display, Path(real)) for path, display, real in stored]
    excluder = _Excluder(root, patterns)
    found: dict[Path, SourceFile] = {}
    for given in paths:
        if not given.exists():
            raise DiscoveryError(f"{given}: no such file or directory")
        if given.is_dir():
            walk_excluder = excluder
            if not force_exclude and _excluded_file(given.resolve() / "__init__.py", excluder):
                walk_excluder = _Excluder(given.resolve(), excluder.patterns, excluder.consulted)
            for file, display, real in _walk(given, walk_excluder):
                found.setdefault(real, SourceFile(file, display, real))
        elif not (force_exclude and _excluded_file(given.resolve(), excluder)):
            found.setdefault(given.resolve(), SourceFile(given, _display(given), given.resolve()))
    sources = sorted(found.values(), key=lambda source: source.display)
    if cache is not None:
        links = {str(source.path): str(source.real_path()) for source in sources if source.path.is_symlink()}
        cache.save(question, [(str(s.path), s.display, str(s.real_path())) for s in sources], excluder.consulted, links)
    return sources


def is_excluded(path: Path, config: Config) -> bool:
    """Whether the config's excludes or a `.gitignore` drop the file at `path` (which need not exist:
    `--stdin-filename` names where a buffer would be saved)."""
    root = config_root(config).resolve()
    return _excluded_file(Path(os.path.abspath(path)), _Excluder(root, exclude_patterns(config)))


def _display(path: Path | str) -> str:
    """The path as given (normalised); absolute paths under the cwd are shown relative to it."""
    text = os.path.normpath(str(path))
    if os.path.isabs(text):
        cwd = os.getcwd()
        if text.startswith(cwd + os.sep):
            return os.path.relpath(text, cwd)
        if text == cwd:
            return os.curdir
    return text


def _walk(top: Path, excluder: _Excluder) -> Iterable[tuple[Path, str, Path]]:
    """(path, display, real path) of every Python file under `top` that no exclude or `.gitignore`
    drops, folder by folder as `os.walk` goes (files first, then sub-folders; symlinked folders are not
    entered, so a folder's real path is the resolved top joined with its relative path)."""
    top_resolved = str(top.resolve())
    above = tuple(excluder.gitignores_above(Path(top_resolved)))
    # each folder carries the `.gitignore` specs that apply in it: those above it and its own
    pending = [(str(top), top_resolved, _display(top), above)]
    while pending:
        folder, resolved_folder, display_folder, active = pending.pop()
        try:
            with os.scandir(folder) as scan:
                entries = sorted(scan, key=lambda entry: entry.name)
        except OSError:
            continue  # unreadable folder: os.walk skips it too
        excluder.consulted.folders.add(resolved_folder)
        if any(entry.name == ".gitignore" for entry in entries):
            spec = excluder.read_gitignore(os.path.join(resolved_folder, ".gitignore"))
            if spec is not None:
                active = (*active, (resolved_folder, spec))
        display_prefix = "" if display_folder == os.curdir else display_folder + os.sep
        folders = []
        for entry in entries:
            name = entry.name
            candidate = os.path.join(resolved_folder, name)
            if _is_folder(entry):
                if not entry.is_symlink() and not excluder.excluded(candidate, is_dir=True) and not _gitignored(active, candidate, True):
                    folders.append((entry.path, candidate, display_prefix + name, active))
            elif name.endswith(PYTHON_SUFFIXES) and not excluder.excluded(candidate, is_dir=False) and not _gitignored(active, candidate, False):
                path = Path(entry.path)
                # realpath, not resolve(): a link in a loop must not end the whole run (RuntimeError)
                yield path, display_prefix + name, Path(os.path.realpath(path)) if entry.is_symlink() else Path(candidate)
        pending.extend(reversed(folders))


def _is_folder(entry: os.DirEntry[str]) -> bool:
    try:
        return entry.is_dir()
    except OSError:
        return False


def _excluded_file(file: Path, excluder: _Excluder) -> bool:
    """Whether excludes or a `.gitignore` (between the root and the file) exclude this file or a folder above it."""
    root = Path(excluder.root)
    if file.parent != root and root not in file.parents:
        return excluder.excluded(file, is_dir=False)
    folders = [folder for folder in reversed(file.parents) if folder == root or root in folder.parents]
    gitignores: list[tuple[str, Callable[[str], bool]]] = []
    for folder in folders:
        if folder != root and excluder.excluded(folder, is_dir=True):
            return True
        spec = excluder.gitignore_in(folder)
        if spec is not None:
            gitignores.append((str(folder), spec))
        if folder != root and _gitignored(gitignores[:-1] if spec is not None else gitignores, str(folder), True):
            return True
    return excluder.excluded(file, is_dir=False) or _gitignored(gitignores, str(file), False)


@lru_cache(maxsize=64)
def _any_pattern(patterns: tuple[str, ...]) -> re.Pattern[str] | None:
    """The patterns' spec as one regex, when no pattern negates (`build`, `*.egg-info`, the defaults): then a
    path is excluded when any pattern matches it, and one search replaces one per pattern."""
    regexes = []
    for pattern in _spec(patterns).patterns:
        if pattern.include is None:
            continue  # a comment or a blank line
        if pattern.include is not True or pattern.regex is None or pattern.regex.flags & ~re.UNICODE:
            return None
        regexes.append(pattern.regex.pattern.replace("(?P<ps_d>", "(?:"))
    return re.compile("|".join(f"(?:{regex})" for regex in regexes)) if regexes else None


def _read_gitignore(path: str) -> Callable[[str], bool] | None:
    try:
        with open(path, encoding="utf-8", errors="replace") as stream:
            lines = tuple(stream.read().splitlines())
    except OSError:
        return None
    return _gitignore_matcher(lines) if lines else None


def _gitignored(active: Sequence[tuple[str, Callable[[str], bool]]], candidate: str, is_dir: bool) -> bool:
    """Whether a `.gitignore` in `active` (each with its folder, which holds `candidate`) drops it."""
    for base, matches in active:
        if candidate.startswith(base + os.sep):
            relative = candidate[len(base) + 1 :]
        else:
            relative = os.path.relpath(candidate, base)
        relative = relative.replace(os.sep, "/") + ("/" if is_dir else "")
        if matches(relative):
            return True
    return False


@lru_cache(maxsize=256)
def _gitignore_matcher(lines: tuple[str, ...]) -> Callable[[str], bool]:
    """`spec.match_file` for the spec of these lines; for one that negates nothing (most), the first
    pattern that matches decides, so its compiled regexes are searched in order without pathspec's
    per-pattern calls (pathspec's own test: `regex.search`)."""
    spec = _spec(lines)
    searches = []
    for pattern in spec.patterns:
        if pattern.include is None:
            continue  # a comment or a blank line
        if pattern.include is not True or pattern.regex is None:
            return _negating_matcher(spec, lines)
        searches.append(pattern.regex.search)
    return lambda relative: any(search(relative) is not None for search in searches)


def _negating_matcher(spec, lines: tuple[str, ...]) -> Callable[[str], bool]:  # type: ignore[no-untyped-def]
    """For a `.gitignore` that negates: a folder (`relative` ends in "/") is decided by the last pattern
    that matches it, as git does (`*` then `!src/` keeps `src/`; pathspec's GitIgnoreSpec lets `*`, which
    matches the name itself, win over a folder pattern); a file by GitIgnoreSpec, whose rule that a file
    under an excluded folder stays excluded matters for files named one by one."""
    import pathspec

    folders = pathspec.PathSpec.from_lines("gitwildmatch", lines)
    return lambda relative: bool(folders.match_file(relative) if relative.endswith("/") else spec.match_file(relative))


@dataclass
class Consulted:
    """What a discovery's answer rests on: the folders it listed (or looked in for a `.gitignore`)
    and the `.gitignore` files it read."""

    folders: set[str] = field(default_factory=set)
    files: set[str] = field(default_factory=set)


class _Excluder:
    """Matches resolved paths against the exclude patterns, anchored at the config root."""

    def __init__(self, root: Path, patterns: tuple[str, ...], consulted: Consulted | None = None) -> None:
        self.root = str(root)
        self.patterns = patterns
        self.spec = _spec(patterns)
        self._any_pattern = _any_pattern(patterns)
        self.consulted = consulted if consulted is not None else Consulted()

    def read_gitignore(self, path: str) -> Callable[[str], bool] | None:
        self.consulted.files.add(path)
        return _read_gitignore(path)

    def gitignore_in(self, folder: Path) -> Callable[[str], bool] | None:
        """The spec of `folder/.gitignore`, if there is one (the folder's listing says whether)."""
        self.consulted.folders.add(str(folder))
        gitignore = folder / ".gitignore"
        return self.read_gitignore(str(gitignore)) if gitignore.is_file() else None

    def excluded(self, path: Path | str, *, is_dir: bool) -> bool:
        text = os.path.normpath(str(path))
        if text.startswith(self.root + os.sep):
            relative = text[len(self.root) + 1 :]
        else:  # outside the project: match on the name only (e.g. "build", "*.egg-info")
            relative = os.path.basename(text)
        relative = relative.replace(os.sep, "/") + ("/" if is_dir else "")
        if self._any_pattern is not None:
            return self._any_pattern.match(relative) is not None
        return bool(self.spec.match_file(relative))

    def gitignores_above(self, top: Path) -> Iterable[tuple[str, Callable[[str], bool]]]:
        """`.gitignore` files between the config root and `top` (exclusive), which also apply inside it."""
        if not (str(top) + os.sep).startswith(self.root + os.sep):
            return
        folder = Path(self.root)
        parts = top.relative_to(folder).parts
        for depth in range(len(parts)):
            current = folder.joinpath(*parts[:depth])
            spec = self.gitignore_in(current)
            if spec is not None:
                yield str(current), spec
