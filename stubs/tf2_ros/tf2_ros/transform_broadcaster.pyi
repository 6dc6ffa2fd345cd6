from typing import Annotated

from geometry_msgs.msg import TransformStamped

from geolint.knowledge.markers import TfFrame

class TransformBroadcaster:
    """Source: ros2/geometry2 tf2_ros_py/tf2_ros/transform_broadcaster.py (0.39.1, commit 1b005c65),
    `sendTransform(self, transform: Union[TransformStamped, List[TransformStamped]]) -> None`: publishes
    `TFMessage(transforms=transform)` on "/tf". Each message's header.frame_id is the parent and child_frame_id the
    child (tf2's BufferCore::setTransform reads them so, tf2/src/buffer_core.cpp 199-230)."""

    def __init__(self, node: object, qos: object = ...) -> None: ...
    def sendTransform(self, transform: Annotated[TransformStamped | list[TransformStamped], TfFrame.PUBLISHED]) -> None: ...
