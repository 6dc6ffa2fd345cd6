"""What a ruff user types on the first day, run through the real CLI in a subprocess: stdin,
`--exclude`, `--output-format concise|full`, `--show-fixes`, severities in the text output and the
exit code, one config per project when several are named, `geolint rule --all`, `geolint rules`
wrapped to the terminal, and `--watch`."""

from __future__ import annotations

import json
import os
import selectors
import signal
import subprocess
import time
from pathlib import Path

from tests.cli.conftest import cli_env, launch_geolint

BAD = "a = bad_thing\nb = risky_thing\n"


def codes(result) -> list[str]:
    return [finding["code"] for finding in json.loads(result.stdout)]


# ---- stdin --------------------------------------------------------------------------------------


def test_stdin_is_linted_as_the_file_it_names(cli):
    cli.write("pyproject.toml", '[tool.geolint]\n[tool.geolint.per-file-ignores]\n"tests/**" = ["GEO191"]\n')
    as_source = cli("check", "-", "--stdin-filename", "src/mod.py", "--output-format", "json", input=BAD)
    assert as_source.returncode == 1, as_source.stderr
    assert [(f["path"], f["code"]) for f in json.loads(as_source.stdout)] == [("src/mod.py", "GEO190"), ("src/mod.py", "GEO191")]
    # the name decides which per-file-ignores apply (nothing is read from disk: src/ does not exist)
    as_test = cli("check", "--stdin-filename", "tests/test_mod.py", "--output-format", "json", input=BAD)
    assert codes(as_test) == ["GEO190"]
    # the text format shows the line that came in
    text = cli("check", "-", "--stdin-filename", "src/mod.py", input=BAD)
    assert text.stdout.splitlines()[:2] == ["src/mod.py:1:5: GEO190 `bad_thing` is bad", "  | a = bad_thing"]
    clean = cli("check", "-", input="good_thing = 1\n")
    assert clean.returncode == 0 and clean.stdout == "All checks passed.\n"


def test_stdin_fix_prints_the_fixed_text_and_reports_on_stderr(cli):
    result = cli("check", "-", "--stdin-filename", "mod.py", "--fix", input=BAD)
    assert result.returncode == 1  # the unsafe fix was not applied: GEO191 remains
    assert result.stdout == "a = good_thing\nb = risky_thing\n"
    assert "mod.py:2:5: GEO191" in result.stderr and "Fixed 1 finding." in result.stderr
    unsafe = cli("check", "-", "--fix", "--unsafe-fixes", input=BAD)
    assert unsafe.returncode == 0 and unsafe.stdout == "a = good_thing\nb = safe_thing\n"
    diff = cli("check", "-", "--stdin-filename", "mod.py", "--diff", input=BAD)
    assert diff.returncode == 1 and "-a = bad_thing\n+a = good_thing\n" in diff.stdout
    # with --force-exclude, an excluded name gets no findings and its text back unchanged
    cli.write("pyproject.toml", '[tool.geolint]\nextend-exclude = ["generated/"]\n')
    excluded = cli("check", "-", "--stdin-filename", "generated/out.py", "--force-exclude", "--fix", input=BAD)
    assert excluded.returncode == 0 and excluded.stdout == BAD
    assert cli("check", "-", "src", input=BAD).returncode == 2  # stdin and paths together


# ---- file selection -----------------------------------------------------------------------------


def test_exclude_and_extend_exclude_on_the_command_line(cli):
    cli.write("pyproject.toml", '[tool.geolint]\nexclude = ["skipped_by_config/"]\n')
    for folder in ("src", "skipped_by_config", "skip_a", "skip_b", "build"):
        cli.write(f"{folder}/mod.py", "x = bad_thing\n")

    def paths(*options: str) -> list[str]:
        return sorted({f["path"] for f in json.loads(cli("check", "--output-format", "json", *options).stdout)})

    assert paths() == ["build/mod.py", "skip_a/mod.py", "skip_b/mod.py", "src/mod.py"]
    # --exclude replaces the config's exclude (and the defaults, as the config's does)
    assert paths("--exclude", "skip_a/,skip_b/") == ["build/mod.py", "skipped_by_config/mod.py", "src/mod.py"]
    # --extend-exclude adds to it; it may be given more than once
    assert paths("--extend-exclude", "skip_a/", "--extend-exclude", "skip_b/") == ["build/mod.py", "src/mod.py"]


