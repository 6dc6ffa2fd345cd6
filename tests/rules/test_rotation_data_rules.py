"""The rotation rules that follow data (GEO301 through reorders and producers, GEO302 through degree
values, GEO304, GEO305): no finding on installed real code, no crash on odd subscripts, and the
evidence chain they report is the one in the code. All through the real CLI."""

from __future__ import annotations

import json
import re
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

SITE = Path(sysconfig.get_paths()["purelib"])
CODES = "GEO301,GEO302,GEO304,GEO305"


def check(paths: list[str], cwd: Path | None = None) -> list[dict]:
    result = subprocess.run(
        [sys.executable, "-m", "geolint", "check", "--select", CODES, "--format", "json", "--no-cache", *paths],
        capture_output=True,
        text=True,
        cwd=cwd,
    )
    assert result.returncode in (0, 1), result.stderr
    assert "internal error" not in result.stderr and "Traceback" not in result.stderr, result.stderr
    return json.loads(result.stdout)


@pytest.mark.slow
def test_no_finding_on_all_installed_packages() -> None:
    """Every installed distribution (numpy, scipy, trimesh, pytransform3d, spatialmath, matplotlib,
    mypy's typeshed stubs...): mature code where a finding of these rules would be false."""
    assert check([str(SITE)]) == []


def test_no_finding_on_scipy_and_pytransform3d_quickly() -> None:
    present = [str(SITE / name) for name in ("scipy/spatial/transform", "pytransform3d") if (SITE / name).exists()]
    if not present:
        pytest.skip("neither scipy nor pytransform3d is installed")
    assert check(present) == []


def test_odd_subscripts_and_shapes_do_not_crash(tmp_path: Path) -> None:
    (tmp_path / "odd.py").write_text(
        "import numpy as np\nfrom scipy.spatial.transform import Rotation\n"
        "x = y[()]\n"
        "d = {'x': a[()], 'y': a[1], 'z': a[2], 'w': a[3]}\n"
        "v = [q[()], q[1], q[2], q[3]]\n"
        "r = Rotation.from_quat(q[..., []])\n"
        "s = Rotation.from_quat(np.roll(q, shift=n))\n"
        "t = Rotation.from_quat(*qs)\n"
        "u = np.cos(np.degrees())\n"
        "w = np.radians()\n"
    )
    assert check(["odd.py"], cwd=tmp_path) == []


def test_the_reported_evidence_names_the_producer_and_its_line(tmp_path: Path) -> None:
    (tmp_path / "labels.py").write_text(
        "from typing import List\n"
        "import quaternion\n"
        "class Label:\n"
        "    pass\n"
        "def make(q):\n"
        "    return Label(quaternion=quaternion.as_float_array(q))\n"
        "def save(labels: List[Label]):\n"
        "    out = []\n"
        "    for label in labels:\n"
        "        out.append({'x': label.quaternion[0], 'y': label.quaternion[1],\n"
        "                    'z': label.quaternion[2], 'w': label.quaternion[3]})\n"
        "    return out\n"
    )
    (finding,) = check(["labels.py"], cwd=tmp_path)
    assert finding["code"] == "GEO301" and finding["line"] == 10
    assert "`Label.quaternion` is set from `quaternion.as_float_array(q)`, line 6" in finding["message"]
    assert "w is component 0" in finding["message"]


def test_a_record_filled_elsewhere_stays_silent(tmp_path: Path) -> None:
    """The same writer with the record built in another module: no producer in sight, no finding."""
    (tmp_path / "writer.py").write_text(
        "from typing import List\nfrom records import Label\n"
        "def save(labels: List[Label]):\n"
        "    return [{'x': l.quaternion[0], 'y': l.quaternion[1], 'z': l.quaternion[2], 'w': l.quaternion[3]} for l in labels]\n"
    )
    assert check(["writer.py"], cwd=tmp_path) == []


