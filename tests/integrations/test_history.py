"""GEO401 on git repositories built here: a bug copied into several files, fixed in one by a commit,
found in the others by the real `geolint check --history`; the history's cache, a shallow clone, merges,
renames, reverts, and a folder with no history."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from geolint.history.fix_edits import fix_shape, parse_statement

BUGGY = "    quat_error = current_quaternion - tgt_quaternion\n"
FIXED = "    quat_error = current_quaternion * tgt_quaternion.conjugate()\n"
ENVIRONMENT = "import quaternion\n\n\ndef reward(current_quaternion, tgt_quaternion):\n" + BUGGY + "    return quat_error.w\n"


def git(repository: Path, *arguments: str) -> str:
    return subprocess.run(["git", "-C", str(repository), *arguments], check=True, capture_output=True, text=True).stdout


def geolint(*arguments: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "geolint", "check", "--output-format", "concise", *arguments], cwd=cwd, capture_output=True, text=True, timeout=300)


def codes(completed: subprocess.CompletedProcess[str]) -> list[str]:
    return sorted(line.split(":")[0] for line in completed.stdout.splitlines() if " GEO401 " in line)


def commit(repository: Path, message: str) -> str:
    git(repository, "add", "-A")
    git(repository, "commit", "-q", "-m", message)
    return git(repository, "rev-parse", "HEAD").strip()


def fix(path: Path) -> None:
    path.write_text(path.read_text().replace(BUGGY, FIXED))


@pytest.fixture
def repository(tmp_path: Path) -> Path:
    """Three copies of an environment; the first commit has them all with the bug."""
    root = tmp_path / "gym"
    (root / "envs").mkdir(parents=True)
    git(root, "init", "-q", "-b", "main")
    git(root, "config", "user.email", "dev@example.com")
    git(root, "config", "user.name", "dev")
    for name in ("mara_v0.py", "mara_v1.py", "mara_v2.py"):
        (root / "envs" / name).write_text(ENVIRONMENT)
    commit(root, "three environments")
    return root


def test_a_fix_in_one_copy_finds_the_others(repository: Path) -> None:
    fix(repository / "envs/mara_v0.py")
    fixed = commit(repository, "fixes rew")
    completed = geolint("--history", "--no-cache", ".", cwd=repository)
    assert completed.returncode == 1, completed.stderr
    assert codes(completed) == ["envs/mara_v1.py", "envs/mara_v2.py"]
    assert (
        f"GEO401 this statement has the shape that commit {fixed[:7]} ('fixes rew') fixed in envs/mara_v0.py:5 "
        "(difference for relative rotation): `quat_error = current_quaternion - tgt_quaternion` became "
        "`quat_error = current_quaternion * tgt_quaternion.conjugate()`; the same change applies here"
    ) in completed.stdout
    # off unless asked for
    assert geolint("--no-cache", ".", cwd=repository).returncode == 0
    # the fix the commit wrote, applied to the copies
    assert geolint("--history", "--no-cache", "--fix", "--unsafe-fixes", ".", cwd=repository).returncode == 0
    assert (repository / "envs/mara_v2.py").read_text() == ENVIRONMENT.replace(BUGGY, FIXED)


def test_no_fix_is_offered_where_the_names_may_hold_other_kinds(repository: Path) -> None:
    """A copy that does not import numpy-quaternion holds arrays: `a * b.conjugate()` would multiply them
    componentwise, so the finding comes without the fix."""
    copy = repository / "envs/mara_v2.py"
    copy.write_text(copy.read_text().replace("import quaternion\n", "import numpy as np\n"))
    commit(repository, "v2 on arrays")
    fix(repository / "envs/mara_v0.py")
    commit(repository, "fixes rew")
    completed = geolint("--history", "--no-cache", "--fix", "--unsafe-fixes", ".", cwd=repository)
    assert codes(completed) == ["envs/mara_v2.py"]  # v1 fixed, v2 left with its finding
    assert BUGGY in copy.read_text()


def test_a_fix_that_also_adds_comments_and_lines(repository: Path) -> None:
    """The real shape of such commits: the old line commented out, the fix, and more code after it."""
    path = repository / "envs/mara_v0.py"
    path.write_text(
        path.read_text().replace(
            BUGGY,
            "    # this is wrong: the difference of two quaternions is no rotation\n"
            "    # quat_error = current_quaternion - tgt_quaternion\n\n"
            + FIXED
            + "    quat_error = quaternion.as_float_array(quat_error)\n",
        )
    )
    commit(repository, "fixes rew")
    assert codes(geolint("--history", "--no-cache", ".", cwd=repository)) == ["envs/mara_v1.py", "envs/mara_v2.py"]


def test_the_history_is_read_once_and_then_only_its_new_commits(repository: Path) -> None:
    fix(repository / "envs/mara_v0.py")
    commit(repository, "fixes rew")
    assert codes(geolint("--history", ".", cwd=repository)) == ["envs/mara_v1.py", "envs/mara_v2.py"]
    stored = json.loads((repository / ".geolint_cache/history-1000.json").read_text())
    assert stored["commits"] == 2 and len(stored["edits"]) == 1
    # a new commit: the findings cache and the history both follow it
    fix(repository / "envs/mara_v1.py")
    head = commit(repository, "fix the second copy too")
    assert codes(geolint("--history", ".", cwd=repository)) == ["envs/mara_v2.py"]
    stored = json.loads((repository / ".geolint_cache/history-1000.json").read_text())
    assert stored["head"] == head and stored["commits"] == 3 and len(stored["edits"]) == 2


def test_a_shallow_clone_is_said_to_be_one(repository: Path, tmp_path: Path) -> None:
    fix(repository / "envs/mara_v0.py")
    commit(repository, "fixes rew")
    (repository / "README.md").write_text("gym\n")
    commit(repository, "readme")
    clone = tmp_path / "clone"
    subprocess.run(["git", "clone", "-q", "--depth", "1", f"file://{repository}", str(clone)], check=True)
    completed = geolint("--history", "--no-cache", ".", cwd=clone)
    assert codes(completed) == []  # the fix is in a commit the clone does not have
    assert "is a shallow clone (1 commits read)" in completed.stderr


def test_a_fix_on_a_merged_branch_and_through_a_rename(repository: Path) -> None:
    git(repository, "checkout", "-q", "-b", "fix-reward")
    git(repository, "mv", "envs/mara_v0.py", "envs/mara_real.py")
    commit(repository, "rename the real robot's environment")
    fix(repository / "envs/mara_real.py")
    commit(repository, "fix the orientation error")
    git(repository, "checkout", "-q", "main")
    (repository / "envs/mara_v1.py").write_text(ENVIRONMENT + "\n# tuned\n")
    commit(repository, "tune v1")
    git(repository, "merge", "-q", "--no-ff", "-m", "merge fix-reward", "fix-reward")
    completed = geolint("--history", "--no-cache", ".", cwd=repository)
    assert codes(completed) == ["envs/mara_v1.py", "envs/mara_v2.py"]
    assert "fixed in envs/mara_real.py:5" in completed.stdout


def test_a_shape_the_history_changed_back_is_not_reported(repository: Path) -> None:
    fix(repository / "envs/mara_v0.py")
    commit(repository, "fix the orientation error")
    (repository / "envs/mara_v0.py").write_text(ENVIRONMENT)
    commit(repository, "revert: the reward was right")
    assert codes(geolint("--history", "--no-cache", ".", cwd=repository)) == []


def test_a_large_commit_that_does_not_say_fix_is_a_refactor(repository: Path) -> None:
    fix(repository / "envs/mara_v0.py")
    (repository / "envs/helpers.py").write_text("".join(f"value_{i} = {i}\n" for i in range(10)))
    commit(repository, "restructure the environments")
    assert codes(geolint("--history", "--no-cache", ".", cwd=repository)) == []


def test_no_repository_and_no_history(tmp_path: Path, repository: Path) -> None:
    loose = tmp_path / "loose"
    loose.mkdir()
    (loose / "env.py").write_text(ENVIRONMENT)
    completed = geolint("--history", "--no-cache", ".", cwd=loose)
    assert completed.returncode == 0 and "not in a git repository" in completed.stderr
    assert codes(geolint("--history", "--no-cache", ".", cwd=repository)) == []  # one commit: nothing was fixed


def test_the_config_turns_it_on_and_names_fixes(repository: Path) -> None:
    (repository / "pyproject.toml").write_text(
        "[tool.geolint]\nhistory = true\nhistory-limit = 50\n"
        'known-fixes = [{ before = "return quat_error.w", after = "return abs(quat_error.w)", reason = "q and -q are one rotation" }]\n'
    )
    completed = geolint("--no-cache", ".", cwd=repository)
    assert codes(completed) == ["envs/mara_v0.py", "envs/mara_v1.py", "envs/mara_v2.py"]
    assert "(`known-fixes`: q and -q are one rotation); the fix writes `return abs(quat_error.w)`" in completed.stdout
    (repository / "pyproject.toml").write_text('[tool.geolint]\nknown-fixes = [{ before = "if x:", after = "y" }]\n')
    broken = geolint("--no-cache", ".", cwd=repository)
    assert broken.returncode == 2 and "known-fixes[0].before" in broken.stderr


@pytest.mark.parametrize(
    ("before", "after", "shape"),
    [
        ("q = [o.x, o.y, o.z, o.w]", "q = [o.w, o.x, o.y, o.z]", "reordered"),
        ("t = buffer.lookup_transform(a, b, now)", "t = buffer.lookup_transform(b, a, now)", "swapped arguments"),
        ("p = T_a_b @ T_b_c", "p = T_b_c @ T_a_b", "swapped operands"),
        ("R_inv = R.T", "R_inv = np.linalg.inv(R)", "transpose for inverse"),
        ("T_inv = np.linalg.inv(T)", "T_inv = T.T", "transpose for inverse"),
        ("r = Rotation.from_euler('xyz', e)", "r = Rotation.from_euler('xyz', e, degrees=True)", "angle unit"),
        ("y = np.sin(np.deg2rad(a))", "y = np.sin(a)", "angle unit"),
        ("vy = twist.y", "vy = -twist.y", "negated"),
        ("C = c2w[:3, 3]", "C = w2c[:3, 3]", "extrinsics direction"),
        ("e = q1 - q2", "e = quaternion_multiply(q1, quaternion_inverse(q2))", "difference for relative rotation"),
        ("mu = -6.0", "mu = 6.0", None),  # a tuned number, not a direction
        ("x = f(a, b)", "x = f(a, b, c)", None),  # an argument added
        ("speed = old_speed", "speed = new_speed", None),  # a rename
        ("e = a - b", "e = a * b", None),  # no inverse: not a relative rotation
        ("q = [a, a, b]", "q = [a, b, a]", None),  # repeated elements: no permutation to speak of
    ],
)
def test_which_edits_are_geometric_fixes(before: str, after: str, shape: str | None) -> None:
    old, new = parse_statement(before), parse_statement(after)
    assert old is not None and new is not None
    assert fix_shape(old, new) == shape
