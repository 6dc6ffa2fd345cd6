from sensor_msgs.msg import PointCloud2

from geolint.typing import PointArray

def create_cloud_xyz32(header: object, points: PointArray) -> PointCloud2:
    """Source: ros/common_msgs sensor_msgs/src/sensor_msgs/point_cloud2.py (noetic-devel, commit 0b5c4432),
    create_cloud_xyz32(header, points): "Create a ... PointCloud2 message with 3 float32 fields (x, y, z)", one
    iterable of (x, y, z) per point; ROS 1 only (ROS 2 moved it to sensor_msgs_py.point_cloud2)."""
