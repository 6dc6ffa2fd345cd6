"""Installing as the docs say, for real: pip into fresh venvs, a wheel, real pre-commit, real mypy.

The snippets install from a checkout (nothing is published yet). These tests copy this working tree
into a local git repository (a checkout as a reader would have it) and run the snippets there as
written; only placeholders the docs tell the reader to fill in (`/path/to/geolint`, the commit id) are
replaced. pip reaches the package index for dependencies (its cache makes that quick); nothing else
is downloaded. Several minutes in all, hence `slow`.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.cli.doc_snippets import REPO_ROOT, block, ci_commands, commands_of, project_version

pytestmark = pytest.mark.slow

BUGGY = """\
def normal_to_world(R_world_cam, t_world_cam, normal_cam):
    return R_world_cam @ normal_cam + t_world_cam
"""
GIT_IDENTITY = {
    "GIT_AUTHOR_NAME": "geolint tests",
    "GIT_AUTHOR_EMAIL": "tests@example.invalid",
    "GIT_COMMITTER_NAME": "geolint tests",
    "GIT_COMMITTER_EMAIL": "tests@example.invalid",
}
# What the docs tell the reader to replace with their own clone's path and commit.
CLONE_PLACEHOLDER = "/path/to/geolint"
COMMIT_PLACEHOLDER = "0" * 40
DEMO_SUMMARY = "Found 7 findings (3 fixable with --fix, 1 more with --fix --unsafe-fixes)."


def clean_env(bin_dir: Path | None = None) -> dict[str, str]:
    """The environment of a reader's shell: no test venv activated, `bin_dir` (if given) first on PATH."""
    env = {k: v for k, v in os.environ.items() if k not in ("VIRTUAL_ENV", "PYTHONPATH", "PYTHONHOME", "COLUMNS", "CI")}
    own_bin = str(Path(sys.executable).parent)
    path = [p for p in env.get("PATH", "").split(os.pathsep) if p and p != own_bin]
    env["PATH"] = os.pathsep.join(([str(bin_dir)] if bin_dir else []) + path)
    env.update(GIT_IDENTITY)
    return env


def bash(script: str, cwd: Path, env: dict[str, str], timeout: int = 900) -> subprocess.CompletedProcess[str]:
    return subprocess.run(["bash", "-c", script], cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)


def git(*args: str, cwd: Path) -> str:
    completed = subprocess.run(["git", *args], cwd=cwd, env=clean_env(), capture_output=True, text=True, check=True)
    return completed.stdout.strip()


@pytest.fixture(scope="module")
def checkout(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """This working tree as a git repository: a clone of geolint as a reader has it."""
    if shutil.which("git") is None:
        pytest.skip("git is not installed")
    try:
        listed = git("ls-files", "-co", "--exclude-standard", "-z", cwd=REPO_ROOT)
    except subprocess.CalledProcessError:
        pytest.skip("not a git checkout")
    repo = tmp_path_factory.mktemp("checkout") / "geolint"
    for relative in filter(None, listed.split("\0")):
        source = REPO_ROOT / relative
        if source.is_file():
            (repo / relative).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, repo / relative)
    git("init", "-q", cwd=repo)
    git("add", "-A", cwd=repo)
    git("commit", "-q", "-m", "snapshot of the working tree", cwd=repo)
    return repo


def fresh_venv(where: Path) -> Path:
    subprocess.run([sys.executable, "-m", "venv", str(where)], check=True, env=clean_env())
    return where / "bin"


def readme_install_lines() -> list[str]:
    return [line.split("  #", 1)[0].strip() for line in commands_of(block("README.md", "Install").body)]


