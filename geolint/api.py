"""The one public entry point to the linter. The CLI, the language server and the pre-commit
hook are thin adapters over these functions, so they always agree.

- `find_config(start)`: the `[tool.geolint]` config that applies at `start` (raises `ConfigError`).
- `lint_text(source, path, config)`: findings for one module's text.
- `fix_text(source, path, config, unsafe=..., only=...)`: the fixed text and what remains.
- `lint_paths(paths, config, jobs=..., use_cache=...)`: files and folders, in parallel, cached.
- `rule_url(code)`: where a rule's documentation lives.
"""

from __future__ import annotations

import gc
import hashlib
import os
import traceback
from collections import Counter
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Collection, Iterator, Sequence

from geolint import config as config_module
from geolint import engine, history
from geolint.cache import DiscoveryCache, FindingsCache, ImportsCache, VotesCache, content_hash, default_cache_dir
from geolint.config import ConfigError, config_root
from geolint.factbase import conventions, ros_packages, tf_workspace
from geolint.factbase.project_files import ImportGraph, consulted_folders, folder_listings, project_root
from geolint.factbase.project_pins import pins_key
from geolint.files import DiscoveryError, SourceFile, discover
from geolint.lint_types import Config, Finding
from geolint.notebook import NotebookError, is_notebook, read_notebook, unreadable_notebook

__all__ = [
    "ConfigError",
    "DiscoveryError",
    "FileResult",
    "find_config",
    "fix_text",
    "lint_paths",
    "lint_text",
    "rule_url",
]

# Below this many files to lint, starting worker processes costs more than it saves.
MIN_FILES_PER_WORKER = 4


@dataclass(frozen=True)
class FileResult:
    """The outcome of linting one file: its findings, or the internal error that stopped it."""

    path: str
    findings: tuple[Finding, ...]
    error: str | None = None
    cached: bool = False
    # The file on disk (the `path` above is for display: as given or relative to the cwd).
    location: Path | None = None
    # The file could not be read (`error` says why): not a crash of geolint's.
    unreadable: bool = False
    # It is a symbolic link to nothing (a build product not built here): skipped with a warning.
    broken_link: bool = False


def _unreadable(source: SourceFile, error: OSError) -> FileResult:
    """What a file that cannot be read gives: why, and whether it is only a link to nothing."""
    path = source.path
    if path.is_symlink() and not path.exists():
        return FileResult(source.display, (), f"broken symbolic link to {os.readlink(path)}", location=path, unreadable=True, broken_link=True)
    return FileResult(source.display, (), error.strerror or str(error), location=path, unreadable=True)


def find_config(start: Path) -> Config:
    """The config of the nearest pyproject.toml with a [tool.geolint] table at or above `start`.

    Defaults when there is none; raises `ConfigError` (naming the file and the key) for a bad one.
    """
    return config_module.find_config(Path(start))


def lint_text(source: str, path: str | Path = "<string>", config: Config | None = None) -> list[Finding]:
    """Findings for one module's text, after select/ignore and suppressions. Never raises for bad code."""
    return engine.lint_source(source, str(path), config or Config())


def fix_text(
    source: str,
    path: str | Path = "<string>",
    config: Config | None = None,
    *,
    unsafe: bool = False,
    only: Collection[str] | None = None,
) -> tuple[str, list[Finding]]:
    """Apply the available fixes; return the new text and the findings that remain.

    `unsafe` also applies fixes marked unsafe; `only` restricts fixing to these code prefixes.
    The new text always parses, and fixing it again changes nothing.
    """
    from geolint.fixes import fix_source

    outcome = fix_source(source, str(path), config or Config(), unsafe=unsafe, only=only)
    return outcome.source, list(outcome.remaining)


