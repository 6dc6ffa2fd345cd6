"""GEO307 euler-angles-in-quaternion: which values count as Euler angles, and which quaternions are checked.

Each case is a small function in a real shape (a ROS node filling a message) run through the engine
with GEO306 and GEO307 enabled, so an overlap with quaternion-component-unset would show too.
"""

from __future__ import annotations

import textwrap

from geolint.engine import lint_source
from geolint.factbase.angles import (
    EULER_METHOD_NAMES,
    RETURNED_EULER_METHODS,
)
from geolint.rules import rule_by_code

RULES = [rule_by_code("GEO306"), rule_by_code("GEO307")]


def findings(source: str) -> list[tuple[int, str, str]]:
    found = lint_source(textwrap.dedent(source), "node.py", rules=RULES)
    return [(finding.line, finding.code, finding.message) for finding in found]


def codes(source: str) -> list[tuple[int, str]]:
    return [(line, code) for line, code, _ in findings(source)]


def test_webots_roll_pitch_yaw_into_imu_orientation() -> None:
    source = """
    from sensor_msgs.msg import Imu

    class Driver:
        def __init__(self, robot):
            self.imu = robot.getDevice("inertial unit")

        def step(self):
            roll, pitch, yaw = self.imu.getRollPitchYaw()
            msg = Imu()
            msg.orientation.x = roll
            msg.orientation.y = pitch
            msg.orientation.z = yaw
            msg.orientation.w = 1.0
            return msg
    """
    (found,) = findings(source)
    assert found[:2] == (11, "GEO307")
    assert "roll: `controller.InertialUnit.getRollPitchYaw` returns them" in found[2]
    assert "getQuaternion()` (x, y, z, w)" in found[2]


def test_one_library_angle_is_enough() -> None:
    source = """
    from geometry_msgs.msg import Pose
    from tf_transformations import euler_from_quaternion

    def heading_only(q):
        pose = Pose()
        pose.orientation.z = float(euler_from_quaternion(q)[2])
        pose.orientation.w = 1.0
        return pose
    """
    assert codes(source) == [(7, "GEO307")]


def test_degrees_of_an_euler_angle_are_still_an_angle() -> None:
    source = """
    import numpy as np
    from geometry_msgs.msg import Quaternion, Transform
    from scipy.spatial.transform import Rotation

    def to_msg(matrix):
        angles = Rotation.from_matrix(matrix).as_euler("xyz")
        return Transform(rotation=Quaternion(x=np.degrees(angles[0]), y=0.0, z=0.0, w=1.0))
    """
    assert codes(source) == [(8, "GEO307")]


def test_half_angle_formula_is_a_component() -> None:
    source = """
    import math
    from geometry_msgs.msg import Pose
    from tf.transformations import euler_from_quaternion

    def yaw_only(q):
        yaw = euler_from_quaternion(q)[2]
        half = yaw / 2.0
        pose = Pose()
        pose.orientation.z = math.sin(half)
        pose.orientation.w = math.cos(half)
        return pose
    """
    assert codes(source) == []


def test_a_single_angle_name_is_no_evidence() -> None:
    source = """
    from geometry_msgs.msg import Pose

    def from_yaw(yaw):
        pose = Pose()
        pose.orientation.z = yaw
        pose.orientation.w = 1.0
        return pose
    """
    assert codes(source) == []


def test_two_names_of_different_angles_are_evidence() -> None:
    source = """
    from geometry_msgs.msg import Pose

    def tilted(roll, pitch):
        pose = Pose()
        pose.orientation.x = roll
        pose.orientation.y = pitch
        pose.orientation.w = 1.0
        return pose
    """
    assert codes(source) == [(6, "GEO307")]


def test_rates_and_formulas_named_like_angles_are_not_angles() -> None:
    source = """
    import math
    from geometry_msgs.msg import Pose

    def odd(roll_rate, pitch_rate, r, p):
        roll = math.sin(r / 2)
        pitch = math.sin(p / 2)
        pose = Pose()
        pose.orientation.x = roll
        pose.orientation.y = pitch
        pose.orientation.z = roll_rate
        pose.orientation.w = pitch_rate
        return pose
    """
    assert codes(source) == []


def test_three_angles_in_a_quaternion_message_only_count_once_it_is_an_orientation() -> None:
    carrier = """
    from geometry_msgs.msg import Quaternion
    from tf.transformations import euler_from_quaternion

    def rpy_topic(pub, q):
        roll, pitch, yaw = euler_from_quaternion(q)
        msg = Quaternion()
        msg.x = roll
        msg.y = pitch
        msg.z = yaw
        pub.publish(msg)
    """
    assert codes(carrier) == []
    placed = carrier.replace("from geometry_msgs.msg import Quaternion", "from geometry_msgs.msg import Pose, Quaternion").replace(
        "pub.publish(msg)", "pose = Pose()\n        pose.orientation = msg\n        pub.publish(pose)"
    )
    assert codes(placed) == [(8, "GEO307")]


def test_other_libraries_quaternion_classes_are_not_checked() -> None:
    # pymavlink's Quaternion((roll, pitch, yaw)) converts Euler angles itself
    source = """
    from pymavlink.quaternion import Quaternion
    from pybullet import getEulerFromQuaternion

    def attitude(q):
        roll, pitch, yaw = getEulerFromQuaternion(q)
        return Quaternion((roll, pitch, yaw))
    """
    assert codes(source) == []


