"""`[tool.geolint]` in pyproject.toml: every key read, and every mistake an exit 2 naming file and key."""

from __future__ import annotations

import json

import pytest


def codes(result) -> list[str]:
    return [finding["code"] for finding in json.loads(result.stdout)]


def test_select_ignore_and_severity_come_from_the_nearest_pyproject(cli):
    cli.write("pyproject.toml", '[tool.geolint]\nignore = ["GEO191"]\nseverity = { GEO190 = "warning" }\n')
    cli.write("pkg/mod.py", "a = bad_thing\nb = risky_thing\n")
    result = cli("check", "--format", "json", "pkg")
    findings = json.loads(result.stdout)
    assert [f["code"] for f in findings] == ["GEO190"]
    assert findings[0]["severity"] == "warning"
    # run from a sub-folder: the same config is found by walking up
    inner = cli("check", "--format", "json", ".", cwd=cli.project / "pkg")
    assert codes(inner) == ["GEO190"]


def test_per_file_ignores_and_extend_exclude(cli):
    cli.write(
        "pyproject.toml",
        "[tool.geolint]\n"
        'extend-exclude = ["vendored/"]\n'
        '[tool.geolint.per-file-ignores]\n"tests/**" = ["GEO19"]\n"conftest.py" = ["GEO190"]\n',
    )
    cli.write("src/mod.py", "a = bad_thing\n")
    cli.write("tests/test_mod.py", "a = bad_thing\nb = risky_thing\n")
    cli.write("src/conftest.py", "a = bad_thing\nb = risky_thing\n")
    cli.write("vendored/lib.py", "a = bad_thing\n")
    result = cli("check", "--format", "json")
    assert sorted((f["path"], f["code"]) for f in json.loads(result.stdout)) == [
        ("src/conftest.py", "GEO191"),
        ("src/mod.py", "GEO190"),
    ]


def test_exclude_replaces_the_defaults(cli):
    cli.write("pyproject.toml", '[tool.geolint]\nexclude = ["skip_me/"]\n')
    cli.write("build/gen.py", "a = bad_thing\n")
    cli.write("skip_me/x.py", "a = bad_thing\n")
    result = cli("check", "--format", "json")
    assert [f["path"] for f in json.loads(result.stdout)] == ["build/gen.py"]


def test_all_documented_keys_are_accepted_in_kebab_and_snake_case(cli):
    cli.write(
        "pyproject.toml",
        "[tool.geolint]\n"
        'select = ["GEO"]\n'
        'extra-direction-names = ["surface_dir"]\n'
        'extra_point_names = ["keypoint"]\n'
        "[tool.geolint.naming]\n"
        "monogram = false\n"
        "prefix-t = true\n"
        "to_style = false\n"
        "[tool.geolint.frame-aliases]\n"
        'cam = "camera"\n',
    )
    cli.write("mod.py", "a = bad_thing\n")
    result = cli("check", "--format", "json", "--verbose")
    assert result.returncode == 1, result.stderr
    assert codes(result) == ["GEO190"]
    assert "pyproject.toml" in result.stderr  # --verbose names the config in use


@pytest.mark.parametrize(
    ("table", "key"),
    [
        ('selct = ["GEO"]', "selct"),
        ('select = "GEO1"', "select"),
        ('ignore = ["E501"]', "ignore"),
        ("[tool.geolint.naming]\nhungarian = true", "naming.hungarian"),
        ('[tool.geolint.naming]\nmonogram = "yes"', "naming.monogram"),
        ('[tool.geolint.severity]\nGEO101 = "fatal"', "severity.GEO101"),
        ("extra-point-names = [\"not a name\"]", "extra-point-names"),
        ('[tool.geolint.per-file-ignores]\n"tests/*" = "GEO1"', "per-file-ignores.tests/*"),
        # well-formed codes that name no rule: a typo must not turn geolint off in silence
        ('select = ["GEO999"]', "select"),
        ('extend-select = ["GEO8"]', "extend-select"),
        ('ignore = ["GEO199"]', "ignore"),
        ('[tool.geolint.per-file-ignores]\n"tests/*" = ["GEO55"]', "per-file-ignores.tests/*"),
        ('[tool.geolint.severity]\nGEO999 = "warning"', "severity.GEO999"),
    ],
)
def test_bad_config_exits_2_naming_the_file_and_the_key(cli, table, key):
    pyproject = cli.write("pyproject.toml", f"[tool.geolint]\n{table}\n")
    cli.write("mod.py", "a = bad_thing\n")
    result = cli("check")
    assert result.returncode == 2
    assert str(pyproject.resolve()) in result.stderr
    assert f"'{key}'" in result.stderr
    assert result.stdout == ""


def test_extend_select_adds_to_select_and_an_unknown_code_says_which(cli):
    cli.write("pyproject.toml", '[tool.geolint]\nselect = ["GEO190"]\nextend-select = ["GEO191"]\n')
    cli.write("mod.py", "a = bad_thing\nb = risky_thing\n")
    assert codes(cli("check", "--format", "json")) == ["GEO190", "GEO191"]
    cli.write("pyproject.toml", '[tool.geolint]\nselect = ["GEO999"]\n')
    result = cli("check")
    assert result.returncode == 2 and result.stdout == ""
    assert "unknown rule selector 'GEO999'" in result.stderr and "All checks passed" not in result.stderr


def test_invalid_toml_and_missing_config_file_exit_2(cli):
    pyproject = cli.write("pyproject.toml", "[tool.geolint\nselect = [\n")
    cli.write("mod.py", "a = 1\n")
    result = cli("check")
    assert result.returncode == 2 and "invalid TOML" in result.stderr and str(pyproject.resolve()) in result.stderr
    missing = cli("check", "--config", "nope.toml")
    assert missing.returncode == 2 and "nope.toml" in missing.stderr


def test_explicit_config_file(cli, tmp_path):
    elsewhere = tmp_path / "shared.toml"
    elsewhere.write_text('[tool.geolint]\nselect = ["GEO191"]\n')
    cli.write("mod.py", "a = bad_thing\nb = risky_thing\n")
    assert codes(cli("check", "--format", "json", "--config", str(elsewhere))) == ["GEO191"]


def test_exclude_patterns_as_one_regex_answer_as_pathspec() -> None:
    """Exclude patterns without a negation are matched as one regex; on paths built from the
    patterns' own pieces it must answer exactly as pathspec's GitIgnoreSpec does."""
    import itertools
    import random

    from geolint.files import DEFAULT_EXCLUDES, _any_pattern, _spec

    specs = [DEFAULT_EXCLUDES, ("build", "docs/_build/", "*.pyc", "/top_only", "a/**/b", "data?")]
    pieces = ["build", ".git", "x.egg-info", "venv", "docs", "_build", "top_only", "a", "b", "c", "data1", "data", "m.py", "n.pyc", "__pycache__"]
    rng = random.Random(9)
    paths = ["/".join(rng.choice(pieces) for _ in range(rng.randint(1, 4))) for _ in range(3000)]
    paths += ["/".join(parts) for parts in itertools.product(pieces[:6], pieces[6:])]
    for patterns in specs:
        spec = _spec(patterns)
        fast = _any_pattern(patterns)
        assert fast is not None
        for path in paths:
            for text in (path, path + "/"):
                assert (fast.match(text) is not None) == bool(spec.match_file(text)), (patterns, text)
    assert _any_pattern(("build", "!build/keep.py")) is None  # a negation: pathspec decides
