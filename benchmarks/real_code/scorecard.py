"""Every finding ever triaged, by rule: TP and FP counted over all ledgers of the real-code benchmark.

    python benchmarks/real_code/scorecard.py        # a Markdown table, one row per rule code
"""

from __future__ import annotations

import sys
from collections import Counter
from pathlib import Path

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

HERE = Path(__file__).resolve().parent


def scorecard(ledgers: list[Path]) -> dict[str, Counter[str]]:
    counts: dict[str, Counter[str]] = {}
    for ledger in ledgers:
        for row in tomllib.loads(ledger.read_text(encoding="utf-8")).get("finding", []):
            counts.setdefault(row["code"], Counter())[row["verdict"]] += 1
    return counts


def main() -> None:
    counts = scorecard(sorted(HERE.glob("*ledger.toml")))
    print("| rule | TP | FP |\n|---|---:|---:|")
    for code in sorted(counts):
        print(f"| {code} | {counts[code]['TP']} | {counts[code]['FP']} |")


if __name__ == "__main__":
    main()
