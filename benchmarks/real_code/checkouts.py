"""Make a corpus's checkouts from local git mirrors, at the commits its manifest pins.

    python benchmarks/real_code/checkouts.py MIRRORS OUT [--manifest benchmarks/real_code/blind7.toml]

MIRRORS holds one git repository per manifest row, named `<owner>+<repo>` (a bare git directory, a
clone, or a folder whose `repo/` is either, as some snapshot tools leave them). Each becomes
OUT/<owner>+<repo>, a clone of it (full history, for `run.py --history`) with the pinned commit checked
out. Nothing is downloaded; a missing mirror or commit is reported and the others are made. Files a
snapshot lists but does not hold (large binaries) are left out of the work tree. Exit 1 if any failed.
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
from pathlib import Path

from run import HERE, load_manifest  # type: ignore[import-not-found]  # run as a script, beside run.py


def git_dir(mirror: Path) -> Path | None:
    for candidate in (mirror / "repo" / ".git", mirror / "repo", mirror / ".git", mirror):
        if (candidate / "HEAD").is_file() and (candidate / "objects").is_dir():
            return candidate
    return None


def make_checkout(source: Path, target: Path, commit: str) -> str | None:
    """None when `target` is a clone of `source` at `commit`; else what went wrong."""
    if target.exists():
        shutil.rmtree(target)
    done = subprocess.run(["git", "clone", "-q", "--no-checkout", str(source), str(target)], capture_output=True, text=True)
    if done.returncode:
        return f"clone failed: {done.stderr.strip()}"
    if subprocess.run(["git", "-C", str(target), "cat-file", "-e", f"{commit}^{{commit}}"], capture_output=True).returncode:
        return f"pinned commit {commit} not in the mirror"
    # a snapshot may list large files it does not hold: check out the rest (git reports those, and goes on)
    subprocess.run(["git", "-C", str(target), "-c", "advice.detachedHead=false", "checkout", "-q", commit], capture_output=True)
    head = subprocess.run(["git", "-C", str(target), "rev-parse", "HEAD"], capture_output=True, text=True).stdout.strip()
    if head != commit:
        subprocess.run(["git", "-C", str(target), "update-ref", "--no-deref", "HEAD", commit], check=True)
        subprocess.run(["git", "-C", str(target), "reset", "-q", "--", "."], capture_output=True)
        subprocess.run(["git", "-C", str(target), "checkout", "-q", "--", "."], capture_output=True)
    return None


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mirrors", type=Path)
    parser.add_argument("out", type=Path)
    parser.add_argument("--manifest", type=Path, default=HERE / "manifest.toml")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    failed = 0
    for repo in load_manifest(args.manifest):
        source = git_dir(args.mirrors / repo.folder)
        problem = "no mirror" if source is None else make_checkout(source, args.out / repo.folder, repo.commit)
        if problem:
            failed += 1
            print(f"FAILED {repo.name}: {problem}", file=sys.stderr)
        else:
            print(f"ok     {repo.name} {repo.commit[:10]}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
