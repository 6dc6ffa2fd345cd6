from geolint.typing import Radians

class Label:
    """Source: label.proto (waymo-research/waymo-open-dataset commit 99a4cb3), message Label { message Box { ... } optional
    Box box = 1; ... }."""

    class Box:
        """Source: label.proto (commit 99a4cb3), Label.Box: "// Box coordinates in vehicle frame. optional double center_x =
        1;", "The heading of the bounding box (in radians). The heading is the angle required to rotate +x to the surface
        normal of the box front face. It is normalized to [-pi, pi). optional double heading = 7;". The generated class
        takes its fields as keywords (`Label.Box(center_x=..., heading=...)`)."""

        def __init__(
            self, *, center_x: float = ..., center_y: float = ..., center_z: float = ..., width: float = ..., length: float = ...,
            height: float = ..., heading: Radians = ..., type: object = ...,
        ) -> None: ...
        heading: Radians
