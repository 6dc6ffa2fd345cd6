"""The tf tree a whole ROS project states: every file's publications and lookups (`tf_statements`) in
one graph, which the frame-graph rules and `geolint frames` read.

The project is the folder `project_files.project_root` gives for a linted file (the nearest one with a
project marker, `.git` included), or the file's own folder. Its files are walked once per process
and read only when their text can state something: a Python file that names one of the knowledge
base's tf calls or launched executables, an XML launch file, a URDF or xacro file, and the launch and
parameter files that set the parameters nodes read their frames from (`ros_parameters`). What each file
states is remembered by its size and modification time, so a second question (another linted file
of the same project, a warm run) reads only what changed.

A linted file's findings depend on the other files of its project: `workspace_key` (folded into the
findings cache's digest of every file that states something) changes when what they state does.
"""

from __future__ import annotations

import ast
import hashlib
import os
import re
import threading
from collections import defaultdict
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Final, Iterable

from geolint.factbase.project_files import PACKAGE_MANIFEST, TEST_FOLDERS, is_test_module, package_of_folder, project_root
from geolint.factbase.ros_parameters import PARAMETER_FILE_SUFFIXES, launch_parameter_keys, may_launch, yaml_keys
from geolint.factbase.tf_statements import (
    URDF_SUFFIXES,
    XML_LAUNCH_SUFFIXES,
    FileFrames,
    LookedUp,
    Published,
    python_statements,
    settled,
    xml_frames,
)
from geolint.knowledge import KnowledgeBase, knowledge_base

_SKIPPED_FOLDERS: Final = frozenset({"node_modules", "__pycache__", "build", "devel", "install", "log", "site-packages"})
_MAX_FILES: Final = 20000
_MAX_PYTHON_BYTES: Final = 2_000_000


@dataclass
class TfGraph:
    """What a project publishes and looks up, with the questions the rules ask of it."""

    published: list[Published] = field(default_factory=list)
    looked_up: list[LookedUp] = field(default_factory=list)
    overridden: frozenset[str] = frozenset()  # the parameters the project's launch and parameter files set

    def __post_init__(self) -> None:
        self.parents: dict[str, dict[str, list[Published]]] = defaultdict(lambda: defaultdict(list))
        self.frames: set[str] = set()
        for edge in self.published:
            if edge.parent is not None and edge.child is not None and edge.parent != edge.child:
                self.parents[edge.child][edge.parent].append(edge)
            self.frames.update(frame for frame in (edge.parent, edge.child) if frame is not None)

    def path_up(self, start: str, goal: str) -> list[Published] | None:
        """Publications leading from `start` up through parents to `goal` (a cycle, when `goal` is a
        child of `start`), breadth first; None when there is none. Linear in the edges."""
        seen = {start}
        frontier: list[tuple[str, list[Published]]] = [(start, [])]
        while frontier:
            following: list[tuple[str, list[Published]]] = []
            for frame, path in frontier:
                for parent, edges in self.parents.get(frame, {}).items():
                    step = [*path, edges[0]]
                    if parent == goal:
                        return step
                    if parent not in seen:
                        seen.add(parent)
                        following.append((parent, step))
            frontier = following
        return None


def graph_of(frames: Iterable[FileFrames]) -> TfGraph:
    """One graph of the files' statements, each frame that is a parameter's default made unknown where
    a launch or parameter file sets that parameter."""
    files = list(frames)
    overridden = frozenset().union(*(file_frames.parameters_set for file_frames in files))
    graph = TfGraph(overridden=overridden)
    for file_frames in files:
        graph.published.extend(settled(edge, overridden) for edge in file_frames.published)
        graph.looked_up.extend(settled(lookup, overridden) for lookup in file_frames.looked_up)
    graph.__post_init__()
    return graph


# -- the project's files ----------------------------------------------------------------------------
_lock = threading.Lock()
_file_frames: dict[str, tuple[tuple[int, int], FileFrames]] = {}  # path -> ((size, mtime), what it states)
_projects: dict[str, list[tuple[str, FileFrames]]] = {}  # project folder -> its files that state something


def project_of(path: str) -> str:
    """The folder whose files make one tf tree with `path`: for a file of a ROS package, the folder of
    its workspace's packages (the package's parent, when it holds other packages and the package is
    not a repository of its own), else the package; for other files, the project root."""
    folder = os.path.dirname(os.path.abspath(path))
    package = package_of_folder(folder)
    if package is None:
        root = project_root(path)
        return str(root) if root is not None else folder
    return _workspace_of_package(package)


@lru_cache(maxsize=4096)
def _workspace_of_package(package: str) -> str:
    parent = os.path.dirname(package)
    if os.path.exists(os.path.join(package, ".git")) or parent == package:
        return package  # a repository of one package: its neighbours are other checkouts
    try:
        names = os.listdir(parent)
    except OSError:
        return package
    siblings = any(
        os.path.isfile(os.path.join(parent, name, PACKAGE_MANIFEST)) for name in names if os.path.join(parent, name) != package
    )
    return parent if siblings else package


def project_graph(path: str, own: FileFrames | None = None) -> TfGraph:
    """The graph of the project around `path`; `own`, when given, stands for that file's statements
    (its text in an editor, which may differ from the disk)."""
    linted = os.path.realpath(path)
    frames = [found for file, found in project_frames(project_of(path)) if own is None or file != linted]
    if own is not None:
        frames.append(own)
    return graph_of(frames)


