"""Peak memory of `geolint check` as a project grows: is it bounded, or does it grow with the project?

Lints growing sets of repositories from the given source trees as one run each, with the real CLI in a subprocess (`--no-cache`, the semantic rules, `--jobs 1` and
`--jobs 2`) and prints the peak resident set size of the geolint processes, read from
`/usr/bin/time -v` when it exists and from `resource.getrusage(RUSAGE_CHILDREN)` otherwise. One
project holding every tree given is the 1M-line case when the real-code and held-out corpora are
both passed.

    python benchmarks/bench_memory.py CORPUS HELDOUT
"""

from __future__ import annotations

import argparse
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def repositories(trees: list[Path]) -> list[Path]:
    return sorted(child for tree in trees for child in tree.iterdir() if child.is_dir() and not child.name.startswith("."))


def count_lines(repository: Path) -> int:
    total = 0
    for path in repository.rglob("*.py"):
        if ".git" in path.parts or not path.is_file():
            continue
        try:
            total += sum(1 for line in path.read_bytes().splitlines() if line.strip())
        except OSError:
            continue
    return total


def lint_peak_rss(roots: list[Path], jobs: int) -> tuple[float, float]:
    """(seconds, peak RSS in MiB of the largest geolint process) for one cold run over all roots."""
    command = [sys.executable, "-m", "geolint", "check", "--no-cache", "--select", "GEO1,GEO2,GEO3", "--jobs", str(jobs), *map(str, roots)]
    project = Path(tempfile.gettempdir())
    time_binary = shutil.which("time") or ("/usr/bin/time" if Path("/usr/bin/time").exists() else None)
    start = time.perf_counter()
    if time_binary is not None:
        result = subprocess.run([time_binary, "-v", *command], cwd=project, capture_output=True, text=True)
        elapsed = time.perf_counter() - start
        match = re.search(r"Maximum resident set size \(kbytes\): (\d+)", result.stderr)
        if match is not None:
            return elapsed, int(match.group(1)) / 1024
    import resource

    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    subprocess.run(command, cwd=project, capture_output=True, text=True)
    elapsed = time.perf_counter() - start
    # ru_maxrss of children is the largest child so far: only meaningful when it grew
    return elapsed, max(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, before) / 1024


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("trees", nargs="+", type=Path, help="folders holding one checkout per repository")
    parser.add_argument("--steps", type=int, default=4, help="project sizes, evenly spaced up to all repositories")
    args = parser.parse_args()
    repos = repositories(args.trees)
    sizes = {repo: count_lines(repo) for repo in repos}
    print(f"{len(repos)} repositories, {sum(sizes.values()):,} non-empty lines; python {sys.version.split()[0]}")
    print(f"{'project lines':>14} {'repos':>6} {'jobs':>5} {'time s':>8} {'peak RSS MiB':>13}")
    for step in range(1, args.steps + 1):
        chosen = repos[: max(1, round(len(repos) * step / args.steps))]
        lines = sum(sizes[repo] for repo in chosen)
        for jobs in (1, 2):
            elapsed, peak = lint_peak_rss(chosen, jobs)
            print(f"{lines:>14,} {len(chosen):>6} {jobs:>5} {elapsed:>8.1f} {peak:>13.0f}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
