"""Every code block of README.md and docs/ is run as written, or is named here as an illustration.

`COVERED` maps each block (file, heading, index) to the test that runs it; a block added to the
docs without a test, or a test left for a block that is gone, fails `test_every_block_is_covered`.
The blocks that need a fresh install, real pre-commit or the package index run in
tests/cli/test_install.py (marked slow); mypy snippets run real mypy (slow).
"""

from __future__ import annotations

import doctest
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.cli.doc_snippets import REPO_ROOT, Block, all_blocks, block, commands_of

INSTALL = "tests/cli/test_install.py"
ILLUSTRATION = "illustration"  # not a command or config to copy: sample output or an API listing

COVERED: dict[tuple[str, str, int], str] = {
    ("README.md", "Install", 0): f"{INSTALL}::test_git_url_install_gives_a_working_linter",
    ("README.md", "Compiled build (optional, faster).", 0): "tests/engine/test_compiled_core.py::test_the_compiled_wheel_finds_what_pure_python_finds",
    ("README.md", "Quick start", 0): f"{INSTALL}::test_readme_quick_start",
    ("README.md", "Quick start", 1): "test_readme_test_command_is_what_ci_runs",
    ("README.md", "What it finds", 0): "test_demo_output_is_what_the_readme_shows",
    ("README.md", "A tour of the runtime", 0): "test_runtime_tours_run_through_their_intentional_errors",
    ("README.md", "The linter: `geolint check`", 0): "test_command_lines_run",
    ("README.md", "The linter: `geolint check`", 1): "test_geolint_config_snippets_are_accepted",
    ("README.md", "Precision and recall on real code.", 0): f"{INSTALL}::test_precision_command_lints_the_named_trees",
    ("README.md", "1. Frame classes, any checker (mypy, pyright, no plugin).", 0): "test_typing_snippets_under_mypy",
    ("README.md", "2. The mypy plugin: string frames and precise messages.", 0): "test_mypy_config_snippets",
    ("README.md", "2. The mypy plugin: string frames and precise messages.", 1): "test_mypy_config_snippets",
    ("README.md", "2. The mypy plugin: string frames and precise messages.", 2): "test_mypy_config_snippets",
    ("README.md", "3. Plain numpy arrays, annotated (`geolint.typing`, zero runtime cost).", 0): "test_typing_snippets_under_mypy",
    ("README.md", "In pre-commit", 0): f"{INSTALL}::test_pre_commit_snippets_at_the_release_tag",
    ("README.md", "In CI", 0): f"{INSTALL}::test_ci_snippet_commands",
    ("README.md", "In CI", 1): f"{INSTALL}::test_ci_snippet_commands",
    ("README.md", "Picture the frames", 0): "test_command_lines_run",
    ("docs/ci.md", "GitHub Actions", 0): f"{INSTALL}::test_ci_snippet_commands",
    ("docs/ci.md", "GitLab CI", 0): f"{INSTALL}::test_ci_snippet_commands",
    ("docs/ci.md", "Adopting geolint on an existing codebase", 0): "test_command_lines_run",
    ("docs/ci.md", "pre-commit", 0): f"{INSTALL}::test_pre_commit_snippets_at_the_release_tag",
    ("docs/frames.md", "Picture the frames: `geolint frames`", 0): "test_command_lines_run",
    ("docs/linter.md", "`geolint check`: command line and configuration", 0): "test_command_lines_run",
    ("docs/linter.md", "text", 0): ILLUSTRATION,  # sample output of the text format
    ("docs/linter.md", "text", 1): "test_evidence_sample_is_what_geolint_prints",
    ("docs/linter.md", "Configuration: `[tool.geolint]`", 0): "test_geolint_config_snippets_are_accepted",
    ("docs/linter.md", "Suppressing a finding", 0): ILLUSTRATION,  # comment placements, not a program
    ("docs/linter.md", "Adopting geolint on an existing codebase", 0): "test_command_lines_run",
    ("docs/real-world.md", "Command", 0): f"{INSTALL}::test_precision_command_lints_the_named_trees",
    ("docs/releasing.md", "Releasing", 0): f"{INSTALL}::test_pre_commit_snippets_at_the_release_tag",
    ("docs/runtime.md", "Tour", 0): "test_runtime_tours_run_through_their_intentional_errors",
    ("docs/runtime.md", "Transforms", 0): ILLUSTRATION,  # API listing (R, t, M are placeholders)
    ("docs/runtime.md", "Applying and composing.", 0): ILLUSTRATION,  # sample error messages
    ("docs/runtime.md", "FrameTree", 0): ILLUSTRATION,  # API listing
    ("docs/runtime.md", "Static typing with no plugin", 0): ILLUSTRATION,  # declarations without values
}


