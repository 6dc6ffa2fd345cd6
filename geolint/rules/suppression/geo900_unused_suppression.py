"""GEO900 unused-suppression: the pseudo-rule the engine reports for a suppression comment that does nothing."""

from __future__ import annotations

import re
from ast import Module

from geolint.lint_types import Severity
from geolint.rules.base import AstRule, Invalid, Valid


class UnusedSuppressionRule(AstRule):
    """## What it does
    Reports a suppression comment (`# geolint: ignore[...]` or `# noqa: GEO...`) that suppresses
    nothing, or that names a rule code that does not exist.

    A code is only called unused when its rule is enabled for the file: with a rule turned off by
    `select`/`ignore`/`per-file-ignores`, geolint cannot know whether the comment is still needed.
    A bare `# noqa` is shared with other tools (flake8, ruff) and is never reported; a bare
    `# geolint: ignore` is.

    ## Why is this bad?
    A suppression outlives the finding it silenced: once the code is fixed (or moved), the
    comment stays and will silently hide the next real bug on that line. A misspelt code
    (`GEO1O1`) suppresses nothing and gives a false sense of safety.

    ## Example
    ```python
    normal_world = R_world_cam @ normal_cam  # geolint: ignore[GEO101]
    ```

    ## Use instead
    ```python
    normal_world = R_world_cam @ normal_cam
    ```

    ## Fix safety
    There is no automatic fix yet; delete the comment or the stale code from it.

    ## Options
    Ignore this code (`ignore = ["GEO900"]`) to keep stale suppressions without being told.
    """

    code = "GEO900"
    name = "unused-suppression"
    default_severity = Severity.WARNING
    # Detected by the engine after all rules ran; this visitor never fires.
    triggers = re.compile(r"(?!)")
    VALID = (Valid("normal_world = R_world_cam @ normal_cam  # noqa: E501\n"),)
    INVALID = (
        Invalid(
            "normal_world = R_world_cam @ normal_cam  # geolint: ignore[GEO999]\n",
            message="unknown rule code GEO999 in suppression",
            range=(1, 42, 1, 67),
        ),
    )

    def check(self, tree: Module) -> None:
        """Nothing to visit: the engine itself reports this code."""
