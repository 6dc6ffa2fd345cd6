"""Expected mypy output written in the checked files themselves, bugbear-style.

A line ending in ``# E: <code>`` expects an error with that code on that line (``# E: <code>: <text>``
also expects <text> inside the message); ``# N: <type>`` expects ``reveal_type`` to show exactly that type.
Every other line must stay silent, so a spurious error fails as loudly as a missing one.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

EXPECTATION = re.compile(r"#\s*(?P<kind>[EN]):\s*(?P<body>.*)$")
MYPY_LINE = re.compile(r"^(?P<path>[^:]+):(?P<line>\d+): (?P<severity>error|note): (?P<message>.*)$")
ERROR_CODE = re.compile(r"\s+\[(?P<code>[a-z-]+)\]$")


@dataclass(frozen=True)
class Reported:
    line: int
    severity: str
    message: str
    code: str | None


def expected_in(path: Path) -> dict[int, list[tuple[str, str]]]:
    """line -> [(kind, body)] for every ``# E:`` / ``# N:`` comment in `path`."""
    expected: dict[int, list[tuple[str, str]]] = {}
    for number, text in enumerate(path.read_text().splitlines(), start=1):
        match = EXPECTATION.search(text)
        if match:
            expected.setdefault(number, []).append((match["kind"], match["body"].strip()))
    return expected


def parse_mypy_output(stdout: str) -> dict[str, list[Reported]]:
    """file name -> what mypy reported in it (notes that continue an error are kept as notes)."""
    reported: dict[str, list[Reported]] = {}
    for text in stdout.splitlines():
        match = MYPY_LINE.match(text)
        if not match:
            continue
        message = _normalized(match["message"])
        code_match = ERROR_CODE.search(message)
        code = code_match["code"] if code_match else None
        if code_match:
            message = message[: code_match.start()]
        entry = Reported(int(match["line"]), match["severity"], message, code)
        reported.setdefault(Path(match["path"]).name, []).append(entry)
    return reported


def mismatches(path: Path, reported: list[Reported]) -> list[str]:
    """Human-readable differences between `path`'s expectations and what mypy reported for it."""
    expected = expected_in(path)
    problems: list[str] = []
    by_line: dict[int, list[Reported]] = {}
    for entry in reported:
        by_line.setdefault(entry.line, []).append(entry)
    for line in sorted(set(expected) | set(by_line)):
        wanted = expected.get(line, [])
        got = by_line.get(line, [])
        errors = [entry for entry in got if entry.severity == "error"]
        reveals = [entry for entry in got if entry.message.startswith("Revealed type is")]
        for kind, body in wanted:
            if kind == "E":
                code, _, text = body.partition(":")
                hits = [e for e in errors if e.code == code.strip() and text.strip() in e.message]
                if not hits:
                    problems.append(f"{path.name}:{line}: expected error [{body}], got {_show(got)}")
                for hit in hits[:1]:
                    errors.remove(hit)
            else:
                want = _normalized(f'Revealed type is "{body}"')
                hits = [r for r in reveals if r.message == want]
                if not hits:
                    problems.append(f"{path.name}:{line}: expected {want}, got {_show(got)}")
                for hit in hits[:1]:
                    reveals.remove(hit)
        for extra in errors:
            problems.append(f"{path.name}:{line}: unexpected error: {extra.message} [{extra.code}]")
    return problems


def _normalized(text: str) -> str:
    """mypy before 1.11 spells builtin generics out (``builtins.list[...]``); compare without the prefix."""
    return text.replace("builtins.", "")


def _show(entries: list[Reported]) -> str:
    return "; ".join(f"{e.severity}: {e.message} [{e.code}]" for e in entries) or "nothing"
