"""Linter throughput on a real source tree, side by side in one run (medians of repeats).

Prints lines/s for (each repeat a round that measures every row once, so drift hits all alike): the `ast.parse` floor (read + decode + parse every file, one process),
geolint cold with 1 job and with 2 jobs (`--no-cache`), geolint warm (an unchanged tree, served
from the cache), `ruff check --select ALL --no-cache`, and optionally `fixit lint` with its
built-in rules. Every geolint, ruff and fixit figure is a real CLI run in a subprocess, start-up
included; geolint runs with the semantic rules only (`--select GEO1,GEO2,GEO3`), as the real-code
benchmark does, with geolint's bytecode compiled first (as a wheel install leaves it).

    python benchmarks/bench_lint.py CORPUS --repeats 3 --skip-fixit   # the real-code corpus
    python benchmarks/bench_lint.py                      # the installed numpy source tree
    python benchmarks/bench_lint.py PATH --repeats 3 --fixit-repeats 1
    python benchmarks/bench_lint.py CORPUS --repeats 3 --skip-fixit --compiled   # + the mypyc build

`--compiled` builds this checkout's optional compiled wheel first (`GEOLINT_MYPYC=1 pip wheel
--no-build-isolation`, a few minutes, not timed; needs mypy and a C compiler) and adds its cold rows
(`--compiled-site DIR` reuses an unpacked one).
"""

from __future__ import annotations

import argparse
import ast
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import zipfile
from pathlib import Path
from typing import Callable


def default_tree() -> Path:
    import numpy

    return Path(numpy.__file__).resolve().parent


def python_files(tree: Path) -> list[Path]:
    """The files geolint itself lints there (same discovery, same excludes)."""
    from geolint.files import discover
    from geolint.lint_types import Config

    # a link to nothing is skipped by geolint with a warning, and not read here either
    return [source.path for source in discover([tree], Config()) if source.path.is_file()]


def count_lines(files: list[Path]) -> int:
    return sum(path.read_bytes().count(b"\n") for path in files)


def time_ast_floor(files: list[Path]) -> tuple[float, float]:
    """(wall seconds, CPU seconds) to read, decode and parse every file in this process."""
    from geolint.engine import decode_source

    start, cpu = time.perf_counter(), time.process_time()
    for path in files:
        try:
            ast.parse(decode_source(path.read_bytes())[0])
        except (SyntaxError, ValueError, UnicodeDecodeError):
            pass
    return time.perf_counter() - start, time.process_time() - cpu