def workspace_key(path: str, data: bytes) -> str:
    """What the findings of the module `path` (whose bytes are `data`) read from the rest of its project,
    for the findings cache: '' when the module states nothing about tf (the frame-graph rules are then
    silent on it, whatever the project holds)."""
    if not _may_state(knowledge_base(), data):
        return ""
    frames = project_frames(project_of(path))
    digest = hashlib.blake2b(digest_size=16)
    for file, found in frames:
        digest.update(f"{file}\0{found!r}\n".encode())
    return f"tf-tree:{digest.hexdigest()}"


def project_frames(root: str) -> list[tuple[str, FileFrames]]:
    """(file, what it states) for every file of the project that states something about tf: walked
    once per process (`forget_projects` walks again), each file read again only when its stat changed."""
    with _lock:
        known = _projects.get(root)
    if known is None:
        known = _read_project(root)
        with _lock:
            _projects[root] = known
    return known


def _read_project(root: str) -> list[tuple[str, FileFrames]]:
    kb = knowledge_base()
    found = []
    for file in _candidate_files(root):
        frames = _frames_of_file(kb, file)
        if frames:
            found.append((file, frames))
    return found


def forget_projects() -> None:
    """Let the next question about each project walk its files again (a long-lived process); a file
    whose size and modification time are unchanged is not read again."""
    with _lock:
        _projects.clear()


def _candidate_files(root: str) -> list[str]:
    files: list[str] = []
    for parent, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(
            name
            for name in dirnames
            if not name.startswith(".") and name not in _SKIPPED_FOLDERS and not _another_tree(os.path.join(parent, name), root)
        )
        # a test's robot descriptions, launch files and nodes describe test set-ups, not the robot
        folder = os.path.relpath(parent, root)
        if any(part in TEST_FOLDERS for part in folder.split(os.sep)):
            continue
        for filename in sorted(filenames):
            if (filename.endswith(".py") and not is_test_module(filename)) or filename.endswith((*URDF_SUFFIXES, *XML_LAUNCH_SUFFIXES, *PARAMETER_FILE_SUFFIXES)):
                files.append(os.path.realpath(os.path.join(parent, filename)))
                if len(files) >= _MAX_FILES:
                    return files
    return files


def _another_tree(folder: str, root: str) -> bool:
    """A ROS package below `root` that belongs to another workspace's tree (a checkout of a workspace
    inside a repository, the fixtures of a test suite)."""
    return os.path.isfile(os.path.join(folder, PACKAGE_MANIFEST)) and _workspace_of_package(folder) != root


_trigger_words: dict[int, tuple[tuple[bytes, ...], re.Pattern[bytes]]] = {}


def _may_state(kb: KnowledgeBase, data: bytes) -> bool:
    """Whether a module's bytes name one of the tf calls or launched executables and import a library
    that has them (a cheap test before it is parsed)."""
    words = _trigger_words.get(id(kb))
    if words is None:
        packages = "|".join(re.escape(package) for package in kb.tf_packages())
        imports = re.compile(rb"^[ \t]*(?:import|from)[ \t]+(?:%s)\b" % packages.encode(), re.MULTILINE)
        words = _trigger_words[id(kb)] = (tuple(word.encode() for word in kb.tf_names()), imports)
    names, imports = words
    return any(word in data for word in names) and imports.search(data) is not None


def _frames_of_file(kb: KnowledgeBase, file: str) -> FileFrames:
    try:
        status = os.stat(file)
    except OSError:
        return FileFrames()
    stamp = (status.st_size, status.st_mtime_ns)
    with _lock:
        known = _file_frames.get(file)
    if known is not None and known[0] == stamp:
        return known[1]
    frames = FileFrames()
    try:
        if file.endswith(".py"):
            if status.st_size <= _MAX_PYTHON_BYTES:
                with open(file, "rb") as stream:
                    data = stream.read()
                if _may_state(kb, data):
                    frames = python_file_frames(file, data.decode("utf-8", errors="replace"))
                elif may_launch(file, data):
                    frames = FileFrames(parameters_set=launch_parameter_keys(ast.parse(data, file)))
        elif file.endswith(PARAMETER_FILE_SUFFIXES):
            with open(file, "rb") as stream:
                frames = FileFrames(parameters_set=yaml_keys(stream.read().decode("utf-8", errors="replace")))
        else:
            with open(file, "rb") as stream:
                frames = xml_frames(kb, file, stream.read().decode("utf-8", errors="replace"))
    except (OSError, SyntaxError, ValueError, RecursionError, MemoryError):
        frames = FileFrames()  # a file that cannot be read states nothing; its own lint reports it
    with _lock:
        _file_frames[file] = (stamp, frames)
    return frames


def python_file_frames(path: str, source: str) -> FileFrames:
    """What a Python module of the project states, read on its own (no cross-module summaries)."""
    from geolint.factbase.index import ModuleIndex
    from geolint.factbase.model import FactBase
    from geolint.lint_types import Config

    tree = ast.parse(source, path)
    facts = FactBase(ModuleIndex(tree, source), Config(), path, cross_module=False)
    try:
        statements = python_statements(facts, path)
    finally:
        facts.close()
    parameters = launch_parameter_keys(tree) if may_launch(path, source.encode("utf-8", errors="replace")) else frozenset()
    return frames_of_statements(statements, parameters)


def frames_of_statements(statements, parameters_set: frozenset[str] = frozenset()) -> FileFrames:  # type: ignore[no-untyped-def]
    published = tuple(found.statement for found in statements if isinstance(found.statement, Published))
    looked_up = tuple(found.statement for found in statements if isinstance(found.statement, LookedUp))
    return FileFrames(published, looked_up, parameters_set)
