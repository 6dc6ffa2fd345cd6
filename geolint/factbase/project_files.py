"""The project around a linted module: its root (the nearest folder with a project marker), the
project file an import resolves to (absolute, relative, a ROS workspace's sibling packages), and the
project modules a file imports, transitively, with one digest of them (`dependency_digest`).

Since a summary may consult modules any number of imports away, the findings cache keys each file
by `dependency_digest`: editing a helper re-lints every module that may read its summary.
"""

from __future__ import annotations

import hashlib
import os
import re
from contextlib import contextmanager
from functools import lru_cache
from pathlib import Path
from typing import Any, Final, Iterable, Iterator, Mapping, Sequence

from geolint.factbase.vocabulary import is_third_party_root

_IMPORT: Final = re.compile(r"^[ \t]*(?:from[ \t]+([.\w]+)[ \t]+import|import[ \t]+([\w.]+))", re.MULTILINE)
# `_IMPORT` at one line start: both its alternatives hold the word "import", so only the lines that
# hold it are tried (the anchored regex alone tries every position of the text).
_IMPORT_AT_LINE_START: Final = re.compile(r"[ \t]*(?:from[ \t]+([.\w]+)[ \t]+import|import[ \t]+([\w.]+))")
_PROJECT_MARKERS: Final = ("pyproject.toml", "setup.py", "setup.cfg", ".git")




TEST_FOLDERS: Final = frozenset({"test", "tests"})


def is_test_module(path: str) -> bool:
    """Whether `path` is a test module: `test_*.py`, `*_test.py`, or a file in a `test` / `tests` folder
    (give a path relative to the project, so that the folders above it do not count)."""
    parts = path.replace("\\", "/").split("/")
    name = parts[-1]
    return name.startswith("test_") or name.endswith("_test.py") or any(part in TEST_FOLDERS for part in parts[:-1])


def project_root(path: str) -> Path | None:
    """The nearest folder above `path`, symlinks resolved, that holds a project marker (pyproject.toml,
    setup.py, setup.cfg, .git): the project whose naming votes the file reads, and whose files one
    worker takes in a row."""
    folder = os.path.dirname(os.path.realpath(path)) if os.path.islink(path) else _real_folder(_folder_of(path))
    root = _root_of_folder(folder)
    return None if root is None else Path(root)


@lru_cache(maxsize=65536)
def _real_folder(folder: str) -> str:
    return os.path.realpath(folder)  # asked once per folder, not once per file


# Module resolution works on `str` paths: it runs for every import line of every file of a run, and
# `Path` objects cost more to build, hash and compare than the lookups themselves.
@lru_cache(maxsize=65536)
def _root_of_folder(folder: str) -> str | None:
    candidate = folder
    while True:
        if any(os.path.exists(os.path.join(candidate, marker)) for marker in _PROJECT_MARKERS):
            return candidate
        parent = os.path.dirname(candidate)
        if parent == candidate:
            return None
        candidate = parent


def module_file(module: str, importer: str, level: int = 0) -> Path | None:
    """The project file a module name resolves to from `importer` (absolute or relative), or None."""
    found = module_path(module, importer, level)
    return None if found is None else _one_path(found)


def module_path(module: str, importer: str, level: int = 0) -> str | None:
    """`module_file` as an absolute `str` path."""
    return _module_file_from(module, _folder_of(importer), level)


def may_be_project_import(imported: str, importer: str) -> bool:
    """Whether a name imported as `imported` (`slam.geometry.apply_pose`) may be a project module's:
    not a known third-party package (`numpy`, `torch`), and one a project folder can hold."""
    top = imported.split(".")[0]
    return not is_third_party_root(top) and (not top or not importer or may_be_project_module(top, importer))


def may_be_project_module(top: str, importer: str) -> bool:
    """Whether an absolute import whose first name is `top` can resolve to a project file from
    `importer`: the first test `_module_in` makes in each folder `module_file` searches (`gym`,
    `carla` and `time` are in none of them). Always True outside `folder_listings`."""
    if _listings is None:
        return True
    here = _folder_of(importer)
    return _top_held_from(top, here) or _top_held_in_workspace(top, here)


