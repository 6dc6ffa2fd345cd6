"""The real-code benchmark: lint public robotics repositories and compare with the triaged ledger.

    python benchmarks/real_code/run.py MIRROR_DIR                 # lint, compare with ledger.toml
    python benchmarks/real_code/run.py MIRROR_DIR --history       # mine history for fixed bugs
    python benchmarks/real_code/run.py MIRROR_DIR --throughput    # geolint -j1/-j2 vs ruff vs ast.parse

MIRROR_DIR holds one checkout per manifest entry, named `<owner>+<repo>` (made beforehand; this
script never downloads anything). `--history` also needs each checkout's git history: a `.git`
directory or a `.git` file (`gitdir: ...`) in the checkout.

The ledger keys a finding by (repository, path, code, hash of the flagged expression with whitespace,
quote style and trailing commas normalised away), so a finding that only moved lines still matches
its verdict. A checkout whose HEAD is not the manifest's commit is linted with a warning. Exit status:
0 unless something went wrong (a missing checkout, a file geolint failed on); findings are data.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections import Counter, defaultdict
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

HERE = Path(__file__).resolve().parent
DEFAULT_SELECT = ("GEO1", "GEO2", "GEO3")
VERDICTS = ("TP", "FP", "unclear")


# --------------------------------------------------------------------------- manifest and ledger


@dataclass(frozen=True)
class Repo:
    name: str
    url: str
    commit: str
    category: str
    torch: bool

    @property
    def folder(self) -> str:
        return self.name.replace("/", "+")


def load_manifest(path: Path) -> list[Repo]:
    data = tomllib.loads(path.read_text())
    return [Repo(r["name"], r["url"], r["commit"], r["category"], bool(r["torch"])) for r in data.get("repo", [])]


@dataclass
class Entry:
    """One triaged finding: where it was seen, and the verdict with its reason."""

    repo: str
    commit: str
    path: str
    line: int
    code: str
    expr_hash: str
    verdict: str
    reason: str


@dataclass
class HistoryBug:
    """A real bug of geolint's classes that upstream fixed, and whether geolint flags it before the fix."""

    repo: str
    fix_commit: str
    path: str
    line: int  # in the pre-fix file
    bug_class: str  # the GEO code it belongs to
    caught: bool
    how_found: str  # "lint-diff" (the fix removed a finding) or "log-search" (found by reading the log)
    reason: str
    issue: str = ""
    expr_hash: str = ""


@dataclass
class Ledger:
    findings: list[Entry] = field(default_factory=list)
    history: list[HistoryBug] = field(default_factory=list)


def load_ledger(path: Path) -> Ledger:
    if not path.exists():
        return Ledger()
    data = tomllib.loads(path.read_text())
    findings = [Entry(**row) for row in data.get("finding", [])]
    for entry in findings:
        if entry.verdict not in VERDICTS:
            raise ValueError(f"{path}: verdict {entry.verdict!r} of {entry.repo}:{entry.path}:{entry.line} is not one of {VERDICTS}")
    history = [HistoryBug(**row) for row in data.get("history", [])]
    return Ledger(findings, history)


