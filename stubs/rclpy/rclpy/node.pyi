from typing import Annotated

from geolint.knowledge.markers import RosParameter

_Name = Annotated[str, RosParameter.NAME]
_Default = Annotated[object, RosParameter.DEFAULT]

class Node:
    """Source: ros2/rclpy rclpy/rclpy/node.py (rolling, commit 32e4eae6): `declare_parameter(self, name: str, value: Any =
    None, descriptor=None, ignore_override=False) -> Parameter` ("Declare and initialize a parameter ... :return:
    Parameter with the effectively assigned value") calls `declare_parameters('', [(name, value, descriptor)])`, which
    declares "namespace.name" for each tuple (no dot when the namespace is '') and takes "parameter overrides set upon
    node creation as the first choice, or provided parameter values as the second one". `get_parameter(self, name)` and
    `get_parameter_or(self, name, alternative_value=None)` return a `Parameter`, whose `.value` (and
    `get_parameter_value().string_value`) is the parameter's value."""

    def declare_parameter(self, name: _Name, value: _Default = ..., descriptor: object = ..., ignore_override: bool = ...) -> object: ...
    def declare_parameters(
        self,
        namespace: Annotated[str, RosParameter.NAMESPACE],
        parameters: Annotated[list[tuple[object, ...]], RosParameter.DECLARATIONS],
        ignore_override: bool = ...,
    ) -> list[object]: ...
    def get_parameter(self, name: _Name) -> object: ...
    def get_parameter_or(self, name: _Name, alternative_value: _Default = ...) -> object: ...
