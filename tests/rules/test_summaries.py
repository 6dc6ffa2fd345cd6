"""Function summaries that compose across the project's modules: a finding reaches a script through a
helper that calls another helper two modules away, recursion and import cycles settle to a fixpoint,
and the findings cache re-lints a module when a module two imports away changes."""

from __future__ import annotations

import ast
import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from geolint._build import is_compiled
from geolint.factbase import facts_for_module
from geolint.factbase.model import FactBase
from geolint.factbase.angle_units import ANGLE_UNITS
from geolint.factbase.kind_summaries import HOMOGENEOUS
from geolint.factbase.project_files import ImportGraph, dependency_digest, imported_names
from geolint.factbase.quaternion_orders import QUATERNIONS
from geolint.factbase.summaries import ProjectSummaries
from geolint.lint_types import Config
from geolint.engine import lint_source

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures" / "projects"
RUN = "lidar/scripts/run.py"


def _check(project: Path, *extra: str) -> tuple[set[tuple[str, int, str]], str]:
    result = subprocess.run(
        [sys.executable, "-m", "geolint", "check", "--format", "json", "--select", "GEO1,GEO2,GEO3", *extra, "."],
        cwd=project,
        capture_output=True,
        text=True,
    )
    assert result.returncode in (0, 1), result.stderr
    return {(Path(f["path"]).as_posix(), f["line"], f["code"]) for f in json.loads(result.stdout)}, result.stderr


def _copy(tmp_path: Path) -> Path:
    project = tmp_path / "lidar_chain"
    shutil.copytree(FIXTURES / "lidar_chain", project)
    return project


def test_a_correct_helper_two_modules_away_keeps_the_script_silent(tmp_path: Path) -> None:
    project = _copy(tmp_path)
    before, _ = _check(project, "--no-cache")
    assert (RUN, 14, "GEO101") in before  # cloud_to_world -> move (alias) -> apply_pose: R x + t
    assert (RUN, 16, "GEO302") in before  # yaw_rotation -> rot_z (relative import) -> np.cos
    transforms = project / "lidar" / "geom" / "transforms.py"
    text = transforms.read_text()
    text = text.replace("return points @ rotation.T + translation", "return points @ rotation.T")
    text = text.replace("c, s = np.cos(theta), np.sin(theta)", "c, s = np.cos(np.deg2rad(theta)), np.sin(np.deg2rad(theta))")
    transforms.write_text(text)
    after, _ = _check(project, "--no-cache")
    assert (RUN, 14, "GEO101") not in after
    assert (RUN, 16, "GEO302") not in after
    assert (RUN, 15, "GEO101") in after  # the other chains still speak


def test_the_cache_relints_a_script_when_a_module_two_imports_away_changes(tmp_path: Path) -> None:
    project = _copy(tmp_path)
    first, _ = _check(project)
    assert (RUN, 14, "GEO101") in first
    again, _ = _check(project)
    assert again == first
    transforms = project / "lidar" / "geom" / "transforms.py"  # run.py -> utils/points.py -> geom/transforms.py
    transforms.write_text(transforms.read_text().replace("return points @ rotation.T + translation", "return points @ rotation.T"))
    after, _ = _check(project)
    assert (RUN, 14, "GEO101") not in after
    assert after == first - {(RUN, 14, "GEO101")}


def test_the_digest_covers_modules_imported_through_other_modules(tmp_path: Path) -> None:
    project = _copy(tmp_path)
    run = project / RUN

    def digest() -> str:
        return dependency_digest(str(run), run.read_bytes(), lambda data: str(hash(data)), ImportGraph(lambda data: str(hash(data))))

    before = digest()
    chain = project / "lidar" / "geom" / "chain.py"  # imported by run.py; imports utils/walk.py, which imports it back
    walk = project / "lidar" / "utils" / "walk.py"
    walk.write_text(walk.read_text() + "\n")
    assert digest() != before
    unrelated = project / "setup.py"
    unrelated.write_text(unrelated.read_text() + "\n")
    assert chain.exists() and digest() != before


