"""The tf tree of a ROS workspace (`geolint.factbase.tf_workspace`): what the fixture workspaces'
nodes, launch files and URDF state, drawn by the real `geolint frames`, checked by the real `geolint
check`, and re-checked when another file of the workspace changes (the findings cache's key)."""

from __future__ import annotations

import ast
import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from geolint.factbase.ros_parameters import launch_parameter_keys, yaml_keys
from geolint.factbase.tf_statements import command_line_frames, publishes_identity, xml_frames
from geolint.factbase.tf_workspace import python_file_frames
from geolint.knowledge import knowledge_base
from geolint.rules.frames.geo214_tf_frame_never_published import _misspelt

ROOT = Path(__file__).resolve().parents[2]
ROS = ROOT / "fixtures" / "ros"


def geolint(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "geolint", *args], cwd=cwd, capture_output=True, text=True, timeout=300)


def drawn(workspace: Path) -> dict[tuple[str, str], dict]:
    completed = geolint("frames", "src", "--format", "json", cwd=workspace)
    assert completed.returncode == 0, completed.stderr
    return {(edge["parent"], edge["child"], edge["lookup"], edge["mismatch"]): edge for edge in json.loads(completed.stdout)["edges"]}


def test_the_graph_holds_every_kind_of_statement_of_a_ros2_workspace() -> None:
    edges = drawn(ROS / "rover_ws")
    urdf = edges[("base_link", "laser_frame", False, False)]  # a xacro property resolved
    assert (urdf["label"], urdf["location"]) == ("URDF fixed joint", "src/rover_description/urdf/rover.urdf.xacro:18")
    assert edges[("map", "odom", False, False)]["label"] == "static_transform_publisher"  # --frame-id style
    assert edges[("base_link", "odom", False, False)]["location"] == "src/rover_bringup/launch/GEO211_bringup.launch.py:20"  # "...".split()
    assert edges[("odom", "base_footprint", False, False)]["label"] == "sendTransform"  # frames from module constants
    assert ("camera_optical_frame", "dock_marker", False, False) in edges  # a list of messages
    assert edges[("base_link", "laserframe", True, False)]["label"] == "lookup_transform"  # dotted
    assert ("base_link", "odom", False, True) in edges  # GEO211's finding, red
    # frames from parameters' declared defaults, which the label names
    assert edges[("base_link", "imu_lnk", True, False)]["label"] == "lookup_transform (defaults of base_frame, imu_frame)"
    # a node's variable names (`laser_to_base = buffer.lookup_transform(...)`) draw nothing of their own
    assert not any(parent == "base" for parent, *_ in edges)


def test_an_xml_launch_file_reads_its_arg_defaults() -> None:
    edges = drawn(ROS / "arm_ws")
    assert edges[("base_link", "table_camera_link", False, False)]["location"] == "src/arm_bringup/launch/arm.launch:5"
    assert ("tool0", "gripper_tip", False, False) in edges  # the quaternion form: 10 arguments with the period


@pytest.mark.parametrize(
    ("package", "arguments", "expected"),
    [
        ("tf2_ros", "0 0 0 0 0 0 map odom", ("map", "odom")),
        ("tf2_ros", "0 0 0 0 0 0 1 map odom", ("map", "odom")),
        ("tf2_ros", "--x 1 --child-frame-id odom --frame-id map", ("map", "odom")),
        ("tf2_ros", "0 0 0 0 0 0 /map odom --ros-args -r __node:=pin", ("map", "odom")),
        ("tf", "0 0 0 0 0 0 map odom 100", ("map", "odom")),
        ("tf", "0 0 0 0 0 0 1 map odom 100", ("map", "odom")),
        ("tf", "0 0 0 0 0 0 map odom", (None, None)),  # tf wants a period: no form has 8 arguments
        ("tf2_ros", "0 0 0 0 0 0 map odom 10", (None, None)),  # tf's period under tf2_ros: '10' is no frame
    ],
)
def test_a_static_publishers_command_line_as_its_metadata_describes_it(package: str, arguments: str, expected: tuple) -> None:
    executable = knowledge_base().executable(package, "static_transform_publisher")
    assert executable is not None
    assert command_line_frames(executable, arguments.split()) == expected


