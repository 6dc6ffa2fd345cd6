"""A repository's geometric fixes, read from its git history, as the statement shapes they fixed.

`git log -p -U0` is read once (newest first, at most `limit` commits, merges left out, renames
followed); every hunk that replaces up to three lines by as many is paired line by line, and a pair
that `fix_edits.fix_shape` calls a geometric fix becomes a `FixedShape`: the statement as it was
before the fix, which no code of the project should still hold. The commit counts as a fix when its
message says so (fix, wrong, bug, flip, order...) or it is small (a few changed lines); a shape that
a later commit changed back, that two commits changed in opposite directions, or whose fixed
statement is no longer in its file at HEAD is dropped: the project's own history disagrees with itself.

What was mined is kept in `<repository>/.geolint_cache/history.json` by the commit it was read up to:
a later run reads only the commits since (`git log OLD..HEAD`), and a rewritten history is read again.
"""

from __future__ import annotations

import ast
import json
import os
import re
import subprocess
import threading
from dataclasses import asdict, dataclass, replace
from typing import Final, Iterator

from geolint.history.fix_edits import SIMPLE_STATEMENTS, fix_shape, parse_statement, shape_key

DEFAULT_LIMIT: Final = 1000
CACHE_VERSION: Final = 1
_MAX_PAIRED_LINES: Final = 3
_MAX_HUNK_LINES: Final = 12
_SMALL_COMMIT_LINES: Final = 6
_FIX_WORDS: Final = re.compile(r"(?i)\b(?:fix\w*|wrong|bug\w*|flip\w*|order|swap\w*|revers\w*|invert\w*|correct\w*|broken|mistake|typo|sign)\b")
_COMMIT: Final = "\x00"
_TIMEOUT_SECONDS: Final = 600


@dataclass(frozen=True)
class FixedShape:
    """A statement shape a commit of the project fixed: `before` became `after` in `path:line`."""

    key: str  # fix_edits.shape_key of `before`
    shape: str  # the kind of fix (fix_edits.fix_shape); '' for an edit that undid such a fix
    before: str
    after: str
    after_key: str
    commit: str
    subject: str
    path: str
    line: int
    imports: tuple[str, ...] = ()  # the top-level modules the fixed file imports at HEAD


@dataclass(frozen=True)
class History:
    """What a repository's history says, and how much of it could be read."""

    shapes: tuple[FixedShape, ...]
    head: str | None  # None: not a git repository (or git is missing)
    shallow: bool = False
    commits_read: int = 0


def git(root: str, *arguments: str) -> str | None:
    """The output of `git -C root ...`, or None when git fails or is missing."""
    try:
        completed = subprocess.run(["git", "-C", root, *arguments], capture_output=True, text=True, errors="replace", timeout=_TIMEOUT_SECONDS)
    except (OSError, subprocess.SubprocessError):
        return None
    return completed.stdout if completed.returncode == 0 else None


_lock = threading.Lock()
_known: dict[tuple[str, int], History] = {}


def history_of(root: str, limit: int = DEFAULT_LIMIT, cache: bool = True, head: str | None = None) -> History:
    """The fixed shapes of the repository at `root` (whose HEAD the caller may know already), read at
    most once per process and HEAD."""
    if head is None:
        asked = git(root, "rev-parse", "HEAD")
        if asked is None:
            return History((), None)
        head = asked.strip()
    with _lock:
        known = _known.get((root, limit))
    if known is not None and known.head == head:
        return known
    found = _read(root, head, limit, cache)
    with _lock:
        _known[(root, limit)] = found
    return found


def _read(root: str, head: str, limit: int, cache: bool) -> History:
    shallow = (git(root, "rev-parse", "--is-shallow-repository") or "").strip() == "true"
    stored = _load(root, limit) if cache else None
    edits: list[FixedShape] = []
    commits = 0
    if stored is not None and stored["head"] == head:
        edits, commits = [_edit(edit) for edit in stored["edits"]], int(stored["commits"])
    elif stored is not None and git(root, "merge-base", "--is-ancestor", stored["head"], head) is not None:
        new, read = _mine(root, f"{stored['head']}..{head}", limit)
        edits = new + [_edit(edit) for edit in stored["edits"]]
        commits = min(limit, read + int(stored["commits"]))
    else:
        edits, commits = _mine(root, head, limit)
    if cache:
        _save(root, limit, {"version": CACHE_VERSION, "geolint": _reader_key(), "head": head, "commits": commits, "edits": [asdict(edit) for edit in edits]})
    return History(_still_fixed(root, _agreed(edits)), head, shallow, commits)


def _edit(stored: dict) -> FixedShape:  # type: ignore[type-arg]
    return FixedShape(**{**stored, "imports": tuple(stored.get("imports", ()))})


def _agreed(edits: list[FixedShape]) -> tuple[FixedShape, ...]:
    """The newest fix of each shape, but none of a shape the history also went back to."""
    reverted = {edit.after_key for edit in edits} & {edit.key for edit in edits}
    found: dict[str, FixedShape] = {}
    for edit in edits:  # newest first
        if edit.shape and edit.key not in reverted and edit.key not in found:
            found[edit.key] = edit
    return tuple(found.values())


def _still_fixed(root: str, shapes: tuple[FixedShape, ...]) -> tuple[FixedShape, ...]:
    """The fixes whose fixed statement is still in their file (one that a later change undid, a revert
    or code restored wholesale, says the project went back on it), with that file's imports."""
    files: dict[str, tuple[set[str], tuple[str, ...]]] = {}
    kept = []
    for shape in shapes:
        if shape.path not in files:
            files[shape.path] = _statements_and_imports(os.path.join(root, shape.path))
        statements, imports = files[shape.path]
        if shape.after_key in statements:
            kept.append(replace(shape, imports=imports))
    return tuple(kept)