def test_digests_do_not_depend_on_the_order_files_are_read(tmp_path: Path) -> None:
    # one graph serves a whole run: an import cycle (chain.py <-> walk.py) reached from different files
    # first, or a module read before or after the files that import it, must give the same digests
    project = _copy(tmp_path)
    files = sorted(project.rglob("*.py"))

    def digests(order: list[Path]) -> dict[Path, str]:
        graph = ImportGraph(lambda data: str(hash(data)))
        return {file: dependency_digest(str(file), file.read_bytes(), lambda data: str(hash(data)), graph) for file in order}

    one_by_one = {
        file: dependency_digest(str(file), file.read_bytes(), lambda data: str(hash(data)), ImportGraph(lambda data: str(hash(data))))
        for file in files
    }
    assert digests(files) == digests(files[::-1]) == one_by_one
    chain, walk = project / "lidar" / "geom" / "chain.py", project / "lidar" / "utils" / "walk.py"
    assert one_by_one[chain] != str(hash(chain.read_bytes()))  # it imports project modules: not its bare hash
    walk.write_text(walk.read_text() + "\n")
    changed = digests(files)
    assert changed[chain] != one_by_one[chain] and changed[project / RUN] != one_by_one[project / RUN]
    assert changed[project / "setup.py"] == one_by_one[project / "setup.py"]  # imports nothing of the project


def test_from_imports_name_submodules() -> None:
    text = "from lidar.utils import points, walk as w\nfrom . import (\n    chain,\n    tree)\nfrom .x import y  # z\n"
    assert imported_names(text, members=True) == [
        "lidar.utils", "lidar.utils.points", "lidar.utils.walk", ".", ".chain", ".tree", ".x", ".x.y",
    ]
    assert imported_names(text) == ["lidar.utils", ".", ".x"]


def _codes(source: str) -> list[tuple[int, str]]:
    return sorted((f.line, f.code) for f in lint_source(source, "<string>", Config()))


def test_recursion_settles_on_what_every_return_agrees_on() -> None:
    recursive = (
        "def unit_normals(mesh, depth):\n"
        "    if depth == 0:\n"
        "        return mesh.vertex_normals\n"
        "    return unit_normals(mesh.parent, depth - 1)\n"
        "\n"
        "def move(T, mesh):\n"
        "    n = unit_normals(mesh, 3)\n"
        "    return n @ T[:3, :3].T + T[:3, 3]\n"
    )
    assert _codes(recursive) == [(8, "GEO101")]
    disagreeing = recursive.replace("return unit_normals(mesh.parent, depth - 1)", "return mesh.vertices")
    assert _codes(disagreeing) == []  # a point on one path, a direction on the other: unknown


def test_mutual_recursion_gives_the_same_summaries_whichever_is_asked_first() -> None:
    source = (
        "import numpy as np\n"
        "def even(points, n):\n"
        "    if n == 0:\n"
        "        return np.hstack([points, np.ones((len(points), 1))])\n"
        "    return odd(points, n - 1)\n"
        "def odd(points, n):\n"
        "    return even(points, n - 1)\n"
    )
    tree = ast.parse(source)
    answers = []
    for order in (("even", "odd"), ("odd", "even")):
        facts = facts_for_module(tree, source, "<string>", Config())
        project = ProjectSummaries(Config(), FactBase)
        answers.append([project.summary(facts, facts.index.functions[name], HOMOGENEOUS) for name in order])
    (even_first, odd_second), (odd_first, even_second) = answers
    assert even_first == even_second and odd_first == odd_second
    assert even_first is not None and even_first.homogenizes == {0: 1}
    assert odd_first is not None and odd_first.homogenizes == {0: 1}


