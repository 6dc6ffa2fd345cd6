# Isaac Sim 4.1's omni.isaac.core.objects (re-exported from objects/capsule.py, cone.py, cuboid.py, cylinder.py, sphere.py).
from typing import Annotated

from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ

_WXYZ = Annotated[QuaternionWXYZ, STACKED]

class DynamicCapsule:
    """Source: omni/isaac/core/objects/capsule.py (Isaac Sim 4.1), DynamicCapsule: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class FixedCapsule:
    """Source: omni/isaac/core/objects/capsule.py (Isaac Sim 4.1), FixedCapsule: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class VisualCapsule:
    """Source: omni/isaac/core/objects/capsule.py (Isaac Sim 4.1), VisualCapsule: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class DynamicCone:
    """Source: omni/isaac/core/objects/cone.py (Isaac Sim 4.1), DynamicCone: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class FixedCone:
    """Source: omni/isaac/core/objects/cone.py (Isaac Sim 4.1), FixedCone: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class VisualCone:
    """Source: omni/isaac/core/objects/cone.py (Isaac Sim 4.1), VisualCone: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class DynamicCuboid:
    """Source: omni/isaac/core/objects/cuboid.py (Isaac Sim 4.1), DynamicCuboid: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class FixedCuboid:
    """Source: omni/isaac/core/objects/cuboid.py (Isaac Sim 4.1), FixedCuboid: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class VisualCuboid:
    """Source: omni/isaac/core/objects/cuboid.py (Isaac Sim 4.1), VisualCuboid: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class DynamicCylinder:
    """Source: omni/isaac/core/objects/cylinder.py (Isaac Sim 4.1), DynamicCylinder: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class FixedCylinder:
    """Source: omni/isaac/core/objects/cylinder.py (Isaac Sim 4.1), FixedCylinder: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class VisualCylinder:
    """Source: omni/isaac/core/objects/cylinder.py (Isaac Sim 4.1), VisualCylinder: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class DynamicSphere:
    """Source: omni/isaac/core/objects/sphere.py (Isaac Sim 4.1), DynamicSphere: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class FixedSphere:
    """Source: omni/isaac/core/objects/sphere.py (Isaac Sim 4.1), FixedSphere: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class VisualSphere:
    """Source: omni/isaac/core/objects/sphere.py (Isaac Sim 4.1), VisualSphere: `orientation` (and a view's `orientations`) is "quaternion orientation ... quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...