@pytest.mark.parametrize(
    ("package", "arguments", "identity"),
    [
        ("tf2_ros", "0 0 0 0 0 0 map odom", True),
        ("tf2_ros", "0 0 0 0 0 0 1 map odom", True),  # the quaternion's w is 1
        ("tf2_ros", "0 0 0 0 0 0 0 map odom", False),
        ("tf2_ros", "0.1 0 0 0 0 0 map odom", False),
        ("tf2_ros", "--x 0 --yaw 0 --frame-id map --child-frame-id odom", True),
        ("tf2_ros", "--qw 1 --frame-id map --child-frame-id odom", True),
        ("tf2_ros", "--x 0.5 --frame-id map --child-frame-id odom", False),
        ("tf", "0 0 0 0 0 0 map odom 100", True),  # the period is not part of the transform
        ("tf", "0 0 0 0 0.3 0 map odom 100", False),
    ],
)
def test_which_command_lines_publish_the_identity(package: str, arguments: str, identity: bool) -> None:
    executable = knowledge_base().executable(package, "static_transform_publisher")
    assert executable is not None
    assert publishes_identity(executable, arguments.split()) is identity


def test_a_file_that_is_not_xml_states_nothing() -> None:
    assert xml_frames(knowledge_base(), "broken.launch", "<launch><node pkg='tf' args='0 0 0 0 0 0 a b 1'") .published == ()


@pytest.mark.parametrize(
    ("frame", "known", "misspelt"),
    [
        ("baselink", "base_link", True),
        ("Base_Link", "base_link", True),
        ("camera_lnik", "camera_link", True),
        ("camera_lnk", "camera_link", True),
        ("camera2_link", "camera1_link", False),  # other digits: another frame
        ("map", "mat", False),  # too short to call a misspelling
        ("base_link", "base_link", False),
        ("laser", "lidar", False),
    ],
)
def test_what_counts_as_a_misspelt_frame(frame: str, known: str, misspelt: bool) -> None:
    assert _misspelt(frame, known) is misspelt


def test_a_change_elsewhere_in_the_workspace_changes_a_nodes_findings(tmp_path: Path) -> None:
    """The findings cache keys each node by what its workspace states: fixing the URDF clears the
    node's GEO213 on the next cached run, although the node itself did not change."""
    workspace = tmp_path / "rover_ws"
    shutil.copytree(ROS / "rover_ws", workspace)
    cache = tmp_path / "cache"
    node = "src/rover_bringup/rover_bringup/GEO213_wheel_odometry.py"
    first = geolint("check", "--select", "GEO213", "--cache-dir", str(cache), "--output-format", "concise", node, cwd=workspace)
    assert first.returncode == 1 and "GEO213" in first.stdout, first.stdout + first.stderr
    urdf = workspace / "src/rover_description/urdf/rover.urdf.xacro"
    urdf.write_text(urdf.read_text().replace('<parent link="base_link"/>\n    <child link="${laser_frame}"/>', '<parent link="base_footprint"/>\n    <child link="${laser_frame}"/>'))
    second = geolint("check", "--select", "GEO213", "--cache-dir", str(cache), "--output-format", "concise", node, cwd=workspace)
    assert second.returncode == 0, second.stdout + second.stderr


def test_a_broken_launch_file_does_not_end_the_run(tmp_path: Path) -> None:
    workspace = tmp_path / "arm_ws"
    shutil.copytree(ROS / "arm_ws", workspace)
    (workspace / "src/arm_bringup/launch/broken.launch").write_text("<launch><node pkg='tf' type='static_transform_publisher'")
    completed = geolint("check", "--no-cache", "--select", "GEO211,GEO212,GEO214", "--output-format", "concise", "src", cwd=workspace)
    assert completed.returncode == 1, completed.stderr
    assert {line.split(": ")[1].split()[0] for line in completed.stdout.splitlines() if ": GEO" in line} == {"GEO211", "GEO212", "GEO214"}


def test_a_second_parent_that_another_robot_description_agrees_with_is_a_variant(tmp_path: Path) -> None:
    """The node publishes laser_frame under base_footprint; the mk1 URDF hangs it from base_link. Add a
    mk2 URDF that agrees with the node: the descriptions are variants, and GEO213 says nothing."""
    workspace = tmp_path / "rover_ws"
    shutil.copytree(ROS / "rover_ws", workspace)
    node = "src/rover_bringup/rover_bringup/GEO213_wheel_odometry.py"
    assert "GEO213" in geolint("check", "--no-cache", "--select", "GEO213", node, cwd=workspace).stdout
    mk2 = workspace / "src/rover_description/urdf/rover_mk2.urdf"
    mk2.write_text(
        '<robot name="rover_mk2"><link name="base_footprint"/><link name="laser_frame"/>'
        '<joint name="laser_joint" type="fixed"><parent link="base_footprint"/><child link="laser_frame"/></joint></robot>'
    )
    assert geolint("check", "--no-cache", "--select", "GEO213", node, cwd=workspace).returncode == 0