def test_a_chain_deeper_than_the_bound_is_unknown_from_its_top() -> None:
    depth = 20
    lines = ["import numpy as np", "def h0(theta):", "    return np.cos(theta)"]
    for level in range(1, depth):
        lines += [f"def h{level}(theta):", f"    return h{level - 1}(theta)"]
    source = "\n".join(lines) + "\n"
    facts = facts_for_module(ast.parse(source), source, "<string>", Config())
    top = facts.project.summary(facts, facts.index.functions[f"h{depth - 1}"], ANGLE_UNITS)
    assert top is not None and top.reads_unit == {}  # the stack stopped short of `np.cos`: nothing known
    assert facts.project.computed <= depth  # and nothing was computed twice
    bottom = facts.project.summary(facts, facts.index.functions["h3"], ANGLE_UNITS)
    assert bottom is not None and bottom.reads_unit[0][0] == "rad"
    # a lint asks from the top too: a helper 19 calls away from `np.cos` is unknown there, and silent;
    # one 4 calls away is known
    assert _codes(source + "def far(yaw_deg):\n    return h19(yaw_deg)\n") == []
    assert len(_codes(source + "def near(yaw_deg):\n    return h3(yaw_deg)\n")) == 1


def test_a_parameter_read_under_a_condition_says_nothing() -> None:
    source = (
        "import numpy as np\n"
        "def rot(angle, degrees=False):\n"
        "    a = np.deg2rad(angle) if degrees else angle\n"
        "    return np.cos(a)\n"
        "def convert(angle, degrees=False):\n"
        "    if degrees:\n"
        "        return np.deg2rad(angle)\n"
        "    return angle\n"
        "def rot_early(angle, degrees=False):\n"
        "    if degrees:\n"
        "        return rot_early(np.deg2rad(angle))\n"
        "    return np.cos(angle)\n"
        "def f(theta_rad, yaw_deg):\n"
        "    return rot(theta_rad), convert(theta_rad), rot_early(yaw_deg, degrees=True)\n"
    )
    assert _codes(source) == []


_GUARDED_HELPERS = """\
import threading
import numpy as np
from scipy.spatial.transform import Rotation

_state_lock = threading.Lock()


def yaw_rotation(yaw):
    with _state_lock:
        c, s = np.cos(yaw), np.sin(yaw)
        return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def yaw_rotation_or_identity(yaw):
    with _state_lock:
        if yaw is None:
            return np.eye(3)
        c, s = np.cos(yaw), np.sin(yaw)
        return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def yaw_of(q):
    with _state_lock:
        return Rotation.from_quat(q).as_euler("zyx")[0]


def yaw_or_zero(q):
    with _state_lock:
        if q is None:
            return 0.0
        return Rotation.from_quat(q).as_euler("zyx")[0]


def yaw_checked(q):
    with _state_lock, open("/tmp/log", "a") as log:
        if len(q) != 4:
            raise ValueError(f"not a quaternion: {q}")
        log.write("yaw")
        return Rotation.from_quat(q).as_euler("zyx")[0]


async def yaw_when_ready(q, ready):
    async with ready:
        with _state_lock:
            if ready.cancelled:
                return None
        return Rotation.from_quat(q).as_euler("zyx")[0]


async def yaw_nested(q, ready):
    async with ready:
        with _state_lock:
            if ready.cancelled:
                return None
            return Rotation.from_quat(q).as_euler("zyx")[0]


def yaw_logged(q):
    with _state_lock:
        yaw = Rotation.from_quat(q).as_euler("zyx")[0]
        if abs(yaw) > 3.0:
            return None  # an exit after the read: the read still always happens
        return yaw


def yaw_retrying(q, busy):
    for _attempt in range(3):
        if busy():
            continue
        return Rotation.from_quat(q).as_euler("zyx")[0]
    return None
"""


