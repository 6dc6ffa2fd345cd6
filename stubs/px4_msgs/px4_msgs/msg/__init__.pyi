# A generated ROS 2 message takes its fields by keyword; only the quaternion fields are stated.
from geolint.typing import QuaternionWXYZ

class VehicleOdometry:
    """Source: PX4-Autopilot msg/versioned/VehicleOdometry.msg (main) and msg/VehicleOdometry.msg (release/1.14):
    "float32[4] q # Quaternion rotation from FRD body frame to reference frame"; PX4's quaternions are Hamilton
    w, x, y, z (VehicleAttitude.msg: "The quaternion uses the Hamilton convention, and the order is q(w, x, y, z)").
    Releases before 1.14 also had `float32[4] q_offset`, the same layout."""

    def __init__(self, *, q: QuaternionWXYZ = ..., q_offset: QuaternionWXYZ = ..., **fields: object) -> None: ...

class VehicleAttitude:
    """Source: PX4-Autopilot msg/versioned/VehicleAttitude.msg (main): "The quaternion uses the Hamilton convention, and
    the order is q(w, x, y, z)"; "float32[4] q # Quaternion rotation from the FRD body frame to the NED earth frame",
    "float32[4] delta_q_reset # Amount by which quaternion has changed during last reset"."""

    def __init__(self, *, q: QuaternionWXYZ = ..., delta_q_reset: QuaternionWXYZ = ..., **fields: object) -> None: ...

class VehicleAttitudeSetpoint:
    """Source: PX4-Autopilot msg/versioned/VehicleAttitudeSetpoint.msg (main): "float32[4] q_d # Desired quaternion for
    quaternion control", a matrix::Quatf (w, x, y, z) as every PX4 quaternion."""

    def __init__(self, *, q_d: QuaternionWXYZ = ..., **fields: object) -> None: ...

class VehicleVisualOdometry:
    """Source: PX4-Autopilot msg/vehicle_odometry.msg before release 1.14, whose topics included
    vehicle_visual_odometry (px4_msgs generated it as its own class): "float32[4] q # Quaternion rotation from FRD
    body frame to reference frame", `float32[4] q_offset`, w, x, y, z."""

    def __init__(self, *, q: QuaternionWXYZ = ..., q_offset: QuaternionWXYZ = ..., **fields: object) -> None: ...

class VehicleMocapOdometry:
    """Source: as VehicleVisualOdometry (the vehicle_mocap_odometry topic of the same msg file before release 1.14)."""

    def __init__(self, *, q: QuaternionWXYZ = ..., q_offset: QuaternionWXYZ = ..., **fields: object) -> None: ...
