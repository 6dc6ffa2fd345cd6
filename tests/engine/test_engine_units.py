"""Unit tests of the engine's pure parts: suppression scanning, selection, config reading, edits, baseline keys.

These run in-process and define no rule classes (a rule class defined here would leak into the
registry other tests read); rule behaviour through the CLI is covered in tests/cli.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from geolint.baseline import finding_keys
from geolint.config import ConfigError, config_from_table, enabled_codes, is_selected
from geolint.engine import apply_edits, cached_ast, lint_bytes, lint_source, split_lines
from geolint.lint_types import Config, Edit, Finding, NamingConventions, Severity
from geolint.suppression import add_suppressions, parse_directives


def directive_summary(source: str) -> list[tuple[int, str, tuple[str, ...] | None, bool, int, int]]:
    return [(d.line, d.kind, d.codes, d.own_line, d.first_line, d.last_line) for d in parse_directives(source)]


def test_directives_inside_strings_are_ignored_and_after_strings_are_found():
    source = (
        '"""A docstring that shows an example:\n'
        "    x = 1  # geolint: ignore[GEO101]\n"
        '"""\n'
        'text = "# noqa: GEO101"  # a real comment  # noqa: GEO102\n'
        'block = """\n'
        '# geolint: ignore[GEO103]\n'
        '"""  # geolint: ignore[GEO104]\n'
        "value = f'{1}'  # geolint: ignore[GEO201]\n"
    )
    assert directive_summary(source) == [
        (4, "noqa", ("GEO102",), False, 4, 4),
        (7, "geolint", ("GEO104",), False, 7, 7),
        (8, "geolint", ("GEO201",), False, 8, 8),
    ]


def test_own_line_directive_spans_the_next_statement_or_a_compound_header():
    source = (
        "# geolint: ignore[GEO101]\n"
        "x = f(\n"
        "    1,\n"
        ")\n"
        "# noqa: GEO102\n"
        "for item in (\n"
        "    a,\n"
        "):\n"
        "    body = 1\n"
        "values = [\n"
        "    # geolint: ignore[GEO103]\n"
        "    first,\n"
        "    second,\n"
        "]\n"
    )
    assert directive_summary(source) == [
        (1, "geolint", ("GEO101",), True, 2, 4),
        (5, "noqa", ("GEO102",), True, 6, 8),
        (11, "geolint", ("GEO103",), True, 12, 12),  # inside brackets: the next line only
    ]


def test_directive_grammar():
    assert directive_summary("x = 1  # GEOLINT: Ignore[geo101,GEO102 GEO103]\n")[0][2] == ("GEO101", "GEO102", "GEO103")
    assert directive_summary("x = 1  # noqa\n")[0][2] is None
    assert directive_summary("x = 1  # noqa: E501,W291\n") == []  # only other tools' codes
    assert directive_summary("x = 1  # noqa:E501,GEO101\n")[0][2] == ("GEO101",)
    assert directive_summary("x = 1  # geolint: ignore\n")[0][2] is None


def test_directives_in_a_file_cpython_cannot_parse_are_still_found():
    source = "def f(:\n    pass  # geolint: ignore[GEO101]\n"
    assert [(d.line, d.codes) for d in parse_directives(source)] == [(2, ("GEO101",))]


def test_selection_by_prefix_most_specific_wins():
    assert is_selected("GEO101", ("GEO",), ())
    assert not is_selected("GEO101", ("GEO2",), ())
    assert not is_selected("GEO101", ("GEO",), ("GEO1",))
    assert is_selected("GEO101", ("GEO101",), ("GEO1",))
    assert not is_selected("GEO101", ("GEO1",), ("GEO1",))  # a tie: ignore wins


def test_per_file_ignores_are_relative_to_the_config_root(tmp_path: Path):
    config = Config(per_file_ignores={"tests/**": ("GEO1",), "conftest.py": ("GEO2",)}, source=tmp_path / "pyproject.toml")
    codes = ("GEO101", "GEO201")
    assert enabled_codes(config, str(tmp_path / "src" / "a.py"), codes) == codes
    assert enabled_codes(config, str(tmp_path / "tests" / "deep" / "t.py"), codes) == ("GEO201",)
    assert enabled_codes(config, str(tmp_path / "src" / "conftest.py"), codes) == ("GEO101",)