def test_a_with_block_that_may_return_before_the_read_reads_nothing() -> None:
    """A helper that leaves its `with` (or `async with`) block early, by `return` or `raise`, before the
    API call does not always read its parameter: no unit or order in its summary, and its callers stay
    silent. A `with` body that reaches the call with no exit before it still reads it; so does one
    whose exit comes after the call. A loop body may not run at all."""
    facts = facts_for_module(ast.parse(_GUARDED_HELPERS), _GUARDED_HELPERS, "<string>", Config())

    def summary(name: str, family):  # type: ignore[no-untyped-def]
        found = facts.project.summary(facts, facts.index.functions[name], family)
        assert found is not None
        return found

    assert summary("yaw_rotation", ANGLE_UNITS).reads_unit[0][0] == "rad"
    assert summary("yaw_rotation_or_identity", ANGLE_UNITS).reads_unit == {}
    assert summary("yaw_of", QUATERNIONS).reads_quaternion[0][0] == summary("yaw_logged", QUATERNIONS).reads_quaternion[0][0] != ""
    for conditional in ("yaw_or_zero", "yaw_checked", "yaw_when_ready", "yaw_nested", "yaw_retrying"):
        assert summary(conditional, QUATERNIONS).reads_quaternion == {}, conditional

    calls = (
        "from transforms3d.quaternions import mat2quat\n"
        "def heading(R, heading_deg, ready):\n"
        "    q = mat2quat(R)\n"
        "    yaw_rotation(heading_deg)\n"
        "    yaw_rotation_or_identity(heading_deg)\n"
        "    yaw_of(q)\n"
        "    yaw_or_zero(q)\n"
        "    yaw_checked(q)\n"
        "    yaw_when_ready(q, ready)\n"
        "    yaw_nested(q, ready)\n"
        "    yaw_logged(q)\n"
        "    yaw_retrying(q, ready.busy)\n"
    )
    source = _GUARDED_HELPERS + calls
    lines = source.splitlines()
    findings = sorted((lines[f.line - 1].strip(), f.code) for f in lint_source(source, "<string>", Config()))
    assert findings == [("yaw_logged(q)", "GEO301"), ("yaw_of(q)", "GEO301"), ("yaw_rotation(heading_deg)", "GEO302")]


def test_a_parameter_named_in_a_unit_is_read_in_it() -> None:
    source = (
        "import numpy as np\n"
        "def normalize(angle_in_degrees):\n"
        "    angle_in_degrees = angle_in_degrees % 360.0\n"
        "    return angle_in_degrees - 360.0 if angle_in_degrees > 180 else angle_in_degrees\n"
        "def wrap(a):\n"
        "    return normalize(a)\n"
        "def f(dx, dy, theta_rad, yaw_deg):\n"
        "    heading = np.arctan2(dy, dx)\n"
        "    return normalize(heading), wrap(heading), normalize(theta_rad), normalize(yaw_deg)\n"
    )
    # computed radians into a degrees parameter, directly and through `wrap`; a name against a name says nothing
    assert _codes(source) == [(9, "GEO305"), (9, "GEO305")]
    contradicted = source.replace("    angle_in_degrees = angle_in_degrees % 360.0\n", "    np.cos(angle_in_degrees)\n")
    assert _codes(contradicted) == [(3, "GEO302")]  # the helper's own bug; its callers get no summary unit


def test_a_helper_returns_its_quaternion_order() -> None:
    source = (
        "from scipy.spatial.transform import Rotation\n"
        "from transforms3d.quaternions import quat2mat\n"
        "def orientation_of(matrix):\n"
        "    return Rotation.from_matrix(matrix).as_quat()\n"
        "def wrapped(matrix):\n"
        "    return orientation_of(matrix)\n"
        "def relative(matrix):\n"
        "    return quat2mat(wrapped(matrix))\n"
        "def reordered(matrix):\n"
        "    return quat2mat(wrapped(matrix)[[3, 0, 1, 2]])\n"
    )
    assert _codes(source) == [(8, "GEO301")]


