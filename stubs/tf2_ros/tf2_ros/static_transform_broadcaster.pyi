from typing import Annotated

from geometry_msgs.msg import TransformStamped

from geolint.knowledge.markers import TfFrame

class StaticTransformBroadcaster:
    """Source: ros2/geometry2 tf2_ros_py/tf2_ros/static_transform_broadcaster.py (0.39.1, commit 1b005c65),
    `sendTransform(self, transform: Union[TransformStamped, List[TransformStamped]]) -> None`: keeps the first message
    per child_frame_id and republishes all of them on "/tf_static" (transient local)."""

    def __init__(self, node: object, qos: object = ...) -> None: ...
    def sendTransform(self, transform: Annotated[TransformStamped | list[TransformStamped], TfFrame.PUBLISHED]) -> None: ...
