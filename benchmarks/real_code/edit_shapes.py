"""Candidate fixed bugs from history, found without geolint: one-line edits shaped like a fix of its classes.

    python benchmarks/real_code/edit_shapes.py MIRROR_DIR [--manifest FILE] [--first N | --skip-first N] [--out FILE]

For each manifest repository (a checkout with history in MIRROR_DIR/<owner>+<repo>), this reads
`git log --all --no-merges -p -U0 -- '*.py'` and keeps the hunks that replace one or two lines by as
many, where the only change is one of the shapes below (a transpose or inverse added or dropped, c2w
swapped for w2c, a degree/radian conversion added or removed, `zeros` swapped for `ones`, a 4-index
permutation changed, quaternion order words changed, components reordered, a bottom-row write moved
to the translation column, a normal's product restricted to the rotation block, the operands of a
product swapped). Every candidate must then be read: most are refactors, and only a commit (or its
issue) that says so, or the algebra, makes one a bug. This is how recall is measured blind
(docs/benchmark.md, "How historical bugs are found and counted"): the search never runs geolint.
"""

from __future__ import annotations

import argparse
import difflib
import json
import re
import subprocess
import sys
from collections import Counter
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import NamedTuple

sys.path.insert(0, str(Path(__file__).resolve().parent))
from run import HERE, load_manifest  # the benchmark's manifest reader

_TRANSPOSE = re.compile(r"\.T\b|\.mT\b|\.t\(\)|\.transpose\([^()]*\)|np\.transpose|torch\.transpose|\.swapaxes\([^()]*\)")
_INVERSE = re.compile(r"np\.linalg\.inv|torch\.linalg\.inv|torch\.inverse|\.inverse\(\)|\binv\b|invertTransform|inverse_matrix|\.inv\(\)|pinv")
_EXTRINSICS_PAIRS = (("c2w", "w2c"), ("cam2world", "world2cam"), ("camera_to_world", "world_to_camera"), ("cam_to_world", "world_to_cam"))
_ANGLE_CONVERSION = re.compile(
    r"radians|deg2rad|rad2deg|degrees|pi\s*/\s*180|180\.?0?\s*/\s*(?:np\.|math\.|torch\.)?pi|/\s*180|\*\s*180|DEG2RAD|RAD2DEG|deg_to_rad|to_rad"
)
_ORDER_WORDS = re.compile(r"wxyz|xyzw|w_last|scalar_first|w_first|scalar_last|np\.roll|torch\.roll")
_FOUR_INDICES = re.compile(r"\[\s*(\d)\s*,\s*(\d)\s*,\s*(\d)\s*,\s*(\d)\s*\]")
_BOTTOM_ROW = re.compile(r"\[\s*(?:\.\.\.\s*,\s*|:\s*,\s*)?3\s*,\s*:\s*3\s*\]")
_TRANSLATION_COLUMN = re.compile(r"\[\s*(?:\.\.\.\s*,\s*|:\s*,\s*)?:\s*3\s*,\s*3\s*\]")
_ROTATION_BLOCK = re.compile(r"\[\s*(?:\.\.\.\s*,\s*|:\s*,\s*)?:\s*3\s*,\s*:\s*3\s*\]")
_PRODUCT = re.compile(r"@|\.dot\(|matmul|multiplyTransforms|\bmul\b|quat_mul|qmul|compose|\*")
_INDEXED = re.compile(r"(\w+)\[(\d)\]")
_TOKEN = re.compile(r"\w+|\S")


def _squeezed(text: str) -> str:
    return re.sub(r"\s+", "", text)


def _similar(old: str, new: str, at_least: float) -> bool:
    return difflib.SequenceMatcher(None, old, new).ratio() > at_least


def _transpose(old: str, new: str) -> bool:
    return _squeezed(_TRANSPOSE.sub("", old)) == _squeezed(_TRANSPOSE.sub("", new)) and len(_TRANSPOSE.findall(old)) != len(_TRANSPOSE.findall(new))


def _inverse(old: str, new: str) -> bool:
    return len(_INVERSE.findall(old)) != len(_INVERSE.findall(new)) and _similar(old, new, 0.6)


def _extrinsics_swap(old: str, new: str) -> bool:
    old, new = old.lower(), new.lower()
    return any((a in old and b in new and b not in old) or (b in old and a in new and a not in old) for a, b in _EXTRINSICS_PAIRS)


def _angle_conversion(old: str, new: str) -> bool:
    return len(_ANGLE_CONVERSION.findall(old)) != len(_ANGLE_CONVERSION.findall(new)) and _similar(old, new, 0.5)


def _homogeneous_pad(old: str, new: str) -> bool:
    return any(a in old and b in new and _squeezed(old.replace(a, b)) == _squeezed(new) for a, b in (("zeros", "ones"), ("ones", "zeros")))


def _permutation(old: str, new: str) -> bool:
    before, after = _FOUR_INDICES.findall(old), _FOUR_INDICES.findall(new)
    return bool(before and after) and before != after and sorted(before[0]) == sorted(after[0])


def _order_words(old: str, new: str) -> bool:
    return bool(_ORDER_WORDS.search(old + new)) and _squeezed(old) != _squeezed(new) and _similar(old, new, 0.6)


