from tf2_ros.buffer import Buffer

class TransformListener:
    """Source: ros2/geometry2 tf2_ros_py/tf2_ros/transform_listener.py (0.39.1, commit 1b005c65),
    `TransformListener(buffer, node, *, spin_thread=False, qos=None, static_qos=None, tf_topic=..., tf_static_topic=...)`: fills `buffer` from "/tf"
    and "/tf_static"."""

    def __init__(self, buffer: Buffer, node: object, *, spin_thread: bool = ..., qos: object = ..., static_qos: object = ..., tf_topic: str = ..., tf_static_topic: str = ...) -> None: ...
