"""The project's naming order, learned from its own code: does `T_a_b` map b into a (dst-first,
`T_world_cam @ p_cam`) or a into b (src-first, autolab_core's `T_obj_world`)?

Evidence, strongest first:

- declarations bound to names: `T_obj_world = RigidTransform(R, t, from_frame="obj", to_frame="world")`,
  `T_a_b = X.as_frames("a", "b")`, `T_a_b = buffer.lookup_transform("a", "b", t)`. A name whose frames
  the call states in the name's order votes for that order.
- the internal consistency of compositions: `T_a_b @ T_b_c` only makes sense dst-first,
  `T_b_c * T_a_b` only src-first.

Declarations decide when there are any (both orders declared: mixed); otherwise compositions
decide when one order outnumbers the other more than four to one. Mixed or absent evidence leaves both orders possible, and the
frame rules then report only what is wrong in both readings. `[tool.geolint] naming` overrides.

Which reading is right is one question; whether names are frame evidence at all is another. On real
code, findings that compared two names and nothing else were never right (waypoints, relative
corrections, typos and loose labels read as frames), so names alone count only where the convention
is *stated*: by `naming = "dst-first" | "src-first"`, or by the project's own declarations, all in
one order. Elsewhere a frame finding needs an explicit declaration on one side (`NameReading.stated`).

Boston Dynamics' `a_tform_b` (`odom_tform_body`) is not a guess of this kind: the SDK's convention
says its direction in the name, so such names are read as declarations in every project
(geolint.factbase.bosdyn) and take no part in the votes.

The whole project is read (once per process and project root; files without a declaration or a
composition of `T_` names are skipped by a substring test before any parsing).
"""

from __future__ import annotations

from ast import AnnAssign, Assign, Attribute, Call, Module, Name
import os
import re
import threading
from dataclasses import astuple, dataclass, fields, replace
from pathlib import Path
from typing import Final, Iterator, NamedTuple

from geolint.factbase.index import parse_of_file
from geolint.factbase.declarations import declared_call_frames
from geolint.factbase.fact_types import DST_FIRST, SRC_FIRST
from geolint.factbase.syntax import statements_under
from geolint.factbase.project_files import project_root
from geolint.knowledge import knowledge_base
from geolint.lint_types import Config
from geolint.parsing import parse_module
from geolint.semantic.names import ROTATION_LETTERS, TRANSFORM_LETTERS, NameFrames, is_frame

_ORDER_NAME: Final = re.compile(r"^_*([TRXH])_([A-Za-z][A-Za-z0-9]*)_([A-Za-z][A-Za-z0-9]*)$")
_COMPOSITION: Final = re.compile(
    r"\b(?:self\.)?[TXH]_([A-Za-z][A-Za-z0-9]*)_([A-Za-z][A-Za-z0-9]*)\b(?:\.inverse\(\))?\s*[@*]\s*"
    r"(?:self\.)?[TXH]_([A-Za-z][A-Za-z0-9]*)_([A-Za-z][A-Za-z0-9]*)\b(?!\.inverse|\.inv|\.T\b)"
)
# What every composition above contains from its first operand on: the regex engine scans for its
# leading letters, where `\b(?:self\.)?` makes it try every position (10x faster on files without one).
_COMPOSED_OPERAND: Final = re.compile(r"[TXH]_[A-Za-z][A-Za-z0-9]*_[A-Za-z][A-Za-z0-9]*\b(?:\.inverse\(\))?\s*[@*]")
_DECLARING: Final = ("from_frame", "as_frames", "lookup_transform", "lookupTransform")
_TF2_IMPORT: Final = re.compile(r"^[ \t]*(?:import|from)[ \t]+tf2_(?:ros|py|geometry_msgs|sensor_msgs|kdl)\b", re.MULTILINE)
_MAX_FILES: Final = 20000
_MAX_BYTES: Final = 2_000_000