@pytest.fixture(scope="module")
def base_install(checkout: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A venv with nothing but the README's first install line (no extras), run in the checkout: its bin folder."""
    bin_dir = fresh_venv(tmp_path_factory.mktemp("base") / "venv")
    command = readme_install_lines()[0]
    assert command == "pip install .", "the first install line is the plain one, without extras"
    installed = bash(command, checkout, clean_env(bin_dir))
    assert installed.returncode == 0, installed.stdout + installed.stderr
    return bin_dir


@pytest.fixture(scope="module")
def wheel(checkout: Path, base_install: Path) -> Path:
    """The wheel the README's build line makes in the checkout."""
    (build,) = [line for line in readme_install_lines() if line.startswith("pip wheel")]
    built = bash(build, checkout, clean_env(base_install))
    assert built.returncode == 0, built.stdout + built.stderr
    (made,) = (checkout / "dist").glob("*.whl")
    return made


def test_plain_install_gives_a_working_linter(base_install: Path, checkout: Path, tmp_path: Path) -> None:
    env = clean_env(base_install)
    python = str(base_install / "python")
    names = subprocess.run(
        [python, "-c", "import importlib.metadata as m; print(m.version('geolint-robotics')); m.distribution('geolint')"],
        cwd=tmp_path, env=env, capture_output=True, text=True,
    )  # fmt: skip
    assert names.stdout.split("\n")[0] == project_version() and "PackageNotFoundError" in names.stderr

    demo = bash("geolint check fixtures/demo", checkout, env)
    assert demo.returncode == 1 and demo.stdout.rstrip().endswith(DEMO_SUMMARY), demo.stdout + demo.stderr
    for command in ("geolint --version", "geolint rules", "geolint rule GEO101", "geolint frames fixtures/frames"):
        result = bash(command, checkout, env)
        assert result.returncode == 0 and "Traceback" not in result.stderr, f"{command}: {result.stderr}"

    # The runtime imports numpy and nothing else beyond the standard library.
    probe = (
        "import sys; before = set(sys.modules); import geolint; "
        "geolint.Transform['a', 'b'](translation=[1, 2, 3]) @ geolint.Point['b']([0, 0, 0]); "
        "loaded = {m.split('.')[0] for m in set(sys.modules) - before}; "
        "print(' '.join(sorted(m for m in loaded if m not in sys.stdlib_module_names and not m.startswith('_'))))"
    )
    imported = subprocess.run([python, "-c", probe], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert imported.stdout.split() == ["geolint", "numpy"], imported.stderr

    # The knowledge base's stubs ship inside the package.
    stubs = "from geolint.knowledge import knowledge_base, stubs_folder; print(stubs_folder().name, len(knowledge_base().libraries))"
    shipped = subprocess.run([python, "-c", stubs], cwd=tmp_path, env=env, capture_output=True, text=True)
    folder, count = shipped.stdout.split()
    assert folder == "_stubs" and int(count) >= 4, shipped.stderr


def test_the_missing_extra_hint_names_an_install_line_that_works(base_install: Path, tmp_path: Path) -> None:
    """`geolint lsp` without the extra says what to install, exit 2; running exactly that makes it work.
    (It installs the extra into the plain install's venv: the tests after it do not depend on its absence.)"""
    bin_dir = base_install
    env = clean_env(bin_dir)
    lsp = subprocess.run([str(bin_dir / "geolint"), "lsp"], env=env, capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=60)
    assert lsp.returncode == 2 and "Traceback" not in lsp.stderr, lsp.stderr
    hint = re.search(r"(pip install .+)$", lsp.stderr, re.M)
    assert hint is not None, lsp.stderr
    fixed = bash(hint.group(1), tmp_path, env)  # elsewhere than the checkout: the hint must not rely on it
    assert fixed.returncode == 0, fixed.stdout + fixed.stderr
    helped = subprocess.run([str(bin_dir / "geolint"), "lsp", "--help"], env=env, capture_output=True, text=True, timeout=60)
    assert helped.returncode == 0 and "--log-file" in helped.stdout, helped.stderr


def test_the_install_with_extras(checkout: Path, tmp_path: Path) -> None:
    (command,) = [line for line in readme_install_lines() if "[lsp,mypy]" in line]
    bin_dir = fresh_venv(tmp_path / "venv")
    env = clean_env(bin_dir)
    installed = bash(command, checkout, env)
    assert installed.returncode == 0, installed.stdout + installed.stderr
    for probe in ("geolint lsp --help", "python -c 'import geolint.mypy, mypy.api'"):
        result = bash(probe, tmp_path, env)
        assert result.returncode == 0, f"{probe}: {result.stderr}"


def test_the_wheel_installs_elsewhere_with_an_extra(wheel: Path, checkout: Path, tmp_path: Path) -> None:
    """The README's wheel line, run in a venv of its own from the checkout where the wheel was built."""
    (command,) = [line for line in readme_install_lines() if line.startswith("pip install") and ".whl" in line]
    assert wheel.relative_to(checkout).as_posix() in command, f"the README names {command}, the build made {wheel.name}"
    bin_dir = fresh_venv(tmp_path / "venv")
    env = clean_env(bin_dir)
    installed = bash(command, checkout, env)
    assert installed.returncode == 0, installed.stdout + installed.stderr
    (tmp_path / "buggy.py").write_text(BUGGY, encoding="utf-8")
    lint = bash("geolint check buggy.py", tmp_path, env)
    assert lint.returncode == 1 and "GEO101" in lint.stdout, lint.stdout + lint.stderr
    assert bash("geolint lsp --help", tmp_path, env).returncode == 0


CI_BLOCKS = [("README.md", "CI", 0), ("README.md", "CI", 1), ("docs/ci.md", "GitHub Actions", 0), ("docs/ci.md", "GitLab CI", 0)]


@pytest.fixture(scope="module")
def ci_venv(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """An empty venv, as a CI image's Python is before the job's `pip install` line runs."""
    return fresh_venv(tmp_path_factory.mktemp("ci") / "venv")


@pytest.mark.parametrize("key", CI_BLOCKS, ids=lambda key: f"{key[0]}:{key[1]}:{key[2]}")
def test_ci_snippet_commands(wheel: Path, ci_venv: Path, tmp_path: Path, key: tuple[str, str, int]) -> None:
    """Every `run:` / `script:` line, in order, in a project that holds the committed wheel where the snippet says."""
    commands = ci_commands(block(*key).body)
    installs = [c for c in commands if c.startswith("pip install")]
    assert len(installs) == 1
    wheel_path = installs[0].split()[-1]
    assert Path(wheel_path).name == wheel.name, f"the snippet installs {wheel_path}, a build makes {wheel.name}"
    project = tmp_path / "project"
    shutil.copytree(REPO_ROOT / "fixtures" / "demo", project)
    (project / wheel_path).parent.mkdir(parents=True, exist_ok=True)
    shutil.copy2(wheel, project / wheel_path)
    env = clean_env(ci_venv)
    for command in commands:
        result = bash(command, project, env, timeout=600)
        if command in installs:
            assert result.returncode == 0, f"{command}: {result.stdout}{result.stderr}"
            continue
        expected = 0 if "--exit-zero" in command else 1  # the demo has findings
        assert result.returncode == expected, f"{command}: {result.stdout}{result.stderr}"
        output = re.search(r"--output (\S+)", command)
        if output:
            assert "GEO101" in (project / output.group(1)).read_text(encoding="utf-8")
        else:
            assert "GEO101" in result.stdout


@pytest.fixture(scope="module")
def pre_commit_home(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("pre-commit-home")


def project_with_a_bug(where: Path) -> Path:
    project = where / "project"
    project.mkdir()
    git("init", "-q", cwd=project)
    (project / "buggy.py").write_text(BUGGY, encoding="utf-8")
    git("add", "-A", cwd=project)
    return project


def run_pre_commit(project: Path, env: dict[str, str], *arguments: str) -> str:
    result = subprocess.run(
        [sys.executable, "-m", "pre_commit", *arguments, "--color", "never"], cwd=project, env=env, capture_output=True, text=True, timeout=900
    )
    output = result.stdout + result.stderr
    assert result.returncode == 1, output  # the hook ran and failed on the finding
    assert re.search(r"buggy\.py:2:\d+: GEO101 ", output), output
    return output


@pytest.mark.parametrize("key", [("README.md", "pre-commit", 0), ("docs/ci.md", "pre-commit", 0)], ids=["README", "ci.md"])
def test_local_pre_commit_hook_with_geolint_installed(base_install: Path, pre_commit_home: Path, tmp_path: Path, key: tuple[str, str, int]) -> None:
    snippet = block(*key).body
    assert "repo: local" in snippet and "language: system" in snippet
    project = project_with_a_bug(tmp_path)
    (project / ".pre-commit-config.yaml").write_text(snippet, encoding="utf-8")
    run_pre_commit(project, clean_env(base_install) | {"PRE_COMMIT_HOME": str(pre_commit_home)}, "run", "--all-files")


def test_pre_commit_hook_from_a_clone_at_a_commit(checkout: Path, pre_commit_home: Path, tmp_path: Path) -> None:
    """pre-commit builds geolint's environment itself from the clone's `.pre-commit-hooks.yaml`."""
    snippet = block("docs/ci.md", "pre-commit", 1).body
    assert CLONE_PLACEHOLDER in snippet and COMMIT_PLACEHOLDER in snippet
    project = project_with_a_bug(tmp_path)
    filled = snippet.replace(CLONE_PLACEHOLDER, str(checkout)).replace(COMMIT_PLACEHOLDER, git("rev-parse", "HEAD", cwd=checkout))
    (project / ".pre-commit-config.yaml").write_text(filled, encoding="utf-8")
    run_pre_commit(project, clean_env() | {"PRE_COMMIT_HOME": str(pre_commit_home)}, "run", "--all-files")


def test_pre_commit_try_repo(checkout: Path, pre_commit_home: Path, tmp_path: Path) -> None:
    (line,) = commands_of(block("docs/ci.md", "pre-commit", 2).body)
    arguments = line.replace(CLONE_PLACEHOLDER, str(checkout)).split()
    assert arguments[:2] == ["pre-commit", "try-repo"]
    project = project_with_a_bug(tmp_path)
    run_pre_commit(project, clean_env() | {"PRE_COMMIT_HOME": str(pre_commit_home)}, *arguments[1:])


def test_the_release_tag_command(checkout: Path, tmp_path: Path) -> None:
    """docs/releasing.md's tag command, in a clone: it tags HEAD with the version of pyproject.toml."""
    clone = tmp_path / "clone"
    git("clone", "-q", str(checkout), str(clone), cwd=tmp_path)
    tag_lines = [line for line in commands_of(block("docs/releasing.md", "Releasing").body) if line.startswith("git tag")]
    assert len(tag_lines) == 1, "docs/releasing.md shows one `git tag` command"
    tagged = bash(tag_lines[0], clone, clean_env(Path(sys.executable).parent))
    assert tagged.returncode == 0, tagged.stderr
    assert git("tag", "--points-at", "HEAD", cwd=clone).split() == [f"v{project_version()}"]


def test_readme_quick_start(checkout: Path, tmp_path: Path) -> None:
    clone = tmp_path / "checkout"
    git("clone", "-q", str(checkout), str(clone), cwd=tmp_path)
    quick = block("README.md", "Quick start", 0).body.strip()
    result = bash(quick, clone, clean_env())
    assert result.returncode == 1, result.stdout + result.stderr  # the demo's bugs
    assert result.stdout.rstrip().endswith(DEMO_SUMMARY)


TYPED_USE = """\
from geolint import Frame, Point, Transform

class World(Frame): pass
class Camera(Frame): pass

def place(T_world_cam: Transform[World, Camera], p_world: Point[World]) -> None:
    reveal_type(T_world_cam @ Point[Camera]([0.0, 0.0, 1.0]))
    T_world_cam @ p_world
"""


def test_editable_install_is_visible_to_mypy_from_another_directory(checkout: Path, tmp_path: Path) -> None:
    """The README's development install (with `[mypy]` instead of `[dev]`: the mode matters, not the extras)."""
    clone = tmp_path / "checkout"
    git("clone", "-q", str(checkout), str(clone), cwd=tmp_path)
    test_command = block("README.md", "Contributing", 0).body.strip()
    install = next(part for part in test_command.split(" && ") if " -e " in part)
    assert "'.[dev]'" in install
    bin_dir = fresh_venv(clone / ".venv")
    installed = bash(install.replace("'.[dev]'", "'.[mypy]'"), clone, clean_env(bin_dir))
    assert installed.returncode == 0, installed.stdout + installed.stderr

    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (elsewhere / "use.py").write_text(TYPED_USE, encoding="utf-8")
    result = subprocess.run(
        [str(bin_dir / "python"), "-m", "mypy", "--ignore-missing-imports", "--no-incremental", "use.py"],
        cwd=elsewhere, env=clean_env(bin_dir), capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    output = result.stdout
    assert re.search(r'use\.py:7: note: Revealed type is "geolint\..*Point\[use\.World\]"', output), output
    assert re.search(r"use\.py:8: error: ", output), output  # a Point[World] given to a Transform from Camera


def test_precision_command_lints_the_named_trees() -> None:
    """docs/real-world.md's command, from the repository root, where the dev venv (and so `$SP`) usually
    sits under the excluded `.venv`."""
    script = block("docs/real-world.md", "Command", 0).body
    assert script.count("geolint check ") == 1
    env = clean_env(Path(sys.executable).parent)
    result = bash(script.replace("geolint check ", "geolint check --verbose "), REPO_ROOT, env)
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout) == []
    files = int(re.search(r"^files: (\d+),", result.stderr, re.M).group(1))
    assert files > 500, result.stderr  # the five trees, not nothing
