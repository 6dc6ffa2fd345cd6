# Isaac Sim 4.1's omni.isaac.core.prims (re-exported from the modules named in each citation).
from typing import Annotated

from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ

_WXYZ = Annotated[QuaternionWXYZ, STACKED]

class XFormPrim:
    """Source: omni/isaac/core/prims/xform_prim.py (Isaac Sim 4.1), XFormPrim: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class XFormPrimView:
    """Source: omni/isaac/core/prims/xform_prim_view.py (Isaac Sim 4.1), XFormPrimView: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_paths_expr: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class RigidPrim:
    """Source: omni/isaac/core/prims/rigid_prim.py (Isaac Sim 4.1), RigidPrim: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class RigidPrimView:
    """Source: omni/isaac/core/prims/rigid_prim_view.py (Isaac Sim 4.1), RigidPrimView: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_paths_expr: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class GeometryPrim:
    """Source: omni/isaac/core/prims/geometry_prim.py (Isaac Sim 4.1), GeometryPrim: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class GeometryPrimView:
    """Source: omni/isaac/core/prims/geometry_prim_view.py (Isaac Sim 4.1), GeometryPrimView: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_paths_expr: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class ClothPrim:
    """Source: omni/isaac/core/prims/soft/cloth_prim.py (Isaac Sim 4.1), ClothPrim: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class ClothPrimView:
    """Source: omni/isaac/core/prims/soft/cloth_prim_view.py (Isaac Sim 4.1), ClothPrimView: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_paths_expr: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...
