"""`geolint check --diff` prints a patch that `git apply` and `patch` apply cleanly, giving exactly
the bytes `--fix` writes (issue 13, "Fixes and diffs").

The corpus is generated: every combination of line ending (LF, CRLF, CR-only), final newline or
not, BOM, latin-1 with a coding cookie, non-ASCII text on and around the fixed lines, and form
feeds, each file holding fixes of the real rules between lines the fixes must not touch.
"""

from __future__ import annotations

import itertools
import random
import shutil
import subprocess
from pathlib import Path

import pytest

# Lines the real rules fix (GEO101: a direction given w = 1; GEO102: a point given w = 0).
FIXABLE = [
    "normal_h = np.append(normal, 1)",
    "p_h = np.append(point, 0)",
    "n_h = np.append(surface_normal, 1)  # normale à la surface",
]
UNTOUCHED = [
    "x = compute(1)",
    "label = 'señal – ß'",
    "# comment with é and 中文",
    "\x0c",
    "def f(a):\n    return a",
    "y = [1,\n     2]",
]
ENDINGS = {"lf": "\n", "crlf": "\r\n", "cr": "\r"}


def corpus_file(rng: random.Random, ending: str, final_newline: bool, encoding: str) -> bytes:
    lines = ["# -*- coding: latin-1 -*-"] if encoding == "latin-1" else []
    lines.append("import numpy as np")
    for _ in range(rng.randint(3, 12)):
        lines.append(rng.choice(FIXABLE if rng.random() < 0.35 else UNTOUCHED))
    lines.append(rng.choice(FIXABLE))  # at least one fix, sometimes on the last line
    if rng.random() < 0.5:
        lines.append(rng.choice(UNTOUCHED))
    text = ENDINGS[ending].join(line.replace("\n", ENDINGS[ending]) for line in lines)
    if final_newline:
        text += ENDINGS[ending]
    if encoding == "latin-1":
        text = text.replace("中文", "ü").replace("–", "-")  # stay inside latin-1
    return text.encode(encoding)


def build_corpus(root: Path, seed: int = 13) -> list[Path]:
    rng = random.Random(seed)
    paths = []
    for index, (ending, final_newline, encoding) in enumerate(
        itertools.product(ENDINGS, (True, False), ("utf-8", "utf-8-sig", "latin-1"))
    ):
        for copy in range(3):
            path = root / f"pkg_{ending}" / f"m{index}_{copy}_{encoding.replace('-', '')}.py"
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_bytes(corpus_file(rng, ending, final_newline, encoding))
            paths.append(path)
    return paths


def snapshot(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*.py"))}


@pytest.mark.skipif(shutil.which("patch") is None or shutil.which("git") is None, reason="needs patch and git")
def test_diff_applies_with_git_apply_and_patch_and_equals_fix(cli_real, tmp_path):
    paths = build_corpus(cli_real.project)
    original = snapshot(cli_real.project)
    diff = subprocess.run(
        [*_cli_command(cli_real), "check", "--diff", "--unsafe-fixes", "--no-cache"], cwd=cli_real.project, capture_output=True
    )
    assert diff.returncode == 1, diff.stderr.decode(errors="replace")
    assert snapshot(cli_real.project) == original, "--diff must not change any file"
    patch_text = diff.stdout
    (tmp_path / "fixes.patch").write_bytes(patch_text)

    with_git = tmp_path / "git"
    with_patch = tmp_path / "patch"
    for copy in (with_git, with_patch):
        shutil.copytree(cli_real.project, copy)
    git = subprocess.run(["git", "apply", "--whitespace=nowarn", str(tmp_path / "fixes.patch")], cwd=with_git, capture_output=True)
    assert git.returncode == 0, git.stderr.decode(errors="replace")
    patched = subprocess.run(
        ["patch", "-p1", "--forward", "-i", str(tmp_path / "fixes.patch")], cwd=with_patch, capture_output=True
    )
    assert patched.returncode == 0, patched.stdout.decode(errors="replace") + patched.stderr.decode(errors="replace")

    fixed = cli_real("check", "--fix", "--unsafe-fixes", "--no-cache")
    assert fixed.returncode in (0, 1), fixed.stderr
    after_fix = snapshot(cli_real.project)
    changed = [name for name in original if after_fix[name] != original[name]]
    assert len(changed) == len(paths), "every corpus file has a fix"
    assert snapshot(with_git) == after_fix
    assert snapshot(with_patch) == after_fix
    assert patch_text.count(b"\\ No newline at end of file") >= 1


def test_diff_of_a_file_without_final_newline_ends_with_the_marker(cli_real):
    (cli_real.project / "tail.py").write_bytes(b"import numpy as np\r\nnormal_h = np.append(normal, 1)")
    diff = subprocess.run([*_cli_command(cli_real), "check", "--diff", "--unsafe-fixes", "--no-cache"], cwd=cli_real.project, capture_output=True)
    assert diff.stdout.endswith(b"+normal_h = np.append(normal, 0)\n\\ No newline at end of file\n")
    assert b"-import" not in diff.stdout  # the CRLF line before it is context, unchanged


def _cli_command(runner) -> list[str]:
    """The argv `cli_real` runs, for calls that need bytes on stdout."""
    import sys

    return [sys.executable, "-m", "geolint"]
