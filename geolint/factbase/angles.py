"""Angle units of device methods matched by name on any receiver (Webots' `InertialUnit`). Library
calls state their units in stubs/ (`geolint.knowledge`).

Each entry names where its unit was checked (the library's documentation or source).
"""

from __future__ import annotations

from typing import Final

DEGREES, RADIANS = "deg", "rad"

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
