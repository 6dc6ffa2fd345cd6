class Quaternion:
    """Source: geometry_msgs/msg/Quaternion.msg (ros/common_msgs noetic-devel, ros2/common_interfaces
    rolling): "float64 x, float64 y, float64 z, float64 w" (ROS 2 defaults w to 1). A generated ROS 1
    message takes its fields by position in that order; ROS 2's by keyword."""

    def __init__(self, x: float = ..., y: float = ..., z: float = ..., w: float = ...) -> None: ...