@dataclass(frozen=True)
class Votes:
    declared_dst: int = 0
    declared_src: int = 0
    composed_dst: int = 0
    composed_src: int = 0
    monogram_modules: int = 0  # modules that import a library named in monogram notation (Drake: `X_WB` read as frames)
    tf2_modules: int = 0  # modules that import tf2 (`ros_packages`: a ROS 1 package's frame ids are tf2's)

    def __add__(self, other: Votes) -> Votes:
        return Votes(
            self.declared_dst + other.declared_dst,
            self.declared_src + other.declared_src,
            self.composed_dst + other.composed_dst,
            self.composed_src + other.composed_src,
            self.monogram_modules + other.monogram_modules,
            self.tf2_modules + other.tf2_modules,
        )

    @property
    def mixed(self) -> bool:
        """Declarations in both orders: a `T_a_b` name alone says nothing in this project."""
        return bool(self.declared_dst and self.declared_src)

    @property
    def stated(self) -> bool:
        """Declarations in one order only: the project states its convention in code."""
        return bool(self.declared_dst) != bool(self.declared_src)

    def orders(self) -> tuple[str, ...]:
        """The readings left open by the evidence."""
        if self.declared_dst or self.declared_src:
            if self.declared_dst and not self.declared_src:
                return (DST_FIRST,)
            if self.declared_src and not self.declared_dst:
                return (SRC_FIRST,)
            return (DST_FIRST, SRC_FIRST)
        # compositions are weaker: a few that read the other way are usually the project's bugs
        if self.composed_dst > 4 * self.composed_src:
            return (DST_FIRST,)
        if self.composed_src > 4 * self.composed_dst:
            return (SRC_FIRST,)
        return (DST_FIRST, SRC_FIRST)


def votes_of_tree(tree: Module) -> Votes:
    """What one module's declarations say about the order of `T_a_b` names."""
    dst = src = 0
    for frames, named in _declarations_bound_to_names(tree):
        for first, second in named:
            if (first, second) == (frames.dst, frames.src):
                dst += 1
            elif (first, second) == (frames.src, frames.dst):
                src += 1
    return Votes(declared_dst=dst, declared_src=src)


def _declarations_bound_to_names(tree: Module) -> Iterator[tuple[NameFrames, list[tuple[str, str]]]]:
    """Each call that declares its frames and is assigned, with those frames and the two frame words
    (lower-cased, in the order written) of each target named like `T_a_b`."""
    for node in statements_under(tree):  # assignments are statements: no expression needs walking
        if not isinstance(node, (Assign, AnnAssign)) or not isinstance(node.value, Call):
            continue
        declared = declared_call_frames(node.value)
        if declared is None:
            continue
        named: list[tuple[str, str]] = []
        for target in node.targets if isinstance(node, Assign) else [node.target]:
            name = target.attr if isinstance(target, Attribute) else target.id if isinstance(target, Name) else None
            match = _ORDER_NAME.match(name or "")
            if match and match.group(1) in TRANSFORM_LETTERS | ROTATION_LETTERS:
                named.append((match.group(2).lower(), match.group(3).lower()))
        yield declared[0], named


def votes_of_text(text: str) -> Votes:
    """What a module's compositions of `T_a_b` names say (inner frames agree in one order only)."""
    dst = src = 0
    if _COMPOSED_OPERAND.search(text) is None:
        return Votes()
    for match in _COMPOSITION.finditer(text):
        a, b, c, d = (group.lower() for group in match.groups())
        if "inverse" in match.group(0):
            continue
        dst_consistent, src_consistent = b == c, a == d
        if dst_consistent and not src_consistent:
            dst += 1
        elif src_consistent and not dst_consistent:
            src += 1
    return Votes(composed_dst=dst, composed_src=src)


def _names_monogram_library(source: str) -> bool:
    """Whether the text names a library whose users name frames in monogram notation (Drake's `X_WB`)."""
    return any(package in source for package in knowledge_base().monogram_packages())