def test_each_project_named_keeps_its_own_config(cli):
    cli.write("one/pyproject.toml", '[tool.geolint]\nselect = ["GEO190"]\n')
    cli.write("two/pyproject.toml", '[tool.geolint]\nselect = ["GEO191"]\n')
    cli.write("two/vendored/pyproject.toml", '[tool.geolint]\nselect = ["GEO19"]\nexclude = ["skipped.py"]\n')
    for folder in ("one", "two", "two/vendored", "three"):
        cli.write(f"{folder}/mod.py", BAD)
    cli.write("two/vendored/skipped.py", BAD)
    result = cli("check", "one", "two", "three", "--output-format", "json")
    assert result.returncode == 1, result.stderr
    found = sorted((f["path"], f["code"]) for f in json.loads(result.stdout))
    assert found == [
        ("one/mod.py", "GEO190"),
        ("three/mod.py", "GEO190"),  # no config of its own: the defaults
        ("three/mod.py", "GEO191"),
        ("two/mod.py", "GEO191"),
        ("two/vendored/mod.py", "GEO190"),  # the sub-project's config, and its exclude
        ("two/vendored/mod.py", "GEO191"),
    ]
    # --config names one config for every file
    shared = cli("check", "one", "two", "--config", "one/pyproject.toml", "--output-format", "json")
    assert sorted(set(codes(shared))) == ["GEO190"] and len(codes(shared)) == 4


# ---- output -------------------------------------------------------------------------------------


def test_concise_and_full_output_formats(cli):
    cli.write("mod.py", "import os\n\n\nvalue = (1 +\n         bad_thing)\nrisky_thing = 2\n")
    concise = cli("check", "--output-format", "concise")
    assert concise.returncode == 1
    assert concise.stdout.splitlines() == [
        "mod.py:5:10: GEO190 [*] `bad_thing` is bad",  # [*]: --fix fixes it
        "mod.py:6:1: GEO191 `risky_thing` is risky",  # an unsafe fix: not without --unsafe-fixes
        "Found 2 findings (1 fixable with --fix, 1 more with --fix --unsafe-fixes).",
    ]
    assert "mod.py:6:1: GEO191 [*] " in cli("check", "--output-format", "concise", "--unsafe-fixes").stdout
    full = cli("check", "--output-format", "full", "--select", "GEO190").stdout.splitlines()
    assert full[:9] == [
        "GEO190 [*] `bad_thing` is bad",
        " --> mod.py:5:10",
        "  |",
        "3 |",
        "4 | value = (1 +",
        "5 |          bad_thing)",
        "  |          ^^^^^^^^^",
        "6 | risky_thing = 2",
        "  |",
    ]
    help_at = full.index("help: apply the fix")
    assert full[help_at + 1 : help_at + 5] == ["  |", "  -          bad_thing)", "5 +          good_thing)", "  |"]
    assert full[help_at + 5] == "  = docs: https://github.com/geolint/geolint/blob/main/docs/rules.md#geo190"
    # $GEOLINT_OUTPUT_FORMAT chooses the default format, as $RUFF_OUTPUT_FORMAT does
    from_env = cli("check", env={"GEOLINT_OUTPUT_FORMAT": "concise"})
    assert from_env.stdout.splitlines()[0] == "mod.py:5:10: GEO190 [*] `bad_thing` is bad"
    assert cli("check", env={"GEOLINT_OUTPUT_FORMAT": "yaml"}).returncode == 2


def test_show_fixes_shows_each_fix_and_lists_what_fix_fixed(cli):
    path = cli.write("mod.py", "def f():\n    return bad_thing\n")
    shown = cli("check", "--show-fixes").stdout.splitlines()
    assert shown[:6] == [
        "mod.py:2:12: GEO190 `bad_thing` is bad",
        "  | return bad_thing",
        "  |        ^^^^^^^^^",
        "  help: apply the fix",
        "  - return bad_thing",
        "  + return good_thing",
    ]
    assert path.read_text() == "def f():\n    return bad_thing\n"  # shown, not applied
    cli.write("other.py", "x = bad_thing\ny = bad_thing\nz = risky_thing\n")
    fixed = cli("check", "--fix", "--show-fixes")
    assert fixed.returncode == 1
    lines = fixed.stdout.splitlines()
    assert lines[:5] == ["Fixed 3 findings:", "- mod.py:", "    1 x GEO190 (bad-thing)", "- other.py:", "    2 x GEO190 (bad-thing)"]
    assert lines[-1] == "Fixed 3 findings. Found 1 finding (1 more with --fix --unsafe-fixes)."


