"""Baselines: record today's findings so that CI fails only on new ones.

A finding is keyed by its code, its file (relative to the baseline file's folder, so the
baseline works from any cwd), the text of the line it starts on with all whitespace removed,
and its occurrence index among findings with the same code, file and text. Line numbers are
deliberately not part of the key: adding or moving code above an old finding, or re-indenting
it, does not resurrect it; editing the flagged line itself, or copying it, does.
"""

from __future__ import annotations

import json
import os
import re
from collections import Counter
from pathlib import Path
from typing import Sequence

from geolint._version import __version__
from geolint.lint_types import Finding

BASELINE_FORMAT = 1
WHITESPACE = re.compile(r"\s+")

Key = tuple[str, str, str, int]


class BaselineError(Exception):
    """A baseline file that cannot be read or is not a geolint baseline."""


def normalise_line(text: str) -> str:
    return WHITESPACE.sub("", text)


def finding_keys(findings: Sequence[Finding], baseline_dir: Path) -> list[Key]:
    """The key of each finding, in order (the occurrence index counts equal code/file/text)."""
    seen: Counter[tuple[str, str, str]] = Counter()
    keys: list[Key] = []
    for finding in findings:
        base = (finding.code, _relative(finding.path, baseline_dir), normalise_line(_line_text(finding.path, finding.line)))
        keys.append((*base, seen[base]))
        seen[base] += 1
    return keys


def write_baseline(findings: Sequence[Finding], file: Path) -> int:
    """Record `findings` in `file`; returns how many were recorded."""
    keys = finding_keys(findings, file.resolve().parent)
    entries = [
        {"code": code, "path": path, "line_text": text, "occurrence": occurrence, "message": finding.message}
        for (code, path, text, occurrence), finding in zip(keys, findings)
    ]
    document = {"geolint_baseline": BASELINE_FORMAT, "geolint_version": __version__, "findings": entries}
    file.write_text(json.dumps(document, indent=2, ensure_ascii=False) + "\n", encoding="utf-8")
    return len(entries)


def read_baseline(file: Path) -> set[Key]:
    try:
        document = json.loads(file.read_text(encoding="utf-8"))
    except OSError as error:
        raise BaselineError(f"{file}: cannot read baseline: {error.strerror or error}") from error
    except ValueError as error:
        raise BaselineError(f"{file}: not a geolint baseline (invalid JSON: {error})") from error
    if not isinstance(document, dict) or document.get("geolint_baseline") != BASELINE_FORMAT:
        raise BaselineError(f"{file}: not a geolint baseline (write one with --write-baseline)")
    try:
        return {(e["code"], e["path"], e["line_text"], int(e["occurrence"])) for e in document["findings"]}
    except (KeyError, TypeError, ValueError) as error:
        raise BaselineError(f"{file}: damaged baseline entry ({error})") from error


def new_findings(findings: Sequence[Finding], file: Path) -> list[Finding]:
    """The findings that the baseline in `file` does not record."""
    known = read_baseline(file)
    keys = finding_keys(findings, file.resolve().parent)
    return [finding for finding, key in zip(findings, keys) if key not in known]


def _relative(path: str, base: Path) -> str:
    return os.path.relpath(os.path.abspath(path), base).replace(os.sep, "/")


def _line_text(path: str, line: int) -> str:
    from geolint.output.source import source_lines

    lines = source_lines(path)
    return lines[line - 1] if 1 <= line <= len(lines) else ""