def _toml_value(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    return json.dumps(str(value), ensure_ascii=False)  # a JSON string is a valid TOML basic string


def dump_ledger(ledger: Ledger, path: Path) -> None:
    lines = [
        "# Every finding of the real-code benchmark with its verdict, and the historical bugs found by",
        "# mining. Matched by (repo, path, code, expr_hash); `line` and `commit` say where it was triaged.",
        "",
    ]
    for table, rows in (("finding", ledger.findings), ("history", ledger.history)):
        for row in sorted(rows, key=lambda r: (r.repo.lower(), r.path, r.line, getattr(r, "code", ""))):
            lines.append(f"[[{table}]]")
            lines += [f"{key} = {_toml_value(value)}" for key, value in vars(row).items()]
            lines.append("")
    path.write_text("\n".join(lines))


def normalised_expression(source_lines: list[str], line: int, column: int, end_line: int, end_column: int) -> str:
    """The flagged source text (1-based lines and columns, end exclusive), whitespace, quote style and
    trailing commas normalised away."""
    if line < 1 or end_line > len(source_lines):
        return ""
    if line == end_line:
        text = source_lines[line - 1][column - 1 : end_column - 1]
    else:
        parts = [source_lines[line - 1][column - 1 :]]
        parts += source_lines[line : end_line - 1]
        parts.append(source_lines[end_line - 1][: end_column - 1])
        text = "\n".join(parts)
    # Formatting changes (black's quotes and magic trailing commas) must not look like a changed expression.
    text = re.sub(r"\s+", "", text).replace("'", '"')
    return re.sub(r",([)\]}])", r"\1", text)


def expression_hash(expr: str) -> str:
    return hashlib.sha1(expr.encode()).hexdigest()[:12]


@dataclass(frozen=True)
class Seen:
    """A finding of this run, keyed for the ledger."""

    repo: str
    path: str
    line: int
    code: str
    expr: str
    message: str

    @property
    def key(self) -> tuple[str, str, str, str]:
        return (self.repo, self.path, self.code, expression_hash(self.expr))


def match(seen: list[Seen], ledger: list[Entry]) -> tuple[list[tuple[Seen, Entry]], list[Seen], list[Entry]]:
    """Pair findings with ledger rows by key (the nearest line first when a key repeats).

    Returns (matched pairs, new findings, gone ledger rows)."""
    by_key: dict[tuple[str, str, str, str], list[Entry]] = defaultdict(list)
    for entry in ledger:
        by_key[(entry.repo, entry.path, entry.code, entry.expr_hash)].append(entry)
    matched: list[tuple[Seen, Entry]] = []
    new: list[Seen] = []
    for finding in sorted(seen, key=lambda f: (f.repo, f.path, f.line)):
        candidates = by_key.get(finding.key)
        if not candidates:
            new.append(finding)
            continue
        best = min(candidates, key=lambda e: abs(e.line - finding.line))
        candidates.remove(best)
        matched.append((finding, best))
    gone = [entry for rows in by_key.values() for entry in rows]
    return matched, new, gone


# --------------------------------------------------------------------------- linting


def geolint_config(select: tuple[str, ...], own_fixes: bool = False):
    from geolint.lint_types import Config

    return Config(select=select, history=own_fixes)


def non_empty_lines(text: str) -> int:
    return sum(1 for line in text.splitlines() if line.strip())


@dataclass
class RepoRun:
    repo: Repo
    files: int = 0
    lines: int = 0
    seconds: float = 0.0
    findings: list[Seen] = field(default_factory=list)
    errors: list[str] = field(default_factory=list)


def lint_repo(repo: Repo, checkout: Path, select: tuple[str, ...], jobs: int, own_fixes: bool = False) -> RepoRun:
    from geolint import api

    run = RepoRun(repo)
    started = time.perf_counter()
    results = list(api.lint_paths([checkout], geolint_config(select, own_fixes), jobs=jobs, use_cache=False))
    run.seconds = time.perf_counter() - started
    for result in results:
        location = result.location or Path(result.path)
        if result.unreadable:  # a link to a build product, say: geolint skipped it, and so does the count
            if not result.broken_link:
                run.errors.append(f"{location}: {result.error}")
            continue
        text = location.read_text(encoding="utf-8", errors="replace")
        relative = location.resolve().relative_to(checkout.resolve()).as_posix()
        run.files += 1
        run.lines += non_empty_lines(text)
        if result.error:
            run.errors.append(f"{relative}: {result.error.strip().splitlines()[-1]}")
        if not result.findings:
            continue
        source_lines = text.splitlines()
        for f in result.findings:
            if f.code == "GEO000":  # a file the repository itself cannot parse (Python 2): not a finding
                continue
            expr = normalised_expression(source_lines, f.line, f.column, f.end_line, f.end_column)
            run.findings.append(Seen(repo.name, relative, f.line, f.code, expr, f.message))
    return run


def compare(args: argparse.Namespace) -> int:
    repos = selected_repos(args)
    ledger = load_ledger(args.ledger)
    select = tuple(args.select.split(","))
    status = 0
    rows = []
    all_new: list[Seen] = []
    all_gone: list[Entry] = []
    header = f"{'repository':40} {'files':>6} {'lines':>7} {'find':>5} {'TP':>4} {'FP':>4} {'uncl':>4} {'new':>4} {'gone':>4} {'time s':>7} {'lines/s':>8}"
    print(header)
    for repo in repos:
        checkout = args.mirror / repo.folder
        if not checkout.is_dir():
            print(f"{repo.name}: no checkout at {checkout}", file=sys.stderr)
            status = 2
            continue
        warn_if_not_pinned(repo, checkout)
        run = lint_repo(repo, checkout, select, args.jobs, args.own_fixes)
        for error in run.errors:
            print(f"{repo.name}: geolint failed on {error}", file=sys.stderr)
            status = 2
        matched, new, gone = match(run.findings, [e for e in ledger.findings if e.repo == repo.name])
        verdicts = Counter(entry.verdict for _, entry in matched)
        rows.append((repo, run, verdicts, len(new), len(gone)))
        all_new += new
        all_gone += gone
        print(
            f"{repo.name:40} {run.files:6d} {run.lines:7d} {len(run.findings):5d} {verdicts['TP']:4d} {verdicts['FP']:4d}"
            f" {verdicts['unclear']:4d} {len(new):4d} {len(gone):4d} {run.seconds:7.1f} {run.lines / max(run.seconds, 1e-9):8.0f}",
            flush=True,
        )
    total = Counter()
    for _, run, verdicts, new_count, gone_count in rows:
        total.update(files=run.files, lines=run.lines, findings=len(run.findings), new=new_count, gone=gone_count)
        total.update(verdicts)
    seconds = sum(run.seconds for _, run, *_ in rows)
    print("-" * len(header))
    print(
        f"{'total (' + str(len(rows)) + ' repositories)':40} {total['files']:6d} {total['lines']:7d} {total['findings']:5d}"
        f" {total['TP']:4d} {total['FP']:4d} {total['unclear']:4d} {total['new']:4d} {total['gone']:4d}"
        f" {seconds:7.1f} {total['lines'] / max(seconds, 1e-9):8.0f}"
    )
    judged = total["TP"] + total["FP"]
    precision = f"{100 * total['TP'] / judged:.1f} %" if judged else "n/a (no judged finding)"
    print(f"precision TP / (TP + FP) = {total['TP']} / {judged} = {precision}; {total['new']} new finding(s) need a verdict")
    if args.markdown:
        write_markdown(args.markdown, rows, total, seconds)
    for finding in all_new:
        print(f"  NEW {finding.repo}:{finding.path}:{finding.line}: {finding.code} {finding.message}")
        if args.context:
            source = (args.mirror / finding.repo.replace("/", "+") / finding.path).read_text(encoding="utf-8", errors="replace").splitlines()
            for number in range(max(1, finding.line - args.context), min(len(source), finding.line + args.context) + 1):
                print(f"      {'>' if number == finding.line else ' '}{number:5d} | {source[number - 1]}")
    for entry in all_gone:
        print(f"  GONE {entry.repo}:{entry.path}:{entry.line}: {entry.code} ({entry.verdict}) {entry.reason}")
    if args.record_new:
        ledger.findings += [
            Entry(f.repo, repo_commit(repos, f.repo), f.path, f.line, f.code, expression_hash(f.expr), "unclear", "untriaged: " + f.message)
            for f in all_new
        ]
        dump_ledger(ledger, args.ledger)
        print(f"recorded {len(all_new)} new finding(s) in {args.ledger} as 'unclear' (untriaged)")
    return status


def write_markdown(path: str, rows: list, total: Counter, seconds: float) -> None:
    """The per-repository table of a run, in Markdown."""
    lines = [
        "| repository | category | torch | commit | files | lines | findings | TP | FP | unclear |",
        "|---|---|---|---|---:|---:|---:|---:|---:|---:|",
    ]
    for repo, run, verdicts, _, _ in rows:
        lines.append(
            f"| [{repo.name}]({repo.url}) | {repo.category} | {'yes' if repo.torch else 'no'} | `{repo.commit[:10]}` |"
            f" {run.files:,} | {run.lines:,} | {len(run.findings)} | {verdicts['TP']} | {verdicts['FP']} | {verdicts['unclear']} |"
        )
    lines.append(
        f"| **total ({len(rows)})** | | | | {total['files']:,} | {total['lines']:,} | {total['findings']} |"
        f" {total['TP']} | {total['FP']} | {total['unclear']} |"
    )
    Path(path).write_text("\n".join(lines) + "\n")


def warn_if_not_pinned(repo: Repo, checkout: Path) -> None:
    """Verdicts were given at the manifest's commit; say so when the checkout is elsewhere."""
    if not (checkout / ".git").exists():
        return
    try:
        head = git(checkout, "rev-parse", "HEAD").strip()
    except (subprocess.CalledProcessError, OSError):
        return
    if head != repo.commit:
        print(f"{repo.name}: warning: checkout is at {head[:10]}, the manifest pins {repo.commit[:10]}", file=sys.stderr)


def repo_commit(repos: list[Repo], name: str) -> str:
    return next(r.commit for r in repos if r.name == name)


def selected_repos(args: argparse.Namespace) -> list[Repo]:
    repos = load_manifest(args.manifest)
    if args.only:
        wanted = set(args.only.split(","))
        repos = [r for r in repos if r.name in wanted or r.folder in wanted]
    return repos


# --------------------------------------------------------------------------- history mining

# A commit is worth linting only if its diff removes a line that looks like geometry.
GEOMETRY_LINE = re.compile(
    r"(\bT_\w|_T_|\bR_\w|2world|2cam|c2w|w2c|\bpose|inv\(|\.inverse\(|\.T\b|transpose|@|\.dot\(|matmul|"
    r"quat|euler|rotvec|normal|\[:3,\s*:?3\]|\[\.\.\.,\s*:3|homogen|append\(|hstack|concatenate|ones\(|"
    r"transform|rotation|translation|extrinsic|frame)",
    re.IGNORECASE,
)


def git(checkout: Path, *arguments: str) -> str:
    return subprocess.run(["git", "-C", str(checkout), *arguments], capture_output=True, text=True, errors="replace", check=True).stdout


def candidate_commits(checkout: Path, limit: int) -> list[tuple[str, list[str]]]:
    """The newest `limit` non-merge commits that modify .py files and remove a geometry-looking line.

    Returns (commit, paths) with the modified files whose removed lines look like geometry (at most 8:
    a sweeping refactor is rarely a bug fix). One `git log -p` pass, newest first.
    """
    if limit <= 0:
        return []
    process = subprocess.Popen(
        ["git", "-C", str(checkout), "log", "--no-merges", "--diff-filter=M", "-p", "-U0", "--no-color", "--format=@@COMMIT %H", "HEAD", "--", "*.py"],
        stdout=subprocess.PIPE,
        text=True,
        errors="replace",
    )
    chosen: list[tuple[str, list[str]]] = []
    sha, path, touched = "", "", []

    def close_commit() -> None:
        if sha and touched:
            chosen.append((sha, touched[:8]))

    assert process.stdout is not None
    for line in process.stdout:
        if line.startswith("@@COMMIT "):
            close_commit()
            if len(chosen) >= limit:
                break
            sha, path, touched = line.split()[1], "", []
        elif line.startswith("+++ b/"):
            path = line[6:].rstrip("\n")
        elif line.startswith("-") and not line.startswith("---") and path and path not in touched:
            if GEOMETRY_LINE.search(line):
                touched.append(path)
    else:
        close_commit()
    process.stdout.close()
    process.kill()
    process.wait()
    return chosen[:limit]


def _lint_pair(item: tuple[str, str, str, str, str, tuple[str, ...]]) -> list[dict]:
    """Findings of the pre-fix file that the fixed file no longer has (by code and expression)."""
    from geolint import api

    repo, sha, path, before, after, select = item
    config = geolint_config(select)
    try:
        old = [f for f in api.lint_text(before, path, config) if f.code != "GEO000"]
        if not old:  # nothing to disappear: the fixed version need not be linted
            return []
        new = api.lint_text(after, path, config)
    except Exception as error:  # noqa: BLE001 - reported, the run goes on
        return [{"error": f"{repo}@{sha[:10]}:{path}: {error!r}"}]
    old_lines, new_lines = before.splitlines(), after.splitlines()

    def keyed(findings, lines):
        return Counter(
            (f.code, normalised_expression(lines, f.line, f.column, f.end_line, f.end_column)) for f in findings if f.code != "GEO000"
        )

    remaining = keyed(new, new_lines)
    out = []
    for f in old:
        if f.code == "GEO000":
            continue
        key = (f.code, normalised_expression(old_lines, f.line, f.column, f.end_line, f.end_column))
        if remaining[key] > 0:
            remaining[key] -= 1
            continue
        out.append({"repo": repo, "commit": sha, "path": path, "line": f.line, "code": f.code, "expr": key[1], "message": f.message})
    return out


def history(args: argparse.Namespace) -> int:
    repos = selected_repos(args)
    select = tuple(args.select.split(","))
    ledger = load_ledger(args.ledger)
    status = 0
    work = []
    for repo in repos:
        checkout = args.mirror / repo.folder
        if not (checkout / ".git").exists():
            print(f"{repo.name}: no git history at {checkout}/.git", file=sys.stderr)
            status = 2
            continue
        commits = candidate_commits(checkout, args.history_limit)
        for sha, paths in commits:
            for path in paths:
                try:
                    before = git(checkout, "show", f"{sha}^:{path}")
                    after = git(checkout, "show", f"{sha}:{path}")
                except subprocess.CalledProcessError:
                    continue  # a blob the snapshot does not hold
                work.append((repo.name, sha, path, before, after, select))
        print(f"{repo.name}: {len(commits)} candidate commit(s)", file=sys.stderr, flush=True)
    started = time.perf_counter()
    with ProcessPoolExecutor(max_workers=args.jobs) as pool:
        results = [row for rows in pool.map(_lint_pair, work, chunksize=4) for row in rows]
    errors = [r["error"] for r in results if "error" in r]
    candidates = [r for r in results if "error" not in r]
    for error in errors:
        print(f"geolint failed: {error}", file=sys.stderr)
        status = 2
    known = {(h.repo, h.fix_commit, h.path) for h in ledger.history}
    print(f"{len(work)} file version pair(s) linted in {time.perf_counter() - started:.0f} s; {len(candidates)} finding(s) removed by a commit")
    for c in candidates:
        mark = "recorded" if (c["repo"], c["commit"], c["path"]) in known else "candidate"
        print(f"  {mark} {c['repo']}@{c['commit'][:10]} {c['path']}:{c['line']} {c['code']} {c['message']}")
    if args.candidates_out:
        Path(args.candidates_out).write_text(json.dumps(candidates, indent=1))
    status = max(status, verify_history(args, ledger, select))
    return status


def verify_history(args: argparse.Namespace, ledger: Ledger, select: tuple[str, ...]) -> int:
    """Lint each recorded historical bug's file at the commit before its fix: is the bug's line flagged today?"""
    from geolint import api

    if not ledger.history:
        return 0
    status = 0
    config = geolint_config(select)
    caught = 0
    changed = 0
    print(f"historical bugs recorded in the ledger: {len(ledger.history)} (linted at the commit before each fix)")
    for bug in ledger.history:
        checkout = args.mirror / bug.repo.replace("/", "+")
        try:
            before = git(checkout, "show", f"{bug.fix_commit}^:{bug.path}")
        except (subprocess.CalledProcessError, OSError):
            print(f"  {bug.repo}@{bug.fix_commit[:10]}:{bug.path}: pre-fix file not available", file=sys.stderr)
            status = 2
            continue
        with tempfile.TemporaryDirectory() as scratch:
            # inside its repository as it was (sibling modules, manifests): the evidence the real CLI reads
            path = _pre_fix_package(checkout, bug.fix_commit, bug.path, Path(scratch))
            hits = [f for f in api.lint_text(before, path, config) if f.code != "GEO000" and f.line <= bug.line <= f.end_line]
        now = bool(hits)
        caught += now
        mark = "CAUGHT" if now else "missed"
        note = "" if now == bug.caught else f"  (ledger says {'caught' if bug.caught else 'missed'})"
        print(f"  {mark:6} {bug.bug_class:22} {bug.repo}@{bug.fix_commit[:10]} {bug.path}:{bug.line}{note}")
        for f in hits:
            print(f"         {f.code} {f.message}")
        if now != bug.caught:
            changed += 1
            bug.caught = now
    print(f"caught at the pre-fix commit: {caught} / {len(ledger.history)} = {100 * caught / len(ledger.history):.0f} %")
    if changed and args.record_new:
        dump_ledger(ledger, args.ledger)
        print(f"updated 'caught' of {changed} historical bug(s) in {args.ledger}")
    return status


_PROJECT_FILES = ("package.xml", "pyproject.toml", "setup.py", "setup.cfg")


def _pre_fix_package(checkout: Path, fix_commit: str, path: str, scratch: Path) -> str:
    """Where to lint `path` as it was before `fix_commit`: inside a copy of its repository at that commit
    (every Python file and the project and ROS package manifests, with a `.git` marker at the root), so
    that helper summaries, constants of sibling modules, naming declarations and package evidence are
    read as the real CLI reads them in an exported pre-fix tree."""
    parent = f"{fix_commit}^"
    names = [
        name
        for name in git(checkout, "ls-tree", "-r", "--name-only", parent).splitlines()
        if name.endswith((".py", ".pyi")) or name.rpartition("/")[2] in _PROJECT_FILES
    ]
    # one `git cat-file --batch` for every blob: a `git show` per file takes minutes on large repositories
    request = "".join(f"{parent}:{name}\n" for name in names).encode()
    output = subprocess.run(["git", "-C", str(checkout), "cat-file", "--batch"], input=request, capture_output=True, check=True).stdout
    offset = 0
    for name in names:
        header_end = output.index(b"\n", offset)
        header = output[offset:header_end].split()
        offset = header_end + 1
        if len(header) != 3 or header[1] != b"blob":  # "<name> missing": a blob the snapshot does not hold
            continue
        size = int(header[2])
        target = scratch / name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(output[offset : offset + size])
        offset += size + 1
    (scratch / ".git").mkdir(exist_ok=True)
    return str(scratch / path)


# --------------------------------------------------------------------------- throughput


def corpus_files(args: argparse.Namespace, repos: list[Repo]) -> list[Path]:
    from geolint.files import discover

    checkouts = [args.mirror / r.folder for r in repos if (args.mirror / r.folder).is_dir()]
    # a link to nothing is skipped by geolint with a warning, and not read here either
    return [source.path for source in discover(checkouts, geolint_config(DEFAULT_SELECT)) if source.path.is_file()]


AST_PARSE = """
import ast, sys, warnings
warnings.simplefilter("ignore")
for path in open(sys.argv[1]).read().splitlines():
    try:
        ast.parse(open(path, "rb").read())
    except (SyntaxError, ValueError):
        pass
"""


def throughput(args: argparse.Namespace) -> int:
    repos = selected_repos(args)
    files = corpus_files(args, repos)
    lines = sum(non_empty_lines(p.read_text(encoding="utf-8", errors="replace")) for p in files)
    checkouts = [str(args.mirror / r.folder) for r in repos if (args.mirror / r.folder).is_dir()]
    list_file = Path(os.environ.get("TMPDIR", "/tmp")) / "geolint_real_code_files.txt"
    list_file.write_text("\n".join(str(p) for p in files))
    geolint = [sys.executable, "-m", "geolint", "check", "--no-cache", "--exit-zero", "-q", "--select", args.select]
    ruff = shutil.which("ruff") or str(Path(sys.executable).with_name("ruff"))
    tools = [
        ("geolint --jobs 1", [*geolint, "--jobs", "1", *checkouts]),
        ("geolint --jobs 2", [*geolint, "--jobs", "2", *checkouts]),
        ("ruff check --select ALL --no-cache (its own threads)", [ruff, "check", "--select", "ALL", "--no-cache", "--exit-zero", "-q", "--output-format", "concise", *[str(p) for p in files]]),
        ("ast.parse, one process", [sys.executable, "-c", AST_PARSE, str(list_file)]),
    ]
    print(f"{len(files)} files, {lines} non-empty lines, {args.repeats} repeat(s) each, interleaved; median wall time")
    times: dict[str, list[float]] = defaultdict(list)
    status = 0
    for _ in range(args.repeats):
        for label, command in tools:
            started = time.perf_counter()
            done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            times[label].append(time.perf_counter() - started)
            if done.returncode not in (0,):
                print(f"{label}: exit {done.returncode}: {done.stderr[-500:]}", file=sys.stderr)
                status = 2
    print(f"{'tool':55} {'median s':>9} {'lines/s':>9}  runs")
    for label, _ in tools:
        median = statistics.median(times[label])
        print(f"{label:55} {median:9.1f} {lines / median:9.0f}  {', '.join(f'{t:.1f}' for t in times[label])}")
    return status


# --------------------------------------------------------------------------- command line


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mirror", type=Path, help="folder holding one checkout per repository, named <owner>+<repo>")
    parser.add_argument("--manifest", type=Path, default=HERE / "manifest.toml")
    parser.add_argument("--ledger", type=Path, default=HERE / "ledger.toml")
    parser.add_argument("--select", default=",".join(DEFAULT_SELECT))
    parser.add_argument("--only", help="comma-separated repository names (owner/repo or owner+repo)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--own-fixes", action="store_true", help="lint with `history = true`: GEO401 reads each checkout's git history (select GEO4)")
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--history", action="store_true", help="lint files before and after each candidate commit")
    mode.add_argument("--throughput", action="store_true", help="time geolint -j1/-j2, ruff and ast.parse on the corpus")
    parser.add_argument(
        "--history-limit", type=int, default=100, help="candidate commits per repository, newest first (0: only re-check the ledger's historical bugs)"
    )
    parser.add_argument("--candidates-out", help="with --history: write the candidates as JSON here")
    parser.add_argument("--context", type=int, default=0, metavar="N", help="print N source lines around each new finding")
    parser.add_argument("--markdown", metavar="FILE", help="also write the per-repository table as markdown to FILE")
    parser.add_argument("--repeats", type=int, default=3, help="with --throughput: runs per tool")
    parser.add_argument(
        "--record-new", action="store_true", help="append new findings to the ledger as 'unclear' for triage; with --history, update 'caught'"
    )
    args = parser.parse_args(argv)
    if not args.mirror.is_dir():
        parser.error(f"{args.mirror}: not a folder")
    if args.history:
        return history(args)
    if args.throughput:
        return throughput(args)
    return compare(args)


if __name__ == "__main__":
    sys.exit(main())
