"""benchmarks/real_code/scorecard.py counts verdicts by rule over every ledger it is given."""

from __future__ import annotations

import importlib.util
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[2] / "benchmarks" / "real_code" / "scorecard.py"


def test_verdicts_are_counted_by_rule_across_ledgers(tmp_path: Path) -> None:
    spec = importlib.util.spec_from_file_location("scorecard", SCRIPT)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    row = 'repo = "a/b"\npath = "x.py"\nline = 1\nexpr_hash = "0"\n'
    (tmp_path / "one_ledger.toml").write_text(
        f'[[finding]]\ncode = "GEO201"\nverdict = "FP"\n{row}\n[[finding]]\ncode = "GEO301"\nverdict = "TP"\n{row}'
    )
    (tmp_path / "two_ledger.toml").write_text(f'[[finding]]\ncode = "GEO201"\nverdict = "TP"\n{row}\n[[history]]\nrepo = "a/b"\n')
    counts = module.scorecard(sorted(tmp_path.glob("*ledger.toml")))
    assert (counts["GEO201"]["TP"], counts["GEO201"]["FP"], counts["GEO301"]["TP"]) == (1, 1, 1)
