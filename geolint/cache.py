"""A content-keyed cache of findings, so a re-run over an unchanged tree costs only reading files.

One JSON file per settings key holds `path -> (content hash, findings)`. The settings key
covers everything besides the file's bytes that can change its findings: the geolint version,
the source of the installed geolint package (so editing a rule invalidates the cache during
development), and the whole config (select/ignore included). The file lives in
`<project root>/.geolint_cache/` (override with `GEOLINT_CACHE_DIR`), which carries its own
`.gitignore` so it never gets committed. Writes are atomic (temp file + rename), so parallel
runs never see a torn file; concurrent runs at worst lose each other's new entries.

A second file, `imports-*.json`, keeps where each file's project imports resolved (`ImportsCache`),
so a re-run reads and hashes each file but neither scans nor resolves its imports again; a third,
`discovery-*.json`, keeps which files the paths given hold (`DiscoveryCache`), so it lists no folder.
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
import time
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any, Iterable

from geolint._version import __version__
from geolint.knowledge import stubs_folder
from geolint.lint_types import Config, Edit, Finding, Fix, Severity

if TYPE_CHECKING:
    from geolint.files import Consulted

CACHE_DIR_ENV = "GEOLINT_CACHE_DIR"
CACHE_FOLDER = ".geolint_cache"
FORMAT_VERSION = 2


def content_hash(data: bytes) -> str:
    return hashlib.blake2b(data, digest_size=16).hexdigest()


# The parts of the package whose code decides what a file's findings are.
FINDINGS_SOURCES = (
    "rules", "semantic", "factbase", "knowledge", "history", "algebra.py", "engine.py", "suppression.py", "config.py", "lint_types.py", "_version.py",
    "files.py",  # which files a folder holds
)  # fmt: skip


@lru_cache(maxsize=1)
def package_fingerprint() -> str:
    """A hash of the names, sizes and mtimes of the geolint sources that decide findings, and of the
    knowledge base's stubs (stats only).

    Editing a rule or a stub invalidates the cache during development; editing the language server does not.
    """
    package_dir = Path(__file__).resolve().parent
    digest = hashlib.blake2b(digest_size=16)
    for entry in FINDINGS_SOURCES:
        top = package_dir / entry
        _fingerprint(digest, os.walk(top) if top.is_dir() else [(str(package_dir), [], [entry])], package_dir, (".py", ".pyi"))
    stubs = stubs_folder()
    _fingerprint(digest, os.walk(stubs), stubs, (".pyi", ".toml"))
    return digest.hexdigest()


def _fingerprint(digest: Any, walked: Iterable[tuple[str, list[str], list[str]]], base: Path, suffixes: tuple[str, ...]) -> None:
    for folder, dirnames, filenames in walked:
        dirnames[:] = sorted(d for d in dirnames if d != "__pycache__")
        for name in sorted(filenames):
            if name.endswith(suffixes):
                try:
                    stat = os.stat(os.path.join(folder, name))
                except OSError:
                    continue
                relative = os.path.relpath(os.path.join(folder, name), base)
                digest.update(f"{relative}:{stat.st_size}:{stat.st_mtime_ns}\n".encode())


def settings_key(config: Config | None) -> str:
    """What, besides a file's bytes, its findings depend on (without a config: what geolint's own code is)."""
    text = f"{FORMAT_VERSION}|{__version__}|{package_fingerprint()}" + ("" if config is None else f"|{config!r}")
    return hashlib.blake2b(text.encode(), digest_size=12).hexdigest()


def default_cache_dir(root: Path) -> Path:
    override = os.environ.get(CACHE_DIR_ENV)
    return Path(override) if override else root / CACHE_FOLDER


class FindingsCache:
    """Findings of previously linted files, valid while their content hash is unchanged."""

    def __init__(self, directory: Path, config: Config) -> None:
        self.directory = directory
        self.file = directory / f"findings-{settings_key(config)}.json"
        self._entries: dict[str, list[Any]] = self._load()
        self._dirty = False

    def _load(self) -> dict[str, list[Any]]:
        try:
            with open(self.file, encoding="utf-8") as stream:
                entries = json.load(stream)
        except (OSError, ValueError):
            return {}  # no cache yet, or a damaged one: start over
        return entries if isinstance(entries, dict) else {}

    def get(self, path: Path, digest: str, display: str) -> list[Finding] | None:
        entry = self._entries.get(str(path))
        if entry is None or entry[0] != digest:
            return None
        return [finding_from_dict(item, display) for item in entry[1]]

    def put(self, path: Path, digest: str, findings: list[Finding]) -> None:
        self._entries[str(path)] = [digest, [finding_to_dict(finding) for finding in findings]]
        self._dirty = True

    def save(self) -> None:
        """Write the cache if anything changed, merged with entries other runs wrote meanwhile."""
        if not self._dirty:
            return
        try:
            _write_atomically(self.directory, self.file, {**self._load(), **self._entries})
        except OSError:
            pass  # a read-only tree still lints; it just does not get faster next time
        self._dirty = False


# the coarsest file-system clock in common use (FAT: 2 s): a stamp this close to a run's start may hide a change
_MTIME_SLACK_NS = 2_000_000_000


class ImportsCache:
    """Where each file's project imports resolved in an earlier run, reused while the file's bytes and
    the folders consulted are unchanged: a folder's mtime changes whenever an entry is added to it,
    removed or renamed (the stamp CPython's own import system trusts). A folder that changed shortly
    before or during the run that listed it may change again within its clock's resolution unseen,
    so such a run stores nothing. Keyed by the package's fingerprint alone: the config does not
    change where an import resolves.
    """

    def __init__(self, directory: Path) -> None:
        self.directory = directory
        self.file = directory / f"imports-{settings_key(None)}.json"
        self.started_ns = time.time_ns()
        self._trusted_folders: set[str] = set()  # the stamps `load` found unchanged

    def load(self) -> dict[str, list[Any]]:
        """file -> [hash, imports] of the last run, or {} when a folder it consulted has changed since."""
        try:
            with open(self.file, encoding="utf-8") as stream:
                stored = json.load(stream)
            folders, files = stored["folders"], stored["files"]
            if not isinstance(folders, dict) or not isinstance(files, dict):
                return {}
        except (OSError, ValueError, KeyError, TypeError):
            return {}  # no cache yet, or a damaged one: resolve everything
        if not all(_is_resolution(entry) for entry in files.values()):
            return {}
        if any(_mtime_ns(folder) != stamp for folder, stamp in folders.items()):
            return {}
        self._trusted_folders = set(folders)
        return files

    def save(self, files: dict[str, list[Any]], folders: Iterable[str]) -> None:
        """Store `files` with the stamps of `folders` (those this run consulted) and of the folders the
        loaded entries were resolved in: a file whose imports were reused did not consult its own."""
        stamps = {folder: _mtime_ns(folder) for folder in {*folders, *self._trusted_folders}}
        if any(stamp is not None and stamp >= self.started_ns - _MTIME_SLACK_NS for stamp in stamps.values()):
            return  # a folder too fresh to trust its stamp
        try:
            _write_atomically(self.directory, self.file, {"folders": stamps, "files": files})
        except OSError:
            pass


class DiscoveryCache:
    """Which files an earlier run found under the paths it was given, reused while every folder it
    listed keeps its mtime, every `.gitignore` it read its mtime and size, and every linked file its
    target (folder stamps as in `ImportsCache`; a run that saw a stamp too fresh stores nothing).
    Keyed by the question (cwd, config root, excludes, paths) and the package's fingerprint."""

    def __init__(self, directory: Path) -> None:
        self.directory = directory
        self.started_ns = time.time_ns()

    def _file(self, question: tuple[Any, ...]) -> Path:
        key = hashlib.blake2b(f"{settings_key(None)}|{question!r}".encode(), digest_size=12).hexdigest()
        return self.directory / f"discovery-{key}.json"

    def load(self, question: tuple[Any, ...]) -> list[tuple[str, str, str]] | None:
        """[(path, display, real path), ...] as the last run with this question found them, or None."""
        try:
            with open(self._file(question), encoding="utf-8") as stream:
                stored = json.load(stream)
            folders, files, links, sources = stored["folders"], stored["files"], stored["links"], stored["sources"]
            if any(_mtime_ns(folder) != stamp for folder, stamp in folders.items()):
                return None
            if any(_stat_stamp(file) != stamp for file, stamp in files.items()):
                return None
            if any(os.path.realpath(link) != target for link, target in links.items()):
                return None
            return [(path, display, real) for path, display, real in sources]
        except (OSError, ValueError, KeyError, TypeError, AttributeError):
            return None  # no answer yet, or a damaged one: walk the folders

    def save(self, question: tuple[Any, ...], sources: list[tuple[str, str, str]], consulted: Consulted, links: dict[str, str]) -> None:
        folders = {folder: _mtime_ns(folder) for folder in consulted.folders}
        files = {file: _stat_stamp(file) for file in consulted.files}
        fresh = [stamp for stamp in folders.values() if stamp is not None]
        fresh += [stamp[0] for stamp in files.values() if stamp is not None]
        if any(stamp >= self.started_ns - _MTIME_SLACK_NS for stamp in fresh):
            return  # a folder or .gitignore too fresh to trust its stamp
        try:
            _write_atomically(self.directory, self._file(question), {"folders": folders, "files": files, "links": links, "sources": sources})
        except OSError:
            pass


class VotesCache:
    """What each project file says about its naming convention (`conventions.remembered_file_votes`),
    reused while the file's mtime and size are unchanged: a warm run learns its projects' conventions,
    which key every file's findings, without reading a file. A file written within the clock's
    resolution before the run may change again unseen, so it is not stored."""

    def __init__(self, directory: Path) -> None:
        self.directory = directory
        self.file = directory / f"votes-{settings_key(None)}.json"
        self.started_ns = time.time_ns()

    def load(self) -> dict[str, list[int]]:
        try:
            with open(self.file, encoding="utf-8") as stream:
                stored = json.load(stream)
        except (OSError, ValueError):
            return {}
        return stored if isinstance(stored, dict) else {}

    def save(self, files: dict[str, list[int]]) -> None:
        kept = {file: entry for file, entry in files.items() if entry[0] < self.started_ns - _MTIME_SLACK_NS}
        try:
            _write_atomically(self.directory, self.file, kept)
        except OSError:
            pass


def _is_resolution(entry: Any) -> bool:
    """[hash, [imported file, ...]], as `ImportGraph.resolved` gives it."""
    return (
        isinstance(entry, list) and len(entry) == 2 and isinstance(entry[0], str) and isinstance(entry[1], list)
        and all(isinstance(file, str) for file in entry[1])
    )  # fmt: skip


def _mtime_ns(folder: str) -> int | None:
    try:
        return os.stat(folder).st_mtime_ns
    except OSError:
        return None  # a folder looked in that does not exist: its creation changes the answer


def _stat_stamp(file: str) -> list[int] | None:
    """[mtime, size] (a list, as JSON gives it back), or None for a file that is not there."""
    try:
        stat = os.stat(file)
    except OSError:
        return None
    return [stat.st_mtime_ns, stat.st_size]


def _write_atomically(directory: Path, file: Path, content: Any) -> None:
    """Write JSON to `file` by renaming a complete temporary file over it (the cache folder keeps a
    `.gitignore` so it is never committed)."""
    directory.mkdir(parents=True, exist_ok=True)
    gitignore = directory / ".gitignore"
    if not gitignore.exists():
        gitignore.write_text("# Created by geolint: the cache never belongs in git.\n*\n", encoding="utf-8")
    handle, temporary = tempfile.mkstemp(dir=directory, prefix=".tmp-", suffix=".json")
    with os.fdopen(handle, "w", encoding="utf-8") as stream:
        json.dump(content, stream, separators=(",", ":"))
    os.replace(temporary, file)


def finding_to_dict(finding: Finding) -> dict[str, Any]:
    fix = finding.fix
    return {
        "line": finding.line,
        "column": finding.column,
        "end_line": finding.end_line,
        "end_column": finding.end_column,
        "code": finding.code,
        "name": finding.name,
        "message": finding.message,
        "severity": finding.severity.value,
        "fix": None
        if fix is None
        else {
            "applicability": fix.applicability,
            "description": fix.description,
            "edits": [[e.line, e.column, e.end_line, e.end_column, e.content] for e in fix.edits],
        },
        "evidence": list(finding.evidence),
        "frames": None if finding.frames is None else list(finding.frames),
    }


def finding_from_dict(item: dict[str, Any], path: str) -> Finding:
    fix = item["fix"]
    return Finding(
        path=path,
        line=item["line"],
        column=item["column"],
        end_line=item["end_line"],
        end_column=item["end_column"],
        code=item["code"],
        name=item["name"],
        message=item["message"],
        severity=Severity(item["severity"]),
        fix=None
        if fix is None
        else Fix(fix["applicability"], tuple(Edit(*edit) for edit in fix["edits"]), fix["description"]),
        evidence=tuple(item.get("evidence", ())),
        frames=_frame_pair(item.get("frames")),
    )


def _frame_pair(value: Any) -> tuple[str, str] | None:
    if isinstance(value, list) and len(value) == 2 and all(isinstance(frame, str) for frame in value):
        return value[0], value[1]
    return None
