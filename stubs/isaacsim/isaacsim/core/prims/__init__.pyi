# Isaac Sim 4.5+'s isaacsim.core.prims: the many-prim classes took the 4.1 names, the one-prim classes are Single*.
from typing import Annotated

from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ

_WXYZ = Annotated[QuaternionWXYZ, STACKED]

class XFormPrim:
    """Source: the isaacsim.core.prims API reference (Isaac Sim 4.5 and 5.0), XFormPrim: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_paths_expr: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class SingleXFormPrim:
    """Source: the isaacsim.core.prims API reference (Isaac Sim 4.5 and 5.0), SingleXFormPrim: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class RigidPrim:
    """Source: the isaacsim.core.prims API reference (Isaac Sim 4.5 and 5.0), RigidPrim: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_paths_expr: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class SingleRigidPrim:
    """Source: the isaacsim.core.prims API reference (Isaac Sim 4.5 and 5.0), SingleRigidPrim: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class GeometryPrim:
    """Source: the isaacsim.core.prims API reference (Isaac Sim 4.5 and 5.0), GeometryPrim: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_paths_expr: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class SingleGeometryPrim:
    """Source: the isaacsim.core.prims API reference (Isaac Sim 4.5 and 5.0), SingleGeometryPrim: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class Articulation:
    """Source: the isaacsim.core.prims API reference (Isaac Sim 4.5 and 5.0), Articulation: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_paths_expr: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class SingleArticulation:
    """Source: the isaacsim.core.prims API reference (Isaac Sim 4.5 and 5.0), SingleArticulation: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class ClothPrim:
    """Source: the isaacsim.core.prims API reference (Isaac Sim 4.5 and 5.0), ClothPrim: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_paths_expr: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class SingleClothPrim:
    """Source: the isaacsim.core.prims API reference (Isaac Sim 4.5 and 5.0), SingleClothPrim: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...
