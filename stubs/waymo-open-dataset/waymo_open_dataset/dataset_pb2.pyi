from typing import Literal

from geolint.typing import Radians, TransformMatrix

# dataset.proto (commit 99a4cb3): "4x4 row major transform matrix that tranforms 3d points from one frame to another. message
# Transform { repeated double transform = 1; }". Which frames depends on the field that holds it, so each field below has a
# class of its own (not a class of the library: the message is a Transform in every case); `transform` is 16 floats, which
# code reshapes (`np.reshape(np.array(frame.pose.transform), [4, 4])`, utils/frame_utils.py).

class _VehicleToWorld:
    """Not a class of the library: the Transform that Frame.pose and CameraImage.pose hold.

    Source: dataset.proto (commit 99a4cb3),
    Frame: "Frame vehicle pose. ... The frame vehicle pose defines the coordinate system which the 3D laser labels
    are defined in."; RangeImage: "[roll, pitch, yaw, x, y, z] represents a transform from vehicle frame to global frame";
    utils/frame_utils.py passes `frame.pose.transform`, reshaped to 4x4, as the `frame_pose` that takes vehicle points
    to the global frame (extract_point_cloud_from_range_image). Waymo's "global" frame is called world here."""

    transform: TransformMatrix[Literal["world"], Literal["vehicle"]]

class _CameraToVehicle:
    """Not a class of the library: the Transform that CameraCalibration.extrinsic holds.

    Source: dataset.proto (commit 99a4cb3),
    CameraCalibration: "// Camera frame to vehicle frame. optional Transform extrinsic = 3;". The camera frame's
    axes are x forward, y left, z up (wdl_limited/camera/camera_model.cc, CameraToImageWithDepth: a point is behind the
    camera when `x <= 0.0`, and `u = -y / x`, `v = -z / x`), which no CameraAxes member states."""

    transform: TransformMatrix[Literal["vehicle"], Literal["camera"]]

class _LidarToVehicle:
    """Not a class of the library: the Transform that LaserCalibration.extrinsic holds.

    Source: dataset.proto (commit 99a4cb3),
    LaserCalibration: "// Lidar frame to vehicle frame. optional Transform extrinsic = 5;"."""

    transform: TransformMatrix[Literal["vehicle"], Literal["lidar"]]

class CameraCalibration:
    """Source: dataset.proto (commit 99a4cb3), message CameraCalibration: "intrinsic = 2" ("1d Array of [f_u, f_v, c_u, c_v,
    k{1, 2}, p{1, 2}, k{3}]"), "extrinsic = 3" ("Camera frame to vehicle frame"), "width = 4", "height = 5". Checked
    against the generated dataset_pb2 (field names; tests/knowledge/test_image_and_scene_facts.py)."""

    extrinsic: _CameraToVehicle

class LaserCalibration:
    """Source: dataset.proto (commit 99a4cb3), message LaserCalibration: "If non-empty, the beam pitch (in radians) is
    non-uniform", "repeated double beam_inclinations = 2", "beam_inclination_{min,max} (in radians) are used to determine
    the mapping", "// Lidar frame to vehicle frame. optional Transform extrinsic = 5;"."""

    beam_inclinations: Radians
    beam_inclination_min: Radians
    beam_inclination_max: Radians
    extrinsic: _LidarToVehicle

class CameraImage:
    """Source: dataset.proto (commit 99a4cb3), message CameraImage: "// SDC pose. optional Transform pose = 3;" (the
    self-driving car's vehicle-to-global pose at the image's pose_timestamp; utils/frame_utils.py stores it as
    `{cam}_POSE`, reshaped to 4x4)."""

    pose: _VehicleToWorld

class Frame:
    """Source: dataset.proto (commit 99a4cb3), message Frame: "optional Context context = 1", "optional Transform pose =
    3" ("Frame vehicle pose"), "repeated CameraImage images = 4"."""

    pose: _VehicleToWorld