def test_config_table_reading():
    config = config_from_table(
        {
            "select": ["GEO1"],
            "per-file-ignores": {"a.py": ["GEO101"]},
            "naming": {"prefix-t": False, "monogram": False},
            "frame_aliases": {"cam": "camera"},
            "severity": {"GEO101": "hint"},
        },
        Path("pyproject.toml"),
    )
    assert config.select == ("GEO1",)
    assert config.naming == NamingConventions(prefix_t=False, monogram=False)
    assert config.frame_aliases == {"cam": "camera"}
    assert config.severity == {"GEO101": Severity.HINT}
    with pytest.raises(ConfigError, match=r"pyproject.toml: \[tool.geolint\] key 'naming.monogrm'.*did you mean 'monogram'"):
        config_from_table({"naming": {"monogrm": True}}, Path("pyproject.toml"))


def test_split_lines_and_apply_edits_count_lines_like_libcst():
    source = "a = 1\r\nb = '\x0c'\rc = 2\n"
    assert split_lines(source) == ["a = 1\r\n", "b = '\x0c'\r", "c = 2\n"]
    edited = apply_edits(source, [Edit(3, 1, 3, 2, "z"), Edit(1, 5, 1, 6, "10")])
    assert edited == "a = 10\r\nb = '\x0c'\rz = 2\n"
    assert apply_edits("x = 1", [Edit(1, 6, 1, 6, "\n")]) == "x = 1\n"


def test_syntax_and_decoding_problems_are_findings_never_exceptions():
    [syntax] = lint_source("def f(:\n")
    assert (syntax.code, syntax.line) == ("GEO000", 1)
    [decoding] = lint_bytes(b"a = 1\nb = '\xe9'\n")
    assert (decoding.code, decoding.line, decoding.column) == ("GEO000", 2, 6)
    assert lint_bytes(b"# -*- coding: latin-1 -*-\nb = '\xe9'\n") == []
    assert lint_source("x = 1\n", config=Config(ignore=("GEO000",))) == []
    assert lint_source("def f(:\n", config=Config(ignore=("GEO000",))) == []


def test_cached_ast_parses_each_text_once():
    text = "x = 1\n"
    assert cached_ast(text) is cached_ast(text)
    with pytest.raises(SyntaxError):
        cached_ast("def f(:\n")


def test_a_file_no_selected_rule_can_read_is_parsed_only_when_a_check_needs_its_tree(tmp_path: Path):
    from geolint import source_text

    def parsed(source: str, config: Config) -> bool:
        path = tmp_path / f"m{len(list(tmp_path.iterdir()))}.py"
        path.write_text(source)
        source_text._last_tree.value = None
        lint_source(source, str(path), config)
        last = source_text._last_tree.value  # the tree the engine parsed last, with its text
        return last is not None and last[0] is source

    no_geometry = "import json\nrows = json.loads(text)\n"
    geometry = "normal_world = T_world_cam @ normal_h\n"
    semantic_only = Config(select=("GEO1", "GEO2", "GEO3"))
    assert not parsed(no_geometry, semantic_only)  # nothing to read it: not parsed
    assert parsed(geometry, semantic_only)
    assert parsed(no_geometry, Config())  # the syntax check (GEO000) reads every file
    assert parsed(no_geometry + "# geolint: ignore[GEO101]\n", Config(select=("GEO1", "GEO900")))  # is the directive unused?
    assert lint_source("def f(:\n", config=semantic_only) == []


def test_add_suppressions_extends_existing_directives_and_respects_strings():
    source = 'x = a  # geolint: ignore[GEO102]\ny = """\n  b\n"""\n'
    findings = [_finding(1, "GEO101"), _finding(3, "GEO103")]
    assert add_suppressions(source, findings) == (
        'x = a  # geolint: ignore[GEO101, GEO102]\n# geolint: ignore[GEO103]\ny = """\n  b\n"""\n'
    )


def test_baseline_keys_ignore_line_numbers_and_indentation(tmp_path: Path):
    before = tmp_path / "a.py"
    before.write_text("x = bad\nx = bad\n")
    keys_before = finding_keys([_finding(1, "GEO101", str(before)), _finding(2, "GEO101", str(before))], tmp_path)
    assert keys_before == [("GEO101", "a.py", "x=bad", 0), ("GEO101", "a.py", "x=bad", 1)]