def test_a_parameter_given_w_1_and_multiplied_is_translated() -> None:
    source = (
        "import numpy as np\n"
        "def transform_points(T, pts):\n"
        "    homog = np.concatenate([pts, np.ones((len(pts), 1))], axis=1)\n"
        "    return (homog @ T.T)[:, :3]\n"
        "def transform_vectors(T, vecs):\n"
        "    homog = np.concatenate([vecs, np.zeros((len(vecs), 1))], axis=1)\n"
        "    return (homog @ T.T)[:, :3]\n"
        "def use(T_world_cam, normals_cam, points_cam):\n"
        "    a = transform_points(T_world_cam, normals_cam)\n"
        "    b = transform_vectors(T_world_cam, normals_cam)\n"
        "    return a, b, transform_points(T_world_cam, points_cam)\n"
    )
    assert _codes(source) == [(9, "GEO101")]


def test_a_method_of_the_same_class_is_read_through_self() -> None:
    source = (
        "import numpy as np\n"
        "class Mapper:\n"
        "    def __init__(self, pose):\n"
        "        self.pose = pose\n"
        "    def to_world(self, points):\n"
        "        return points @ self.pose[:3, :3].T + self.pose[:3, 3]\n"
        "    def rotate(self, vectors):\n"
        "        return vectors @ self.pose[:3, :3].T\n"
        "    def insert(self, scan, scan_normals):\n"
        "        return self.to_world(scan), self.to_world(scan_normals), self.rotate(scan_normals)\n"
        "class Other:\n"
        "    def place(self, scan_normals):\n"
        "        return self.to_world(scan_normals)  # another class's method, maybe not this one's\n"
        "    @staticmethod\n"
        "    def rotate(vectors):\n"
        "        return vectors\n"
    )
    found = _codes(source)
    assert found == [(10, "GEO101")]


def test_a_long_chain_of_helpers_keeps_its_evidence_short() -> None:
    """Chains nest one helper at a time: a text spelling every hop would grow with the square of the
    chain's length (a 3,000-helper chain took 237 MB)."""
    lines = ["import numpy as np", "def h0(theta):", "    return np.cos(theta)"]
    for level in range(1, 2000):
        lines += [f"def h{level}(theta):", f"    return h{level - 1}(theta)"]
    lines += [f"x{level} = h{level}(yaw_deg)" for level in range(0, 2000, 7)]
    findings = lint_source("\n".join(lines) + "\n", "<string>", Config())
    assert findings and all(f.code == "GEO302" for f in findings)
    assert max(len(f.message) for f in findings) < 300
    assert any("-> ... ->" in f.message for f in findings)


_HELPERS_OF_THREE_FAMILIES = """\
import numpy as np
from scipy.spatial.transform import Rotation


def apply_pose(T, p):
    return T[:3, :3] @ p + T[:3, 3]


def heading(q):
    return Rotation.from_quat(q).as_euler("zyx")[0]


def wrapped_yaw(theta):
    return np.degrees(np.arctan2(np.sin(theta), np.cos(theta)))


def to_world(T_world_cam, normal_cam, q):
    yaw = heading(q)
    normal_world = apply_pose(T_world_cam, normal_cam)
    return normal_world, wrapped_yaw(yaw)
"""

# The modules that answer angle-unit and quaternion-order questions.
_ROTATION_MODULES = frozenset(
    {"geolint.factbase.angle_units", "geolint.factbase.quaternion_orders", "geolint.factbase.quaternion_formulas", "geolint.factbase.rotations"}
)


def _rotation_functions_run(select: tuple[str, ...]) -> set[str]:
    """The functions of `_ROTATION_MODULES` that run while `_HELPERS_OF_THREE_FAMILIES` is linted with `select`."""
    from geolint.rules import all_rules

    all_rules()  # every module imported: what runs below is the lint, not an import
    ran: set[str] = set()

    def profile(frame, event, arg):  # type: ignore[no-untyped-def]
        if event == "call" and frame.f_globals.get("__name__") in _ROTATION_MODULES:
            ran.add(f"{frame.f_globals['__name__']}.{frame.f_code.co_name}")

    sys.setprofile(profile)
    try:
        found = lint_source(_HELPERS_OF_THREE_FAMILIES, "<string>", Config(select=select))
    finally:
        sys.setprofile(None)
    if select == ("GEO101",):
        assert [(finding.code, finding.line) for finding in found] == [("GEO101", 19)]  # through `apply_pose`'s summary
    return ran


