"""Angle units of library calls, by qualified name: what unit a call returns its angles in, and which
calls read an angle as the length of a rotation vector.

Each entry names where its unit was checked (the library's documentation or source).
"""

from __future__ import annotations

from typing import Final

DEGREES, RADIANS = "deg", "rad"

# Library calls whose every returned angle (a tuple or array of Euler angles) is in one unit.
RETURNED_ANGLES: Final[dict[str, str]] = {
    # tf_conversions.transformations: Gohlke's transformations.py as ROS 1's tf_conversions ships it;
    # euler_from_matrix computes each angle with math.atan2, and its doctest reads
    # euler_from_quaternion([0.06146124, 0, 0, 0.99810947]) back as [0.123, 0, 0]: radians. (tf.transformations,
    # tf_transformations, transforms3d, pytransform3d, pybullet: stubs/.)
    **{f"tf_conversions.transformations.{name}": RADIANS for name in ("euler_from_quaternion", "euler_from_matrix")},
}

# Library methods that return Euler angles, by qualified `module.Class.method`: (unit, the angles in
# order, the method of the same object that returns the orientation as a quaternion instead, with its
# component order). A device object's class is seldom known where it is read (`robot.getDevice(name)`),
# so a call is matched by its method name on any receiver: the names are the API's own, camelCase.
RETURNED_EULER_METHODS: Final[dict[str, tuple[str, tuple[str, ...], str]]] = {
    # Webots' Python controller API: "wb_inertial_unit_get_roll_pitch_yaw returns the current roll, pitch
    # and yaw angles ... indices 0, 1 and 2 return the roll, pitch and yaw angles respectively", in
    # [-pi, pi] (radians; the noise field's "pi/2 radians"); "wb_inertial_unit_get_quaternion ... indices
    # 0, 1, 2, and 3 return the x, y, z, and w components" (cyberbotics/webots docs/reference/inertialunit.md;
    # controller/inertial_unit.py returns `wb_inertial_unit_get_roll_pitch_yaw(tag)[:3]`)
    "controller.InertialUnit.getRollPitchYaw": (RADIANS, ("roll", "pitch", "yaw"), "getQuaternion()` (x, y, z, w"),
}
EULER_METHOD_NAMES: Final = {qualified.rpartition(".")[2]: qualified for qualified in RETURNED_EULER_METHODS}

# Library calls that read a rotation vector (axis times angle) as their first argument, in radians:
# numpy-quaternion's from_rotation_vector "Each vector represents the axis of the rotation, with norm
# proportional to the angle of the rotation in radians" (moble/quaternion, quaternion/__init__.py).
# (scipy's `Rotation.from_rotvec` is known through `is_scipy_rotation_method`.)
ROTATION_VECTOR_READERS: Final = frozenset({"quaternion.from_rotation_vector"})
