"""String frames on geolint classes imported through a project module, and a clear error where the plugin
cannot tell that a subscripted name is geolint's class (the string is then read as a name)."""

import reexported_geometry as geometry
from reexported_geometry import Point, Transform


def through_a_reexport(T: Transform["map", "odom"]) -> Point["map"]:
    p = Point["odom"]([1.0, 2.0, 3.0])
    reveal_type(p)  # N: geolint.runtime.primitives.Point[Literal['odom']]
    reveal_type(T @ p)  # N: geolint.runtime.primitives.Point[Literal['map']]
    return T @ p


def unresolved(T: Transform["map", "odom"], p: Point["odom"]) -> None:
    q = geometry.Point["map"]([1.0, 2.0, 3.0])  # through a project module's attribute: not recognised
    T @ p - q  # E: geo-frame: Point[map]: the frame "map" was read as Python's builtin map, not as a string frame