def test_a_quaternion_spread_into_a_component_constructor(tmp_path: Path) -> None:
    """`np.quaternion(*q)` / `Quaternion(*q)` spread four values into (w, x, y, z) parameters: scipy's
    x, y, z, w is flagged there, a w-first spread and an unrelated `np.quaternion` are not."""
    (tmp_path / "spread.py").write_text(
        "import numpy as np\nimport quaternion\nfrom pyquaternion import Quaternion\n"
        "from scipy.spatial.transform import Rotation\n"
        "def numpy_quaternion(M):\n    return quaternion.quaternion(*Rotation.from_matrix(M).as_quat())\n"
        "def pyquaternion(M):\n    return Quaternion(*Rotation.from_matrix(M).as_quat())\n"
        "def w_first(M):\n    return np.quaternion(*Rotation.from_matrix(M).as_quat(scalar_first=True))\n"
        "def listed(M):\n    return np.quaternion(*Rotation.from_matrix(M).as_quat(), 1.0)\n"
    )
    (tmp_path / "other.py").write_text(
        "import numpy as np\nfrom scipy.spatial.transform import Rotation\n"
        "def f(M):\n    return np.quaternion(*Rotation.from_matrix(M).as_quat())\n"
    )
    findings = check(["spread.py", "other.py"], cwd=tmp_path)
    assert sorted((f["path"], f["line"]) for f in findings) == [("spread.py", 6), ("spread.py", 8)], findings
    assert all("expects scalar-first (w, x, y, z)" in f["message"] for f in findings)


def test_px4_messages_are_known_only_from_their_class(tmp_path: Path) -> None:
    """px4_msgs quaternions are (w, x, y, z): flagged when the class is known (subscription callback,
    `self` attribute stored from it, besides None and the subscription handle), silent when it is not imported, when the callback
    is also called directly, when it is registered through a lambda, or when another store is unknown."""
    (tmp_path / "known.py").write_text(
        "from px4_msgs.msg import VehicleAttitude, VehicleOdometry\nfrom scipy.spatial.transform import Rotation\n"
        "class Node:\n"
        "    def __init__(self):\n        self.attitude = None\n"
        "        self.create_subscription(VehicleOdometry, 'odom', self.on_odometry, 10)\n"
        "        self.attitude = self.create_subscription(VehicleAttitude, 'att', self.on_attitude, 10)\n"
        "    def on_odometry(self, msg):\n        return Rotation.from_quat(msg.q)\n"
        "    def on_attitude(self, msg):\n        self.attitude = msg\n"
        "    def yaw(self):\n        q = self.attitude.q\n        return Rotation.from_quat([q[0], q[1], q[2], q[3]])\n"
    )
    (tmp_path / "unknown.py").write_text(
        "from px4_msgs.msg import VehicleOdometry\nfrom nav_msgs.msg import Odometry\nfrom scipy.spatial.transform import Rotation\n"
        "class Node:\n"
        "    def __init__(self, other):\n        self.pose = other\n"
        "        self.create_subscription(Odometry, 'a', self.on_ros_odometry, 10)\n"
        "        self.create_subscription(VehicleOdometry, 'b', self.on_odometry, 10)\n"
        "        self.create_subscription(VehicleOdometry, 'c', lambda m: self.on_lambda(m), 10)\n"
        "    def on_ros_odometry(self, msg):\n        return Rotation.from_quat(msg.q)\n"
        "    def on_odometry(self, msg):\n        self.pose = msg\n        return Rotation.from_quat(msg.q)\n"
        "    def replay(self, recorded):\n        return self.on_odometry(recorded)\n"
        "    def on_lambda(self, msg):\n        return Rotation.from_quat(msg.q)\n"
        "    def later(self):\n        return Rotation.from_quat(self.pose.q)\n"
    )
    (tmp_path / "not_imported.py").write_text(
        "from scipy.spatial.transform import Rotation\nclass Node:\n"
        "    def __init__(self):\n        self.create_subscription(VehicleOdometry, 'odom', self.on_odometry, 10)\n"
        "    def on_odometry(self, msg):\n        return Rotation.from_quat(msg.q)\n"
    )
    findings = check(["known.py", "unknown.py", "not_imported.py"], cwd=tmp_path)
    assert sorted((f["path"], f["line"]) for f in findings) == [("known.py", 9), ("known.py", 14)], findings
    assert all("px4_msgs `Vehicle" in f["message"] for f in findings)


