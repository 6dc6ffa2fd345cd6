"""`--fix`, `--unsafe-fixes`, `--diff`, `--exit-non-zero-on-fix`: formatting kept, always parses, idempotent."""

from __future__ import annotations

import ast
import json

SOURCE = (
    "# a comment that must survive\n"
    "def f(x):\n"
    "    total = (bad_thing   +   risky_thing)  # spacing kept\n"
    "    return total * bad_thing\n"
)


def test_fix_applies_safe_fixes_only_and_reports_what_remains(cli):
    path = cli.write("mod.py", SOURCE)
    result = cli("check", "--fix", "--format", "json")
    assert path.read_text() == SOURCE.replace("bad_thing", "good_thing")
    remaining = json.loads(result.stdout)
    assert [f["code"] for f in remaining] == ["GEO191"]  # the unsafe one stays
    assert result.returncode == 1
    assert "Fixed 2 findings" in result.stderr


def test_unsafe_fixes_and_exit_non_zero_on_fix(cli):
    path = cli.write("mod.py", SOURCE)
    result = cli("check", "--fix", "--unsafe-fixes", "--exit-non-zero-on-fix")
    assert path.read_text() == SOURCE.replace("bad_thing", "good_thing").replace("risky_thing", "safe_thing")
    assert result.returncode == 1 and result.stdout == "Fixed 3 findings. All checks passed.\n"  # nothing left, but files changed
    again = cli("check", "--fix", "--unsafe-fixes", "--exit-non-zero-on-fix")
    assert again.returncode == 0  # idempotent: the second run has nothing to do
    assert path.read_text() == SOURCE.replace("bad_thing", "good_thing").replace("risky_thing", "safe_thing")


def test_diff_shows_the_fix_and_writes_nothing(cli):
    path = cli.write("pkg/mod.py", SOURCE)
    result = cli("check", "--diff")
    assert path.read_text() == SOURCE
    assert result.returncode == 1
    assert result.stdout.startswith("--- a/pkg/mod.py\n+++ b/pkg/mod.py\n")
    assert "-    return total * bad_thing\n" in result.stdout
    assert "+    return total * good_thing\n" in result.stdout
    assert "risky_thing" not in [line[1:].strip() for line in result.stdout.splitlines() if line.startswith("+")]
    clean = cli.write("pkg/mod.py", "x = 1\n")
    assert cli("check", "--diff").returncode == 0 and clean.read_text() == "x = 1\n"


def test_a_fix_that_would_break_the_file_is_dropped(cli):
    source = "breaks_fix = 2\nvalue = bad_thing\n"
    path = cli.write("mod.py", source)
    result = cli("check", "--fix", "--format", "json")
    fixed = path.read_text()
    ast.parse(fixed)
    assert fixed == "breaks_fix = 2\nvalue = good_thing\n"
    assert [f["code"] for f in json.loads(result.stdout)] == ["GEO192"]


def test_fix_keeps_encoding_bom_and_line_endings(cli):
    latin = cli.write("latin.py", "# -*- coding: latin-1 -*-\nname = 'café'\nx = bad_thing\n", encoding="latin-1")
    crlf = cli.project / "crlf.py"
    crlf.write_bytes(b"\xef\xbb\xbfa = 1\r\nx = bad_thing\r\n")
    result = cli("check", "--fix")
    assert result.returncode == 0, result.stdout + result.stderr
    assert latin.read_bytes() == "# -*- coding: latin-1 -*-\nname = 'café'\nx = good_thing\n".encode("latin-1")
    assert crlf.read_bytes() == b"\xef\xbb\xbfa = 1\r\nx = good_thing\r\n"
