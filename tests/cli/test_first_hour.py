"""Traps a newcomer meets in the first hour, each checked through the real `python -m geolint`.

A typo'd suppression code, a bad `--select`, a table wider than the terminal, a summary printed
out of order in a piped log, a run that silently lints nothing, a missing extra that ends in a
traceback, `import geolint` pulling in the linter's dependencies.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

from tests.cli.conftest import run_module

BUGGY = """\
def normal_to_world(R_world_cam, t_world_cam, normal_cam):
    return R_world_cam @ normal_cam + t_world_cam
"""


def write(folder: Path, relative: str, text: str) -> Path:
    path = folder / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("comment", ["# noqa: GEO1O1", "# geolint: ignore[GEO1O1]", "# noqa: geo1o1, E501"])
def test_a_misspelt_suppression_code_is_reported_as_written(tmp_path: Path, comment: str) -> None:
    write(tmp_path, "mod.py", f"x = 1  {comment}\n")
    result = run_module("check", "--no-cache", "mod.py", cwd=tmp_path)
    written = comment.split(":", 1)[1].strip().removeprefix("ignore[").rstrip("]").split(",")[0]
    assert result.returncode == 1, result.stdout + result.stderr
    assert f"GEO900 warning: unknown rule code {written} in suppression" in result.stdout


def test_a_misspelt_noqa_code_does_not_suppress_the_real_one(tmp_path: Path) -> None:
    write(tmp_path, "mod.py", BUGGY.replace("t_world_cam\n", "t_world_cam  # noqa: GEO1O1\n"))
    codes = [f["code"] for f in json.loads(run_module("check", "--no-cache", "--format", "json", cwd=tmp_path).stdout)]
    assert sorted(codes) == ["GEO101", "GEO900"]


@pytest.mark.parametrize("option", ["--select", "--ignore"])
def test_a_bad_selector_on_the_command_line_is_blamed_on_the_option(tmp_path: Path, option: str) -> None:
    write(tmp_path, "pyproject.toml", "[tool.geolint]\nselect = ['GEO']\n")
    write(tmp_path, "mod.py", "x = 1\n")
    result = run_module("check", option, "GEO1,GEOX", cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr == f"geolint: error: {option}: invalid rule selector 'GEOX' (expected e.g. GEO, GEO2, GEO201)\n"
    assert "<config>" not in result.stderr and "pyproject" not in result.stderr and result.stdout == ""


@pytest.mark.parametrize("columns", [80, 60, 40])
def test_rules_fits_the_terminal_width(tmp_path: Path, columns: int) -> None:
    result = run_module("rules", cwd=tmp_path, env={"COLUMNS": str(columns)})
    assert result.returncode == 0
    lines = result.stdout.splitlines()
    too_wide = [line for line in lines if len(line) > columns]
    assert too_wide == []
    listed = json.loads(run_module("rules", "--format", "json", cwd=tmp_path).stdout)
    # Nothing lost to the wrapping. A word wider than the column (a long call signature) has to be
    # broken, so compare the characters in order, whitespace aside.
    text = "".join(result.stdout.split())
    for rule in listed:
        assert rule["code"] in result.stdout and "".join(rule["summary"].split()) in text


def test_rules_into_a_pipe_is_wrapped_starts_each_row_with_its_code_and_survives_a_closed_reader(tmp_path: Path) -> None:
    env = {k: v for k, v in os.environ.items() if k != "COLUMNS"}
    whole = subprocess.run([sys.executable, "-m", "geolint", "rules"], cwd=tmp_path, env=env, capture_output=True, text=True)
    codes = [rule["code"] for rule in json.loads(run_module("rules", "--format", "json", cwd=tmp_path).stdout)]
    lines = whole.stdout.splitlines()
    assert max(len(line) for line in lines) <= 100  # no 1,600-character rows in a pager or a log
    assert [line.split()[0] for line in lines if line.startswith("GEO")] == codes  # `| grep GEO301` finds its row
    # `geolint rules | head -1`: the reader goes away; no traceback.
    piped = subprocess.run(
        f"{sys.executable} -m geolint rules | head -1", shell=True, cwd=tmp_path, env=env, capture_output=True, text=True
    )
    assert piped.stdout.startswith("CODE") and "Traceback" not in piped.stderr and piped.stderr == ""


def test_the_summary_follows_the_findings_in_one_piped_log(tmp_path: Path) -> None:
    write(tmp_path, "a.py", BUGGY)
    write(tmp_path, "b.py", BUGGY)
    # One pipe for both streams, as a CI log captures them.
    merged = subprocess.run(
        [sys.executable, "-m", "geolint", "check", "--no-cache"],
        cwd=tmp_path,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    lines = merged.stdout.splitlines()
    assert merged.returncode == 1
    assert [line.split(":")[0] for line in lines if ": GEO101 " in line] == ["a.py", "b.py"]
    assert lines[-1] == "Found 2 findings (2 fixable with --fix)."
    assert sum("Found 2 findings" in line for line in lines) == 1
    # A CI runner that reads the two streams separately interleaves them by arrival: the summary
    # is on stdout, behind the findings, so no interleaving can put it first.
    separate = run_module("check", "--no-cache", cwd=tmp_path)
    assert separate.stdout.splitlines()[-1] == "Found 2 findings (2 fixable with --fix)." and separate.stderr == ""


def test_machine_formats_keep_stdout_machine_readable(tmp_path: Path) -> None:
    write(tmp_path, "a.py", BUGGY)
    result = run_module("check", "--no-cache", "--format", "json", cwd=tmp_path)
    assert [f["code"] for f in json.loads(result.stdout)] == ["GEO101"]
    assert result.stderr.strip() == "Found 1 finding (1 fixable with --fix)."


def test_zero_files_linted_warns(tmp_path: Path) -> None:
    write(tmp_path, "README.txt", "no python here\n")
    write(tmp_path, ".venv/lib/pkg/mod.py", BUGGY)  # excluded by default, so nothing is left
    result = run_module("check", "--no-cache", ".", cwd=tmp_path)
    assert result.returncode == 0
    assert result.stderr.startswith("geolint: warning: no Python files found under . (")
    some = run_module("check", "--no-cache", cwd=tmp_path / ".venv" / "lib")
    assert "no Python files found" not in some.stderr  # one file is enough to stay quiet


def test_a_folder_named_on_the_command_line_is_linted_even_inside_an_excluded_one(tmp_path: Path) -> None:
    """Why the docs' `geolint check $SP/numpy` silently linted nothing from a project with its venv in `.venv`."""
    write(tmp_path, "pyproject.toml", "[tool.geolint]\n")
    write(tmp_path, ".gitignore", ".venv/\n")
    write(tmp_path, ".venv/lib/site-packages/pkg/mod.py", BUGGY)
    write(tmp_path, ".venv/lib/site-packages/pkg/build/generated.py", BUGGY)  # still excluded below the named folder
    named = run_module("check", "--no-cache", "--format", "json", ".venv/lib/site-packages/pkg", cwd=tmp_path)
    assert [(f["path"], f["code"]) for f in json.loads(named.stdout)] == [(".venv/lib/site-packages/pkg/mod.py", "GEO101")]
    absolute = run_module("check", "--no-cache", "--format", "json", str(tmp_path / ".venv/lib/site-packages/pkg"), cwd=tmp_path)
    assert len(json.loads(absolute.stdout)) == 1
    whole = run_module("check", "--no-cache", ".", cwd=tmp_path)
    assert whole.returncode == 0 and "no Python files found" in whole.stderr
    forced = run_module("check", "--no-cache", "--force-exclude", ".venv/lib/site-packages/pkg", cwd=tmp_path)
    assert forced.returncode == 0 and "no Python files found" in forced.stderr


