# Isaac Sim 4.5+'s isaacsim.core.api.robots.
from typing import Annotated

from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ

_WXYZ = Annotated[QuaternionWXYZ, STACKED]

class Robot:
    """Source: the isaacsim.core.api.robots API reference (Isaac Sim 4.5 and 5.0), Robot: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class RobotView:
    """Source: the isaacsim.core.api.robots API reference (Isaac Sim 4.5 and 5.0), RobotView: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_paths_expr: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...
