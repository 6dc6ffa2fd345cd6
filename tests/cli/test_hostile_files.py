"""Hostile files never crash, hang or spoil a run (issue 13, "The linter").

Each file below used to kill the process with signal 11 (libcst's native parser recursing), run
for minutes (libcst's parse time grows with the square of an expression's depth), or end in
"internal error ... please report it" followed by "All checks passed.". Now every file gets one
result (GEO000 or GEO001), the other files of the run keep theirs, and the exit code is 1.
"""

from __future__ import annotations

import json
import time

import pytest

from tests.conftest import DECLARES_DST_FIRST

TERMS = 20_000
# Geometry names throughout, so the prefilter lets every file through to the analysis.
HOSTILE = {
    "brackets.py": "p_world = T_world_cam @ " + "[" * 2000 + "p_cam" + "]" * 2000 + "\n",
    "parens_unclosed.py": "p_world = T_world_cam @ " + "(" * 2000 + "p_cam\n",
    "unary_chain.py": "p_world = T_world_cam @ " + "-" * 100_000 + "p_cam\n",
    "attribute_chain.py": "p_world = T_world_cam @ p_cam" + ".x" * 100_000 + "\n",
    "sum_chain.py": "p_world = p_cam + " + " + ".join(f"v{i}_world" for i in range(TERMS)) + "\n",
    "difference_chain.py": "v_world = p_cam - " + " - ".join(f"p{i}_world" for i in range(TERMS)) + "\n",
    "call_chain.py": "p_world = T_world_cam @ p_cam" + "()" * TERMS + "\n",
    "power_chain.py": "x = " + "**".join(["p_cam"] * TERMS) + "\n",
    "nested_201.py": "p_world = T_world_cam @ " + "[" * 201 + "p_cam" + "]" * 201 + "\n",
    "elif_5000.py": "if mode == 0:\n    p_world = T_world_cam @ p_cam\n"
    + "".join(f"elif mode == {i}:\n    p_world = T_world_cam @ p_cam\n" for i in range(1, 5000)),
    "conditional_5000.py": "p_world = "
    + " ".join(f"T_world_cam @ p_cam if mode == {i} else" for i in range(5000))
    + " p_cam\n",
    "huge_integer.py": "import numpy as np\nangle = np.sin(" + "9" * 5000 + ")\np_world = T_world_cam @ p_cam\n",
}
# A file the real rules flag (GEO201, frame mismatch), to show the rest of the run is unaffected.
ORDINARY = "p_world = T_world_cam @ p_base\n" + DECLARES_DST_FIRST
# Files that must be analysed normally: an infinite or huge literal is a value, not a crash; libcst
# nested thousands of adjacent string literals one level each (a RecursionError).
ANALYSED = {
    "odd_literals.py": "import numpy as np\nangle = np.sin(1e999)\nturn = np.cos(-1e999)\nbig = np.sin(1" + "0" * 400 + ")\n"
    "from scipy.spatial.transform import Rotation\nr = Rotation.from_euler('xyz', [1e999, 0, 1" + "0" * 400 + "])\n",
    "adjacent_strings.py": "label = (" + " ".join(f"'p{i}'" for i in range(3000)) + ")\np_world = T_world_cam @ p_cam\n",
}


def findings_by_path(stdout: str) -> dict[str, list[dict]]:
    grouped: dict[str, list[dict]] = {}
    for finding in json.loads(stdout):
        grouped.setdefault(finding["path"], []).append(finding)
    return grouped


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_every_hostile_file_gets_one_result_and_the_run_goes_on(cli_real, jobs):
    for name, text in HOSTILE.items():
        cli_real.write(name, text)
    cli_real.write("ordinary.py", ORDINARY)
    for name, text in ANALYSED.items():
        cli_real.write(name, text)
    started = time.perf_counter()
    result = cli_real("check", "--no-cache", "--format", "json", "--jobs", jobs)
    elapsed = time.perf_counter() - started
    assert result.returncode == 1, result.stderr[-2000:]
    assert "internal error" not in result.stderr and "Traceback" not in result.stderr
    found = findings_by_path(result.stdout)
    for name in HOSTILE:
        assert [f["code"] for f in found.get(name, [])] in (["GEO000"], ["GEO001"]), (name, found.get(name))
    assert [f["code"] for f in found["ordinary.py"]] == ["GEO201"]
    assert not set(ANALYSED) & set(found), found
    assert "All checks passed." not in result.stderr + result.stdout
    # Each of these used to take minutes on its own; together they now take seconds.
    assert elapsed < 60, f"{elapsed:.1f} s"


