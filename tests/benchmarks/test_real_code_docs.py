"""The real-code benchmark's results page, its ledgers, the README's summary and the documented
commands agree (no corpus or network needed).

The per-repository numbers come from running the benchmark (benchmarks/real_code/run.py); what can be
checked offline is that the tables count what the ledgers hold, that the README quotes the tables,
and that every command docs/benchmark.md shows runs, here on a tiny corpus made with git.
"""

from __future__ import annotations

import importlib.util
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BENCHMARK = ROOT / "benchmarks" / "real_code"
_spec = importlib.util.spec_from_file_location("real_code_run", BENCHMARK / "run.py")
assert _spec is not None and _spec.loader is not None
real_code = sys.modules.setdefault("real_code_run", importlib.util.module_from_spec(_spec))
if not hasattr(real_code, "load_ledger"):
    _spec.loader.exec_module(real_code)

RESULTS = (BENCHMARK / "RESULTS.md").read_text(encoding="utf-8")
README = (ROOT / "README.md").read_text(encoding="utf-8")


def table_after(heading: str, text: str = RESULTS) -> list[list[str]]:
    """The cells of the first Markdown table under `heading`, header and rule rows dropped."""
    section = text[text.index(heading) :]
    rows = []
    for line in section.splitlines()[1:]:
        if line.startswith("## "):
            break
        if line.startswith("|") and not line.startswith("|---"):
            rows.append([cell.strip() for cell in line.strip("|").split("|")])
        elif rows and not line.startswith("|"):
            break
    return rows[1:]


def number(cell: str) -> int:
    return int(cell.strip("*").replace(",", ""))


def ledger_of(manifest: str) -> str:
    return "ledger.toml" if manifest == "manifest.toml" else manifest.replace(".toml", "_ledger.toml")


def test_the_ledger_table_counts_what_the_ledgers_hold() -> None:
    rows = table_after("## The ledgers as they stand")
    listed = {row[0].strip("`") for row in rows}
    on_disk = {p.name for p in BENCHMARK.glob("*.toml") if not p.name.endswith("ledger.toml")}
    assert listed == on_disk, "every manifest has a row"
    for manifest_cell, ledger_cell, repositories, true, false, caught in rows:
        manifest = manifest_cell.strip("`")
        assert ledger_cell.strip("`") == ledger_of(manifest)
        ledger = real_code.load_ledger(BENCHMARK / ledger_of(manifest))
        assert number(repositories) == len(real_code.load_manifest(BENCHMARK / manifest)), manifest
        assert number(true) == sum(e.verdict == "TP" for e in ledger.findings), manifest
        assert number(false) == sum(e.verdict == "FP" for e in ledger.findings), manifest
        assert caught == f"{sum(bool(b.caught) for b in ledger.history)} / {len(ledger.history)}", manifest


def test_the_blind_round_totals_add_up_and_name_real_manifests() -> None:
    rows = table_after("## Blind rounds: first contact")
    rounds = [row for row in rows if not row[0].startswith("**")]
    totals = {row[0].strip("*"): row for row in rows if row[0].startswith("**")}
    for row in rounds:
        manifest = BENCHMARK / f"blind{row[0]}.toml"
        assert number(row[3]) == len(real_code.load_manifest(manifest)), row[0]
    for name, total in totals.items():
        first, last = name.split(" to ")
        order = [row[0] for row in rounds]
        chosen = rounds[order.index(first) : order.index(last) + 1]
        for column in (3, 4, 5, 6):
            assert number(total[column]) == sum(number(row[column]) for row in chosen), (name, column)
        caught = [tuple(map(int, row[7].split(" / "))) for row in chosen]
        assert total[7].strip("*") == f"{sum(c for c, _ in caught)} / {sum(n for _, n in caught)}", name


def test_the_readme_quotes_the_blind_figures() -> None:
    rows = table_after("## Blind rounds: first contact")
    end_states = next(row for row in rows if row[0] == "**5 to 13**")
    latest = [row for row in rows if not row[0].startswith("**")][-1]
    repositories, lines, findings, true = (number(end_states[column]) for column in (3, 4, 5, 6))
    caught, bugs = map(int, end_states[7].strip("*").split(" / "))
    quoted = README[README.index("## How good is it") :]
    quoted = quoted[: quoted.index("\n## ", 1)]
    assert f"{repositories} repositories, {lines / 1e6:.1f} million" in quoted
    assert f"**{findings} findings, about {findings / lines * 1e5:.1f} per 100,000 lines" in quoted
    assert f"{true} of them ({round(100 * true / findings)} %)" in quoted
    assert f"of {bugs} bugs" in quoted and f"it flags {caught} at" in quoted
    assert f"{latest[3]} repositories, {latest[4]} lines) gave {latest[5]} findings, {latest[6]}" in quoted.replace("\n", " ")
    tuned = next(row for row in table_after("## The tuned corpora") if row[2] == "main corpus")
    repositories = len(real_code.load_manifest(BENCHMARK / "manifest.toml"))
    assert f"On the {repositories} repositories the rules were developed against" in quoted.replace("\n", " ")
    assert f"reports {tuned[3]} findings, {'all' if tuned[3] == tuned[4] else tuned[4]} real" in quoted.replace("\n", " ")