def _statements_and_imports(path: str) -> tuple[set[str], tuple[str, ...]]:
    try:
        with open(path, encoding="utf-8", errors="replace") as stream:
            tree = ast.parse(stream.read(), path)
    except (OSError, SyntaxError, ValueError, RecursionError, MemoryError):
        return set(), ()
    return {shape_key(node) for node in ast.walk(tree) if isinstance(node, SIMPLE_STATEMENTS)}, tuple(sorted(imported_modules(tree)))


def imported_modules(tree: ast.AST) -> set[str]:
    """The top-level modules a module imports (absolute imports only)."""
    found: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.update(alias.name.partition(".")[0] for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            found.add(node.module.partition(".")[0])
    return found


def _mine(root: str, revisions: str, limit: int) -> tuple[list[FixedShape], int]:
    text = git(root, "log", "--no-merges", "-M", "--unified=0", "-p", f"--max-count={limit}", "--format=%x00%H%x01%s", revisions, "--", "*.py")
    if text is None:
        return [], 0
    edits: list[FixedShape] = []
    commits = 0
    for commit, subject, hunks in _commits(text):
        commits += 1
        changed = sum(len(removed) + len(added) for _, _, removed, added in hunks)
        says_fix = bool(_FIX_WORDS.search(subject)) or changed <= _SMALL_COMMIT_LINES
        for path, line, removed, added in hunks:
            for old, new, new_line in _paired(removed, added, line):
                before, after = parse_statement(old), parse_statement(new)
                if before is None or after is None:
                    continue
                shape = fix_shape(before, after)
                # an edit that undoes such a fix is kept too (shape ''): it says the project disagrees
                if shape is None and fix_shape(after, before) is None:
                    continue
                if shape is not None and not says_fix:
                    continue  # a large commit that does not say it fixes: a refactor, no evidence either way
                edits.append(FixedShape(shape_key(before), shape or "", old.strip(), new.strip(), shape_key(after), commit, subject, path, new_line))
    return edits, commits


def _paired(removed: list[str], added: list[str], first_line: int) -> Iterator[tuple[str, str, int]]:
    """(old line, new line, its line number) of a hunk's edits: line by line when as many lines of code
    went as came, else each removed assignment with the added one to the same target (a fix that also
    added comments and a conversion after it)."""
    old_code = [text for text in removed if _is_code(text)]
    new_code = [(text, first_line + position) for position, text in enumerate(added) if _is_code(text)]
    if not old_code or len(old_code) > _MAX_PAIRED_LINES or len(new_code) > _MAX_HUNK_LINES:
        return
    if len(old_code) == len(new_code):
        yield from ((old, new, number) for old, (new, number) in zip(old_code, new_code))
        return
    for old in old_code:
        target = _target(old)
        if target is None:
            continue
        for new, number in new_code:
            if _target(new) == target:
                yield old, new, number
                break


def _is_code(text: str) -> bool:
    stripped = text.strip()
    return bool(stripped) and not stripped.startswith("#")


def _target(text: str) -> str | None:
    statement = parse_statement(text)
    if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
        return shape_key(statement.targets[0])
    return None


def _commits(text: str) -> Iterator[tuple[str, str, list[tuple[str, int, list[str], list[str]]]]]:
    """(commit, subject, [(path, first new line, removed lines, added lines)]) of `git log -p -U0`."""
    for block in text.split(_COMMIT)[1:]:
        header, _, body = block.partition("\n")
        commit, _, subject = header.partition("\x01")
        hunks: list[tuple[str, int, list[str], list[str]]] = []
        path = ""
        for line in body.split("\n"):
            if line.startswith("+++ "):
                path = line[6:] if line.startswith("+++ b/") else ""
            elif line.startswith("@@"):
                match = re.match(r"@@ -\d+(?:,\d+)? \+(\d+)(?:,\d+)? @@", line)
                hunks.append((path, int(match.group(1)) if match else 0, [], []))
            elif hunks and path and line.startswith("-") and not line.startswith("--- "):
                hunks[-1][2].append(line[1:])
            elif hunks and path and line.startswith("+"):
                hunks[-1][3].append(line[1:])
        yield commit, subject, hunks


def _cache_file(root: str, limit: int) -> str:
    return os.path.join(root, ".geolint_cache", f"history-{limit}.json")


def _load(root: str, limit: int) -> dict | None:  # type: ignore[type-arg]
    try:
        with open(_cache_file(root, limit), encoding="utf-8") as stream:
            stored = json.load(stream)
    except (OSError, ValueError):
        return None
    if not isinstance(stored, dict) or stored.get("version") != CACHE_VERSION or stored.get("geolint") != _reader_key():
        return None  # another geolint classified these edits
    return stored


def _reader_key() -> str:
    from geolint.cache import package_fingerprint

    return package_fingerprint()


def _save(root: str, limit: int, data: dict) -> None:  # type: ignore[type-arg]
    path = _cache_file(root, limit)
    try:
        os.makedirs(os.path.dirname(path), exist_ok=True)
        ignore = os.path.join(os.path.dirname(path), ".gitignore")
        if not os.path.exists(ignore):
            with open(ignore, "w", encoding="utf-8") as stream:
                stream.write("*\n")
        temporary = f"{path}.{os.getpid()}.tmp"
        with open(temporary, "w", encoding="utf-8") as stream:
            json.dump(data, stream)
        os.replace(temporary, path)
    except OSError:
        pass  # a read-only checkout: the history is read again next time
