"""Installing as the README says, for real: pip into fresh venvs, real git tags, real pre-commit, real mypy.

The README's snippets name the public repository; these tests copy this working tree into a
local git repository, create the release tag exactly as docs/releasing.md says, and point the
snippets' URL at that repository (`git+file://...` for pip, a path for pre-commit). Everything
else in the snippets runs as written. pip reaches the package index for dependencies (its cache
makes that quick); nothing else is downloaded. Several minutes in all, hence `slow`.
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

from tests.cli.doc_snippets import PUBLIC_URL, REPO_ROOT, all_blocks, block, ci_commands, commands_of, project_version

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
def released(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """This working tree as a git repository, tagged by the documented release command."""
    if shutil.which("git") is None:
        pytest.skip("git is not installed")
    try:
        listed = git("ls-files", "-co", "--exclude-standard", "-z", cwd=REPO_ROOT)
    except subprocess.CalledProcessError:
        pytest.skip("not a git checkout")
    repo = tmp_path_factory.mktemp("released") / "geolint"
    for relative in filter(None, listed.split("\0")):
        source = REPO_ROOT / relative
        if source.is_file():
            (repo / relative).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, repo / relative)
    git("init", "-q", cwd=repo)
    git("add", "-A", cwd=repo)
    git("commit", "-q", "-m", "snapshot of the working tree", cwd=repo)
    tag_lines = [line for line in commands_of(block("docs/releasing.md", "Releasing").body) if line.startswith("git tag")]
    assert len(tag_lines) == 1, "docs/releasing.md shows one `git tag` command"
    tagged = bash(tag_lines[0], repo, clean_env(Path(sys.executable).parent))
    assert tagged.returncode == 0, tagged.stderr
    assert git("tag", "--points-at", "HEAD", cwd=repo).split() == [f"v{project_version()}"]
    return repo


def fresh_venv(where: Path) -> Path:
    subprocess.run([sys.executable, "-m", "venv", str(where)], check=True, env=clean_env())
    return where / "bin"


def local(text: str, repo: Path) -> str:
    """A snippet with the public repository's URL pointed at the local one.

    pip's requirement parser wants a host in a `git+file:` URL, so `localhost` (git accepts it).
    """
    return text.replace(f"git+{PUBLIC_URL}", f"git+file://localhost{repo}").replace(PUBLIC_URL, str(repo))


def readme_install_lines() -> list[str]:
    return [line.split("  #", 1)[0].strip() for line in commands_of(block("README.md", "Install").body)]


@pytest.fixture(scope="module")
def base_install(released: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A venv with nothing but the README's first install line (no extras): its bin folder."""
    bin_dir = fresh_venv(tmp_path_factory.mktemp("base") / "venv")
    command = readme_install_lines()[0]
    assert "[" not in command.split("@")[0], "the first install line is the plain one, without extras"
    installed = bash(local(command, released), released, clean_env(bin_dir))
    assert installed.returncode == 0, installed.stdout + installed.stderr
    return bin_dir


def test_every_version_reference_names_the_project_version() -> None:
    tag = f"v{project_version()}"
    refs = []
    for snippet in all_blocks():
        refs += re.findall(r"rev: (\S+)", snippet.body) + re.findall(rf"{re.escape(PUBLIC_URL)}@(\S+?)[\"'\s]", snippet.body)
    assert refs and set(refs) == {tag}