def _top_held_in_workspace(top: str, here: str) -> bool:
    """`top` (or `top.py`) in a folder of the ROS workspace around `here` (`_workspace_folders`)."""
    folders = _workspace_folders(here)
    if not folders:
        return False
    key = (top, here)
    found = _workspace_tops.get(key)
    if found is None:
        found = _workspace_tops[key] = any(_may_hold(base, top) or _may_hold(base, top + ".py") for base in folders)
    return found


def _top_held_from(top: str, here: str) -> bool:
    """`top` (or `top.py`) in `here` or a folder searched after it: the folders searched from a folder
    below the project root are that folder and those searched from its parent, so each answer is
    one listing lookup plus its parent's answer."""
    key = (top, here)
    found = _listed_tops.get(key)
    if found is None:
        folders = _search_folders(here, 0)
        found = bool(folders) and (
            _may_hold(folders[0], top) or _may_hold(folders[0], top + ".py") or (len(folders) > 1 and _top_held_from(top, folders[1]))
        )
        _listed_tops[key] = found
    return found


@lru_cache(maxsize=65536)
def _folder_of(path: str) -> str:
    return os.path.dirname(os.path.abspath(path))


@lru_cache(maxsize=65536)
def _module_file_from(module: str, here: str, level: int) -> str | None:
    parts = tuple(part for part in module.split(".") if part)
    if not parts:
        return None
    for base in _search_folders(here, level):
        found = _module_in(base, parts)
        if found is not None:
            return found
    if not level:
        for base in _workspace_folders(here):
            found = _module_in(base, parts)
            if found is not None:
                return found
    return None


PACKAGE_MANIFEST: Final = "package.xml"  # a ROS package (REP 140/149)


@lru_cache(maxsize=65536)
def _workspace_folders(here: str) -> tuple[str, ...]:
    """Where the other packages of a ROS workspace keep their modules, for a file in one of them: the
    packages beside its own (each with a `package.xml`), their `src/` (catkin) and themselves
    (ament_python). A workspace's packages import each other (`carla_common.transforms` from
    `carla_ros_bridge`), and none of them holds the others."""
    package = package_of_folder(here)
    if package is None:
        return ()
    workspace = os.path.dirname(package)
    try:
        names = sorted(os.listdir(workspace))
    except OSError:
        return ()
    found: list[str] = []
    for name in names:
        sibling = os.path.join(workspace, name)
        if sibling != package and os.path.isfile(os.path.join(sibling, PACKAGE_MANIFEST)):
            found += [os.path.join(sibling, "src"), sibling]
    return tuple(found)


@lru_cache(maxsize=65536)
def package_of_folder(folder: str) -> str | None:
    """The ROS package a folder belongs to: the nearest folder at or above it holding a `package.xml`."""
    candidate = folder
    while True:
        if os.path.isfile(os.path.join(candidate, PACKAGE_MANIFEST)):
            return candidate
        parent = os.path.dirname(candidate)
        if parent == candidate:
            return None
        candidate = parent


@lru_cache(maxsize=65536)
def _search_folders(here: str, level: int) -> tuple[str, ...]:
    """Where a module name imported from folder `here` may live (relative: `level` folders up)."""
    if level:
        base = here
        for _ in range(level - 1):
            base = os.path.dirname(base)
        return (base,)
    root = _root_of_folder(here)
    if root is None:
        return ()
    candidates = []
    folder = here
    while True:  # src layouts and scripts next to their package: any folder up to the root
        candidates.append(folder)
        parent = os.path.dirname(folder)
        if folder == root or parent == folder:
            break
        folder = parent
    return tuple(candidates)


@lru_cache(maxsize=65536)
def _one_path(file: str) -> Path:
    """One `Path` object per module file: the summaries' dicts then find it by identity."""
    return Path(file)


