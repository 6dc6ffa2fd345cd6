# A message class's constructor parameters are its fields, in the .msg file's order (a generated ROS 1
# message takes them by position in that order, ROS 2's by keyword); a field's annotation is the message
# class it holds and, for a 3-vector, what the vector is: a Point is a position, the parts of a Twist, an
# Accel and a Wrench are free vectors, a Transform's translation is a translation.
from typing import Annotated

from geolint.typing import PointArray, Translation, VectorArray

class Point:
    """Source: geometry_msgs/msg/Point.msg (ros/common_msgs noetic-devel, ros2/common_interfaces rolling):
    "This contains the position of a point in free space", "float64 x, float64 y, float64 z"."""

    def __init__(self, x: float = ..., y: float = ..., z: float = ...) -> None: ...

class Vector3:
    """Source: geometry_msgs/msg/Vector3.msg (ros/common_msgs noetic-devel, ros2/common_interfaces rolling):
    "This represents a vector in free space. It is only meant to represent a direction. Therefore, it does
    not make sense to apply a translation to it (e.g., when applying a generic rigid transformation to a
    Vector3, tf2 will only apply the rotation)"; "float64 x, float64 y, float64 z"."""

    def __init__(self, x: float = ..., y: float = ..., z: float = ...) -> None: ...

class Quaternion:
    """Source: geometry_msgs/msg/Quaternion.msg (ros/common_msgs noetic-devel, ros2/common_interfaces
    rolling): "float64 x, float64 y, float64 z, float64 w" (ROS 2 defaults w to 1). A generated ROS 1
    message takes its fields by position in that order; ROS 2's by keyword."""

    def __init__(self, x: float = ..., y: float = ..., z: float = ..., w: float = ...) -> None: ...

class PointStamped:
    """Source: geometry_msgs/msg/PointStamped.msg: "Header header, Point point"."""

    def __init__(self, header: object = ..., point: Annotated[Point, PointArray] = ...) -> None: ...

class Vector3Stamped:
    """Source: geometry_msgs/msg/Vector3Stamped.msg: "Header header, Vector3 vector"."""

    def __init__(self, header: object = ..., vector: Annotated[Vector3, VectorArray] = ...) -> None: ...

class Pose:
    """Source: geometry_msgs/msg/Pose.msg: "A representation of pose in free space, composed of position and
    orientation. Point position, Quaternion orientation"."""

    def __init__(self, position: Annotated[Point, PointArray] = ..., orientation: Quaternion = ...) -> None: ...

class PoseStamped:
    """Source: geometry_msgs/msg/PoseStamped.msg: "Header header, Pose pose"."""

    def __init__(self, header: object = ..., pose: Pose = ...) -> None: ...

class PoseWithCovariance:
    """Source: geometry_msgs/msg/PoseWithCovariance.msg: "Pose pose, float64[36] covariance"."""

    def __init__(self, pose: Pose = ..., covariance: object = ...) -> None: ...

class PoseWithCovarianceStamped:
    """Source: geometry_msgs/msg/PoseWithCovarianceStamped.msg: "Header header, PoseWithCovariance pose"."""

    def __init__(self, header: object = ..., pose: PoseWithCovariance = ...) -> None: ...

class Twist:
    """Source: geometry_msgs/msg/Twist.msg: "This expresses velocity in free space broken into its linear and
    angular parts. Vector3 linear, Vector3 angular"."""

    def __init__(self, linear: Annotated[Vector3, VectorArray] = ..., angular: Annotated[Vector3, VectorArray] = ...) -> None: ...

class TwistStamped:
    """Source: geometry_msgs/msg/TwistStamped.msg: "Header header, Twist twist"."""

    def __init__(self, header: object = ..., twist: Twist = ...) -> None: ...

class TwistWithCovariance:
    """Source: geometry_msgs/msg/TwistWithCovariance.msg: "Twist twist, float64[36] covariance"."""

    def __init__(self, twist: Twist = ..., covariance: object = ...) -> None: ...

class TwistWithCovarianceStamped:
    """Source: geometry_msgs/msg/TwistWithCovarianceStamped.msg: "Header header, TwistWithCovariance twist"."""

    def __init__(self, header: object = ..., twist: TwistWithCovariance = ...) -> None: ...

class Accel:
    """Source: geometry_msgs/msg/Accel.msg: "This expresses acceleration in free space broken into its linear
    and angular parts. Vector3 linear, Vector3 angular"."""

    def __init__(self, linear: Annotated[Vector3, VectorArray] = ..., angular: Annotated[Vector3, VectorArray] = ...) -> None: ...

class AccelStamped:
    """Source: geometry_msgs/msg/AccelStamped.msg: "Header header, Accel accel"."""

    def __init__(self, header: object = ..., accel: Accel = ...) -> None: ...

class Wrench:
    """Source: geometry_msgs/msg/Wrench.msg: "This represents force in free space, separated into its linear
    and angular parts. Vector3 force, Vector3 torque"."""

    def __init__(self, force: Annotated[Vector3, VectorArray] = ..., torque: Annotated[Vector3, VectorArray] = ...) -> None: ...

class WrenchStamped:
    """Source: geometry_msgs/msg/WrenchStamped.msg: "Header header, Wrench wrench"."""

    def __init__(self, header: object = ..., wrench: Wrench = ...) -> None: ...

class Transform:
    """Source: geometry_msgs/msg/Transform.msg: "This represents the transform between two coordinate frames in
    free space. Vector3 translation, Quaternion rotation"."""

    def __init__(self, translation: Annotated[Vector3, Translation] = ..., rotation: Quaternion = ...) -> None: ...

class TransformStamped:
    """Source: geometry_msgs/msg/TransformStamped.msg: "This expresses a transform from coordinate frame
    header.frame_id to the coordinate frame child_frame_id at the time of header.stamp"; "Header header,
    string child_frame_id, Transform transform"."""

    def __init__(self, header: object = ..., child_frame_id: str = ..., transform: Transform = ...) -> None: ...