def votes_of_source(source: str, tree: Module | None = None, file: tuple[str, tuple[int, int]] | None = None) -> Votes:
    """What one module's text says; `file` (its path, size and mtime) lets a parse serve its lint too."""
    votes = votes_of_text(source) if "_" in source else Votes()
    if _names_monogram_library(source):
        votes = votes + Votes(monogram_modules=1)
    if "tf2_" in source and _TF2_IMPORT.search(source):
        votes = votes + Votes(tf2_modules=1)
    if any(word in source for word in _DECLARING):
        if tree is None:
            try:
                tree = parse_module(source) if file is None else parse_of_file(file[0], source, file[1])
            except (SyntaxError, ValueError, MemoryError, RecursionError):
                return votes
            if tree is None:
                return votes
        votes = votes + votes_of_tree(tree)
    return votes


_lock = threading.Lock()
_project_votes: dict[Path, Votes] = {}
# file -> (mtime_ns, size, votes): what a file says, reused while its stat is unchanged; a warm run
# gets it from the cache (`remembered_file_votes` / `remember_file_votes`) and reads no file for it
_file_votes: dict[str, tuple[int, int, Votes]] = {}
_files_read = [0]  # how many files were read for their votes in this process


def _is_project(folder: str) -> bool:
    return any(os.path.exists(os.path.join(folder, marker)) for marker in ("pyproject.toml", "setup.py", "setup.cfg"))


def project_votes(root: Path) -> Votes:
    """The votes of every Python file under `root` (cached per process)."""
    with _lock:
        cached = _project_votes.get(root)
    if cached is not None:
        return cached
    total = Votes()
    count = 0
    for folder, dirnames, filenames in os.walk(root):
        dirnames[:] = [
            d
            for d in dirnames
            if not d.startswith(".")
            and d not in ("node_modules", "__pycache__", "build", "dist")
            and not _is_project(os.path.join(folder, d))  # a nested project has its own conventions
        ]
        for filename in filenames:
            if not filename.endswith(".py"):
                continue
            count += 1
            if count > _MAX_FILES:
                break
            total = total + _votes_of_file(os.path.join(folder, filename))
    with _lock:
        _project_votes[root] = total
    return total


def forget_project_totals() -> None:
    """Let the next `project_votes` of each project look at its files again (a long-lived process)."""
    with _lock:
        _project_votes.clear()


def file_votes(path: str) -> Votes:
    """What one file says (read once while its stat is unchanged)."""
    return _votes_of_file(path)


def _votes_of_file(path: str) -> Votes:
    try:
        stat = os.stat(path)
    except OSError:
        return Votes()
    known = _file_votes.get(path)
    if known is not None and known[0] == stat.st_mtime_ns and known[1] == stat.st_size:
        return known[2]
    try:
        with open(path, "rb") as stream:
            data = stream.read(_MAX_BYTES)
    except OSError:
        return Votes()
    text = data.decode("utf-8", errors="replace")
    votes = Votes()
    if _names_monogram_library(text) or "tf2_" in text or "_" in text and ("from_frame" in text or "as_frames" in text or "lookup" in text or "T_" in text or "H_" in text or "X_" in text):
        whole = len(data) < _MAX_BYTES  # a truncated text is not the file's
        votes = votes_of_source(text, file=(path, (stat.st_size, stat.st_mtime_ns)) if whole else None)
    _file_votes[path] = (stat.st_mtime_ns, stat.st_size, votes)
    _files_read[0] += 1
    return votes


def file_votes_read() -> bool:
    """Whether any file had to be read for its votes in this process (else the stored votes all held)."""
    return _files_read[0] > 0


def project_key(path: str) -> str:
    """What the project around `path` says about its names, for the findings cache: a file's findings
    change with a declaration in another file of its project ('' outside a project)."""
    root = project_root(path)
    if root is None:
        return ""
    votes = project_votes(root)  # what the findings read of it, not the counts (an edited composition elsewhere)
    return repr((votes.orders(), votes.mixed, votes.stated, bool(votes.monogram_modules)))


