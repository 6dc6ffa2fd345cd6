"""GEO001 too-complex-to-analyse: the pseudo-rule the engine reports for a file past an analysis limit."""

from __future__ import annotations

from typing import Final

import re
from ast import Module

from geolint.lint_types import Severity
from geolint.rules.base import AstRule, Invalid, Valid

_DEEP_SUM: Final = "total = " + " + ".join(f"offset_{i}" for i in range(200)) + "\n"


class TooComplexToAnalyse(AstRule):
    """## What it does
    Reports a file that geolint did not analyse because it is past one of its limits: longer than
    `max-file-size` characters (default 1,000,000), a syntax tree nested deeper than
    `max-nesting-depth` levels (default 150), or nested too deeply for Python's own parser.
    The file gets exactly one finding saying which limit and how to raise it; every other file of
    the run is checked as usual.

    ## Why is this bad?
    A file that is not analysed is a file whose geometric bugs go unreported, so geolint says so
    instead of passing it silently. The limits exist because analysis walks the syntax tree
    recursively and libcst's parser slows down with the square of an expression's depth: without
    them one generated file (a sum of 20,000 terms on one line, 5,000 `elif` branches) could hang
    or crash a whole run. Real code stays far below them (the deepest module among 5,200 installed
    packages' files is 87 levels deep).

    ## Example
    ```python
    total = offset_0 + offset_1 + offset_2 + ...  # 200 terms on one line: 200 levels deep
    ```

    ## Use instead
    ```python
    total = sum([offset_0, offset_1, offset_2, ...])
    ```

    ## Fix safety
    There is no automatic fix.

    ## Options
    Raise the limit in pyproject.toml, e.g. `max-nesting-depth = 400` or `max-file-size = 5000000`
    under `[tool.geolint]`, or exclude generated files with `extend-exclude`.
    """

    code = "GEO001"
    name = "too-complex-to-analyse"
    default_severity = Severity.WARNING
    # Detected by the engine before any rule runs; this visitor never fires.
    triggers = re.compile(r"(?!)")
    VALID = (Valid("total = sum([offset_0, offset_1, offset_2])\n"),)
    INVALID = (
        Invalid(
            _DEEP_SUM,
            message="file not analysed: its syntax tree is nested more than 150 levels deep here; raise `max-nesting-depth` in [tool.geolint] to analyse it",
            range=(1, 9, 1, 10),
        ),
    )

    def check(self, tree: Module) -> None:
        """Nothing to visit: the engine itself reports this code."""