def test_git_url_install_gives_a_working_linter(base_install: Path, released: Path, tmp_path: Path) -> None:
    env = clean_env(base_install)
    python = str(base_install / "python")
    names = subprocess.run(
        [python, "-c", "import importlib.metadata as m; print(m.version('geolint-robotics')); m.distribution('geolint')"],
        cwd=tmp_path, env=env, capture_output=True, text=True,
    )  # fmt: skip
    assert names.stdout.split("\n")[0] == project_version() and "PackageNotFoundError" in names.stderr

    demo = bash("geolint check fixtures/demo", released, env)
    assert demo.returncode == 1 and demo.stdout.rstrip().endswith("Found 7 findings (3 fixable with --fix, 1 more with --fix --unsafe-fixes)."), demo.stdout + demo.stderr
    for command in ("geolint --version", "geolint rules", "geolint rule GEO101", "geolint frames fixtures/frames"):
        result = bash(command, released, env)
        assert result.returncode == 0 and "Traceback" not in result.stderr, f"{command}: {result.stderr}"

    # The missing extra is named, exit 2, no traceback.
    lsp = subprocess.run([str(base_install / "geolint"), "lsp"], env=env, capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=60)
    assert lsp.returncode == 2, lsp.stderr
    assert "pip install 'geolint-robotics[lsp]'" in lsp.stderr and "Traceback" not in lsp.stderr

    # The runtime imports numpy and nothing else beyond the standard library.
    probe = (
        "import sys; before = set(sys.modules); import geolint; "
        "geolint.Transform['a', 'b'](translation=[1, 2, 3]) @ geolint.Point['b']([0, 0, 0]); "
        "loaded = {m.split('.')[0] for m in set(sys.modules) - before}; "
        "print(' '.join(sorted(m for m in loaded if m not in sys.stdlib_module_names and not m.startswith('_'))))"
    )
    imported = subprocess.run([python, "-c", probe], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert imported.stdout.split() == ["geolint", "numpy"], imported.stderr


CI_BLOCKS = [("README.md", "In CI", 0), ("README.md", "In CI", 1), ("docs/ci.md", "GitHub Actions", 0), ("docs/ci.md", "GitLab CI", 0)]


@pytest.mark.parametrize("key", CI_BLOCKS, ids=lambda key: f"{key[0]}:{key[1]}:{key[2]}")
def test_ci_snippet_commands(base_install: Path, tmp_path: Path, key: tuple[str, str, int]) -> None:
    commands = ci_commands(block(*key).body)
    installs = [c for c in commands if c.startswith("pip install")]
    assert [c.split("  #", 1)[0].strip() for c in installs] == [readme_install_lines()[0]]  # installed by the fixture
    shutil.copytree(REPO_ROOT / "fixtures" / "demo", tmp_path / "demo")
    env = clean_env(base_install)
    for command in commands:
        if command in installs:
            continue
        result = bash(command, tmp_path, env, timeout=300)
        expected = 0 if "--exit-zero" in command else 1  # the demo has findings
        assert result.returncode == expected, f"{command}: {result.stdout}{result.stderr}"
        output = re.search(r"--output (\S+)", command)
        if output:
            written = (tmp_path / output.group(1)).read_text(encoding="utf-8")
            assert "GEO101" in written
        else:
            assert "GEO101" in result.stdout


@pytest.fixture(scope="module")
def pre_commit_home(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("pre-commit-home")


@pytest.mark.parametrize("key", [("README.md", "In pre-commit", 0), ("docs/ci.md", "pre-commit", 0)], ids=["README", "ci.md"])
def test_pre_commit_snippets_at_the_release_tag(released: Path, pre_commit_home: Path, tmp_path: Path, key: tuple[str, str, int]) -> None:
    snippet = block(*key).body
    assert f"rev: v{project_version()}" in snippet and PUBLIC_URL in snippet
    project = tmp_path / "project"
    project.mkdir()
    git("init", "-q", cwd=project)
    (project / ".pre-commit-config.yaml").write_text(local(snippet, released), encoding="utf-8")
    (project / "buggy.py").write_text(BUGGY, encoding="utf-8")
    git("add", "-A", cwd=project)
    env = clean_env() | {"PRE_COMMIT_HOME": str(pre_commit_home)}
    result = subprocess.run(
        [sys.executable, "-m", "pre_commit", "run", "--all-files", "--color", "never"],
        cwd=project, env=env, capture_output=True, text=True, timeout=900,
    )  # fmt: skip
    output = result.stdout + result.stderr
    assert result.returncode == 1, output
    assert re.search(r"buggy\.py:2:\d+: GEO101 ", output), output


def test_readme_quick_start(released: Path, tmp_path: Path) -> None:
    checkout = tmp_path / "checkout"
    git("clone", "-q", str(released), str(checkout), cwd=tmp_path)
    quick = block("README.md", "Quick start", 0).body.strip()
    result = bash(quick, checkout, clean_env())
    assert result.returncode == 1, result.stdout + result.stderr  # the demo's bugs
    assert result.stdout.rstrip().endswith("Found 7 findings (3 fixable with --fix, 1 more with --fix --unsafe-fixes).")


TYPED_USE = """\
from geolint import Frame, Point, Transform

class World(Frame): pass
class Camera(Frame): pass

def place(T_world_cam: Transform[World, Camera], p_world: Point[World]) -> None:
    reveal_type(T_world_cam @ Point[Camera]([0.0, 0.0, 1.0]))
    T_world_cam @ p_world
"""


def test_editable_install_is_visible_to_mypy_from_another_directory(released: Path, tmp_path: Path) -> None:
    """The README's development install (with `[mypy]` instead of `[dev]`: the mode matters, not the extras)."""
    checkout = tmp_path / "checkout"
    git("clone", "-q", str(released), str(checkout), cwd=tmp_path)
    test_command = block("README.md", "Quick start", 1).body.strip()
    install = next(part for part in test_command.split(" && ") if " -e " in part)
    assert "'.[dev]'" in install
    bin_dir = fresh_venv(checkout / ".venv")
    installed = bash(install.replace("'.[dev]'", "'.[mypy]'"), checkout, clean_env(bin_dir))
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


@pytest.mark.parametrize("key", [("README.md", "Precision and recall on real code.", 0), ("docs/real-world.md", "Command", 0)], ids=["README", "real-world.md"])
def test_precision_command_lints_the_named_trees(key: tuple[str, str, int]) -> None:
    """Run from the repository root, where the dev venv (and so `$SP`) usually sits under the excluded `.venv`."""
    script = block(*key).body
    assert script.count("geolint check ") == 1
    env = clean_env(Path(sys.executable).parent)
    result = bash(script.replace("geolint check ", "geolint check --verbose "), REPO_ROOT, env)
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout) == []
    files = int(re.search(r"^files: (\d+),", result.stderr, re.M).group(1))
    assert files > 500, result.stderr  # the five trees, not nothing
