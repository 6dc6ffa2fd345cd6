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

from tests.cli.doc_snippets import PUBLIC_URL, REPO_ROOT, Block, all_blocks, block, commands_of

INSTALL = "tests/cli/test_install.py"
COMPILED = "Compiled build (optional, about a quarter faster)."
TYPING = "Static typing: generics and the mypy plugin"
ILLUSTRATION = "illustration"  # not a command or config to copy: sample output or an API listing

COVERED: dict[tuple[str, str, int], str] = {
    ("README.md", "What it finds", 0): "test_demo_output_is_what_the_readme_shows",
    ("README.md", "Install", 0): f"{INSTALL}::test_plain_install_gives_a_working_linter",  # each line has its own test there
    ("README.md", COMPILED, 0): "tests/engine/test_compiled_core.py::test_the_compiled_wheel_finds_what_pure_python_finds",
    ("README.md", "Quick start", 0): f"{INSTALL}::test_readme_quick_start",
    ("README.md", "The runtime: `import geolint`", 0): "test_runtime_tours_run_through_their_intentional_errors",
    ("README.md", "The linter: `geolint check`", 0): "test_command_lines_run",
    ("README.md", TYPING, 0): "test_mypy_config_snippets",
    ("README.md", TYPING, 1): "test_mypy_config_snippets",
    ("README.md", "Editors", 0): "test_readme_editor_snippets_are_the_tested_ones",
    ("README.md", "Editors", 1): "test_readme_editor_snippets_are_the_tested_ones",
    ("README.md", "pre-commit", 0): f"{INSTALL}::test_local_pre_commit_hook_with_geolint_installed",
    ("README.md", "CI", 0): f"{INSTALL}::test_ci_snippet_commands",
    ("README.md", "CI", 1): f"{INSTALL}::test_ci_snippet_commands",
    ("README.md", "Configuration", 0): "test_geolint_config_snippets_are_accepted",
    ("README.md", "Contributing", 0): "test_readme_test_command_is_what_ci_runs",
    ("docs/benchmark.md", "Running it", 0): "tests/benchmarks/test_real_code_docs.py::test_the_documented_commands_run",
    ("docs/benchmark.md", "Running it", 1): "tests/benchmarks/test_real_code_docs.py::test_the_documented_commands_run",
    ("docs/benchmark.md", "Shape families: the knowledge base, API by API", 0): "tests/benchmarks/test_shape_families.py::test_the_documented_commands_run",
    ("docs/ci.md", "GitHub Actions", 0): f"{INSTALL}::test_ci_snippet_commands",
    ("docs/ci.md", "GitLab CI", 0): f"{INSTALL}::test_ci_snippet_commands",
    ("docs/ci.md", "Adopting geolint on an existing codebase", 0): "test_command_lines_run",
    ("docs/ci.md", "pre-commit", 0): f"{INSTALL}::test_local_pre_commit_hook_with_geolint_installed",
    ("docs/ci.md", "pre-commit", 1): f"{INSTALL}::test_pre_commit_hook_from_a_clone_at_a_commit",
    ("docs/ci.md", "pre-commit", 2): f"{INSTALL}::test_pre_commit_try_repo",
    ("docs/frames.md", "Picture the frames: `geolint frames`", 0): "test_command_lines_run",
    ("docs/linter.md", "Architecture", 0): "tests/engine/test_layers.py::test_the_architecture_section_names_modules_that_exist",
    ("docs/linter.md", "`geolint check`: command line and configuration", 0): "test_command_lines_run",
    ("docs/linter.md", "text", 0): ILLUSTRATION,  # sample output of the text format
    ("docs/linter.md", "The project's own fixes: `--history`", 0): "tests/integrations/test_history.py::test_a_fix_in_one_copy_finds_the_others",
    ("docs/linter.md", "text", 1): "test_evidence_sample_is_what_geolint_prints",
    ("docs/linter.md", "Configuration: `[tool.geolint]`", 0): "test_geolint_config_snippets_are_accepted",
    ("docs/linter.md", "Suppressing a finding", 0): ILLUSTRATION,  # comment placements, not a program
    ("docs/linter.md", "Adopting geolint on an existing codebase", 0): "test_command_lines_run",
    ("docs/real-world.md", "Command", 0): f"{INSTALL}::test_precision_command_lints_the_named_trees",
    ("docs/releasing.md", "Releasing", 0): f"{INSTALL}::test_the_release_tag_command",
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
    command = block("README.md", "Contributing", 0).body.strip()
    assert "--config-settings editable_mode=compat" in command  # type checkers must see the editable install
    assert command.endswith('python -m pytest -q -n auto -m "not slow"')  # the fast subset; .ci/run adds the slow tests
    ci_run = (REPO_ROOT / ".ci" / "run").read_text(encoding="utf-8")
    # .ci/run creates and activates the venv itself; the rest of the line is the same text.
    assert command.split(" && ", 2)[2] in ci_run
    assert "-m slow" in ci_run


def test_no_snippet_names_an_unpublished_release() -> None:
    """Nothing is tagged or on PyPI yet: a `rev:` tag, a git URL of the public repository or
    `pip install geolint-robotics` would fail for every reader (docs/releasing.md says when they may come)."""
    offenders = []
    for snippet in all_blocks():
        body = snippet.body
        if re.search(r"rev: v\d", body) or PUBLIC_URL in body or re.search(r"pip install [\"']?geolint-robotics\b", body):
            offenders.append(f"{snippet.file}:{snippet.line}")
    assert offenders == []


def test_readme_editor_snippets_are_the_tested_ones() -> None:
    """The README's editor snippets are copies of docs/editors.md's, which tests/integrations/test_lsp_docs.py runs."""
    editors = (REPO_ROOT / "docs" / "editors.md").read_text(encoding="utf-8")
    for index in (0, 1):
        snippet = block("README.md", "Editors", index)
        assert f"```{snippet.language}\n{snippet.body}```" in editors, f"README.md:{snippet.line} differs from docs/editors.md"


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


@pytest.mark.parametrize("where", [("README.md", "The runtime: `import geolint`"), ("docs/runtime.md", "Tour")])
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
    "key", [("README.md", "Configuration", 0), ("docs/linter.md", "Configuration: `[tool.geolint]`", 0)]
)
def test_geolint_config_snippets_are_accepted(tmp_path: Path, key: tuple[str, str, int]) -> None:
    snippet = block(*key)
    assert snippet.language == "toml"
    project = demo_project(tmp_path)
    (project / "pyproject.toml").write_text(snippet.body, encoding="utf-8")
    result = bash("geolint check --no-cache --verbose src", project)
    assert result.returncode in (0, 1), result.stderr
    assert f"config: {(project / 'pyproject.toml').resolve()}" in result.stderr