def _finding(line: int, code: str, path: str = "<string>") -> Finding:
    return Finding(path, line, 1, line, 2, code, "name", "message", Severity.ERROR)


def test_the_fact_base_walk_measures_depth_as_the_guards_do() -> None:
    """The engine measures the nesting depth on the fact base's index walk when a rule runs; it must
    find the same verdict and the same first node past the limit as the guards' level-by-level walk."""
    import ast

    from geolint import guards
    from geolint.factbase.index import ModuleIndex

    sources = [
        "total_world = p_cam + " + " + ".join(f"v{i}_world" for i in range(60)) + "\n",
        "x = " + "-" * 50 + "a\n",
        "x = a < b < (c < d)\n",
        "def f():\n" + "".join("    " * (i + 1) + "if a:\n" for i in range(12)) + "    " * 13 + "pass\n",
        "f = " + "lambda: " * 30 + "1\n",
        "y = " + "[" * 30 + "]" * 30 + "\nz = {'a': [(1, 2)]}\n",
        "w = f" + "()" * 40 + "\nv = a" + ".b" * 40 + "\n",
        "class A:\n    def g(self, x=lambda: (" + "1+" * 30 + "1)):\n        return [i for i in r if i < 2 < 3]\n",
        "with a as (b, c):\n    try:\n        pass\n    except E as e:\n        match x:\n            case [1, *r]:\n                pass\n",
    ]
    compared = 0
    for source in sources:
        tree = ast.parse(source)
        for limit in range(2, 64, 3):
            expected = guards.too_deep(tree, limit)
            index = ModuleIndex(tree, source, limit)
            found = guards.past_depth_limit(index.too_deep_at, limit) if index.too_deep else None
            assert found == expected, (source[:40], limit)
            compared += expected is not None
    assert compared > 50  # most cases are past the limit somewhere


def test_import_scan_finds_what_the_anchored_regex_finds() -> None:
    """The cache's dependency digest scans only the lines that hold "import"; on random text it must
    find exactly the module names the line-anchored regex finds."""
    import random

    from geolint.factbase.project_files import _IMPORT, imported_names

    pieces = ["from", "import", " ", "\t", "\n", "\r", "a", ".", "x", "os", "#", "fromimport", "_", "é"]
    rng = random.Random(7)
    for _ in range(20_000):
        text = "".join(rng.choice(pieces) for _ in range(rng.randint(1, 10)))
        assert imported_names(text) == [m.group(1) or m.group(2) for m in _IMPORT.finditer(text)], text
    assert imported_names("import os\n  from .utils import f\nx = 'import y'\n") == ["os", ".utils"]


def test_a_run_leaves_the_cycle_collector_as_it_found_it(tmp_path: Path) -> None:
    """`lint_paths` raises the collector's threshold while linting; afterwards the threshold is the
    caller's again, nothing stays frozen, and what the run allocated is not left as a young backlog."""
    import gc

    from geolint.api import lint_paths

    (tmp_path / "pose.py").write_text("import numpy as np\n\ndef f(T, p):\n    return T[:3, :3] @ p + T[:3, 3]\n")
    before = gc.get_threshold()
    list(lint_paths([tmp_path], Config(select=("GEO1", "GEO2", "GEO3")), use_cache=False))
    assert gc.get_threshold() == before
    assert gc.get_freeze_count() == 0
    assert gc.get_count()[0] < 1_000


def test_the_directive_precheck_answers_as_its_regex() -> None:
    """`may_have_directives` first looks for its keywords in the lowered text; on random text, with
    the characters `re.IGNORECASE` matches to `i` (`ı`, `İ`), it must answer as `CANDIDATE_LINE`."""
    import random

    from geolint.suppression import CANDIDATE_LINE, may_have_directives

    pieces = ["#", "# ", "noqa", "NOQA", "nOqA", "geolint", "GEOLINT", "geolİnt", "geolınt", "geol", "int", "no", "qa", "\n", "\r", "x", "İ", "ı", "K", ":"]
    rng = random.Random(20261128)
    for _ in range(20_000):
        text = "".join(rng.choice(pieces) for _ in range(rng.randint(1, 8)))
        assert may_have_directives(text) == (CANDIDATE_LINE.search(text) is not None), text
