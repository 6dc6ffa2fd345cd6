"""Suppression comments through the real CLI: where they apply, and GEO900 for stale or unknown ones."""

from __future__ import annotations

import json


def findings(result) -> list[tuple[int, str]]:
    return [(f["line"], f["code"]) for f in json.loads(result.stdout)]


def test_line_end_directive_suppresses_only_its_codes_on_its_line(cli):
    cli.write(
        "mod.py",
        "a = bad_thing + risky_thing  # geolint: ignore[GEO190]\n"
        "b = bad_thing  # noqa: GEO190\n"
        "c = bad_thing  # noqa: E501, GEO190\n"
        "d = bad_thing  # type: ignore  # geolint: ignore[GEO191, GEO190]\n"
        "e = bad_thing\n",
    )
    result = cli("check", "--format", "json")
    assert findings(result) == [(1, "GEO191"), (4, "GEO900"), (5, "GEO190")]
    stale = json.loads(result.stdout)[1]
    assert "unused suppression of GEO191" in stale["message"] and stale["severity"] == "warning"


def test_own_line_directive_covers_the_whole_next_statement(cli):
    cli.write(
        "mod.py",
        "# geolint: ignore[GEO190]\n"
        "value = compute(\n"
        "    bad_thing,\n"
        "    other=bad_thing,\n"
        ")\n"
        "after = bad_thing\n"
        "if True:\n"
        "    # geolint: ignore[GEO190]\n"
        "\n"
        "    # (a blank line and a comment in between are fine)\n"
        "    nested = bad_thing\n"
        "    not_covered = bad_thing\n",
    )
    assert findings(cli("check", "--format", "json")) == [(6, "GEO190"), (12, "GEO190")]


def test_blanket_forms(cli):
    cli.write(
        "mod.py",
        "a = bad_thing + risky_thing  # noqa\n"
        "b = bad_thing  # geolint: ignore\n"
        "c = 1  # noqa\n"
        "d = 1  # geolint: ignore\n",
    )
    # a bare noqa is shared with other tools and never reported; a bare geolint ignore is
    result = cli("check", "--format", "json")
    assert findings(result) == [(4, "GEO900")]
    assert "blanket" in json.loads(result.stdout)[0]["message"]


def test_unknown_codes_are_reported_and_disabled_rules_are_not_called_unused(cli):
    cli.write(
        "mod.py",
        "a = 1  # geolint: ignore[GEO1O1]\n"
        "b = 1  # noqa: GEO999\n"
        "c = 1  # geolint: ignore[GEO191]\n",
    )
    result = cli("check", "--format", "json", "--ignore", "GEO191")
    reported = json.loads(result.stdout)
    assert [(f["line"], f["code"]) for f in reported] == [(1, "GEO900"), (2, "GEO900")]
    assert "unknown rule code GEO1O1" in reported[0]["message"]
    assert "GEO999" in reported[1]["message"]
    assert result.returncode == 1
    # GEO900 itself can be turned off like any rule
    assert findings(cli("check", "--format", "json", "--ignore", "GEO900,GEO191")) == []


def test_directive_text_inside_a_string_is_not_a_directive(cli):
    cli.write("mod.py", 'a = bad_thing; text = "# geolint: ignore[GEO190]"\n')
    assert findings(cli("check", "--format", "json")) == [(1, "GEO190")]