def _px4_drone(tmp_path: Path, module: str, helpers: str, message: str, returned: str) -> None:
    """A package `drone` whose `module` holds `helpers`, and a node whose callback for the px4_msgs
    `message` returns `returned` (calls of those helpers on `msg.q`) on line 7 of drone/node.py."""
    (tmp_path / "setup.py").write_text("")
    (tmp_path / "drone").mkdir()
    (tmp_path / "drone" / "__init__.py").write_text("")
    (tmp_path / "drone" / f"{module}.py").write_text(helpers)
    names = ", ".join(re.findall(r"(\w+)\(msg", returned))
    (tmp_path / "drone" / "node.py").write_text(
        f"from px4_msgs.msg import {message}\nfrom drone.{module} import {names}\n"
        "class Node:\n"
        f"    def __init__(self):\n        self.create_subscription({message}, 'topic', self.on_message, 10)\n"
        "    def on_message(self, msg):\n"
        f"        return {returned}\n"
    )


def test_a_quaternion_passed_to_a_helper_of_another_module(tmp_path: Path) -> None:
    """A known order handed to a project helper (in another module) that passes its parameter to
    scipy's from_quat: flagged at the call; a helper that reorders first, or only under a flag, is not."""
    _px4_drone(
        tmp_path,
        "geometry",
        "from scipy.spatial.transform import Rotation\n"
        "def heading(q):\n    return Rotation.from_quat(q).as_euler('zyx')[0]\n"
        "def heading_wxyz(q):\n    return Rotation.from_quat([q[1], q[2], q[3], q[0]]).as_euler('zyx')[0]\n"
        "def heading_maybe(q, wxyz):\n    if wxyz:\n        return Rotation.from_quat(q, scalar_first=True)\n    return Rotation.from_quat(q)\n",
        "VehicleAttitude",
        "heading(msg.q), heading_wxyz(msg.q), heading_maybe(msg.q, True)",
    )
    findings = check(["drone"], cwd=tmp_path)
    assert [(f["path"], f["line"], f["column"]) for f in findings] == [("drone/node.py", 7, 24)], findings
    assert "`heading` (which passes its parameter `q` to `Rotation.from_quat`)" in findings[0]["message"]


def test_the_order_a_helper_reads_from_its_yaw_formula(tmp_path: Path) -> None:
    """A helper in another module that computes the textbook yaw by index (w taken from `q[3]`) reads
    its parameter as (x, y, z, w): PX4's (w, x, y, z) `msg.q` handed to it is flagged at the call. A
    helper whose formula takes w from `q[0]`, one whose index pattern is also another formula (the
    yaw of x, y, z, w is the roll of w, x, y, z) with no name choosing, and one that reads the formula
    only under a branch are not."""
    _px4_drone(
        tmp_path,
        "angles",
        "import math\n"
        "def yaw_last(q):\n"
        "    qw, qx, qy, qz = q[3], q[0], q[1], q[2]\n"
        "    return math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))\n"
        "def yaw_first(q):\n"
        "    return math.atan2(2 * (q[0] * q[3] + q[1] * q[2]), 1 - 2 * (q[2] ** 2 + q[3] ** 2))\n"
        "def angle(q):\n"
        "    return math.atan2(2 * (q[3] * q[2] + q[0] * q[1]), 1 - 2 * (q[1] ** 2 + q[2] ** 2))\n"
        "def yaw_maybe(q, last):\n"
        "    if last:\n"
        "        return math.atan2(2 * (q[3] * q[2] + q[0] * q[1]), 1 - 2 * (q[1] ** 2 + q[2] ** 2))\n"
        "    return 0.0\n",
        "VehicleOdometry",
        "yaw_last(msg.q), yaw_first(msg.q), angle(msg.q), yaw_maybe(msg.q, True)",
    )
    findings = check(["drone"], cwd=tmp_path)
    assert [(f["path"], f["line"], f["column"]) for f in findings] == [("drone/node.py", 7, 25)], findings
    assert "`yaw_last` (which passes its parameter `q` to the yaw formula at line 4, whose w is `q[3]`)" in findings[0]["message"]


