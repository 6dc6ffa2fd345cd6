from typing import Annotated

from geometry_msgs.msg import Quaternion, Vector3

from geolint.knowledge.markers import CameraAxes
from geolint.typing import Degrees, VectorArray

# the header of camera data: its frame_id names the camera's optical frame (x right, y down, z forward)
_OpticalHeader = Annotated[object, CameraAxes.OPENCV]

class NavSatFix:
    """Source: sensor_msgs/msg/NavSatFix.msg (ros2/common_interfaces 5.4.2, commit c0c0bc57; ros/common_msgs
    commit 30624af5): "Latitude [degrees]. Positive is north of equator", "Longitude [degrees]. Positive
    is east of prime meridian", "Altitude [m]. Positive is above the WGS 84 ellipsoid". Fields in the order header,
    status, latitude, longitude, altitude, position_covariance, position_covariance_type: a generated ROS 1 message
    takes them by position in that order, ROS 2's by keyword."""

    def __init__(
        self,
        header: object = ...,
        status: object = ...,
        latitude: Degrees = ...,
        longitude: Degrees = ...,
        altitude: float = ...,
        position_covariance: object = ...,
        position_covariance_type: int = ...,
    ) -> None: ...

class Imu:
    """Source: sensor_msgs/msg/Imu.msg (ros2/common_interfaces 5.4.2, commit c0c0bc57; ros/common_msgs commit 6f4180b2, the same fields):
    `geometry_msgs/Quaternion orientation`, `geometry_msgs/Vector3 angular_velocity`, `geometry_msgs/Vector3
    linear_acceleration` (each followed by its float64[9] covariance, "Row major about x, y, z axes");
    "Accelerations should be in m/s^2 (not in g's), and rotational velocity should be in rad/sec". The two Vector3
    fields are free vectors (rates, not positions). A generated ROS 1 message takes the fields by position in this
    order, ROS 2's by keyword."""

    def __init__(
        self,
        header: object = ...,
        orientation: Quaternion = ...,
        orientation_covariance: object = ...,
        angular_velocity: Annotated[Vector3, VectorArray] = ...,
        angular_velocity_covariance: object = ...,
        linear_acceleration: Annotated[Vector3, VectorArray] = ...,
        linear_acceleration_covariance: object = ...,
    ) -> None: ...

class MagneticField:
    """Source: sensor_msgs/msg/MagneticField.msg (ros2/common_interfaces 5.4.2, commit c0c0bc57; ros/common_msgs, the same
    fields): "Measurement of the Magnetic Field vector at a specific location"; `geometry_msgs/Vector3 magnetic_field`
    ("x, y, and z components of the field vector in Tesla"), then its covariance. A free vector."""

    def __init__(self, header: object = ..., magnetic_field: Annotated[Vector3, VectorArray] = ..., magnetic_field_covariance: object = ...) -> None: ...

class Image:
    """Source: sensor_msgs/msg/Image.msg (ros2/common_interfaces 5.4.2, commit c0c0bc57; ros/common_msgs, the same text):
    "Header frame_id should be optical frame of camera / origin of frame should be optical center of camera / +x should
    point to the right in the image / +y should point down in the image / +z should point into to plane of the image".
    Fields header, height, width, encoding, is_bigendian, step, data."""

    def __init__(
        self, header: _OpticalHeader = ..., height: int = ..., width: int = ..., encoding: str = ..., is_bigendian: int = ..., step: int = ..., data: object = ...
    ) -> None: ...

class CompressedImage:
    """Source: sensor_msgs/msg/CompressedImage.msg (ros2/common_interfaces 5.4.2): "Header frame_id should be optical frame
    of camera / origin of frame should be optical center of camera / +x should point to the right in the image / +y should
    point down in the image / +z should point into to plane of the image". Fields header, format, data."""

    def __init__(self, header: _OpticalHeader = ..., format: str = ..., data: object = ...) -> None: ...

class CameraInfo:
    """Source: sensor_msgs/msg/CameraInfo.msg (ros2/common_interfaces 5.4.2): "Header frame_id should be the optical frame
    of the camera / origin of frame should be optical center of cameara / +x should point to the right in the image / +y
    should point down in the image / +z should point into the plane of the image" (and "If the frame_id here and the
    frame_id of the CameraInfo message associated with the image conflict the behavior is undefined")."""

    def __init__(
        self, header: _OpticalHeader = ..., height: int = ..., width: int = ..., distortion_model: str = ..., d: object = ..., k: object = ..., r: object = ..., p: object = ..., **fields: object
    ) -> None: ...
