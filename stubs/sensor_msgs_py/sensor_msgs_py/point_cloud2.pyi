from sensor_msgs.msg import PointCloud2

from geolint.typing import PointArray

def create_cloud_xyz32(header: object, points: PointArray) -> PointCloud2:
    """Source: ros2/common_interfaces sensor_msgs_py/sensor_msgs_py/point_cloud2.py (5.4.2, commit c0c0bc57),
    `create_cloud_xyz32(header: Header, points: Iterable) -> PointCloud2`: "Create a sensor_msgs.msg.PointCloud2
    message with (x, y, z) fields" (three FLOAT32 PointFields at offsets 0, 4, 8)."""
