# Isaac Sim 4.1's omni.isaac.core.articulations.
from typing import Annotated

from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ

_WXYZ = Annotated[QuaternionWXYZ, STACKED]

class Articulation:
    """Source: omni/isaac/core/articulations/articulation.py (Isaac Sim 4.1), Articulation: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class ArticulationView:
    """Source: omni/isaac/core/articulations/articulation_view.py (Isaac Sim 4.1), ArticulationView: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_paths_expr: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...
