"""`geolint check`: exit codes, the JSON contract, the text format, select/ignore, output options."""

from __future__ import annotations

import json
from pathlib import Path

JSON_KEYS = {"path", "line", "column", "end_line", "end_column", "code", "name", "message", "severity", "fix"}


def test_clean_tree_exits_0_and_json_is_an_empty_array(cli):
    cli.write("pkg/clean.py", "good_thing = 1\n")
    result = cli("check", "--format", "json")
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout) == []


def test_findings_exit_1_with_exactly_the_contract_keys(cli):
    cli.write("pkg/mod.py", "x = 1\nvalue = bad_thing + risky_thing\n")
    result = cli("check", "pkg", "--format", "json")
    assert result.returncode == 1, result.stderr
    findings = json.loads(result.stdout)
    assert [f["code"] for f in findings] == ["GEO190", "GEO191"]
    for finding in findings:
        assert set(finding) == JSON_KEYS
        assert finding["path"] == "pkg/mod.py"  # as given, joined with the file found under it
        assert set(finding["fix"]) == {"applicability", "edits"}
    bad, risky = findings
    # 1-based columns, end exclusive: `bad_thing` spans columns 9..17 of line 2
    assert (bad["line"], bad["column"], bad["end_line"], bad["end_column"]) == (2, 9, 2, 18)
    assert bad["name"] == "bad-thing" and bad["severity"] == "error"
    assert bad["fix"]["applicability"] == "safe" and risky["fix"]["applicability"] == "unsafe"
    assert bad["fix"]["edits"] == [{"line": 2, "column": 9, "end_line": 2, "end_column": 18, "content": "good_thing"}]


def test_exit_zero_and_usage_errors(cli):
    cli.write("mod.py", "bad_thing = 1\n")
    assert cli("check", "--exit-zero").returncode == 0
    missing = cli("check", "nowhere.py")
    assert missing.returncode == 2 and "nowhere.py" in missing.stderr
    assert cli("check", "--format", "yaml").returncode == 2
    assert cli("check", "--jobs", "0").returncode == 2
    bad_selector = cli("check", "--select", "E501")
    assert bad_selector.returncode == 2 and "E501" in bad_selector.stderr
    # well-formed but naming no rule (ruff: "Unknown rule selector"): an error, never a silent pass
    for option in ("--select", "--extend-select", "--ignore"):
        unknown = cli("check", option, "GEO999")
        assert unknown.returncode == 2 and unknown.stdout == "", option
        assert f"{option}: unknown rule selector 'GEO999'" in unknown.stderr
    assert cli("check", "--select", "GEO8").returncode == 2  # a prefix of no rule


def test_select_and_ignore_match_prefixes(cli):
    cli.write("mod.py", "a = bad_thing\nb = risky_thing\n")

    def codes(*options: str) -> list[str]:
        result = cli("check", "--format", "json", *options)
        return [f["code"] for f in json.loads(result.stdout)]

    assert codes() == ["GEO190", "GEO191"]
    assert codes("--select", "GEO190") == ["GEO190"]
    assert codes("--select", "GEO19") == ["GEO190", "GEO191"]
    assert codes("--ignore", "GEO191") == ["GEO190"]
    assert codes("--ignore", "GEO1") == []
    # the more specific selector wins: ignore a family, keep one of its rules
    assert codes("--select", "GEO,GEO191", "--ignore", "GEO19") == ["GEO191"]
    # --extend-select adds to the selection (the config's, or --select's)
    assert codes("--select", "GEO190", "--extend-select", "GEO191") == ["GEO190", "GEO191"]


def test_text_format_shows_location_source_line_and_caret(cli):
    cli.write("mod.py", "import os\n    \nvalue = (1 +\n         bad_thing)\n")
    result = cli("check")
    assert result.returncode == 1
    lines = result.stdout.splitlines()
    assert lines[0] == "mod.py:4:10: GEO190 `bad_thing` is bad"
    assert lines[1].endswith("bad_thing)")
    caret_line = lines[2]
    assert caret_line.count("^") == len("bad_thing")
    assert caret_line.index("^") == lines[1].index("bad_thing")
    assert "\x1b[" not in result.stdout + result.stderr  # piped: no colour, no progress bar
    assert lines[-1] == "Found 1 finding (1 fixable with --fix)."  # the summary follows the findings on stdout
    assert result.stderr == ""


def test_text_format_says_what_evidence_a_finding_stands_on(cli_real):
    cli_real.write(
        "node.py",
        "def wrong_source(buffer, stamp, p_camera):\n"
        "    T_lookup = buffer.lookup_transform('map', 'base_link', stamp)\n"
        "    return T_lookup @ p_camera\n",
    )
    result = cli_real("check", "--no-cache")
    assert result.returncode == 1
    lines = result.stdout.splitlines()
    assert lines[0].startswith("node.py:3:12: GEO201")
    evidence = lines[3]
    assert evidence.startswith("  = evidence: ") and "line 2" in evidence and "p_camera" in evidence


