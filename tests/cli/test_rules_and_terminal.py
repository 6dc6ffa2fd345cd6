"""`geolint rule` / `geolint rules`, the generated docs page, and colour only on a real terminal."""

from __future__ import annotations

import json
import re
import os
import pty
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
SECTIONS = ("## What it does", "## Why is this bad?", "## Example", "## Use instead", "## Fix safety")


@pytest.mark.parametrize("code", ["GEO000", "geo900"])
def test_rule_prints_the_documentation_of_the_engine_pseudo_rules(cli_real, code):
    result = cli_real("rule", code)
    assert result.returncode == 0
    assert result.stdout.startswith(f"# {code.upper()} ")
    for section in SECTIONS:
        assert section in result.stdout


def test_rule_accepts_a_name_and_rejects_unknown_codes(cli_real):
    assert cli_real("rule", "unused-suppression").stdout.startswith("# GEO900 unused-suppression")
    unknown = cli_real("rule", "GEO999")
    assert unknown.returncode == 2 and "GEO999" in unknown.stderr and "GEO000" in unknown.stderr


def test_rules_lists_every_rule_with_fixability(cli):
    listed = json.loads(cli("rules", "--format", "json").stdout)
    by_code = {row["code"]: row for row in listed}
    assert {"GEO000", "GEO900", "GEO190", "GEO191"} <= set(by_code)
    assert by_code["GEO190"]["fixable"] is True and by_code["GEO000"]["fixable"] is False
    assert by_code["GEO190"]["summary"] == "Flags the name `bad_thing` (a stand-in rule for the CLI tests)."
    text = cli("rules").stdout.splitlines()
    assert text[0].split() == ["CODE", "NAME", "FIX", "SUMMARY"]
    assert any(line.startswith("GEO190") and " yes " in line for line in text)


def test_an_opt_in_rule_runs_only_when_its_own_code_is_selected(cli_real):
    cli_real.write("grasp.py", "grasp_position = object_centroid + gripper_position\n")
    codes = lambda *args: [f["code"] for f in json.loads(cli_real("check", "--no-cache", "--format", "json", *args).stdout)]
    assert codes() == [] and codes("--select", "GEO1") == [] and codes("--select", "GEO") == []
    assert codes("--select", "GEO103") == ["GEO103"]
    assert codes("--extend-select", "GEO103") == ["GEO103"]
    cli_real.write("pyproject.toml", '[tool.geolint]\nselect = ["GEO", "GEO103"]\n')
    assert codes() == ["GEO103"]
    listed = {rule["code"]: rule for rule in json.loads(cli_real("rules", "--format", "json").stdout)}
    assert listed["GEO103"]["opt_in"] is True and listed["GEO101"]["opt_in"] is False


def test_docs_rules_md_is_up_to_date():
    generated = subprocess.run(
        [sys.executable, "-m", "geolint.docs"], cwd=REPO, capture_output=True, text=True, check=True
    ).stdout
    committed = (REPO / "docs" / "rules.md").read_text(encoding="utf-8")
    assert committed == generated, "docs/rules.md is stale: run `python -m geolint.docs > docs/rules.md`"


def test_readme_rule_table_names_every_semantic_rule_by_its_code_and_name():
    from geolint.rules import all_rules

    readme = (REPO / "README.md").read_text(encoding="utf-8")
    rows = dict(re.findall(r"^\| (GEO\d{3}) \| ([a-z-]+) \|", readme, re.M))
    semantic = {rule.code: rule.name for rule in all_rules() if rule.code[3] in "1234"}
    assert rows == semantic


def _run_on_a_tty(args: list[str], cwd: Path, env: dict[str, str]) -> str:
    """Run the CLI with stdout and stderr on a pseudo-terminal; return everything it wrote."""
    leader, follower = pty.openpty()
    process = subprocess.Popen(args, cwd=cwd, env=env, stdout=follower, stderr=follower, stdin=subprocess.DEVNULL)
    os.close(follower)
    chunks = []
    while True:
        try:
            chunk = os.read(leader, 4096)
        except OSError:  # the follower side closed
            break
        if not chunk:
            break
        chunks.append(chunk)
    process.wait(timeout=60)
    os.close(leader)
    return b"".join(chunks).decode("utf-8", "replace")


def test_colour_only_on_a_terminal_and_never_with_no_color(cli):
    cli.write("mod.py", "x = bad_thing\n")
    launcher = [sys.executable, "-c", "import sys, sample_rules; from geolint.cli import main; sys.exit(main(sys.argv[1:]))"]
    env = {k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "CI")}
    env.update(PYTHONPATH=str(Path(__file__).parent), GEOLINT_CACHE_DIR=str(cli.cache_dir), TERM="xterm")
    on_tty = _run_on_a_tty([*launcher, "check", "--no-cache"], cli.project, env)
    assert "GEO190" in on_tty and "\x1b[" in on_tty
    no_color = _run_on_a_tty([*launcher, "check", "--no-cache"], cli.project, {**env, "NO_COLOR": "1"})
    assert "GEO190" in no_color and "\x1b[" not in no_color
    piped = cli("check", "--no-cache")
    assert "GEO190" in piped.stdout and "\x1b[" not in piped.stdout + piped.stderr


def test_progress_bar_only_on_an_interactive_terminal_outside_ci(cli):
    for index in range(3):
        cli.write(f"m{index}.py", "x = bad_thing\n")
    launcher = [sys.executable, "-c", "import sys, sample_rules; from geolint.cli import main; sys.exit(main(sys.argv[1:]))"]
    env = {k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "CI")}
    env.update(PYTHONPATH=str(Path(__file__).parent), GEOLINT_CACHE_DIR=str(cli.cache_dir), TERM="xterm")
    interactive = _run_on_a_tty([*launcher, "check", "--no-cache"], cli.project, env)
    assert "3 files" in interactive and "\r[" in interactive
    in_ci = _run_on_a_tty([*launcher, "check", "--no-cache"], cli.project, {**env, "CI": "true"})
    assert "GEO190" in in_ci and "\r[" not in in_ci
    quiet = _run_on_a_tty([*launcher, "check", "--no-cache", "--quiet"], cli.project, env)
    assert "GEO190" in quiet and "\r[" not in quiet
