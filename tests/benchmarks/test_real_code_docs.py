"""docs/real-code.md and the committed ledger tell the same story (no corpus or network needed).

The per-repository numbers come from running the benchmark (benchmarks/real_code/run.py); what can be
checked offline is that every recorded verdict the page relies on is explained there.
"""

from __future__ import annotations

import importlib.util
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("real_code_run", ROOT / "benchmarks" / "real_code" / "run.py")
assert _spec is not None and _spec.loader is not None
real_code = sys.modules.setdefault("real_code_run", importlib.util.module_from_spec(_spec))
if not hasattr(real_code, "load_ledger"):
    _spec.loader.exec_module(real_code)

DOC = (ROOT / "docs" / "real-code.md").read_text(encoding="utf-8")
LEDGER = real_code.load_ledger(ROOT / "benchmarks" / "real_code" / "ledger.toml")
HELDOUT_LEDGER = real_code.load_ledger(ROOT / "benchmarks" / "real_code" / "heldout_ledger.toml")


def test_every_false_positive_pattern_cited_in_the_ledger_has_a_row_on_the_page() -> None:
    findings = [*LEDGER.findings, *HELDOUT_LEDGER.findings]
    cited = {m for e in findings if e.verdict == "FP" for m in re.findall(r"\bFP\d+\b", e.reason)}
    assert cited, "FP verdicts name their pattern (FP1, FP2, ...)"
    rows = set(re.findall(r"^\| (FP\d+) \|", DOC, re.M))
    assert cited <= rows


def test_every_true_positive_and_historical_bug_is_explained_on_the_page() -> None:
    for entry in [*LEDGER.findings, *HELDOUT_LEDGER.findings]:
        if entry.verdict == "TP":
            assert f"{entry.path}:{entry.line}" in DOC, entry
    for bug in [*LEDGER.history, *HELDOUT_LEDGER.history]:
        assert bug.fix_commit[:10] in DOC and f"{bug.path}:{bug.line}" in DOC, bug


def test_the_manifest_has_the_promised_size() -> None:
    repos = real_code.load_manifest(ROOT / "benchmarks" / "real_code" / "manifest.toml")
    assert len(repos) >= 30 and len({r.name for r in repos}) == len(repos)
    assert sum(r.torch for r in repos) >= 5
    assert all(re.fullmatch(r"[0-9a-f]{40}", r.commit) for r in repos)


def test_the_held_out_corpus_is_separate_and_fully_triaged() -> None:
    main = {r.name for r in real_code.load_manifest(ROOT / "benchmarks" / "real_code" / "manifest.toml")}
    held_out = real_code.load_manifest(ROOT / "benchmarks" / "real_code" / "heldout.toml")
    assert len(held_out) >= 15 and not main & {r.name for r in held_out}
    assert all(e.verdict in ("TP", "FP") for e in HELDOUT_LEDGER.findings)