@pytest.mark.skipif(is_compiled(), reason="compiled functions are not seen by sys.setprofile")
def test_a_rule_pays_only_for_the_summaries_it_asks() -> None:
    """Summaries are per family and computed on first use: GEO101 reads what helpers return and
    translate, so linting with it alone runs no angle-unit or quaternion-order code, though the
    module's helpers return and read angles and quaternions. GEO302 and GEO301 run it."""
    assert _rotation_functions_run(("GEO101",)) == set()
    ran = _rotation_functions_run(("GEO301", "GEO302"))
    assert "geolint.factbase.angle_units._summarize_angle_units" in ran
    assert "geolint.factbase.quaternion_orders._summarize_quaternions" in ran


def test_summaries_are_kept_per_lint() -> None:
    """Each linted module gets its own summaries: a long-running process never serves one computed
    against an older version of a module."""
    tree = ast.parse("x = 1\n")
    first = facts_for_module(tree, "x = 1\n", "<string>", Config())
    second = facts_for_module(tree, "x = 1\n", "<string>", Config())
    assert isinstance(first, FactBase) and first.project is not second.project
    assert first.scratch().project is first.project


_FIELD_HELPERS = """\
from geometry_msgs.msg import Quaternion
def to_msg(q):
    m = Quaternion()
    m.x = q[0]
    m.y = q[1]
    m.z = q[2]
    m.w = q[3]
    return m
def to_msg_wxyz(q):
    m = Quaternion()
    m.w = q[0]
    m.x = q[1]
    m.y = q[2]
    m.z = q[3]
    return m
def to_msg_axes(q):
    m = Quaternion()
    m.y = q[0]
    m.x = q[1]
    m.z = q[2]
    m.w = q[3]
    return m
def to_msg_maybe(q, ready):
    m = Quaternion()
    if ready:
        m.x = q[0]
        m.y = q[1]
        m.z = q[2]
        m.w = q[3]
    return m
def to_msg_rebound(q):
    q = list(q)
    m = Quaternion()
    m.x = q[0]
    m.y = q[1]
    m.z = q[2]
    m.w = q[3]
    return m
def to_msg_three(q):
    m = Quaternion()
    m.x = q[0]
    m.y = q[1]
    m.z = q[2]
    return m
"""


def test_a_helper_that_writes_its_parameter_into_fields_reads_it_in_their_order() -> None:
    """`m.x = q[0]` ... `m.w = q[3]`, unconditionally, on a parameter never rebound: the parameter is read
    as x, y, z, w (or w, x, y, z); an axis permutation, a branch, a rebinding or a missing field say nothing."""
    facts = facts_for_module(ast.parse(_FIELD_HELPERS), _FIELD_HELPERS, "<string>", Config())

    def reads(name: str) -> dict[int, str]:
        found = facts.project.summary(facts, facts.index.functions[name], QUATERNIONS)
        assert found is not None
        return {index: order for index, (order, _) in found.reads_quaternion.items()}

    assert reads("to_msg") == {0: "xyzw"}
    assert reads("to_msg_wxyz") == {0: "wxyz"}
    for silent in ("to_msg_axes", "to_msg_maybe", "to_msg_rebound", "to_msg_three"):
        assert reads(silent) == {}, silent
    calls = (
        "from transforms3d.euler import euler2quat\n"
        "from scipy.spatial.transform import Rotation\n"
        "def publish(r, p, y, R):\n"
        "    q = euler2quat(r, p, y)\n"
        "    s = Rotation.from_matrix(R).as_quat()\n"
        "    return to_msg(q), to_msg_wxyz(q), to_msg(s), to_msg_wxyz(s), to_msg_maybe(q, True)\n"
    )
    source = _FIELD_HELPERS + calls
    lines = source.splitlines()
    findings = sorted((f.line, f.column, f.code) for f in lint_source(source, "<string>", Config()))
    line = len(lines)
    assert [(found_line, code) for found_line, _, code in findings] == [(line, "GEO301"), (line, "GEO301")]
    flagged = [lines[line - 1][: column - 1].rsplit(" ", 1)[-1] for _, column, _ in findings]
    assert flagged == ["to_msg(", "to_msg_wxyz("]  # w, x, y, z into x, y, z, w fields, and the reverse


