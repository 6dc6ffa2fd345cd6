"""Bounded fuzzing of the linter (issue 13): grammar-generated programs (hypothesmith) and mutated real
files (our fixtures). Whatever the input: the CLI exits 0 or 1 with no traceback, every finding's code
is a known one, fixes give code that parses, and fixing again changes nothing.

Bounded: about 40 generated programs in process and one real-CLI run over 240 mutated files, a few tens
of seconds together. Seeds are fixed, so a failure reproduces.
"""

from __future__ import annotations

import ast
import json
import random
import subprocess
import sys
from pathlib import Path

import hypothesmith
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from geolint import api, guards
from geolint.lint_types import Config
from geolint.rules import all_rules

REPO = Path(__file__).resolve().parents[2]
KNOWN_CODES = {rule.code for rule in all_rules()}
# The engine raises the recursion limit on first use; do it before hypothesis records the limit.
guards.make_room_for_recursion(Config())
# Geometry lines spliced into generated programs, so the rules (not only the parser) see them.
GEOMETRY = [
    "p_world = T_world_cam @ p_cam",
    "normal_h = np.append(normal, 1)",
    "p_h = np.append(point, 0)",
    "T_cam_world = T_world_cam.T",
    "q = Rotation.from_quat([q.w, q.x, q.y, q.z])",
    "mid = p_world + q_world",
    "angle = np.sin(90)",
    "n_world = R @ normal + t",
]


def parses(source: str) -> bool:
    try:
        ast.parse(source)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return False
    return True


def check_lint_and_fix(source: str) -> None:
    findings = api.lint_text(source, "fuzzed.py")
    assert {f.code for f in findings} <= KNOWN_CODES
    fixed, _ = api.fix_text(source, "fuzzed.py", unsafe=True)
    if fixed != source:
        assert parses(source), "a file with a syntax error is never rewritten"
        assert parses(fixed), f"the fix broke the code:\n{fixed}"
        assert api.fix_text(fixed, "fuzzed.py", unsafe=True)[0] == fixed, "fixing twice changed the code again"


@settings(
    max_examples=40,
    deadline=None,
    database=None,
    derandomize=True,
    suppress_health_check=list(HealthCheck),
)
@given(program=hypothesmith.from_grammar(), geometry=st.lists(st.sampled_from(GEOMETRY), max_size=3))
def test_generated_programs(program: str, geometry: list[str]) -> None:
    check_lint_and_fix(program)
    spliced = "import numpy as np\n" + "\n".join(geometry) + "\n" + program
    check_lint_and_fix(spliced)


# ---- mutated real files ----------------------------------------------------------------------------

def seed_files() -> list[Path]:
    return sorted((REPO / "fixtures").glob("*.py")) + sorted((REPO / "fixtures" / "clean").glob("*.py"))


def mutate(text: str, rng: random.Random) -> str:
    """One to three random edits of the kinds an editor, a merge or a hostile generator makes."""
    for _ in range(rng.randint(1, 3)):
        lines = text.split("\n")
        where = rng.randrange(len(lines))
        kind = rng.randrange(12)
        if kind == 0:  # delete a slice of characters
            start = rng.randrange(len(text) + 1)
            text = text[:start] + text[start + rng.randint(1, 40) :]
        elif kind == 1:  # duplicate a line, maybe dedented
            lines.insert(where, lines[where].lstrip() if rng.random() < 0.3 else lines[where])
            text = "\n".join(lines)
        elif kind == 2:  # swap two lines
            other = rng.randrange(len(lines))
            lines[where], lines[other] = lines[other], lines[where]
            text = "\n".join(lines)
        elif kind == 3:  # truncate
            text = text[: rng.randrange(len(text) + 1)]
        elif kind == 4:  # odd line endings and characters
            text = text.replace("\n", rng.choice(["\r\n", "\r", "\n\x0c", "\n\u2028"]), rng.randint(1, 50))
        elif kind == 5:  # unbalanced or deep brackets
            opener = rng.choice("([{")
            lines[where] += opener * rng.choice([1, 3, 250, 2500])
            text = "\n".join(lines)
        elif kind == 6:  # a long operator chain
            lines.insert(where, "total = " + " + ".join(f"p{i}_world" for i in range(rng.choice([10, 400, 5000]))))
            text = "\n".join(lines)
        elif kind == 7:  # non-ASCII, emoji and NUL
            start = rng.randrange(len(text) + 1)
            text = text[:start] + rng.choice(["é", "中", "😀", "\x00", "\ufeff", "\t"]) + text[start:]
        elif kind == 8:  # huge or infinite literals
            lines.insert(where, rng.choice(["angle = np.sin(1e999)", "x = " + "9" * 5000, "y = np.cos(1" + "0" * 400 + ")"]))
            text = "\n".join(lines)
        elif kind == 9:  # replace a name with a geometry name
            text = text.replace(rng.choice(["x", "p", "T", "R", "n", "q"]), rng.choice(["T_world_cam", "p_cam", "normal"]), 5)
        elif kind == 10:  # a stray token
            start = rng.randrange(len(text) + 1)
            text = text[:start] + rng.choice([":", "@", "lambda", "elif", ")", "'''", "#", "\\"]) + text[start:]
        else:  # deep indentation
            lines.insert(where, "".join("    " * i + "if a:\n" for i in range(rng.choice([5, 120]))) + "    " * 120 + "pass")
            text = "\n".join(lines)
    return text


def snapshot(root: Path) -> dict[str, bytes]:
    return {str(path.relative_to(root)): path.read_bytes() for path in sorted(root.glob("*.py"))}


def run_cli(root: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "geolint", "check", "--no-cache", "--jobs", "2", *args],
        cwd=root,
        capture_output=True,
        text=True,
        timeout=600,
    )


MUTATED_FILES = 240


@pytest.mark.slow  # the real CLI over many mutated files
def test_mutated_real_files_through_the_cli(tmp_path: Path) -> None:
    rng = random.Random(13)
    seeds = seed_files()
    assert seeds, "no fixtures to mutate"
    root = tmp_path / "fuzzed"
    root.mkdir()
    for index in range(MUTATED_FILES):
        seed = seeds[index % len(seeds)]
        text = mutate(seed.read_text(encoding="utf-8"), rng)
        (root / f"case_{index:03}_{seed.stem}.py").write_bytes(text.encode("utf-8", errors="surrogatepass"))

    result = run_cli(root, "--format", "json")
    assert result.returncode in (0, 1), result.stderr[-3000:]
    assert "Traceback" not in result.stderr and "internal error" not in result.stderr
    findings = json.loads(result.stdout)
    assert {finding["code"] for finding in findings} <= KNOWN_CODES

    before = snapshot(root)
    fixed = run_cli(root, "--fix", "--unsafe-fixes", "-q")
    assert fixed.returncode in (0, 1), fixed.stderr[-3000:]
    assert "Traceback" not in fixed.stderr
    after = snapshot(root)
    for name, data in after.items():
        if data != before[name]:
            assert parses(before[name].decode("utf-8")), f"{name}: a file with a syntax error was rewritten"
            assert parses(data.decode("utf-8")), f"{name}: the fix broke the file"
    again = run_cli(root, "--fix", "--unsafe-fixes", "-q")
    assert again.returncode in (0, 1)
    assert snapshot(root) == after, "a second --fix changed files again"