def test_a_quaternion_order_carried_through_a_tuple_return_of_another_module(tmp_path: Path) -> None:
    """`return center, orientation` with trimesh's (w, x, y, z) `quaternion_from_matrix` in one module;
    another unpacks or indexes the tuple and hands the quaternion to pybullet or scipy (x, y, z, w),
    or names it `quat_xyzw`. A position the returns disagree on, and the position part, say nothing."""
    (tmp_path / "setup.py").write_text("")
    (tmp_path / "sim").mkdir()
    (tmp_path / "sim" / "__init__.py").write_text("")
    (tmp_path / "sim" / "boxes.py").write_text(
        "import trimesh.transformations as tra\nfrom scipy.spatial.transform import Rotation\n"
        "def box_pose(transform):\n    return transform[:3, 3], tra.quaternion_from_matrix(transform)\n"
        "def either_pose(transform, scipy_order):\n"
        "    if scipy_order:\n        return transform[:3, 3], Rotation.from_matrix(transform[:3, :3]).as_quat()\n"
        "    return transform[:3, 3], tra.quaternion_from_matrix(transform)\n"
    )
    (tmp_path / "sim" / "place.py").write_text(
        "import pybullet as p\nfrom scipy.spatial.transform import Rotation\nfrom sim.boxes import box_pose, either_pose\n"
        "def place(body, transform):\n    center, orientation = box_pose(transform)\n"
        "    p.resetBasePositionAndOrientation(body, center, orientation)\n"
        "def rotation_of(transform):\n    return Rotation.from_quat(box_pose(transform)[1])\n"
        "def named(transform):\n    pose = box_pose(transform)\n    quat_xyzw = pose[1]\n    return quat_xyzw\n"
        "def unknown(body, transform):\n    center, orientation = either_pose(transform, True)\n"
        "    p.resetBasePositionAndOrientation(body, center, orientation)\n"
    )
    findings = check(["sim"], cwd=tmp_path)
    assert [(f["path"], f["line"]) for f in findings] == [("sim/place.py", 6), ("sim/place.py", 8), ("sim/place.py", 11)], findings
    assert all("`box_pose`, which returns it at position 1" in f["message"] for f in findings)


def test_simulator_quaternions_across_modules(tmp_path: Path) -> None:
    """A task ported from Isaac Gym to Isaac Sim: one module computes start rotations with Isaac Gym's
    (x, y, z, w) `quat_from_euler_xyz` (star-imported, as Isaac Gym tasks do) and a helper that hands
    its parameter to an Isaac Sim prim's (w, x, y, z) `orientation=`; another module passes the rotation
    to the prim directly and through the helper. Flagged at both calls; the rotation reordered with
    `[:, [3, 0, 1, 2]]`, and Isaac Sim's own (w, x, y, z) `euler_angles_to_quat`, stay silent."""
    (tmp_path / "setup.py").write_text("")
    (tmp_path / "tasks").mkdir()
    (tmp_path / "tasks" / "__init__.py").write_text("")
    (tmp_path / "tasks" / "rotations.py").write_text(
        "import torch\nfrom isaacgym.torch_utils import *\nfrom omni.isaac.core.prims import XFormPrim\n"
        "def start_rotation(yaw):\n    zeros = torch.zeros_like(yaw)\n    return quat_from_euler_xyz(zeros, zeros, yaw)\n"
        "def place(path, orientation):\n    return XFormPrim(path, orientation=orientation)\n"
    )
    (tmp_path / "tasks" / "scene.py").write_text(
        "from omni.isaac.core.objects import DynamicCuboid\nfrom omni.isaac.core.utils.rotations import euler_angles_to_quat\n"
        "from tasks.rotations import place, start_rotation\n"
        "def spawn(path, yaw):\n    rotation = start_rotation(yaw)\n"
        "    cube = DynamicCuboid(prim_path=path, orientation=rotation)\n"
        "    marker = place(path + '/marker', rotation)\n"
        "    ok = DynamicCuboid(prim_path=path, orientation=rotation[:, [3, 0, 1, 2]])\n"
        "    return cube, marker, ok, place(path, euler_angles_to_quat([0.0, 0.0, 1.0]))\n"
    )
    findings = check(["tasks"], cwd=tmp_path)
    assert [(f["path"], f["line"]) for f in findings] == [("tasks/scene.py", 6), ("tasks/scene.py", 7)], findings
    assert "`start_rotation`, which returns it" in findings[0]["message"] and "`DynamicCuboid` expects scalar-first" in findings[0]["message"]
    assert "`place` (which passes its parameter `orientation` to `XFormPrim`)" in findings[1]["message"]