@lru_cache(maxsize=65536)
def _module_in(base: str, parts: tuple[str, ...]) -> str | None:
    """`base/a/b.py` or `base/a/b/__init__.py` for module `a.b`, when it is a file: asked once per folder
    (the modules of sibling folders share the folders above them)."""
    if not _may_hold(base, parts[0]) and not (len(parts) == 1 and _may_hold(base, parts[0] + ".py")):
        return None
    folder = os.path.join(base, *parts[:-1])
    target = os.path.join(folder, parts[-1])
    # the listing of the module's own folder first: most names tried are not there (`from utils
    # import helper_function` tries `utils/helper_function.py`), and a listing is read once per folder
    if _may_hold(folder, parts[-1] + ".py") and os.path.isfile(target + ".py"):
        return target + ".py"
    if _may_hold(folder, parts[-1]) and os.path.isfile(os.path.join(target, "__init__.py")):
        return os.path.join(target, "__init__.py")
    return None


# folder -> its entries' names, casefolded, while `folder_listings` is active (one listing per folder
# instead of a stat per module name per folder: `import numpy` is looked for in every folder up to the root)
_listings: dict[str, frozenset[str]] | None = None
_listed_tops: dict[tuple[str, str], bool] = {}  # `may_be_project_module`'s answers, for one listing
_workspace_tops: dict[tuple[str, str], bool] = {}  # the same, for the packages of a ROS workspace


@contextmanager
def folder_listings() -> Iterator[None]:
    """Within this block, a folder's listing says which module names it cannot hold (for a run that
    resolves the imports of many files at one moment; the files found are still checked one by one)."""
    global _listings
    _listings = {}
    _listed_tops.clear()
    _workspace_tops.clear()
    try:
        yield
    finally:
        _listings = None
        _listed_tops.clear()
        _workspace_tops.clear()


def consulted_folders(files: Iterable[str]) -> set[str]:
    """The folders whose entries decided where the imports of `files` (absolute paths) resolved within
    this `folder_listings` block: every folder listed, and each file's folders up to its project root
    (where project markers were looked for; up to the file system's root when there is none)."""
    folders = set(_listings or ())
    climbed: set[str] = set()
    for folder in {_folder_of(file) for file in files}:
        root = _root_of_folder(folder)
        while folder not in climbed:
            climbed.add(folder)
            parent = os.path.dirname(folder)
            if folder == root or parent == folder:
                break
            folder = parent
    return folders | climbed


def _may_hold(folder: str, name: str) -> bool:
    listings = _listings
    if listings is None:
        return True
    names = listings.get(folder)
    if names is None:
        try:
            names = frozenset(entry.casefold() for entry in os.listdir(folder))
        except OSError:
            names = frozenset()
        listings[folder] = names
    return name.casefold() in names  # casefolded: a case-insensitive file system finds `Geometry.py` too


def imported_files(path: str, source: str, read: bool = False) -> list[str]:
    """The project files `source` imports directly (by a cheap scan of its import lines): the modules
    named, and for `from pkg import geom` the submodule `pkg.geom` too. `read`: the caller read
    `source` from the file at `path` (no need to check that it is one)."""
    if not read and not os.path.isfile(path):
        return []
    found = []
    tops: dict[str, bool] = {}  # `from numpy import a, b, c` asks about `numpy` once
    for name in imported_names(source, members=True):
        level = len(name) - len(name.lstrip("."))
        if not level:
            top = name.partition(".")[0]
            held = tops.get(top)
            if held is None:
                held = tops[top] = may_be_project_module(top, path)
            if not held:
                continue  # `numpy`, `torch.nn`: no project folder holds the package
        file = module_path(name.lstrip("."), path, level)
        if file is not None and file not in found:
            found.append(file)
    return found