def _ros_workspace(root: Path, with_manifests: bool = True) -> Path:
    """Two catkin packages side by side, each its own project (`setup.py`): the node in one imports a
    helper of the other, which reads its parameter as x, y, z, w."""
    workspace = root / "src"
    common = workspace / "robot_common"
    node = workspace / "robot_bridge"
    (common / "src" / "robot_common").mkdir(parents=True)
    (node / "src" / "robot_bridge").mkdir(parents=True)
    for package in (common, node):
        (package / "setup.py").write_text("from setuptools import setup\nsetup()\n")
        if with_manifests:
            (package / "package.xml").write_text(f"<package><name>{package.name}</name></package>\n")
    (common / "src" / "robot_common" / "__init__.py").write_text("")
    (common / "src" / "robot_common" / "transforms.py").write_text(_FIELD_HELPERS)
    (node / "src" / "robot_bridge" / "__init__.py").write_text("")
    (node / "src" / "robot_bridge" / "imu.py").write_text(
        "from transforms3d.euler import euler2quat\n"
        "import robot_common.transforms as trans\n"
        "def orientation(roll, pitch, yaw):\n"
        "    q = euler2quat(roll, pitch, yaw)\n"
        "    return trans.to_msg(q)\n"
    )
    return workspace


def test_a_helper_in_a_sibling_ros_package_is_read(tmp_path: Path) -> None:
    """A ROS workspace's packages import each other: the node's w-first quaternion reaches the sibling
    package's x, y, z, w helper. Without the manifests the folders are two unrelated projects."""
    found, _ = _check(_ros_workspace(tmp_path / "ws"), "--no-cache")
    assert ("robot_bridge/src/robot_bridge/imu.py", 5, "GEO301") in found
    unrelated, _ = _check(_ros_workspace(tmp_path / "plain", with_manifests=False), "--no-cache")
    assert not any(path.endswith("imu.py") for path, _, _ in unrelated)


_POSED_OBJECT = (
    "import pybullet as p\n"
    "import trimesh.transformations as tt\n"
    "class Posed:\n"
    "    def __init__(self, pose):\n"
    "        self.pose = pose\n"
    "    def orientation(self):\n"
    "        return tt.quaternion_from_matrix(self.pose)\n"
    "    def position_orientation(self):\n"
    "        return self.pose[:3, 3], tt.quaternion_from_matrix(self.pose)\n"
    "    @property\n"
    "    def quat(self):\n"
    "        return tt.quaternion_from_matrix(self.pose)\n"
)


def test_a_method_of_a_project_class_instance_is_read_through_the_object() -> None:
    """`obj.method()` runs the class's method when every binding of `obj` says which class: a
    constructor call, a parameter annotated with the class (or its name as a string), `self.attr`
    stored once as the constructor; a tuple it returns is read element by element."""
    source = _POSED_OBJECT + (
        "class Other:\n"
        "    def orientation(self):\n"
        "        return (0.0, 0.0, 0.0, 1.0)\n"
        "class Placer:\n"
        "    def __init__(self, pose):\n"
        "        self.target = Posed(pose)\n"
        "    def place(self, body):\n"
        "        p.resetBasePositionAndOrientation(body, (0, 0, 0), self.target.orientation())\n"
        "def by_constructor(body, pose):\n"
        "    posed = Posed(pose)\n"
        "    pos, orn = posed.position_orientation()\n"
        "    p.resetBasePositionAndOrientation(body, pos, orn)\n"
        "def by_annotation(body, posed: Posed, later: 'Posed'):\n"
        "    p.resetBasePositionAndOrientation(body, (0, 0, 0), posed.orientation())\n"
        "    p.resetBasePositionAndOrientation(body, (0, 0, 0), later.orientation())\n"
        "def unknown_class(body, posed, pose, flag):\n"
        "    p.resetBasePositionAndOrientation(body, (0, 0, 0), posed.orientation())\n"
        "    either = Posed(pose) if flag else Other()\n"
        "    p.resetBasePositionAndOrientation(body, (0, 0, 0), either.orientation())\n"
        "    other = Other()\n"
        "    p.resetBasePositionAndOrientation(body, (0, 0, 0), other.orientation())\n"
    )
    assert _codes(source) == [(20, "GEO301"), (24, "GEO301"), (26, "GEO301"), (27, "GEO301")]


