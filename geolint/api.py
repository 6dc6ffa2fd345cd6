"""The one public entry point to the linter. The CLI, the language server and the pre-commit
hook are thin adapters over these functions, so they always agree.

(Skeleton by the lead: the engine/CLI owner completes it; the signatures are the contract.)
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Collection, Iterator, Sequence

from geolint import engine
from geolint.lint_types import Config, Finding


@dataclass(frozen=True)
class FileResult:
    """The outcome of linting one file: its findings, or the internal error that stopped it."""

    path: str
    findings: tuple[Finding, ...]
    error: str | None = None


def find_config(start: Path) -> Config:
    """The config of the nearest pyproject.toml with a [tool.geolint] table at or above `start`."""
    return Config()


def lint_text(source: str, path: str | Path = "<string>", config: Config | None = None) -> list[Finding]:
    """Findings for one module's text, after select/ignore and suppressions. Never raises for bad code."""
    return engine.lint_source(source, str(path), config or Config())


def fix_text(
    source: str,
    path: str | Path = "<string>",
    config: Config | None = None,
    *,
    unsafe: bool = False,
    only: Collection[str] | None = None,
) -> tuple[str, list[Finding]]:
    """Apply the available fixes; return the new text and the findings that remain."""
    raise NotImplementedError


def lint_paths(
    paths: Sequence[Path], config: Config | None = None, *, jobs: int | None = None, use_cache: bool = True
) -> Iterator[FileResult]:
    """Lint files and folders (honouring excludes), in parallel, with a content-keyed cache."""
    raise NotImplementedError


def rule_url(code: str) -> str:
    """Where a rule's documentation lives (used by the language server and SARIF)."""
    return f"https://github.com/geolint/geolint/blob/main/docs/rules.md#{code.lower()}"
