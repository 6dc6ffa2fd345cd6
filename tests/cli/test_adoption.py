"""Adopting geolint on existing code: `--write-baseline` / `--baseline` and `--add-noqa`."""

from __future__ import annotations

import ast
import json

LEGACY = (
    "def legacy(a):\n"
    "    first = bad_thing\n"
    "    second = bad_thing\n"
    "    return risky_thing\n"
)


def test_baseline_hides_known_findings_even_when_code_moves(cli):
    path = cli.write("legacy.py", LEGACY)
    written = cli("check", "--write-baseline", "geolint-baseline.json")
    assert written.returncode == 0 and "Recorded 3 findings" in written.stderr
    assert cli("check", "--baseline", "geolint-baseline.json").returncode == 0

    # code added above and re-indented: the old findings stay hidden
    moved = "import os\n\n\nclass Wrapper:\n" + "".join("    " + line + "\n" for line in LEGACY.splitlines())
    path.write_text(moved)
    assert cli("check", "--baseline", "geolint-baseline.json").returncode == 0

    # a new finding (even on a copy of a known line) is reported, and only it
    path.write_text(moved + "    third = bad_thing\n    second = bad_thing\n")
    result = cli("check", "--baseline", "geolint-baseline.json", "--format", "json")
    assert result.returncode == 1
    assert [(f["line"], f["code"]) for f in json.loads(result.stdout)] == [(9, "GEO190"), (10, "GEO190")]

    # the baseline works from another cwd (paths are relative to the baseline file)
    sub = cli.project / "sub"
    sub.mkdir()
    from_sub = cli("check", "..", "--baseline", "../geolint-baseline.json", "--format", "json", cwd=sub)
    assert len(json.loads(from_sub.stdout)) == 2


def test_a_file_that_is_not_a_baseline_is_a_usage_error(cli):
    cli.write("legacy.py", LEGACY)
    cli.write("not-a-baseline.json", '{"hello": 1}')
    result = cli("check", "--baseline", "not-a-baseline.json")
    assert result.returncode == 2 and "not-a-baseline.json" in result.stderr
    assert cli("check", "--baseline", "missing.json").returncode == 2


def test_add_noqa_silences_every_finding_and_keeps_the_file_valid(cli):
    source = (
        "value = (bad_thing +\n"
        "         risky_thing)  # keep this comment\n"
        'doc = f"""{bad_thing}\n'
        '"""\n'
        "total = bad_thing + \\\n"
        "    1\n"
        "if True:\n"
        "    x = bad_thing + risky_thing  # geolint: ignore[GEO191]\n"
    )
    path = cli.write("mod.py", source)
    added = cli("check", "--add-noqa")
    assert added.returncode == 0, added.stderr
    fixed = path.read_text()
    ast.parse(fixed)
    after = cli("check", "--format", "json")
    assert json.loads(after.stdout) == [] and after.returncode == 0  # nothing left, and no GEO900
    assert "risky_thing)  # keep this comment  # geolint: ignore[GEO191]" in fixed
    assert "x = bad_thing + risky_thing  # geolint: ignore[GEO190, GEO191]" in fixed
    # where a comment cannot go at the end of the line, it goes above the statement
    assert '# geolint: ignore[GEO190]\ndoc = f"""' in fixed
    assert cli("check", "--add-noqa").returncode == 0 and path.read_text() == fixed  # idempotent
