"""GEO000 syntax-error: the pseudo-rule the engine reports for a file it cannot read."""

from __future__ import annotations

import re
from ast import Module

from geolint.lint_types import Severity
from geolint.rules.base import AstRule, Invalid, Valid


class SyntaxErrorRule(AstRule):
    """## What it does
    Reports a file that is not valid Python 3.10-3.13, or whose bytes cannot be decoded with its
    declared encoding (a PEP 263 coding cookie, a UTF-8 BOM, else UTF-8). The file gets exactly
    one finding, at the first error, and the rest of the run goes on. Syntax newer than the running
    interpreter's (`type X = ...` or a PEP 701 f-string under Python 3.11) is no error: the file is
    analysed as under the newer Python. The message names the versions whose grammar rejects it.

    ## Why is this bad?
    geolint reads code without running it; a file it cannot parse is a file it cannot check, so
    every geometric bug in it would go unreported. Usually the file is simply broken (a merge
    conflict, a half-finished edit), or it is Python 2 code, or it is not Python at all.

    ## Example
    ```python
    def transform_normals(R, normals:
        return normals @ R.T
    ```

    ## Use instead
    ```python
    def transform_normals(R, normals):
        return normals @ R.T
    ```

    ## Fix safety
    There is no automatic fix: only a person knows what the broken code meant.

    ## Options
    Exclude files that are not Python with `exclude`/`extend-exclude`, or turn the check off for
    them with `per-file-ignores = { "legacy/**" = ["GEO000"] }`.
    """

    code = "GEO000"
    name = "syntax-error"
    default_severity = Severity.ERROR
    # Detected by the engine before any rule runs; this visitor never fires.
    triggers = re.compile(r"(?!)")
    VALID = (Valid("normal = R @ normal\n"),)
    INVALID = (
        Invalid(
            "def transform_normals(R, normals:\n    return normals @ R.T\n",
            message="syntax error for Python 3.10-3.13: '(' was never closed",
            range=(1, 22, 1, 23),
        ),
    )

    def check(self, tree: Module) -> None:
        """Nothing to visit: the engine itself reports this code."""