def test_a_file_too_deep_names_the_limit_and_the_key_that_raises_it(cli_real):
    deep_sum = "total_world = p_cam + " + " + ".join(f"v{i}_world" for i in range(200)) + "\n"
    cli_real.write("deep.py", deep_sum)
    [finding] = json.loads(cli_real("check", "--no-cache", "--format", "json").stdout)
    assert (finding["code"], finding["name"], finding["line"]) == ("GEO001", "too-complex-to-analyse", 1)
    assert "150 levels" in finding["message"] and "max-nesting-depth" in finding["message"]

    # Raising the limit analyses the file (and the analysis copes with the depth it allows).
    cli_real.write("pyproject.toml", "[tool.geolint]\nmax-nesting-depth = 400\n")
    result = cli_real("check", "--no-cache", "--format", "json")
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout) == []


def test_a_file_too_large_names_the_limit_and_the_key_that_raises_it(cli_real):
    cli_real.write("pyproject.toml", "[tool.geolint]\nmax-file-size = 1000\n")
    cli_real.write("large.py", "".join(f"p{i}_world = T_world_cam @ p{i}_cam\n" for i in range(100)))
    cli_real.write("small.py", ORDINARY)
    result = cli_real("check", "--no-cache", "--format", "json")
    found = findings_by_path(result.stdout)
    [finding] = found["large.py"]
    assert finding["code"] == "GEO001"
    assert "1,000" in finding["message"] and "max-file-size" in finding["message"]
    assert [f["code"] for f in found["small.py"]] == ["GEO201"]


def test_a_bad_limit_in_the_config_is_a_config_error(cli_real):
    cli_real.write("pyproject.toml", "[tool.geolint]\nmax-nesting-depth = 0\n")
    cli_real.write("a.py", "x = 1\n")
    result = cli_real("check")
    assert result.returncode == 2
    assert "max-nesting-depth" in result.stderr and "positive integer" in result.stderr


def test_no_all_checks_passed_after_an_internal_error(cli):
    cli.write("a_fine.py", "x = 1\n")
    cli.write("b_crash.py", "crash_here = 1\n")
    result = cli("check")
    assert result.returncode == 2
    assert "internal error" in result.stderr
    assert "All checks passed." not in result.stderr + result.stdout
    assert "1 file could not be checked" in result.stderr + result.stdout


@pytest.mark.parametrize("cache", [[], ["--no-cache"]])
def test_a_link_to_nothing_is_skipped_with_a_warning_and_the_run_goes_on(cli_real, cache):
    """A checked-in link to a build product (`pb2.py -> ../build/pb2.py`) not built here: ruff users
    expect a warning and the other files' results, not an internal error (ruff issue 19421)."""
    cli_real.write("ordinary.py", ORDINARY)
    (cli_real.project / "generated").mkdir()
    (cli_real.project / "generated" / "messages_pb2.py").symlink_to("../build/messages_pb2.py")
    result = cli_real("check", "--format", "json", *cache)
    assert result.returncode == 1, result.stderr  # the ordinary file's finding
    assert [f["code"] for f in findings_by_path(result.stdout)["ordinary.py"]] == ["GEO201"]
    assert "warning: skipped generated/messages_pb2.py: broken symbolic link to ../build/messages_pb2.py" in result.stderr
    assert "internal error" not in result.stderr and "could not be checked" not in result.stderr


def test_a_link_in_a_loop_is_skipped_and_does_not_end_the_run(cli_real):
    """`Path.resolve()` raised RuntimeError on a loop while the folder was walked: no file was checked."""
    cli_real.write("ordinary.py", ORDINARY)
    (cli_real.project / "loop.py").symlink_to("loop.py")
    result = cli_real("check", "--no-cache", "--format", "json")
    assert result.returncode == 1, result.stderr
    assert "warning: skipped loop.py: broken symbolic link to loop.py" in result.stderr
    assert "Traceback" not in result.stderr and "internal error" not in result.stderr
    assert [f["code"] for f in findings_by_path(result.stdout)["ordinary.py"]] == ["GEO201"]


def test_a_file_that_cannot_be_read_says_why_and_is_no_internal_error(tmp_path):
    """Permission denied cannot be staged for root (CI's user), so the result is built from the OSError a read raises."""
    from geolint.api import _unreadable
    from geolint.files import SourceFile

    path = tmp_path / "locked.py"
    path.write_text("x = 1\n")
    result = _unreadable(SourceFile(path, "locked.py"), PermissionError(13, "Permission denied", str(path)))
    assert (result.error, result.unreadable, result.broken_link) == ("Permission denied", True, False)