def time_command(command: list[str], cwd: Path, env: dict[str, str]) -> tuple[float, float]:
    """(wall seconds, CPU seconds of the command and its worker processes)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    result = subprocess.run(command, cwd=cwd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    elapsed = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if result.returncode not in (0, 1):
        raise SystemExit(f"{' '.join(command)} failed ({result.returncode}):\n{result.stderr[-2000:]}")
    return elapsed, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def medians(runs: list[tuple[float, float]]) -> tuple[float, float]:
    """Medians of wall and CPU seconds (on a shared machine, CPU time is the steadier of the two)."""
    return statistics.median(run[0] for run in runs), statistics.median(run[1] for run in runs)


def main() -> int:
    sys.stdout.reconfigure(line_buffering=True)  # progress shows up when piped to a file
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("tree", nargs="?", type=Path, default=None, help="source tree (default: installed numpy)")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--fixit-repeats", type=int, default=1)
    parser.add_argument("--skip-fixit", action="store_true")
    parser.add_argument("--compiled", action="store_true", help="also time the mypyc-compiled build (built first)")
    parser.add_argument("--compiled-site", type=Path, default=None, help="an unpacked compiled wheel to time")
    args = parser.parse_args()

    tree = (args.tree or default_tree()).resolve()
    files = python_files(tree)
    lines = count_lines(files)
    jobs = os.cpu_count() or 1
    workdir = Path(tempfile.mkdtemp(prefix="geolint-bench-"))  # no pyproject: default config
    env = {key: value for key, value in os.environ.items() if key not in ("NO_COLOR", "CI")}
    env["GEOLINT_CACHE_DIR"] = str(workdir / "cache")
    geolint = [
        sys.executable, "-m", "geolint", "check", str(tree), "--exit-zero", "--quiet", "--format", "json",
        "--select", "GEO1,GEO2,GEO3",
    ]  # fmt: skip

    # Byte-compile geolint as `pip install` does for a wheel: with PYTHONDONTWRITEBYTECODE set (as on
    # this machine) an editable checkout would otherwise recompile every module at each start.
    import geolint as package

    subprocess.run([sys.executable, "-m", "compileall", "-q", str(Path(package.__file__).parent)], check=True, stdout=subprocess.DEVNULL)
    print(f"tree: {tree}")
    print(f"files: {len(files)}, lines: {lines}, cores: {jobs}, repeats: {args.repeats} (fixit: {args.fixit_repeats})")
    print(f"date: {time.strftime('%Y-%m-%d %H:%M')} (figures are medians; a shared machine adds noise)")
    print(f"load average at start: {' '.join(f'{value:.2f}' for value in os.getloadavg())}")
    # Each repeat is a round that measures every row once, in the same order: on a machine whose speed
    # drifts (a shared VM's did by 40% within an hour), drift then moves every row alike and the ratios
    # between rows, the figures that count, stay put; medians are taken over the rounds.
    measures: dict[str, Callable[[], tuple[float, float]]] = {
        "ast.parse floor (1 process)": lambda: time_ast_floor(files),
        "geolint cold, --jobs 1": lambda: time_command([*geolint, "--no-cache", "--jobs", "1"], workdir, env),
        "geolint cold, --jobs 2": lambda: time_command([*geolint, "--no-cache", "--jobs", "2"], workdir, env),
        "geolint warm (cache)": lambda: time_command(geolint, workdir, env),
    }
    compiled_site = args.compiled_site or (build_compiled(workdir) if args.compiled else None)
    if compiled_site is not None:
        compiled_env = {**env, "PYTHONPATH": str(compiled_site)}
        version = subprocess.run([sys.executable, "-m", "geolint", "--version"], env=compiled_env, cwd=workdir, capture_output=True, text=True).stdout
        assert "(compiled)" in version, f"{compiled_site} holds no compiled build: {version}"
        measures["geolint cold, --jobs 1, compiled"] = lambda: time_command([*geolint, "--no-cache", "--jobs", "1"], workdir, compiled_env)
        measures["geolint cold, --jobs 2, compiled"] = lambda: time_command([*geolint, "--no-cache", "--jobs", "2"], workdir, compiled_env)
    shutil.rmtree(workdir / "cache", ignore_errors=True)
    time_command(geolint, workdir, env)  # fill the cache (the cold rows run with --no-cache: they leave it alone)
    ruff = shutil.which("ruff", path=str(Path(sys.executable).parent)) or shutil.which("ruff")
    if ruff is None:
        print("ruff: not installed (pip install ruff), skipped")
    else:
        ruff_command = [ruff, "check", "--select", "ALL", "--no-cache", "--exit-zero", "--quiet", "--isolated", str(tree)]
        measures["ruff check --select ALL"] = lambda: time_command(ruff_command, workdir, env)
    runs: dict[str, list[tuple[float, float]]] = {label: [] for label in measures}
    for round_number in range(1, args.repeats + 1):
        for label, measure in measures.items():
            runs[label].append(measure())
        print(f"round {round_number}: " + ", ".join(f"{label.split(' (')[0]} {runs[label][-1][0]:.1f} s" for label in measures))
    rows: list[tuple[str, tuple[float, float]]] = [(label, medians(runs[label])) for label in measures]
    if not args.skip_fixit:
        fixit = shutil.which("fixit", path=str(Path(sys.executable).parent)) or shutil.which("fixit")
        if fixit is None:
            print("fixit: not installed, skipped")
        else:
            rows.append(("fixit lint (built-in rules)", medians([time_command([fixit, "lint", str(tree)], workdir, env) for _ in range(args.fixit_repeats)])))

    print(f"{'':32} {'wall s':>8} {'lines/s':>10} {'CPU s':>8} {'lines/CPU s':>12}")
    for label, (wall, cpu) in rows:
        print(f"{label:32} {wall:8.2f} {lines / wall:10.0f} {cpu:8.2f} {lines / cpu:12.0f}")
    by_label = dict(rows)
    cold, cold_cpu = by_label["geolint cold, --jobs 1"]
    parse, parse_cpu = by_label["ast.parse floor (1 process)"]
    warm, warm_cpu = by_label["geolint warm (cache)"]
    print(f"warm / cold(jobs 1): {warm / cold:.1%} wall, {warm_cpu / cold_cpu:.1%} CPU")
    print(f"cold(jobs 1) / ast.parse: {cold / parse:.1f}x wall, {cold_cpu / parse_cpu:.1f}x CPU")
    print(f"jobs 2 speed-up over jobs 1 (wall): {cold / by_label['geolint cold, --jobs 2'][0]:.2f}x")
    # the same ratios within each round (drift between rounds cancels), and their medians
    parse_ratios = [c[0] / p[0] for c, p in zip(runs["geolint cold, --jobs 1"], runs["ast.parse floor (1 process)"])]
    jobs_ratios = [one[0] / two[0] for one, two in zip(runs["geolint cold, --jobs 1"], runs["geolint cold, --jobs 2"])]
    print(f"per round, cold(jobs 1) / ast.parse: {', '.join(f'{r:.2f}x' for r in parse_ratios)} (median {statistics.median(parse_ratios):.2f}x)")
    print(f"per round, jobs 2 speed-up: {', '.join(f'{r:.2f}x' for r in jobs_ratios)} (median {statistics.median(jobs_ratios):.2f}x)")
    if "geolint cold, --jobs 1, compiled" in runs:
        compiled_ratios = [c[0] / p[0] for c, p in zip(runs["geolint cold, --jobs 1, compiled"], runs["ast.parse floor (1 process)"])]
        speedups = [p[0] / c[0] for c, p in zip(runs["geolint cold, --jobs 1, compiled"], runs["geolint cold, --jobs 1"])]
        print(f"per round, compiled cold(jobs 1) / ast.parse: {', '.join(f'{r:.2f}x' for r in compiled_ratios)} (median {statistics.median(compiled_ratios):.2f}x)")
        print(f"per round, compiled speed-up over pure (jobs 1): {', '.join(f'{r:.2f}x' for r in speedups)} (median {statistics.median(speedups):.2f}x)")
    if "fixit lint (built-in rules)" in by_label:
        print(f"geolint cold (jobs 1) vs fixit: {by_label['fixit lint (built-in rules)'][0] / cold:.1f}x faster")
    print(f"load average at end: {' '.join(f'{value:.2f}' for value in os.getloadavg())}")
    shutil.rmtree(workdir, ignore_errors=True)
    return 0


def build_compiled(workdir: Path) -> Path:
    """Build this checkout's compiled wheel (GEOLINT_MYPYC=1) and unpack it; the unpacked folder."""
    project = Path(__file__).resolve().parents[1]
    wheels, site = workdir / "wheel", workdir / "compiled"
    print("building the compiled wheel (not timed) ...")
    subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "-q", "--no-build-isolation", "--no-deps", "-w", str(wheels), str(project)],
        check=True, env={**os.environ, "GEOLINT_MYPYC": "1"}, stdout=subprocess.DEVNULL,
    )  # fmt: skip
    with zipfile.ZipFile(next(wheels.glob("*.whl"))) as wheel:
        wheel.extractall(site)
    return site


if __name__ == "__main__":
    sys.exit(main())