def test_output_file_and_statistics(cli, tmp_path):
    cli.write("a.py", "x = bad_thing\ny = bad_thing\nz = risky_thing\n")
    report = tmp_path / "report.json"
    result = cli("check", "--format", "json", "--output", str(report))
    assert result.returncode == 1 and result.stdout == ""
    assert len(json.loads(report.read_text())) == 3
    stats = cli("check", "--statistics")
    assert stats.returncode == 1
    rows = [line.split("\t") for line in stats.stdout.splitlines()]
    assert rows == [["2", "GEO190", "[*] bad-thing"], ["1", "GEO191", "[*] risky-thing"]]


def test_quiet_and_verbose(cli):
    cli.write("a.py", "x = bad_thing\n")
    quiet = cli("check", "--quiet")
    assert quiet.stderr == "" and "GEO190" in quiet.stdout
    verbose = cli("check", "--verbose")
    assert "files: 1" in verbose.stderr and "config:" in verbose.stderr


def test_default_excludes_and_gitignore(cli):
    cli.write("src/mod.py", "x = bad_thing\n")
    cli.write(".venv/lib/site.py", "x = bad_thing\n")
    cli.write("build/lib/mod.py", "x = bad_thing\n")
    cli.write("generated/out.py", "x = bad_thing\n")
    cli.write("src/notes.txt", "bad_thing\n")
    cli.write(".gitignore", "generated/\n")
    result = cli("check", "--format", "json")
    assert sorted({f["path"] for f in json.loads(result.stdout)}) == ["src/mod.py"]
    # a file named explicitly is linted even when excluded, unless --force-exclude
    explicit = cli("check", "--format", "json", "generated/out.py")
    assert [f["path"] for f in json.loads(explicit.stdout)] == ["generated/out.py"]
    forced = cli("check", "--format", "json", "--force-exclude", "generated/out.py")
    assert json.loads(forced.stdout) == []


def test_a_gitignore_that_ignores_everything_but_what_it_names(cli):
    """`*` then `!driver/` and `!*.py` keeps the driver's modules, as git does (`git check-ignore`
    agrees); a folder it does not name stays out, and so does a file under an ignored folder."""
    cli.write(".gitignore", "*\n!.gitignore\n!*.py\n!driver/\n!driver/nodes/\n")
    cli.write("driver/nodes/node.py", "x = bad_thing\n")
    cli.write("driver/build/gen.py", "x = bad_thing\n")
    cli.write("setup.py", "x = bad_thing\n")
    result = cli("check", "--format", "json")
    assert sorted({f["path"] for f in json.loads(result.stdout)}) == ["driver/nodes/node.py", "setup.py"]


def test_stub_files_are_linted(cli):
    cli.write("types.pyi", "bad_thing: int\n")
    result = cli("check", "--format", "json")
    assert [f["path"] for f in json.loads(result.stdout)] == ["types.pyi"]


def test_json_frame_mismatches_name_the_two_frames_and_the_cache_keeps_them(cli_real):
    cli_real.write(
        "node.py",
        "def wrong_source(buffer, stamp, p_camera, p_base, T_base_cam):\n"
        "    T_lookup = buffer.lookup_transform('map', 'base_link', stamp)\n"
        "    p_base = T_base_cam @ p_camera\n"
        "    return T_lookup @ p_camera\n",
    )
    for run in ("cold", "cached"):
        result = cli_real("check", "--format", "json")
        assert result.returncode == 1, (run, result.stderr)
        findings = json.loads(result.stdout)
        assert [(f["code"], f["line"]) for f in findings] == [("GEO201", 4)], run
        # the transform maps base_link data; it is given camera data
        assert findings[0]["frames"] == ["base_link", "camera"], run
        assert set(findings[0]) == JSON_KEYS | {"evidence", "frames"}


def test_the_command_flushes_everything_before_its_fast_exit(tmp_path: Path) -> None:
    """`python -m geolint` ends with `os._exit` (no teardown of the run's trees and caches): every
    finding must still reach a pipe, in both formats, with the exit code of the run."""
    from geolint.rules import all_rules
    from tests.cli.conftest import run_module

    lines = ["import pybullet as p"] + [f"orn_{i} = p.getQuaternionFromEuler([90, 0, {i % 7}])" for i in range(3000)]
    (tmp_path / "scene.py").write_text("\n".join(lines) + "\n")
    buffered = {"PYTHONUNBUFFERED": ""}
    as_json = run_module("check", "scene.py", "--no-cache", "--select", "GEO302", "--format", "json", cwd=tmp_path, env=buffered)
    assert as_json.returncode == 1, as_json.stderr
    assert len(json.loads(as_json.stdout)) == 3000
    as_text = run_module("check", "scene.py", "--no-cache", "--select", "GEO302", cwd=tmp_path, env=buffered)
    assert as_text.returncode == 1, as_text.stderr
    assert as_text.stdout.count("scene.py:") == 3000 and as_text.stdout.rstrip().endswith("Found 3000 findings.")
    assert run_module("check", "scene.py", "--no-cache", "--select", "GEO302", "--exit-zero", cwd=tmp_path).returncode == 0
    # `geolint rules` leaves its output to the interpreter's buffers: the exit flushes them
    listed = run_module("rules", cwd=tmp_path, env={"PYTHONUNBUFFERED": ""})  # block-buffered, as in most shells' pipes
    assert listed.returncode == 0 and all(rule.code in listed.stdout for rule in all_rules())