def test_every_false_positive_pattern_cited_in_a_ledger_has_a_row() -> None:
    findings = [entry for path in BENCHMARK.glob("*ledger.toml") for entry in real_code.load_ledger(path).findings]
    cited = {m for e in findings if e.verdict == "FP" for m in re.findall(r"\bFP\d+\b", e.reason)}
    assert cited, "FP verdicts name their pattern (FP1, FP2, ...)"
    rows = set(re.findall(r"^\| (FP\d+) \|", RESULTS, re.M))
    assert cited <= rows


def test_the_manifest_has_the_promised_size() -> None:
    repos = real_code.load_manifest(BENCHMARK / "manifest.toml")
    assert len(repos) >= 30 and len({r.name for r in repos}) == len(repos)
    assert sum(r.torch for r in repos) >= 5
    assert all(re.fullmatch(r"[0-9a-f]{40}", r.commit) for r in repos)


def test_the_held_out_corpus_is_separate_and_fully_triaged() -> None:
    main = {r.name for r in real_code.load_manifest(BENCHMARK / "manifest.toml")}
    held_out = real_code.load_manifest(BENCHMARK / "heldout.toml")
    heldout_ledger = real_code.load_ledger(BENCHMARK / "heldout_ledger.toml")
    assert len(held_out) >= 15 and not main & {r.name for r in held_out}
    assert all(e.verdict in ("TP", "FP") for e in heldout_ledger.findings)


# --- the commands of docs/benchmark.md, on a corpus of one repository made here ----------------------

BUGGY = """\
import numpy as np


def normal_to_world(R_world_cam, t_world_cam, normal_cam):
    return R_world_cam @ normal_cam + t_world_cam
"""
FIXED = BUGGY.replace("R_world_cam @ normal_cam + t_world_cam", "R_world_cam @ normal_cam")


def git(repo: Path, *arguments: str) -> str:
    return subprocess.run(
        ["git", "-C", str(repo), "-c", "user.name=t", "-c", "user.email=t@t", *arguments], check=True, capture_output=True, text=True
    ).stdout.strip()


@pytest.mark.slow  # the runner's every mode, --throughput's timed repeats included
@pytest.mark.skipif(shutil.which("git") is None, reason="needs git")
def test_the_documented_commands_run(tmp_path: Path) -> None:
    """Each command as written, with the placeholders (MIRRORS, CORPUS) and the corpus files pointed here."""
    from tests.cli.doc_snippets import block, commands_of

    mirror = tmp_path / "mirrors" / "someone+grasp-demo"
    mirror.mkdir(parents=True)
    git(mirror, "init", "-q")
    (mirror / "grasp.py").write_text(BUGGY, encoding="utf-8")
    git(mirror, "add", "grasp.py")
    git(mirror, "commit", "-q", "-m", "first")
    (mirror / "grasp.py").write_text(FIXED, encoding="utf-8")
    git(mirror, "commit", "-q", "-am", "fix: the normal must not be translated")
    manifest = tmp_path / "manifest.toml"
    manifest.write_text(
        f'[[repo]]\nname = "someone/grasp-demo"\nurl = "https://example.invalid/grasp-demo"\n'
        f'commit = "{git(mirror, "rev-parse", "HEAD~1")}"\ncategory = "grasping"\ntorch = false\n',
        encoding="utf-8",
    )
    ledger = tmp_path / "ledger.toml"
    ledger.write_text("", encoding="utf-8")
    corpus = tmp_path / "corpus"
    commands = commands_of(block("docs/benchmark.md", "Running it", 0).body) + commands_of(block("docs/benchmark.md", "Running it", 1).body)
    assert commands[0].startswith("python benchmarks/real_code/checkouts.py")
    for line in commands:
        command = line.split("  #", 1)[0].split()
        assert command[0] == "python"
        command = [sys.executable, *command[1:]]
        command = [str(tmp_path / "mirrors") if word == "MIRRORS" else str(corpus) if word == "CORPUS" else word for word in command]
        if "--manifest" in command:
            command[command.index("--manifest") + 1] = str(manifest)
        else:
            command += ["--manifest", str(manifest)]
        if "run.py" in command[1]:
            command += ["--ledger", str(ledger), "--jobs", "1"]
        done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True, timeout=600, check=False)
        assert done.returncode == 0, f"{line}: {done.stdout[-2000:]}{done.stderr[-2000:]}"
    assert "GEO101" in ledger.read_text(encoding="utf-8")  # --record-new recorded the finding for triage