def test_the_tables_name_their_methods_once() -> None:
    assert EULER_METHOD_NAMES == {"getRollPitchYaw": "controller.InertialUnit.getRollPitchYaw"}
    unit, names, _ = RETURNED_EULER_METHODS["controller.InertialUnit.getRollPitchYaw"]
    assert (unit, names) == ("rad", ("roll", "pitch", "yaw"))


def test_three_elements_in_a_row_with_w_unset_are_geo306() -> None:
    source = """
    from sensor_msgs.msg import Imu

    def attitude(unit, table):
        values = unit.getValues()
        msg = Imu()
        msg.orientation.x = lookup(values[0], table)
        msg.orientation.y = lookup(values[1], table)
        msg.orientation.z = lookup(values[2], table)
        return msg
    """
    ((line, code, message),) = findings(source)
    assert (line, code) == (7, "GEO306")
    assert "`lookup` of `values[0]`, `values[1]`, `values[2]`" in message
    assert codes(source.replace("lookup(values[2], table)", "lookup(values[2], other)")) == []
    assert codes(source.replace("values[2]", "values[1]")) == []
    assert codes(source.replace("return msg", "msg.orientation.w = 1.0\n        return msg")) == []


def test_a_vector_of_angles_copied_into_an_orientation() -> None:
    source = """
    from geometry_msgs.msg import Pose

    def from_state(state):
        pose = Pose()
        pose.orientation.x = state.rpy.x
        pose.orientation.y = state.rpy.y
        pose.orientation.z = state.rpy.z
        pose.orientation.w = 1.0
        return pose
    """
    assert codes(source) == [(6, "GEO307")]
    assert codes(source.replace("rpy", "rotation")) == []


def test_names_that_say_quaternion_are_not_angles() -> None:
    source = """
    from geometry_msgs.msg import Pose

    def from_parts(roll_q, yaw_q):
        pose = Pose()
        pose.orientation.x = roll_q
        pose.orientation.z = yaw_q
        return pose
    """
    assert codes(source) == []


def test_webots_roll_pitch_yaw_are_radians_for_the_unit_rules() -> None:
    source = """
    import math

    def heading(robot):
        imu = robot.getDevice("inertial unit")
        yaw = imu.getRollPitchYaw()[2]
        return math.radians(yaw), math.degrees(yaw)
    """
    found = lint_source(textwrap.dedent(source), "node.py", rules=[rule_by_code("GEO305")])
    assert [(finding.line, finding.code) for finding in found] == [(7, "GEO305")]
    assert "`controller.InertialUnit.getRollPitchYaw` returns its angles in radians" in found[0].message


# -- pybullet parameters that take whole quaternions ---------------------------------------------------


def test_roll_pitch_yaw_records_as_pybullet_shape_frames() -> None:
    """A list comprehension of URDF rpy triples given as visualFrameOrientations (one quaternion per shape)."""
    source = """
    import pybullet as p

    def clone_visuals(shapes):
        return p.createVisualShapeArray(
            shapeTypes=[s.kind for s in shapes],
            visualFramePositions=[s.origin_xyz for s in shapes],
            visualFrameOrientations=[s.origin_rpy for s in shapes],
        )
    """
    (found,) = findings(source)
    assert found[:2] == (8, "GEO307")
    assert "`s.origin_rpy` holds Euler angles (the name `origin_rpy` says Euler angles)" in found[2]
    assert "`createVisualShapeArray` reads `visualFrameOrientations` as a quaternion" in found[2]
    assert "pybullet ignores a sequence that is not four long" in found[2]


def test_converted_shape_frames_and_positions_named_rpy_are_silent() -> None:
    source = """
    import pybullet as p

    def clone_visuals(shapes):
        return p.createVisualShapeArray(
            shapeTypes=[s.kind for s in shapes],
            visualFramePositions=[s.origin_rpy for s in shapes],
            visualFrameOrientations=[p.getQuaternionFromEuler(s.origin_rpy) for s in shapes],
        )
    """
    assert codes(source) == []


def test_each_item_of_a_link_orientation_list_is_checked() -> None:
    source = """
    import pybullet as p

    def build(base_shape, link_shape, joint_rpy, base_euler):
        return p.createMultiBody(
            baseCollisionShapeIndex=base_shape,
            baseInertialFrameOrientation=p.getQuaternionFromEuler(base_euler),
            linkCollisionShapeIndices=[link_shape],
            linkOrientations=[[0.0, 0.0, 0.0, 1.0], joint_rpy],
            linkInertialFrameOrientations=[p.getQuaternionFromEuler(joint_rpy)],
        )
    """
    assert codes(source) == [(9, "GEO307")]


def test_pybullet_euler_angles_given_back_as_an_orientation() -> None:
    """A library says the value is Euler angles (whatever its name): a positional orientation argument."""
    source = """
    import pybullet as pb

    def align(body, reference):
        position, orientation = pb.getBasePositionAndOrientation(reference)
        angles = pb.getEulerFromQuaternion(orientation)
        pb.resetBasePositionAndOrientation(body, position, angles)
    """
    (found,) = findings(source)
    assert found[:2] == (7, "GEO307")
    assert "getEulerFromQuaternion` returns Euler angles" in found[2]
    assert "its orientation argument" in found[2] and "not four long" not in found[2]


def test_a_quaternion_named_after_its_angles_is_not_euler() -> None:
    source = """
    import pybullet as p

    def spawn(path, position, roll, pitch, yaw):
        orientation_from_euler = p.getQuaternionFromEuler([roll, pitch, yaw])
        start_euler = p.getQuaternionFromEuler([0.0, 0.0, yaw])
        p.loadURDF(path, position, start_euler)
        return p.loadURDF(path, position, baseOrientation=orientation_from_euler)
    """
    assert codes(source) == []