def test_a_test_folders_robot_description_is_not_the_robots(tmp_path: Path) -> None:
    workspace = tmp_path / "arm_ws"
    shutil.copytree(ROS / "arm_ws", workspace)
    tests = workspace / "src/arm_bringup/test"
    tests.mkdir()
    (tests / "table.urdf").write_text(  # a test robot whose link is spelled like the misspelt lookup
        '<robot name="t"><link name="base_link"/><link name="table_camera_lnk"/>'
        '<joint name="j" type="fixed"><parent link="base_link"/><child link="table_camera_lnk"/></joint></robot>'
    )
    completed = geolint("check", "--no-cache", "--select", "GEO214", "--output-format", "concise", "src", cwd=workspace)
    assert "GEO214" in completed.stdout, completed.stdout + completed.stderr


def frames_of(source: str, path: str = "node.py") -> list[tuple[str, str | None, str | None, tuple]]:
    found = python_file_frames(path, source)
    return [
        (type(statement).__name__, *(getattr(statement, role) for role in roles), statement.parameters)
        for statement, roles in [*((edge, ("parent", "child")) for edge in found.published), *((lookup, ("target", "source")) for lookup in found.looked_up)]
    ]


ROS2_NODE = """
import rclpy
from rclpy.node import Node
from tf2_ros import Buffer, TransformBroadcaster
from geometry_msgs.msg import TransformStamped

class Odometry(Node):
    def __init__(self):
        super().__init__("odometry")
        self.declare_parameter("odom_frame", "odom")
        self.odom_frame = self.get_parameter("odom_frame").get_parameter_value().string_value
        self.base_frame = self.declare_parameter("base_frame", "base_link").value
        self.declare_parameters(namespace="sensors", parameters=[("laser", "laser_link"), ("rate", 10.0)])
        self.buffer = Buffer()
        self.broadcaster = TransformBroadcaster(self)

    def tick(self):
        t = TransformStamped()
        t.header.frame_id = self.odom_frame
        t.child_frame_id = self.base_frame
        self.broadcaster.sendTransform(t)
        laser = self.get_parameter("sensors.laser").value
        return self.buffer.lookup_transform(self.base_frame, laser, rclpy.time.Time())
"""


def test_a_ros2_nodes_frames_come_from_its_declared_parameter_defaults() -> None:
    assert frames_of(ROS2_NODE) == [
        ("Published", "odom", "base_link", (("parent", "odom_frame"), ("child", "base_frame"))),
        ("LookedUp", "base_link", "laser_link", (("target", "base_frame"), ("source", "sensors.laser"))),
    ]


def test_a_parameter_read_without_one_agreed_default_is_unknown() -> None:
    source = ROS2_NODE.replace('self.declare_parameter("odom_frame", "odom")', 'self.declare_parameter("odom_frame", "odom")\n        self.declare_parameter("odom_frame", "world")')
    assert frames_of(source)[0][1] is None  # two defaults
    rebound = ROS2_NODE.replace("self.broadcaster = TransformBroadcaster(self)", "self.broadcaster = TransformBroadcaster(self)\n        self.base_frame = compute()")
    assert frames_of(rebound)[0][2] is None  # `self.base_frame` also set to something else


def test_a_ros1_nodes_frames_come_from_get_param_defaults() -> None:
    source = "import rospy, tf\nlistener = tf.TransformListener()\nBASE = rospy.get_param('~base_frame', 'base_link')\n" "def run(now):\n    return listener.lookupTransform(BASE, rospy.get_param('/laser_frame', 'laser'), now)\n"
    assert frames_of(source) == [("LookedUp", "base_link", "laser", (("target", "~base_frame"), ("source", "/laser_frame")))]