def test_an_inherited_method_is_read_from_the_base_class() -> None:
    source = _POSED_OBJECT + (
        "class Arm(Posed):\n"
        "    def place(self, body):\n"
        "        p.resetBasePositionAndOrientation(body, (0, 0, 0), self.orientation())\n"
        "class Mixed(Posed, dict):\n"
        "    def place(self, body):\n"
        "        p.resetBasePositionAndOrientation(body, (0, 0, 0), self.orientation())\n"
        "def use(body, pose):\n"
        "    arm = Arm(pose)\n"
        "    p.resetBasePositionAndOrientation(body, (0, 0, 0), arm.orientation())\n"
    )
    # two bases: which one's method runs is the method resolution order's answer, not followed
    assert _codes(source) == [(15, "GEO301"), (21, "GEO301")]


def test_a_method_of_a_class_from_another_project_module_is_read(tmp_path: Path) -> None:
    project = tmp_path / "sim"
    (project / "sim").mkdir(parents=True)
    (project / "pyproject.toml").write_text("[project]\nname = 'sim'\n")
    (project / "sim" / "__init__.py").write_text("")
    (project / "sim" / "objects.py").write_text(_POSED_OBJECT)
    (project / "sim" / "scene.py").write_text(
        "import pybullet as p\n"
        "from sim.objects import Posed\n"
        "def place(body, pose, placed: Posed):\n"
        "    pos, orn = Posed(pose).position_orientation()\n"
        "    p.resetBasePositionAndOrientation(body, pos, orn)\n"
        "    p.resetBasePositionAndOrientation(body, pos, placed.orientation())\n"
        "    p.resetBasePositionAndOrientation(body, pos, placed.quat)\n"
    )
    found, _ = _check(project, "--no-cache")
    assert {(path, line) for path, line, code in found if code == "GEO301"} == {("sim/scene.py", line) for line in (5, 6, 7)}


def test_a_property_read_returns_what_its_getter_returns() -> None:
    """`obj.prop` runs the class's `@property` getter: its quaternion order, angle unit and kind reach
    the read as a helper's return would; a property with a setter, or a plain attribute, says nothing."""
    source = _POSED_OBJECT + (
        "    @property\n"
        "    def heading(self):\n"
        "        import numpy as np\n"
        "        return np.arctan2(self.pose[1, 0], self.pose[0, 0])\n"
        "class Settable(Posed):\n"
        "    @property\n"
        "    def quat(self):\n"
        "        return tt.quaternion_from_matrix(self.pose)\n"
        "    @quat.setter\n"
        "    def quat(self, value):\n"
        "        self.pose = value\n"
        "def place(body, posed: Posed, settable: Settable, pose):\n"
        "    import math\n"
        "    p.resetBasePositionAndOrientation(body, (0, 0, 0), posed.quat)\n"
        "    p.resetBasePositionAndOrientation(body, (0, 0, 0), settable.quat)\n"
        "    p.resetBasePositionAndOrientation(body, (0, 0, 0), Posed(pose).pose)\n"
        "    return math.radians(posed.heading)\n"
    )
    assert _codes(source) == [(26, "GEO301"), (29, "GEO305")]