def remembered_file_votes() -> dict[str, list[int]]:
    """Each file's votes as the findings cache stores them: file -> [mtime_ns, size, *votes]."""
    return {file: [mtime, size, *astuple(votes)] for file, (mtime, size, votes) in _file_votes.items()}


def remember_file_votes(stored: dict[str, list[int]]) -> None:
    """Take back what `remembered_file_votes` gave an earlier run (each entry used while the file's
    stat is unchanged)."""
    width = len(fields(Votes))
    for file, entry in stored.items():
        if isinstance(entry, list) and len(entry) == 2 + width and all(type(item) is int for item in entry):
            _file_votes.setdefault(file, (entry[0], entry[1], Votes(*entry[2:])))


class NameReading(NamedTuple):
    """How one file's frame names read."""

    orders: tuple[str, ...]  # the readings of `T_a_b` names left open
    mixed: bool  # both orders declared: a `T_a_b` name alone says nothing
    stated: bool  # the convention is stated (config, or declarations in one order): names alone are evidence
    monogram: bool = False  # the project imports a library named in monogram notation (Drake): `X_WB`, `p_BQ` are frames


def naming_config(config: Config, reading: NameReading) -> Config:
    """`config` with the monogram convention decided for this file: as configured, else on in Drake projects."""
    if config.naming.monogram is not None:
        return config
    key = (id(config), reading.monogram)
    decided = _decided_configs.get(key)
    if decided is None or decided[0] is not config:  # one copy per run's config, not one per file
        decided = _decided_configs[key] = (config, replace(config, naming=replace(config.naming, monogram=reading.monogram)))
    return decided[1]


_decided_configs: dict[tuple[int, bool], tuple[Config, Config]] = {}


def orders_for(path: str, source: str, tree: Module, setting: str = "auto") -> NameReading:
    """How this file's `T_a_b` names read: the config's order, or what the project's code says."""
    root = project_root(path) if os.path.isfile(path) else None
    votes = project_votes(root) if root is not None else votes_of_source(source, tree)
    monogram = bool(votes.monogram_modules) or _names_monogram_library(source)
    if setting == DST_FIRST:
        return NameReading((DST_FIRST,), False, True, monogram)
    if setting == SRC_FIRST:
        return NameReading((SRC_FIRST,), False, True, monogram)
    return NameReading(votes.orders(), votes.mixed, votes.stated, monogram)


def learned_aliases(tree: Module, source: str, orders: tuple[str, ...]) -> dict[str, str]:
    """Frame words a module's names use for its declared frames: `T_ee_rot = RigidTransform(...,
    from_frame='franka_tool', to_frame='franka_tool')` says `ee` is franka_tool (`rot` is no frame).

    Like GEO203 (a declaration bound to a name with other words is a label, not a bug, unless it
    reverses the name), a token paired with a declared frame in every open reading is that frame's
    alias; a token that is itself some declaration's frame, or that pairs with two frames, is none.
    """
    if not any(word in source for word in _DECLARING):
        return {}
    explicit: set[str] = set()
    found: dict[str, set[str]] = {}
    for frames, named in _declarations_bound_to_names(tree):
        explicit.update(frame for frame in (frames.src, frames.dst) if frame is not None)
        for first, second in named:
            readings: set[frozenset[tuple[str, str]]] = set()
            for order in orders:
                dst_token, src_token = (first, second) if order == DST_FIRST else (second, first)
                readings.add(
                    frozenset(
                        (token, frame)
                        for token, frame in ((dst_token, frames.dst), (src_token, frames.src))
                        if frame is not None and token != frame and is_frame(token)
                    )
                )
            if len(readings) != 1:
                continue  # the readings pair the tokens differently: no alias is certain
            for token, frame in readings.pop():
                found.setdefault(token, set()).add(frame)
    return {
        token: next(iter(frames))
        for token, frames in found.items()
        if len(frames) == 1 and token not in explicit and not frames & found.keys()
    }