def test_the_parameters_a_projects_launch_and_parameter_files_set() -> None:
    assert yaml_keys("odometry:\n  ros__parameters:\n    base_frame: base_link\n    sensors.laser: laser\n---\n/robot/odom_frame: odom\n") == {
        "odometry", "ros__parameters", "base_frame", "laser", "odom_frame",
    }  # fmt: skip
    assert yaml_keys("key: [unclosed") == frozenset()  # not YAML: sets nothing
    launch = "from launch_ros.actions import Node\nNode(package='p', executable='e', parameters=['a.yaml', {'base_frame': 'base_link', 'use_sim_time': True}])\n"
    assert launch_parameter_keys(ast.parse(launch)) == {"base_frame", "use_sim_time"}
    xml = (
        '<launch><node pkg="p" type="e"><param name="~odom_frame" value="odom"/><rosparam param="gains">[1, 2]</rosparam>'
        "<rosparam>base_frame: base_link\nmap_frame: $(arg map)</rosparam></node></launch>"
    )
    assert xml_frames(knowledge_base(), "a.launch", xml).parameters_set == {"odom_frame", "gains"}  # the text with $(arg) is not read


def test_a_parameter_the_project_sets_makes_its_default_unknown(tmp_path: Path) -> None:
    """The clean workspace's odometry node declares defaults that the launch file and a parameter file
    override; remove the overrides and its defaults are its frames, with GEO213 and GEO214 findings."""
    workspace = tmp_path / "ros_ws"
    shutil.copytree(ROOT / "fixtures" / "clean" / "ros_ws", workspace)
    node = "src/fleet_nodes/fleet_nodes/odometry.py"
    assert geolint("check", "--no-cache", node, cwd=workspace).returncode == 0
    (workspace / "src/fleet_nodes/config/odometry.yaml").unlink()
    launch = workspace / "src/fleet_nodes/launch/fleet.launch.py"
    launch.write_text(launch.read_text().replace('{"camera_frame": "camera1_link"}', "{}"))
    completed = geolint("check", "--no-cache", "--output-format", "concise", node, cwd=workspace)
    codes = sorted(line.split(": ")[1].split()[0] for line in completed.stdout.splitlines() if ": GEO" in line)
    assert codes == ["GEO213", "GEO214"], completed.stdout + completed.stderr
    assert "'camera1_lnk' (the default of parameter 'camera_frame')" in completed.stdout
    assert ("odom", "camera1_link", False, True) in drawn(workspace)  # the drawing settles the same way


def test_the_drawing_leaves_out_a_default_the_project_overrides() -> None:
    edges = drawn(ROOT / "fixtures" / "clean" / "ros_ws")
    assert not any(child == "camera1_link" and parent == "odom" for parent, child, *_ in edges)


def test_a_transform_kept_on_self_and_sent_from_a_callback() -> None:
    source = (
        "from geometry_msgs.msg import TransformStamped\nfrom tf2_ros import TransformBroadcaster\n\n"
        "class Odometry:\n    def __init__(self, node):\n        self.broadcaster = TransformBroadcaster(node)\n"
        "        self.transform = TransformStamped()\n        self.transform.header.frame_id = 'odom'\n"
        "        self.transform.child_frame_id = 'base_footprint'\n\n"
        "    def on_wheels(self, x):\n        self.transform.transform.translation.x = x\n        self.broadcaster.sendTransform(self.transform)\n"
    )
    assert frames_of(source) == [("Published", "odom", "base_footprint", ())]
    # stamped in two places: which one is sent is not known here
    twice = source.replace("        self.transform.transform.translation.x = x\n", "        self.transform.header.frame_id = 'world'\n")
    assert frames_of(twice) == [("Published", None, "base_footprint", ())]


def test_a_static_publisher_started_as_a_process() -> None:
    source = (
        "from launch import LaunchDescription\nfrom launch.actions import ExecuteProcess\n\n"
        "def generate_launch_description():\n    return LaunchDescription([\n"
        "        ExecuteProcess(cmd=['ros2', 'run', 'tf2_ros', 'static_transform_publisher', '0.1', '0', '0', '0', '0', '0', 'base_link', 'laser']),\n"
        "        ExecuteProcess(cmd='rosrun tf static_transform_publisher 0 0 0 0 0 0 map odom 100'.split()),\n"
        "        ExecuteProcess(cmd=['/opt/ros/humble/lib/tf2_ros/static_transform_publisher', '--frame-id', 'base_link', '--child-frame-id', 'imu']),\n"
        "        ExecuteProcess(cmd=['ros2', 'launch', 'nav2_bringup', 'navigation_launch.py']),\n"
        "    ])\n"
    )
    assert [(kind, parent, child) for kind, parent, child, _ in frames_of(source, "bringup.launch.py")] == [
        ("Published", "base_link", "laser"),
        ("Published", "map", "odom"),
        ("Published", "base_link", "imu"),
    ]
