from typing import Annotated, overload

from geolint.knowledge.markers import LaunchNode

_Package = Annotated[str, LaunchNode.PACKAGE]
_Executable = Annotated[str, LaunchNode.EXECUTABLE]
_Arguments = Annotated[list[str], LaunchNode.ARGUMENTS]

class Node:
    """Source: ros2/launch_ros launch_ros/launch_ros/actions/node.py (jazzy 0.26.5), `Node.__init__(self, *, executable,
    package=None, name=None, namespace=None, exec_name=None, parameters=None, remappings=None, ros_arguments=None,
    arguments=None, **kwargs)`: ":param: executable the name of the executable to find if a package is provided or
    otherwise a path to the executable to run. :param: package the package in which the node executable can be found
    ... :param: arguments list of extra arguments for the node". Dashing and Eloquent (0.8, 0.9) named the first two
    `node_executable` and `node_name`."""

    @overload
    def __init__(
        self, *, executable: _Executable, package: _Package = ..., arguments: _Arguments = ..., **kwargs: object
    ) -> None: ...
    @overload
    def __init__(
        self, *, node_executable: _Executable, package: _Package = ..., arguments: _Arguments = ..., **kwargs: object
    ) -> None: ...