def imported_names(source: str, members: bool = False) -> list[str]:
    """The module names of the import statements in `source`, exactly as `_IMPORT.finditer` finds them
    (a match never spans lines, so each line start gives at most one). With `members`, each name a
    `from X import a, b` brings in is added as `X.a`, `X.b` too (it may be a submodule)."""
    names = []
    tried = -1
    at = source.find("import")
    while at >= 0:
        line = source.rfind("\n", 0, at) + 1
        if line != tried:
            tried = line
            match = _IMPORT_AT_LINE_START.match(source, line)
            if match is not None:
                names.append(match.group(1) or match.group(2))
                if members and match.group(1):
                    names.extend(_joined(match.group(1), member) for member in _imported_members(source, match.end()))
        at = source.find("import", at + 6)
    return names


_MEMBER: Final = re.compile(r"[A-Za-z_]\w*")


def _imported_members(source: str, start: int) -> list[str]:
    """The names after `from X import` (up to the line's end, or the closing parenthesis)."""
    rest = source[start : start + 2000]
    stripped = rest.lstrip(" \t")
    if stripped.startswith("("):
        text = stripped[1 : stripped.find(")") if ")" in stripped else len(stripped)]
    else:
        text = rest.split("\n", 1)[0]
        while text.rstrip().endswith("\\"):  # a continued line
            consumed = len(text) + 1
            text = text.rstrip()[:-1] + " " + rest[consumed:].split("\n", 1)[0]
    members = []
    for part in text.split("#", 1)[0].split(","):
        words = part.split()
        if words and _MEMBER.fullmatch(words[0]):
            members.append(words[0])
    return members


def _joined(module: str, member: str) -> str:
    return f"{module}{member}" if module.endswith(".") else f"{module}.{member}"


_UNREADABLE: Final = "-"  # the hash of a module that could not be read


