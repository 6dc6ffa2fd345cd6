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


def render(findings: Sequence[Finding], format_name: str, **options: object) -> str:
    function = renderer(format_name)
    accepted = inspect.signature(function).parameters
    return function(findings, **{name: value for name, value in options.items() if name in accepted})
