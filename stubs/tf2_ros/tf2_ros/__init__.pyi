# tf2_ros_py/tf2_ros/__init__.py (0.39.1): `from .buffer import *`, `from .transform_broadcaster import *`,
# `from .static_transform_broadcaster import *`, `from .transform_listener import *` (and buffer_interface, buffer_client)
from tf2_ros.buffer import Buffer as Buffer
from tf2_ros.static_transform_broadcaster import (
    StaticTransformBroadcaster as StaticTransformBroadcaster,
)
from tf2_ros.transform_broadcaster import TransformBroadcaster as TransformBroadcaster
from tf2_ros.transform_listener import TransformListener as TransformListener