class ImportGraph:
    """The project modules each file imports, transitively, and one digest of them per file.

    Files are registered with their text and hash as a run reads them (`register`); a module outside
    the run is read when first reached. Digests are computed once per strongly connected component
    of the import graph (an import cycle is one component): the digest of a component combines its
    members' hashes with the digests of the components it imports, so each module is read, scanned
    and hashed once and each edge followed once, however many files reach it.
    """

    def __init__(self, content_hash, resolved_before: Mapping[str, Sequence[Any]] | None = None) -> None:  # type: ignore[no-untyped-def]
        self.content_hash = content_hash
        # file -> [its hash, its imports] from an earlier run whose folders are unchanged (`resolved`):
        # a file with the same hash imports the same files, without being decoded or scanned
        self._resolved_before = resolved_before or {}
        self.reused = 0  # files whose imports came from `resolved_before`
        self._imports: dict[str, list[str]] = {}
        self._hashes: dict[str, str] = {}
        self._component: dict[str, int] = {}  # file -> its component's number
        self._component_digest: list[str | None] = []  # None: the component imports nothing else

    def register(self, path: str, source: str, own_hash: str, read: bool = False) -> str:
        """A file of the run, given by the caller (`read`: read from `path` just now): its hash and
        direct imports (its absolute path is returned)."""
        key = os.path.abspath(path)
        if key not in self._imports:
            self._hashes[key] = own_hash
            self._imports[key] = imported_files(path, source, read) if "import" in source else []
        return key

    def register_file(self, path: str, data: bytes, read: bool = False) -> tuple[str, str]:
        """`register` from the file's bytes: (its hash, its key)."""
        own = self.content_hash(data)
        key = os.path.abspath(path)
        if key not in self._imports and not self._reuse(key, own):
            self.register(path, data.decode("utf-8", errors="replace"), own, read)
        return own, key

    def _reuse(self, key: str, own_hash: str) -> bool:
        """Take the file's imports from the earlier run when its bytes are the same."""
        before = self._resolved_before.get(key)
        if before is None or before[0] != own_hash:
            return False
        self._hashes[key], self._imports[key] = own_hash, list(before[1])
        self.reused += 1
        return True

    @property
    def all_reused(self) -> bool:
        """Whether every file read so far took its imports from `resolved_before`."""
        return self.reused == len(self._hashes)

    def resolved(self) -> dict[str, list[Any]]:
        """file -> [its hash, the project files it imports] for every file read so far (what
        `resolved_before` takes in a later run)."""
        return {file: [own, self._imports[file]] for file, own in self._hashes.items() if own != _UNREADABLE}

    def file_digest(self, key: str, own_hash: str) -> str:
        """The digest a registered file is cached under: its own hash, combined with `digest(key)`."""
        imported = self.digest(key)
        if imported is None:
            return own_hash
        return hashlib.blake2b(f"{own_hash}:{imported}".encode(), digest_size=16).hexdigest()

    def _read(self, file: str) -> None:
        try:
            with open(file, "rb") as stream:
                data = stream.read()
        except OSError:
            self._hashes[file], self._imports[file] = _UNREADABLE, []
            return
        own = self._hashes[file] = self.content_hash(data)
        if not self._reuse(file, own):
            source = data.decode("utf-8", errors="replace")
            self._imports[file] = imported_files(file, source, read=True) if "import" in source else []

    def _successors(self, file: str) -> list[str]:
        if file not in self._imports:
            self._read(file)
        return self._imports[file]

    def digest(self, key: str) -> str | None:
        """The digest of everything `key` (registered) imports, directly or not, itself included when
        it is in a cycle; None when it imports no project module."""
        if key not in self._component:
            self._number_components(key)
        return self._component_digest[self._component[key]]

    def _number_components(self, start: str) -> None:
        """Tarjan's algorithm, iterative, from `start`: number every new component and compute its
        digest (a component is finished only after every component it imports)."""
        index: dict[str, int] = {}
        lowlink: dict[str, int] = {}
        stack: list[str] = []
        on_stack: set[str] = set()
        work = [(start, iter(self._successors(start)))]
        index[start] = lowlink[start] = 0
        stack.append(start)
        on_stack.add(start)
        while work:
            file, successors = work[-1]
            pushed = False
            for successor in successors:
                if successor in self._component:
                    continue  # finished in an earlier call
                if successor not in index:
                    index[successor] = lowlink[successor] = len(index)
                    stack.append(successor)
                    on_stack.add(successor)
                    work.append((successor, iter(self._successors(successor))))
                    pushed = True
                    break
                if successor in on_stack:
                    lowlink[file] = min(lowlink[file], index[successor])
            if pushed:
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                lowlink[parent] = min(lowlink[parent], lowlink[file])
            if lowlink[file] == index[file]:
                members = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    members.append(member)
                    if member == file:
                        break
                self._finish_component(members)

    def _finish_component(self, members: list[str]) -> None:
        number = len(self._component_digest)
        for member in members:
            self._component[member] = number
        inside = set(members)
        # a module that imports nothing stands for itself by its hash
        imported = sorted(
            {self._component_digest[self._component[file]] or self._hashes[file]
             for member in members for file in self._imports[member] if file not in inside}
        )  # fmt: skip
        in_cycle = len(members) > 1 or members[0] in self._imports[members[0]]
        if not imported and not in_cycle:
            self._component_digest.append(None)
            return
        digest = hashlib.blake2b(digest_size=16)
        for member in sorted(members):
            digest.update(self._hashes[member].encode())
        for part in imported:
            digest.update(part.encode())
        self._component_digest.append(digest.hexdigest())


def dependency_digest(path: str, data: bytes, content_hash, graph: ImportGraph | None = None) -> str:  # type: ignore[no-untyped-def]
    """The file's own hash, combined with the digest of every project module it imports, directly or
    through other project modules (a summary may read a helper any number of imports away).

    A run passes one `graph` for all its files, so each module is read and scanned once; a run that
    registers all its files first (`register_file`) never reads one of them a second time.
    """
    graph = graph or ImportGraph(content_hash)
    own, key = graph.register_file(path, data)
    return graph.file_digest(key, own)
