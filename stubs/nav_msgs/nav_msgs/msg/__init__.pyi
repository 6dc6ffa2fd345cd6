from geometry_msgs.msg import PoseWithCovariance, TwistWithCovariance

class Odometry:
    """Source: nav_msgs/msg/Odometry.msg (ros/common_msgs noetic-devel, ros2/common_interfaces rolling): "This
    represents an estimate of a position and velocity in free space. The pose in this message should be specified in
    the coordinate frame given by header.frame_id. The twist in this message should be specified in the coordinate
    frame given by the child_frame_id"; "Header header, string child_frame_id, geometry_msgs/PoseWithCovariance
    pose, geometry_msgs/TwistWithCovariance twist"."""

    def __init__(self, header: object = ..., child_frame_id: str = ..., pose: PoseWithCovariance = ..., twist: TwistWithCovariance = ...) -> None: ...