def test_a_missing_extra_names_the_extra_and_exits_2(tmp_path: Path) -> None:
    """The language server's packages hidden from the import system, as in a plain `pip install geolint-robotics`.

    tests/cli/test_install.py runs the same command in a real venv without the extra.
    """
    hide = "import sys; sys.modules['pygls'] = None; sys.modules['lsprotocol'] = None; from geolint.cli import main; sys.exit(main(sys.argv[1:]))"
    result = subprocess.run([sys.executable, "-c", hide, "lsp"], cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert result.returncode == 2
    # the extra's own requirements, which install from the package index although geolint is not on it
    with open(Path(__file__).resolve().parents[2] / "pyproject.toml", "rb") as stream:
        lsp_extra = tomllib.load(stream)["project"]["optional-dependencies"]["lsp"]
    assert "pip install " + " ".join(f"'{requirement}'" for requirement in lsp_extra) in result.stderr
    assert "geolint-robotics[" not in result.stderr
    assert "Traceback" not in result.stderr and "internal error" not in result.stderr


def test_import_geolint_loads_numpy_and_nothing_else_outside_the_standard_library(tmp_path: Path) -> None:
    probe = (
        "import sys; before = set(sys.modules); import geolint; "
        "T = geolint.Transform['a', 'b'](translation=[1, 2, 3]) @ geolint.Point['b']([0, 0, 0]); "
        "loaded = {m.split('.')[0] for m in set(sys.modules) - before}; "
        "print(' '.join(sorted(m for m in loaded if m not in sys.stdlib_module_names and not m.startswith('_'))))"
    )
    result = subprocess.run([sys.executable, "-c", probe], cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == ["geolint", "numpy"]


def test_the_lint_benchmark_finds_a_tree_under_the_projects_venv(tmp_path: Path) -> None:
    """`python benchmarks/bench_lint.py` from the repository root benchmarks the numpy of `.venv`, not zero files."""
    write(tmp_path, ".venv/lib/site-packages/numpy/core.py", BUGGY)
    write(tmp_path, ".venv/lib/site-packages/numpy/linalg.py", BUGGY)
    benchmarks = Path(__file__).resolve().parents[2] / "benchmarks"
    probe = (
        f"import sys; sys.path.insert(0, {str(benchmarks)!r}); from pathlib import Path; "
        "from bench_lint import python_files; print(len(python_files(Path('.venv/lib/site-packages/numpy').resolve())))"
    )
    result = subprocess.run([sys.executable, "-c", probe], cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert result.stdout.strip() == "2", result.stderr