def test_a_degree_constant_is_followed_only_while_it_is_the_one_store(tmp_path: Path) -> None:
    """GEO302 reads `self.phi = 73.17` as degrees only when the module stores `.phi` nowhere else and
    nothing may rebind the name (`global`, `+=`, a computed `setattr`, a base class)."""
    flagged = (
        "import math\n"
        "TILT = 45\n"
        "class Leg:\n"
        "    def __init__(self):\n"
        "        self.phi = 73.17\n"
        "    def offset(self):\n"
        "        return math.sin(self.phi) + math.cos(TILT)\n"
    )
    silent = {
        "rebound.py": flagged.replace("    def offset", "    def tune(self, value):\n        self.phi = value\n    def offset"),
        "augmented.py": flagged.replace("    def offset", "    def tune(self):\n        self.phi += 0.1\n    def offset"),
        "setattr.py": flagged.replace("    def offset", "    def load(self, key, value):\n        setattr(self, key, value)\n    def offset"),
        "based.py": flagged.replace("class Leg:", "class Leg(BaseLeg):").replace(" + math.cos(TILT)", ""),
        "global.py": flagged.replace("class Leg:", "def retune():\n    global TILT\n    TILT = 0.3\nclass Leg:").replace("math.sin(self.phi) + ", ""),
        "radians.py": flagged.replace("73.17", "1.2771").replace("45", "0.785"),
    }
    (tmp_path / "flagged.py").write_text(flagged)
    for name, source in silent.items():
        (tmp_path / name).write_text(source)
    found = sorted((f["path"].rsplit("/", 1)[-1], f["line"], f["code"]) for f in check(["."], cwd=tmp_path))
    assert ("flagged.py", 7, "GEO302") in found
    assert [item for item in found if item[0] == "flagged.py"] == [("flagged.py", 7, "GEO302"), ("flagged.py", 7, "GEO302")]
    # the module constant stays flagged where only `self.phi` is disturbed
    assert {item[0] for item in found} == {"flagged.py", "rebound.py", "augmented.py", "setattr.py"}
    assert all(f["message"].count("TILT") for f in check([str(tmp_path / name) for name in ("rebound.py", "augmented.py")]))


def test_a_parse_table_needs_a_radian_converter_and_a_plain_parser(tmp_path: Path) -> None:
    """The field table check: one row converts the field to radians (every `return` of its converter),
    another parses it as a plain number; a converter of unknown unit on either side is silent."""
    table = (
        "import math\n"
        "def parse_number(text):\n    return float(text)\n"
        "def to_radians(text):\n    return math.radians(float(text))\n"
        "def parse_course(text):\n    return lookup(text)\n"
        "FIELDS = {'RMC': [('course', to_radians, 8)], 'VTG': [('course', {other}, 1)]}\n"
    )
    (tmp_path / "plain.py").write_text(table.replace("{other}", "parse_number"))
    (tmp_path / "builtin.py").write_text(table.replace("{other}", "float"))
    (tmp_path / "unknown.py").write_text(table.replace("{other}", "parse_course"))
    (tmp_path / "both.py").write_text(table.replace("{other}", "to_radians"))
    (tmp_path / "library.py").write_text("from math import radians\nFIELDS = {'RMC': [('course', radians, 8)], 'VTG': [('course', float, 1)]}\n")
    found = sorted((f["path"].rsplit("/", 1)[-1], f["line"]) for f in check(["."], cwd=tmp_path))
    assert found == [("builtin.py", 8), ("library.py", 2), ("plain.py", 8)]


