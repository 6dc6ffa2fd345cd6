"""The `AstRule` contract: the engine runs `check` on the cached `ast`, turns reports into findings
with character columns, and turns replacement text into a fix over exactly the node's span, built
through libcst only for a file that has one."""

from __future__ import annotations

import ast
import subprocess
import sys
from collections.abc import Iterator

import pytest

from geolint import cst_fixes
from geolint.engine import apply_edits, lint_source
from geolint.fixes import fix_source
from geolint.lint_types import Severity
from geolint.rules import all_rules
from geolint.rules.base import AstRule, Invalid, RuleContext, Valid


def make_rule() -> type[AstRule]:
    """A tiny rule, made per test and dropped after it, so it never joins the real registry."""

    class DoubledPoint(AstRule):
        """## What it does
        Flags `p + p` (a name added to itself) in these tests.

        ## Why is this bad?
        A test needs a rule.

        ## Example
        ```python
        q = p + p
        ```

        ## Use instead
        ```python
        q = 2 * p
        ```

        ## Fix safety
        Safe.
        """

        code = "GEO998"
        name = "doubled-point"
        default_severity = Severity.WARNING
        VALID = (Valid("q = p + r\n"),)
        INVALID = (Invalid("q = p + p\n", expected_fix="q = 2 * p\n"),)

        def check(self, tree: ast.Module) -> None:
            assert isinstance(self.context, RuleContext) and self.context.source
            for node in ast.walk(tree):
                if (
                    isinstance(node, ast.BinOp)
                    and isinstance(node.op, ast.Add)
                    and isinstance(node.left, ast.Name)
                    and isinstance(node.right, ast.Name)
                    and node.left.id == node.right.id
                ):
                    self.report(node, "a name added to itself", replacement=f"2 * {node.left.id}", fix_description="double it")

    return DoubledPoint


@pytest.fixture
def rule() -> Iterator[type[AstRule]]:
    made = make_rule()
    yield made
    del made.code  # a class without its own `code` is not a rule: it cannot join the registry later
    all_rules.cache_clear()


def test_findings_use_character_columns_after_non_ascii_text(rule: type[AstRule]) -> None:
    source = 'label = "Punkt größer"; q = p + p\n'
    (finding,) = lint_source(source, "x.py", rules=[rule])
    start = source.index("p + p")
    assert (finding.line, finding.column, finding.end_column) == (1, start + 1, start + len("p + p") + 1)
    assert finding.severity == Severity.WARNING and finding.name == "doubled-point"
    assert apply_edits(source, finding.fix.edits) == 'label = "Punkt größer"; q = 2 * p\n'


def test_multi_line_node_and_replacement(rule: type[AstRule]) -> None:
    source = "é = 1\nq = (pß +\n     pß)\n"
    (finding,) = lint_source(source, "x.py", rules=[rule])
    assert (finding.line, finding.column, finding.end_line, finding.end_column) == (2, 6, 3, 8)
    assert apply_edits(source, finding.fix.edits) == "é = 1\nq = (2 * pß)\n"


def test_examples_through_the_engine(rule: type[AstRule]) -> None:
    for example in [*rule.VALID, *rule.INVALID]:
        check_example(rule, example)


def check_example(rule: type[AstRule], example: Valid | Invalid) -> None:
    found = lint_source(example.code, "x.py", rules=[rule])
    if isinstance(example, Valid):
        assert found == []
    else:
        assert len(found) == 1 and apply_edits(example.code, found[0].fix.edits) == example.expected_fix


def test_a_file_without_a_fix_is_never_parsed_with_libcst(rule: type[AstRule], monkeypatch: pytest.MonkeyPatch) -> None:
    def refuse(source: str):  # type: ignore[no-untyped-def]
        raise AssertionError("libcst parse for a file without a fix")

    monkeypatch.setattr(cst_fixes, "_parse", refuse)
    assert lint_source("q = p + r\n", "x.py", rules=[rule]) == []
    pose_rule = next(registered for registered in all_rules() if registered.code == "GEO105")  # no fix
    source = "import numpy as np\nR = np.eye(3)\nR[:3, 3] = t\n"
    assert [(f.code, f.fix) for f in lint_source(source, "x.py", rules=[pose_rule])] == [("GEO105", None)]


def test_a_fix_is_built_and_applied_on_one_libcst_parse(rule: type[AstRule], monkeypatch: pytest.MonkeyPatch) -> None:
    parsed: list[str] = []
    parse = cst_fixes._parse
    monkeypatch.setattr(cst_fixes, "_parse", lambda source: parsed.append(source) or parse(source))
    source = "".join(["q = p + p", "\n"])  # a text no earlier test left parsed
    outcome = fix_source(source, "x.py", rules=[rule])
    assert outcome.source == "q = 2 * p\n" and outcome.fixed == 1
    assert parsed == [source]  # the fixed text has no finding left: not parsed again


def test_a_test_rule_does_not_leak_into_the_registry() -> None:
    assert "GEO998" not in {registered.code for registered in all_rules()}


def test_importing_the_ast_base_does_not_import_libcst() -> None:
    code = "import sys, geolint.rules.base, geolint.engine; print('libcst' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"


def test_linting_findings_without_fixes_does_not_import_libcst() -> None:
    code = (
        "import sys, geolint.engine as e\n"
        "found = e.lint_source('import numpy as np\\nR = np.eye(3)\\nR[:3, 3] = t\\n', 'x.py')\n"
        "print([f.code for f in found], 'libcst' in sys.modules)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "['GEO105'] False"