def _components_reordered(old: str, new: str) -> bool:
    before, after = _INDEXED.findall(old), _INDEXED.findall(new)
    return len(before) >= 3 and sorted(before) == sorted(after) and before != after


def _bottom_row(old: str, new: str) -> bool:
    return bool((_BOTTOM_ROW.search(old) and _TRANSLATION_COLUMN.search(new)) or (_TRANSLATION_COLUMN.search(old) and _BOTTOM_ROW.search(new)))


def _normal_rotation_only(old: str, new: str) -> bool:
    return "normal" in old.lower() and len(_ROTATION_BLOCK.findall(new)) > len(_ROTATION_BLOCK.findall(old))


def _operands_swapped(old: str, new: str) -> bool:
    before, after = _TOKEN.findall(old), _TOKEN.findall(new)
    return before != after and sorted(before) == sorted(after) and _PRODUCT.search(old) is not None


SHAPES: dict[str, Callable[[str, str], bool]] = {
    "transpose": _transpose,
    "inverse": _inverse,
    "c2w/w2c": _extrinsics_swap,
    "degrees": _angle_conversion,
    "zeros/ones": _homogeneous_pad,
    "quaternion permutation": _permutation,
    "quaternion order words": _order_words,
    "components reordered": _components_reordered,
    "bottom row": _bottom_row,
    "normal rotation only": _normal_rotation_only,
    "operands swapped": _operands_swapped,
}


def shapes_of(old: str, new: str) -> list[str]:
    """The fix shapes the edit of line `old` into line `new` has."""
    return [name for name, test in SHAPES.items() if test(old, new)]


class Candidate(NamedTuple):
    repo: str
    commit: str
    subject: str
    path: str
    old: str
    new: str
    shapes: list[str]


class _Hunk(NamedTuple):
    commit: str
    subject: str
    path: str
    removed: list[str]
    added: list[str]


def _hunks(log: Iterator[str]) -> Iterator[_Hunk]:
    """The hunks of `git log -p -U0 --format='@@COMMIT %H %s'` output, with their commit and file."""
    commit = subject = path = ""
    removed: list[str] = []
    added: list[str] = []
    for line in log:
        line = line.rstrip("\n")
        if line.startswith(("@@COMMIT ", "+++ ", "--- ", "@@")):
            if removed or added:
                yield _Hunk(commit, subject, path, removed, added)
            removed, added = [], []
            if line.startswith("@@COMMIT "):
                commit, _, subject = line[len("@@COMMIT ") :].partition(" ")
            elif line.startswith("+++ "):
                path = line[len("+++ b/") :] if line.startswith("+++ b/") else line[len("+++ ") :]
        elif line.startswith("-"):
            removed.append(line[1:])
        elif line.startswith("+"):
            added.append(line[1:])
    if removed or added:
        yield _Hunk(commit, subject, path, removed, added)


def candidates(checkout: Path, repo: str, skip: frozenset[str] = frozenset()) -> Iterator[Candidate]:
    """Every one- or two-line edit in the history of `checkout` whose change has a fix shape."""
    command = ["git", "-C", str(checkout), "log", "--all", "--no-merges", "-p", "-U0", "--no-color", "--format=@@COMMIT %H %s", "--", "*.py"]
    with subprocess.Popen(command, stdout=subprocess.PIPE, text=True, errors="replace") as process:
        assert process.stdout is not None
        seen: set[tuple[str, str, str]] = set()
        for hunk in _hunks(process.stdout):
            if hunk.commit in skip or not 0 < len(hunk.removed) == len(hunk.added) <= 2:
                continue
            for old, new in zip(hunk.removed, hunk.added):
                key = (hunk.path, _squeezed(old), _squeezed(new))
                if key[1] == key[2] or key in seen:
                    continue
                found = shapes_of(old, new)
                if found:
                    seen.add(key)
                    yield Candidate(repo, hunk.commit, hunk.subject, hunk.path, old.strip(), new.strip(), found)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mirror", type=Path, help="folder holding one checkout with history per manifest entry")
    parser.add_argument("--manifest", type=Path, default=HERE / "manifest.toml")
    parser.add_argument("--skip-first", type=int, default=0, help="leave out the manifest's first N repositories")
    parser.add_argument("--skip-commits", type=Path, help="a file of commit hashes to leave out (one per line)")
    parser.add_argument("--out", type=Path, help="write the candidates as JSON here")
    args = parser.parse_args(argv)
    skip = frozenset(args.skip_commits.read_text().split()) if args.skip_commits else frozenset()
    found: list[Candidate] = []
    for repo in load_manifest(args.manifest)[args.skip_first :]:
        checkout = args.mirror / repo.folder
        if not (checkout / ".git").exists():
            print(f"{repo.name}: no git history at {checkout}", file=sys.stderr)
            continue
        found.extend(candidates(checkout, repo.name, skip))
    for candidate in found:
        print(f"{candidate.repo} {candidate.commit[:10]} {candidate.path}: {', '.join(candidate.shapes)}\n  - {candidate.old}\n  + {candidate.new}")
    counts = Counter(shape for candidate in found for shape in candidate.shapes)
    print(f"{len(found)} candidates to read: " + ", ".join(f"{shape} {count}" for shape, count in counts.most_common()))
    if args.out:
        args.out.write_text(json.dumps([candidate._asdict() for candidate in found], indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
