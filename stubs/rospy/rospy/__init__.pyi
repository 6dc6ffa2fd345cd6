from typing import Annotated

from geolint.knowledge.markers import RosParameter

def get_param(param_name: Annotated[str, RosParameter.NAME], default: Annotated[object, RosParameter.DEFAULT] = ...) -> object:
    """Source: ros/ros_comm clients/rospy/src/rospy/client.py (noetic), `def get_param(param_name,
    default=_unspecified)`: "Retrieve a parameter from the param server ... @param default: (optional) default value to
    return if key is not set ... @raise KeyError: if value not set and default is not given"; rospy/__init__.py
    re-exports it (`from .client import ... get_param ...`)."""