def lint_paths(
    paths: Sequence[Path],
    config: Config | None = None,
    *,
    jobs: int | None = None,
    use_cache: bool = True,
    force_exclude: bool = False,
    cache_dir: Path | None = None,
    progress: Callable[[int, int], None] | None = None,
    stats: dict[str, int] | None = None,
    sources: Sequence[SourceFile] | None = None,
) -> Iterator[FileResult]:
    """Lint files and folders (honouring excludes), in parallel, with a content-keyed cache.

    Results come sorted by display path whatever `jobs` is, so output is deterministic.
    `progress(done, total)` is called as files finish; `stats` (if given) receives the counts
    `files`, `cache_hits`, `linted`, `errors`. Raises `DiscoveryError` for a path that does not exist.
    `sources`, when given, are the files to lint, already found (`paths` is then not walked).
    """
    config = config or Config()
    directory = cache_dir or default_cache_dir(config_root(config))
    if sources is None:
        listing = DiscoveryCache(directory) if use_cache else None
        sources = discover([Path(p) for p in paths], config, force_exclude=force_exclude, cache=listing)
    cache = FindingsCache(directory, config) if use_cache else None
    resolved = ImportsCache(directory) if use_cache else None
    votes = VotesCache(directory) if use_cache else None
    if votes is not None:
        conventions.remember_file_votes(votes.load())
    results: dict[str, FileResult] = {}
    pending: list[tuple[SourceFile, bytes, str]] = []
    total = len(sources)
    # each imported module is read, hashed and scanned once (not scanned at all when unchanged since the last run)
    imports = ImportGraph(content_hash, resolved.load() if resolved is not None else None)

    read: list[tuple[SourceFile, bytes, str, str]] = []
    with folder_listings():  # the imports of every file resolved against one listing per folder
        for source in sources:
            try:
                data = source.path.read_bytes()
                if is_notebook(source.path):
                    data = read_notebook(data).python.encode("utf-8")
            except OSError as error:
                results[source.display] = _unreadable(source, error)
                continue
            except NotebookError as error:
                results[source.display] = FileResult(source.display, tuple(unreadable_notebook(source.display, config, error)), location=source.path)
                continue
            if cache is None:  # nothing to look up or store: no digest to compute
                pending.append((source, data, ""))
                continue
            # every file of the run registered before any digest: an imported one is then never read twice
            read.append((source, data, *imports.register_file(str(source.path), data, read=True)))
        for source, data, own, key in read:
            # the file's bytes and those of the project modules it imports, directly or not (their summaries feed its findings)
            digest = imports.file_digest(key, own)
            # and what its project's declarations say about names: one added elsewhere changes its findings
            naming = conventions.project_key(str(source.path)) + ros_packages.package_key(str(source.path)) + pins_key(str(source.path))
            naming += tf_workspace.workspace_key(str(source.path), data) + history.history_key(str(source.path), config)
            if naming:
                digest = hashlib.blake2b(f"{digest}:{naming}".encode(), digest_size=16).hexdigest()
            cached = cache.get(source.real_path(), digest, source.display) if cache is not None else None
            if cached is not None:
                results[source.display] = FileResult(source.display, tuple(cached), cached=True, location=source.path)
            else:
                pending.append((source, data, digest))
        if resolved is not None and not imports.all_reused:  # else what is stored still holds
            files_read = imports.resolved()
            resolved.save(files_read, consulted_folders(files_read))
        if votes is not None and conventions.file_votes_read():  # else what is stored still holds
            votes.save(conventions.remembered_file_votes())
    if progress:
        progress(len(results), total)

    # one listing per folder while linting too: a module name a project folder does not hold (`gym`,
    # `time`) is ruled out before any argument of its calls is looked at (the run reads one snapshot)
    with _fewer_collections(), folder_listings():
        linted = _lint_all(pending, config, jobs, progress, len(results), total)
    for (source, _, digest), result in zip(pending, linted):
        results[source.display] = result
        if cache is not None and result.error is None:
            cache.put(source.real_path(), digest, list(result.findings))
    if cache is not None:
        cache.save()
    if stats is not None:
        stats.update(
            files=total,
            cache_hits=sum(1 for r in results.values() if r.cached),
            linted=len(pending),
            errors=sum(1 for r in results.values() if r.error),
        )
    for display in sorted(results):
        yield results[display]