# --- mypy: the plugin's configuration in its forms (the typing guide's examples: tests/typing) ------

ALIAS_PROBE = '''\
from geolint import Point, Transform

def to_base(T: Transform["base", "camera"], p: Point["camera"]) -> Point["base_link"]:
    return T @ p  # "base" is an alias of "base_link" in the configuration
'''
TYPING_GUIDE_PLUGIN = "2. The mypy plugin, with string frames and precise messages"


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
@pytest.mark.parametrize(
    "source, form",
    [("README.md", "mypy.ini"), ("README.md", "setup.cfg"), ("docs/typing.md", "mypy.ini"), ("docs/typing.md", "pyproject.toml")],
)
def test_mypy_config_snippets(tmp_path: Path, source: str, form: str) -> None:
    """The README's plugin config in both ini files, and the typing guide's (with frame aliases) as ini and toml."""
    if source == "README.md":
        config, example = block(source, TYPING, 0), block(source, TYPING, 1)
    else:
        config = block(source, TYPING_GUIDE_PLUGIN, 1 if form == "pyproject.toml" else 0)
        example = block(source, TYPING_GUIDE_PLUGIN, 2)
    assert config.language == ("toml" if form == "pyproject.toml" else "ini")
    (tmp_path / form).write_text(config.body, encoding="utf-8")
    (tmp_path / "example.py").write_text(example.body, encoding="utf-8")
    files = ["example.py"]
    if "frame_aliases" in config.body:
        (tmp_path / "alias.py").write_text(ALIAS_PROBE, encoding="utf-8")
        files.append("alias.py")
    result = run_mypy(tmp_path, *files)
    output = result.stdout + result.stderr
    wanted = expected_errors(example.body)
    assert wanted and all(message in output for message in wanted), output
    assert "alias.py" not in output, output  # the alias took effect
    assert result.returncode == 1 and output.count("error:") == len(wanted), output
