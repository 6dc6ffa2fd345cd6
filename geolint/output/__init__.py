"""Output formats for findings. Each format is a module with
`render(findings: Sequence[Finding], *, color: bool = False, ...) -> str`; a format takes the
options it names (`color`, `show_fixes`, `unsafe_fixes`) and is never handed the others.

Modules are imported on use so the common text path stays cheap.
"""

from __future__ import annotations

import importlib
import inspect
from typing import Callable, Sequence

from geolint.lint_types import Finding

FORMATS = ("text", "concise", "full", "json", "github", "sarif", "junit", "gitlab")

Renderer = Callable[..., str]


def renderer(format_name: str) -> Renderer:
    """The `render` function of an output format (one of FORMATS)."""
    if format_name not in FORMATS:
        raise ValueError(f"unknown output format {format_name!r}; choose one of {', '.join(FORMATS)}")
    return importlib.import_module(f"geolint.output.{format_name}").render


# Formats that show a notebook's cells themselves; the others get `cell N: ` before the message.
CELL_AWARE = ("text", "concise", "full", "json")


def render(findings: Sequence[Finding], format_name: str, **options: object) -> str:
    function = renderer(format_name)
    if format_name not in CELL_AWARE:
        findings = [_cell_named(finding) for finding in findings]
    accepted = inspect.signature(function).parameters
    return function(findings, **{name: value for name, value in options.items() if name in accepted})


def _cell_named(finding: Finding) -> Finding:
    from dataclasses import replace

    from geolint.output.source import in_cell

    shown, cell = in_cell(finding)
    return shown if cell is None else replace(shown, message=f"cell {cell}: {shown.message}")
