"""Two tiny rules the CLI tests register in the subprocess they start (never in pytest's own process).

They make the tests independent of what the real rules flag: GEO190 flags the name `bad_thing`
and offers a safe fix (rename it `good_thing`); GEO191 flags `risky_thing` with an unsafe fix.
"""

from __future__ import annotations

import re

import libcst as cst

from geolint.rules.base import Invalid, Rule, Valid


class BadThingRule(Rule):
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
    INVALID = (Invalid("bad_thing = 1\n", "good_thing = 1\n"),)

    def visit_Name(self, node: cst.Name) -> None:
        if node.value == "bad_thing":
            self.report(node, "`bad_thing` is bad", replacement=node.with_changes(value="good_thing"))


class RiskyThingRule(Rule):
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
    INVALID = (Invalid("risky_thing = 1\n", "safe_thing = 1\n"),)

    def visit_Name(self, node: cst.Name) -> None:
        if node.value == "risky_thing":
            self.report(
                node, "`risky_thing` is risky", replacement=node.with_changes(value="safe_thing"), applicability="unsafe"
            )


class BrokenFixRule(Rule):
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

    def visit_Name(self, node: cst.Name) -> None:
        if node.value == "breaks_fix":
            self.report(node, "`breaks_fix` has a broken fix", replacement=cst.Integer("1"))  # `1 = 2` does not compile


class CrashingRule(Rule):
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

    def visit_Name(self, node: cst.Name) -> None:
        if node.value == "crash_here":
            raise RuntimeError("this rule crashed on purpose")