def test_every_block_is_covered() -> None:
    found = {b.key: b for b in all_blocks()}
    missing = [f"{b.file}:{b.line} under {b.heading!r} (#{b.index})" for key, b in found.items() if key not in COVERED]
    stale = [key for key in COVERED if key not in found]
    assert missing == [], "code blocks no test runs; add them to COVERED and run them"
    assert stale == [], "COVERED names blocks that are gone"
    here = set(globals())
    absent = [
        test for test in set(COVERED.values()) - {ILLUSTRATION}
        if ("::" in test and f"def {test.split('::')[1]}(" not in (REPO_ROOT / test.split("::")[0]).read_text(encoding="utf-8"))
        or ("::" not in test and test not in here)
    ]  # fmt: skip
    assert absent == [], "COVERED names tests that do not exist"


def geolint_env() -> dict[str, str]:
    """The environment a reader has after installing: this interpreter's `geolint` first on PATH."""
    env = {k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "CI", "FORCE_COLOR", "COLUMNS")}
    env["PATH"] = os.pathsep.join([str(Path(sys.executable).parent), env.get("PATH", "")])
    return env


def bash(script: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(["bash", "-c", script], cwd=cwd, env=geolint_env(), capture_output=True, text=True, timeout=300)


def test_readme_test_command_is_what_ci_runs() -> None:
    command = block("README.md", "Quick start", 1).body.strip()
    assert "--config-settings editable_mode=compat" in command  # type checkers must see the editable install
    ci_run = (REPO_ROOT / ".ci" / "run").read_text(encoding="utf-8")
    # .ci/run creates and activates the venv itself; the rest of the line is the same text.
    assert command.split(" && ", 2)[2] in ci_run


def test_demo_output_is_what_the_readme_shows(tmp_path: Path) -> None:
    shown = block("README.md", "What it finds", 0).body
    prompt, expected = shown.split("\n", 1)
    assert prompt == "$ geolint check fixtures/demo"
    shutil.copytree(REPO_ROOT / "fixtures" / "demo", tmp_path / "fixtures" / "demo")
    result = bash(prompt.removeprefix("$ "), tmp_path)
    assert result.returncode == 1
    assert result.stdout == expected  # the findings, then the summary line, in the order a log shows them
    assert result.stderr == ""


def test_evidence_sample_is_what_geolint_prints() -> None:
    shown = block("docs/linter.md", "text", 1).body.splitlines()
    result = bash("geolint check --no-cache tf_node", REPO_ROOT / "fixtures" / "projects" / "ros_tf_node")
    assert result.returncode == 1, result.stderr
    printed = result.stdout.splitlines()
    # the fixture's line carries an `# expect:` comment the page leaves out; header and evidence agree
    assert printed[0] == shown[0] and printed[3] == shown[3]
    assert printed[1].startswith(shown[1]) and printed[2] == shown[2]


@pytest.mark.parametrize("where", [("README.md", "A tour of the runtime"), ("docs/runtime.md", "Tour")])
def test_runtime_tours_run_through_their_intentional_errors(where: tuple[str, str]) -> None:
    tour = block(*where)
    assert tour.language == "pycon"
    test = doctest.DocTestParser().get_doctest(tour.body, {}, f"{tour.file}:{tour.line}", tour.file, tour.line)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    runner.run(test, out=lambda text: None)
    results = runner.summarize(verbose=False)
    assert results.attempted >= 15 and results.failed == 0, f"{tour.file}:{tour.line}: run `python -m doctest` on it"
    assert tour.body.count("Traceback (most recent call last):") >= 2  # the intentional errors are part of it


def demo_project(tmp_path: Path) -> Path:
    """A folder with the names the command snippets use: src/, tools/grasp.py, fixtures/frames."""
    # the snippets' own pyproject.toml is the config here, not the demo's
    shutil.copytree(REPO_ROOT / "fixtures" / "demo", tmp_path / "src", ignore=shutil.ignore_patterns("pyproject.toml"))
    (tmp_path / "tools").mkdir()
    shutil.copy(REPO_ROOT / "fixtures" / "demo" / "grasp_planner.py", tmp_path / "tools" / "grasp.py")
    shutil.copytree(REPO_ROOT / "fixtures" / "frames", tmp_path / "fixtures" / "frames")
    return tmp_path


COMMAND_BLOCKS = [
    ("README.md", "The linter: `geolint check`", 0),
    ("README.md", "Picture the frames", 0),
    ("docs/ci.md", "Adopting geolint on an existing codebase", 0),
    ("docs/frames.md", "Picture the frames: `geolint frames`", 0),
    ("docs/linter.md", "`geolint check`: command line and configuration", 0),
    ("docs/linter.md", "Adopting geolint on an existing codebase", 0),
]


@pytest.mark.parametrize("key", COMMAND_BLOCKS, ids=lambda key: f"{key[0]}:{key[1]}")
def test_command_lines_run(tmp_path: Path, key: tuple[str, str, int]) -> None:
    project = demo_project(tmp_path)
    for line in commands_of(block(*key).body):
        command = line.split("  #", 1)[0].replace(" [PATH ...]", "")
        result = bash(command, project)
        output = result.stdout + result.stderr
        if "--format svg" in command and shutil.which("dot") is None:
            assert result.returncode == 2 and "apt-get install graphviz" in output, output
            continue
        assert result.returncode in (0, 1), f"{key}: {command!r} exited {result.returncode}:\n{output}"
        assert "error" not in result.stderr.lower(), f"{command!r}: {result.stderr}"
        if "--baseline" in command and "--write-baseline" not in command:
            assert result.returncode == 0, output  # fresh baseline: nothing new
    # The baseline workflow really recorded something.
    if key[1].startswith("Adopting"):
        assert any(path.name.endswith("baseline.json") and path.stat().st_size > 2 for path in project.iterdir())


@pytest.mark.parametrize(
    "key", [("README.md", "The linter: `geolint check`", 1), ("docs/linter.md", "Configuration: `[tool.geolint]`", 0)]
)
def test_geolint_config_snippets_are_accepted(tmp_path: Path, key: tuple[str, str, int]) -> None:
    snippet = block(*key)
    assert snippet.language == "toml"
    project = demo_project(tmp_path)
    (project / "pyproject.toml").write_text(snippet.body, encoding="utf-8")
    result = bash("geolint check --no-cache --verbose src", project)
    assert result.returncode in (0, 1), result.stderr
    assert f"config: {(project / 'pyproject.toml').resolve()}" in result.stderr


# --- mypy: the plugin's configuration in its three forms, and the typing examples -----------------

ALIAS_PROBE = '''\
from geolint import Point, Transform

def to_base(T: Transform["base", "camera"], p: Point["camera"]) -> Point["base_link"]:
    return T @ p  # "base" is an alias of "base_link" in the README's configuration
'''


def run_mypy(project: Path, *files: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "mypy", "--no-incremental", "--show-error-codes", "--no-error-summary", *files],
        cwd=project,
        capture_output=True,
        text=True,
        timeout=600,
    )


