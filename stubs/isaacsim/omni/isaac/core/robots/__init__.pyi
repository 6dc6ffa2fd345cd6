# Isaac Sim 4.1's omni.isaac.core.robots.
from typing import Annotated

from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ

_WXYZ = Annotated[QuaternionWXYZ, STACKED]

class Robot:
    """Source: omni/isaac/core/robots/robot.py (Isaac Sim 4.1), Robot: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class RobotView:
    """Source: omni/isaac/core/robots/robot_view.py (Isaac Sim 4.1), RobotView: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_paths_expr: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...