# Linting allocates a syntax tree and its index per file and frees them by reference counting (a
# file's fact bases are closed after its rules ran, so no cycle keeps a tree alive). Every collection
# would still walk the live tree of the file being linted: at the default threshold (700) the cycle
# collector ran hundreds of times per file, at 10,000 it took a fifth of a cold run. A run's net growth
# (bounded caches) stays under a million objects, so it rarely runs at all.
_GC_THRESHOLD_WHILE_LINTING = (1_000_000, 20, 100)


@contextmanager
def _fewer_collections() -> Iterator[None]:
    """Run the cycle collector less often while linting (forked workers inherit the setting)."""
    before = gc.get_threshold()
    gc.set_threshold(*_GC_THRESHOLD_WHILE_LINTING)
    try:
        yield
    finally:
        # the objects allocated since the last collection (up to a million) join the oldest generation
        # instead of being walked by a young collection the restored threshold would start at once
        # (a fifth of a second at the end of a run)
        gc.freeze()
        gc.set_threshold(*before)
        gc.unfreeze()


def _lint_all(
    pending: list[tuple[SourceFile, bytes, str]],
    config: Config,
    jobs: int | None,
    progress: Callable[[int, int], None] | None,
    done: int,
    total: int,
) -> list[FileResult]:
    """Lint the files the cache could not answer, in this process or across worker processes."""
    jobs = jobs or os.cpu_count() or 1
    work = [(source.display, str(source.path), data, config) for source, data, _ in pending]
    if jobs <= 1 or len(work) < MIN_FILES_PER_WORKER * 2:
        results = []
        for item in work:
            results.append(_lint_one(item))
            done += 1
            if progress:
                progress(done, total)
        return results

    from geolint.workers import run_in_workers

    engine.registered_rules()  # import the rules once, so forked workers inherit them
    # A worker keeps to one project while it has files left: the helper modules it parsed and indexed
    # for one file's summaries serve the next. Largest projects first, and big files first within one,
    # so one large file does not finish alone at the end.
    project_of = {location: str(project_root(location)) for _, location, _, _ in work}
    size_of_project: Counter[str] = Counter()
    for _, location, data, _ in work:
        size_of_project[project_of[location]] += len(data)
    order = sorted(range(len(work)), key=lambda index: (
        -size_of_project[project_of[work[index][1]]], project_of[work[index][1]], -len(work[index][2])
    ))

    def finished(_: int) -> None:
        nonlocal done
        done += 1
        if progress:
            progress(done, total)

    ordered = run_in_workers([work[i] for i in order], _lint_one, _crashed, jobs, finished, group=lambda item: project_of[item[1]])
    results_by_index = dict(zip(order, ordered))
    return [results_by_index[index] for index in range(len(work))]


def _crashed(item: tuple[str, str, bytes, Config], why: str) -> FileResult:
    """The result of a file whose worker process died while checking it (the run goes on)."""
    display, location, _, _ = item
    return FileResult(display, (), f"{why}; the file was not checked", location=Path(location))


def _lint_one(item: tuple[str, str, bytes, Config]) -> FileResult:
    """Lint one file's bytes; an exception inside geolint becomes the result's error, not a crash."""
    display, location, data, config = item
    try:
        return FileResult(display, tuple(engine.lint_bytes(data, display, config)), location=Path(location))
    except Exception:  # an internal error in one file must not stop the run
        return FileResult(display, (), traceback.format_exc(), location=Path(location))


def rule_url(code: str) -> str:
    """Where a rule's documentation lives (used by the language server and SARIF)."""
    return f"https://github.com/geolint/geolint/blob/main/docs/rules.md#{code.lower()}"