def expected_errors(python: str) -> list[str]:
    """The `# error: ...` comments of a snippet (the message mypy prints, code included)."""
    return [m.group(1).strip() for m in re.finditer(r"# error: (.+)$", python, re.M)]


@pytest.mark.slow
@pytest.mark.parametrize("form", ["mypy.ini", "setup.cfg", "pyproject.toml"])
def test_mypy_config_snippets(tmp_path: Path, form: str) -> None:
    heading = "2. The mypy plugin: string frames and precise messages."
    config = block("README.md", heading, 1 if form == "pyproject.toml" else 0)
    example = block("README.md", heading, 2)
    assert config.language == ("toml" if form == "pyproject.toml" else "ini")
    (tmp_path / form).write_text(config.body, encoding="utf-8")
    (tmp_path / "example.py").write_text(example.body, encoding="utf-8")
    (tmp_path / "alias.py").write_text(ALIAS_PROBE, encoding="utf-8")
    result = run_mypy(tmp_path, "example.py", "alias.py")
    output = result.stdout + result.stderr
    wanted = expected_errors(example.body)
    assert wanted and all(message in output for message in wanted), output
    assert "alias.py" not in output, output  # the alias took effect
    assert result.returncode == 1 and output.count("error:") == len(wanted), output


@pytest.mark.slow
def test_typing_snippets_under_mypy(tmp_path: Path) -> None:
    classes = block("README.md", "1. Frame classes, any checker (mypy, pyright, no plugin).", 0)
    arrays = block("README.md", "3. Plain numpy arrays, annotated (`geolint.typing`, zero runtime cost).", 0)
    (tmp_path / "classes.py").write_text(classes.body, encoding="utf-8")
    plain = run_mypy(tmp_path, "classes.py")  # no plugin, no config
    assert plain.returncode == 0, plain.stdout + plain.stderr
    (tmp_path / "mypy.ini").write_text(block("README.md", "2. The mypy plugin: string frames and precise messages.", 0).body)
    (tmp_path / "arrays.py").write_text(arrays.body, encoding="utf-8")
    with_plugin = run_mypy(tmp_path, "arrays.py")
    output = with_plugin.stdout
    line = next(n for n, text in enumerate(arrays.body.splitlines(), 1) if "# error:" in text)
    assert re.search(rf"^arrays\.py:{line}: error: .*\[geo-translation\]$", output, re.M), output
    assert output.count("error:") == 1, output