def test_a_class_constructor_reads_its_parameter_only_through_one_unconditional_store(tmp_path: Path) -> None:
    """GEO305 reads `Heading(yaw)` as taking degrees when `__init__` stores `self.yaw = yaw` once and a
    method converts `self.yaw` from degrees; any other store, a conditional one, or a method that reads
    it in radians too leaves the constructor's unit unknown."""
    flagged = (
        "import math\n"
        "class Heading:\n"
        "    def __init__(self, yaw):\n"
        "        self.yaw = yaw\n"
        "    def forward(self):\n"
        "        return math.cos(math.radians(self.yaw))\n"
        "def heading_to(dy, dx):\n"
        "    return Heading(math.atan2(dy, dx))\n"
    )
    silent = {
        "setter.py": flagged.replace("    def forward", "    def turn(self, yaw_rad):\n        self.yaw = math.degrees(yaw_rad)\n    def forward"),
        "conditional.py": flagged.replace("        self.yaw = yaw\n", "        if yaw is not None:\n            self.yaw = yaw\n"),
        "both_units.py": flagged.replace("    def forward", "    def sine(self):\n        return math.sin(self.yaw)\n    def forward"),
        "under_branch.py": flagged.replace("        return math.cos(math.radians(self.yaw))", "        if self.yaw:\n            return math.cos(math.radians(self.yaw))"),
        "converted.py": flagged.replace("Heading(math.atan2(dy, dx))", "Heading(math.degrees(math.atan2(dy, dx)))"),
    }
    (tmp_path / "flagged.py").write_text(flagged)
    for name, source in silent.items():
        (tmp_path / name).write_text(source)
    found = sorted((f["path"].rsplit("/", 1)[-1], f["line"], f["code"]) for f in check(["."], cwd=tmp_path))
    assert found == [("flagged.py", 8, "GEO305")], found
    message = check(["flagged.py"], cwd=tmp_path)[0]["message"]
    assert "`Heading` stores its parameter `yaw` for `math.radians` (as `self.yaw`, in `forward`)" in message
    assert "`math.atan2` returns radians" in message


def test_library_euler_conversions_return_radians_through_aliases(tmp_path: Path) -> None:
    """tf / transforms3d / pybullet Euler conversions, imported under any name, return radians: given
    to a call that reads degrees, each is GEO305; converted first, silent."""
    (tmp_path / "aliases.py").write_text(
        "import cv2\n"
        "import numpy as np\n"
        "import pybullet as pb\n"
        "import tf.transformations as tft\n"
        "from transforms3d import euler as t3e\n"
        "def a(q):\n"
        "    return cv2.getRotationMatrix2D((0, 0), tft.euler_from_quaternion(q)[2], 1.0)\n"
        "def b(q):\n"
        "    _, _, yaw = t3e.quat2euler(q)\n"
        "    return cv2.getRotationMatrix2D((0, 0), yaw, 1.0)\n"
        "def c(q):\n"
        "    return cv2.getRotationMatrix2D((0, 0), pb.getEulerFromQuaternion(q)[2], 1.0)\n"
        "def d(q):\n"
        "    return cv2.getRotationMatrix2D((0, 0), np.degrees(tft.euler_from_quaternion(q)[2]), 1.0)\n"
    )
    found = [(f["line"], f["code"]) for f in check(["aliases.py"], cwd=tmp_path)]
    assert found == [(7, "GEO305"), (10, "GEO305"), (12, "GEO305")], found


def test_a_loop_over_its_own_name_ends_the_class_search():
    """`for elem in elem:` (an XML indent helper) loops over its own name: the search for the class of
    a stored-to object must stop there, not recurse until the file is lost to GEO001 (and, compiled,
    to a crash)."""
    import ast
    from textwrap import dedent

    from geolint.factbase import facts_for_module
    from geolint.lint_types import Config
    from geolint.factbase.quaternion_orders import QuaternionFlow

    source = dedent(
        """
        def indent(elem, level=0):
            if len(elem):
                for elem in elem:
                    indent(elem, level + 1)
                if not elem.tail:
                    elem.tail = " " * level

        def orientation(record: Record):
            return record.solver
        """
    )
    tree = ast.parse(source)
    facts = facts_for_module(tree, source, "indent.py", Config())
    read = next(node for node in ast.walk(tree) if isinstance(node, ast.Attribute) and node.attr == "solver")
    assert facts.shared(QuaternionFlow).order_of(read) is None


def test_literal_angles_in_a_test_module_are_test_data(tmp_path: Path) -> None:
    """pyquaternion reads `angle=` in radians (stubs/): `angle=90` is a degree slip in a module, test data
    in a test (a translation test may rotate by any number)."""
    source = "from pyquaternion import Quaternion\nq = Quaternion(axis=(0.0, 0.0, 1.0), angle=90)\n"
    (tmp_path / "boxes.py").write_text(source)
    (tmp_path / "tests").mkdir()
    (tmp_path / "tests" / "test_boxes.py").write_text(source)
    found = check(["boxes.py", "tests/test_boxes.py"], cwd=tmp_path)
    assert [(finding["path"], finding["code"]) for finding in found] == [("boxes.py", "GEO302")]