def test_severity_is_shown_and_only_errors_and_warnings_fail_the_run(cli):
    cli.write("mod.py", BAD)
    cli.write("pyproject.toml", '[tool.geolint.severity]\nGEO190 = "warning"\nGEO191 = "info"\n')
    result = cli("check")
    assert result.returncode == 1
    headers = [line for line in result.stdout.splitlines() if line.startswith("mod.py")]
    assert headers == ["mod.py:1:5: GEO190 warning: `bad_thing` is bad", "mod.py:2:5: GEO191 info: `risky_thing` is risky"]
    assert result.stdout.splitlines()[-1] == (
        "Found 2 findings (1 warning, 1 info; 1 fixable with --fix, 1 more with --fix --unsafe-fixes)."
    )
    assert "mod.py:1:5: GEO190 [*] warning: `bad_thing` is bad" in cli("check", "--output-format", "concise").stdout
    cli.write("pyproject.toml", '[tool.geolint.severity]\nGEO190 = "hint"\nGEO191 = "info"\n')
    info_only = cli("check")
    assert info_only.returncode == 0, info_only.stdout  # info and hint findings are shown, but pass
    assert "Info and hint findings do not fail the run." in info_only.stdout
    assert "GEO190 hint: " in info_only.stdout


# ---- rules --------------------------------------------------------------------------------------


def test_rule_all_prints_every_rule(cli):
    result = cli("rule", "--all")
    assert result.returncode == 0
    listed = json.loads(cli("rules", "--format", "json").stdout)
    headings = [line for line in result.stdout.splitlines() if line.startswith("# GEO")]
    assert headings == [f"# {rule['code']} {rule['name']}" for rule in listed]
    as_json = json.loads(cli("rule", "--all", "--output-format", "json").stdout)
    assert [rule["code"] for rule in as_json] == [rule["code"] for rule in listed]
    assert "## What it does" in as_json[0]["explanation"]
    assert cli("rule").returncode == 2  # a code, or --all


def test_rules_are_wrapped_to_the_terminal_width(cli_real):
    for width in (80, 120):
        listed = cli_real("rules", env={"COLUMNS": str(width)}).stdout.splitlines()
        assert max(len(line) for line in listed) <= width
        assert any(line.startswith("GEO301 ") for line in listed)
    piped = cli_real("rules").stdout.splitlines()  # no terminal, no COLUMNS: a readable 100 columns
    assert max(len(line) for line in piped) <= 100


# ---- --watch ------------------------------------------------------------------------------------


def _read_until(process: subprocess.Popen, stream, wanted: str, timeout: float) -> str:
    """What `stream` printed until a line containing `wanted` (or until `timeout`)."""
    seen = ""
    selector = selectors.DefaultSelector()
    selector.register(stream, selectors.EVENT_READ)
    deadline = time.monotonic() + timeout
    while wanted not in seen and time.monotonic() < deadline:
        if selector.select(timeout=0.2):
            chunk = os.read(stream.fileno(), 65536).decode()
            if not chunk:
                break
            seen += chunk
    return seen


def test_watch_checks_again_when_a_file_changes(cli):
    path = cli.write("mod.py", "x = 1\n")
    process = subprocess.Popen(
        launch_geolint("check", "--watch", "--output-format", "concise", "--no-cache"),
        cwd=cli.project,
        env=cli_env(),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        start_new_session=True,
    )
    try:
        assert "All checks passed." in _read_until(process, process.stdout, "All checks passed.", 60)
        assert "Watching for file changes." in _read_until(process, process.stderr, "Watching", 30)
        path.write_text("x = bad_thing\n")
        changed = _read_until(process, process.stdout, "Found 1 finding", 60)
        assert "mod.py:1:5: GEO190 [*] `bad_thing` is bad" in changed
        cli.write("pyproject.toml", '[tool.geolint]\nignore = ["GEO190"]\n')  # a config change is one too
        assert "All checks passed." in _read_until(process, process.stdout, "All checks passed.", 60)
        assert process.poll() is None  # still watching
    finally:
        os.killpg(process.pid, signal.SIGTERM)
        process.wait(timeout=30)
