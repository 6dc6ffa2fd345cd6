# launch_ros/launch_ros/actions/__init__.py: `from .node import Node`
from launch_ros.actions.node import Node as Node
