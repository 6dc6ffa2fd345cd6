"""Two tiny rules the CLI tests register in the subprocess they start (never in pytest's own process).

They make the tests independent of what the real rules flag: GEO190 flags the name `bad_thing`
and offers a safe fix (rename it `good_thing`); GEO191 flags `risky_thing` with an unsafe fix.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator

from geolint.rules.base import AstRule, Invalid, Valid


def names(tree: ast.Module, name: str) -> Iterator[ast.Name]:
    """Every use or binding of the name `name`."""
    return (node for node in ast.walk(tree) if isinstance(node, ast.Name) and node.id == name)


class BadThingRule(AstRule):
    """## What it does
    Flags the name `bad_thing` (a stand-in rule for the CLI tests).

    ## Why is this bad?
    It is a test double.

    ## Example
    ```python
    bad_thing = 1
    ```

    ## Use instead
    ```python
    good_thing = 1
    ```

    ## Fix safety
    Safe: renames the name.
    """

    code = "GEO190"
    name = "bad-thing"
    triggers = re.compile(r"\bbad_thing\b")
    VALID = (Valid("good_thing = 1\n"),)
    INVALID = (Invalid("bad_thing = 1\n", "good_thing = 1\n", message="`bad_thing` is bad", range=(1, 1, 1, 10)),)

    def check(self, tree: ast.Module) -> None:
        for node in names(tree, "bad_thing"):
            self.report(node, "`bad_thing` is bad", replacement="good_thing")


class RiskyThingRule(AstRule):
    """## What it does
    Flags the name `risky_thing` (a stand-in rule for the CLI tests).

    ## Why is this bad?
    It is a test double.

    ## Example
    ```python
    risky_thing = 1
    ```

    ## Use instead
    ```python
    safe_thing = 1
    ```

    ## Fix safety
    Unsafe: renaming might change behaviour.
    """

    code = "GEO191"
    name = "risky-thing"
    triggers = re.compile(r"\brisky_thing\b")
    VALID = (Valid("safe_thing = 1\n"),)
    INVALID = (Invalid("risky_thing = 1\n", "safe_thing = 1\n", message="`risky_thing` is risky", range=(1, 1, 1, 12)),)

    def check(self, tree: ast.Module) -> None:
        for node in names(tree, "risky_thing"):
            self.report(node, "`risky_thing` is risky", replacement="safe_thing", applicability="unsafe")


class BrokenFixRule(AstRule):
    """## What it does
    Flags the name `breaks_fix` and offers a fix that would not parse (tests that such fixes are dropped).

    ## Why is this bad?
    It is a test double.

    ## Example
    ```python
    breaks_fix = 1
    ```

    ## Use instead
    ```python
    fine = 1
    ```

    ## Fix safety
    Its fix is deliberately broken.
    """

    code = "GEO192"
    name = "broken-fix"
    triggers = re.compile(r"\bbreaks_fix\b")

    def check(self, tree: ast.Module) -> None:
        for node in names(tree, "breaks_fix"):
            self.report(node, "`breaks_fix` has a broken fix", replacement="1")  # `1 = 2` does not compile


class CrashingRule(AstRule):
    """## What it does
    Raises on the name `crash_here` (tests that an internal error in one file does not stop the run).

    ## Why is this bad?
    It is a test double.

    ## Example
    ```python
    crash_here = 1
    ```

    ## Use instead
    ```python
    calm = 1
    ```

    ## Fix safety
    No fix.
    """

    code = "GEO193"
    name = "crashing-rule"
    triggers = re.compile(r"\bcrash_here\b")

    def check(self, tree: ast.Module) -> None:
        for _ in names(tree, "crash_here"):
            raise RuntimeError("this rule crashed on purpose")
