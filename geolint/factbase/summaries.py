"""Function summaries: what a helper does to its parameters, so call sites in this module and in
the modules that import it know (`to_homogeneous(x)` appends w = 1 to x; `apply_pose(T, x)` rotates
and translates x; `load_normals()` returns directions).

A summary is computed from the helper's own module (parsed and indexed once per process), one level
deep: a summary never consults a third module, so a file's findings depend only on its own text and
the text of the project modules it imports directly. `dependency_digest` hashes exactly that, and
the findings cache keys each file by it: editing a helper re-lints the modules that import it.
"""

from __future__ import annotations

import ast
import hashlib
import os
import re
import threading
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING

from geolint.algebra import FREE, Kind

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

_IMPORT = re.compile(r"^[ \t]*(?:from[ \t]+([.\w]+)[ \t]+import|import[ \t]+([\w.]+))", re.MULTILINE)
# `_IMPORT` at one line start: both its alternatives hold the word "import", so only the lines that
# hold it are tried (the anchored regex alone tries every position of the text).
_IMPORT_AT_LINE_START = re.compile(r"[ \t]*(?:from[ \t]+([.\w]+)[ \t]+import|import[ \t]+([\w.]+))")
_PROJECT_MARKERS = ("pyproject.toml", "setup.py", "setup.cfg", ".git")


@dataclass
class FunctionSummary:
    """What one function does, as far as its own module shows."""

    parameters: tuple[str, ...] = ()
    returns: Kind | None = None  # the kind every `return` agrees on
    # parameter index -> w, when the function returns that parameter made homogeneous
    homogenizes: dict[int, int] = field(default_factory=dict)
    # parameters the function moves by a rotation AND a translation (`R @ x + t`, `T @ [x; 1]`)
    translates: set[int] = field(default_factory=set)


def summarize(facts: FactBase, function: ast.FunctionDef | ast.AsyncFunctionDef) -> FunctionSummary:
    """The summary of a function of `facts`' module."""
    from geolint.factbase.model import transposed_value

    params = tuple(arg.arg for arg in (*function.args.posonlyargs, *function.args.args))
    summary = FunctionSummary(parameters=params)
    scope = facts.index.scopes.get(function)
    if scope is None:
        return summary
    kinds = {facts.kind_of(value) for value in scope.returns}
    if len(kinds) == 1:
        summary.returns = kinds.pop()
    for value in scope.returns:
        homogeneous = facts.homogeneous(value)
        if homogeneous is not None and isinstance(homogeneous.inner, ast.Name) and homogeneous.inner.id in params:
            summary.homogenizes[params.index(homogeneous.inner.id)] = homogeneous.w
    # `R @ x + t` (or row form `x @ R.T + t`) on a parameter x
    from geolint.factbase.model import walk_within

    for node in walk_within(function):
        if not isinstance(node, ast.BinOp) or not isinstance(node.op, ast.Add):
            continue
        for rotated, other in ((node.left, node.right), (node.right, node.left)):
            inner = transposed_value(rotated) or rotated
            product = facts.matmul(inner)
            if product is None or not facts.is_translation_like(other):
                continue
            for operand in (product.left, product.right):
                operand = transposed_value(operand) or operand
                if isinstance(operand, ast.Name) and operand.id in params and facts.kind_of(operand) not in FREE:
                    operator = product.right if operand is product.left else product.left
                    if facts.kind_of(operator) not in (Kind.POINT, Kind.VECTOR, Kind.DIRECTION):
                        summary.translates.add(params.index(operand.id))
    return summary


# --- the project: modules imported by qualified name ------------------------------------------

_lock = threading.Lock()
_modules: dict[tuple[str, int, int, int], object] = {}


def project_root(path: str) -> Path | None:
    return _root_of_folder(_folder_of(path))


@lru_cache(maxsize=4096)
def _root_of_folder(folder: Path) -> Path | None:
    for candidate in (folder, *folder.parents):
        if any((candidate / marker).exists() for marker in _PROJECT_MARKERS):
            return candidate
    return None


def module_file(module: str, importer: str, level: int = 0) -> Path | None:
    """The project file a module name resolves to from `importer` (absolute or relative), or None."""
    return _module_file_from(module, _folder_of(importer), level)


@lru_cache(maxsize=4096)
def _folder_of(path: str) -> Path:
    return Path(os.path.dirname(os.path.abspath(path)))


@lru_cache(maxsize=16384)
def _module_file_from(module: str, here: Path, level: int) -> Path | None:
    parts = [part for part in module.split(".") if part]
    if level:
        base = here
        for _ in range(level - 1):
            base = base.parent
        candidates = [base]
    else:
        root = _root_of_folder(here)
        if root is None:
            return None
        candidates = []
        folder = here
        while True:  # src layouts and scripts next to their package: any folder up to the root
            candidates.append(folder)
            if folder == root or folder.parent == folder:
                break
            folder = folder.parent
    for base in candidates:
        target = base.joinpath(*parts)
        for file in (target.with_suffix(".py"), target / "__init__.py"):
            if parts and file.is_file():
                return file
    return None


def imported_files(path: str, source: str) -> list[Path]:
    """The project files `source` imports directly (by a cheap scan of its import lines)."""
    if not os.path.isfile(path):
        return []
    found = []
    for name in imported_names(source):
        level = len(name) - len(name.lstrip("."))
        file = module_file(name.lstrip("."), path, level)
        if file is not None and file not in found:
            found.append(file)
    return found


def imported_names(source: str) -> list[str]:
    """The module names of the import statements in `source`, exactly as `_IMPORT.finditer` finds them
    (a match never spans lines, so each line start gives at most one)."""
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
        at = source.find("import", at + 6)
    return names


def dependency_digest(path: str, data: bytes, content_hash, hash_of_file=None) -> str:  # type: ignore[no-untyped-def]
    """The file's own hash, combined with the hashes of the project modules it imports directly.

    `hash_of_file(path)` (default: read and hash it) lets a run hash each imported module once.
    """
    own = content_hash(data)
    try:
        source = data.decode("utf-8", errors="replace")
    except Exception:  # noqa: BLE001 - a digest never fails
        return own
    if "import" not in source:
        return own
    files = imported_files(path, source)
    if not files:
        return own
    digest = hashlib.blake2b(own.encode(), digest_size=16)
    for file in sorted(files):
        try:
            digest.update((hash_of_file(file) if hash_of_file else content_hash(file.read_bytes())).encode())
        except OSError:
            digest.update(b"-")
    return digest.hexdigest()


def external_facts(file: Path, config) -> FactBase | None:  # type: ignore[no-untyped-def]
    """The fact base of another project module (cached per process by path, size and mtime)."""
    from geolint.factbase.index import ModuleIndex
    from geolint.factbase.model import FactBase

    try:
        stat = file.stat()
    except OSError:
        return None
    key = (str(file), stat.st_size, stat.st_mtime_ns, hash(config))
    with _lock:
        cached = _modules.get(key)
    if cached is None:
        try:
            source = file.read_bytes().decode("utf-8", errors="replace")
            tree = ast.parse(source)
            cached = FactBase(ModuleIndex(tree, source), config, str(file), cross_module=False)
        except (SyntaxError, ValueError, MemoryError, RecursionError, OSError):
            cached = False  # type: ignore[assignment]
        with _lock:
            if len(_modules) > 512:
                _modules.clear()
            _modules[key] = cached
    return cached or None  # type: ignore[return-value]
