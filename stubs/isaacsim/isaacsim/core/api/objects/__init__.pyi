# Isaac Sim 4.5+'s isaacsim.core.api.objects.
from typing import Annotated

from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ

_WXYZ = Annotated[QuaternionWXYZ, STACKED]

class DynamicCapsule:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), DynamicCapsule: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class FixedCapsule:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), FixedCapsule: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class VisualCapsule:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), VisualCapsule: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class DynamicCone:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), DynamicCone: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class FixedCone:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), FixedCone: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class VisualCone:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), VisualCone: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class DynamicCuboid:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), DynamicCuboid: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class FixedCuboid:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), FixedCuboid: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class VisualCuboid:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), VisualCuboid: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class DynamicCylinder:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), DynamicCylinder: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class FixedCylinder:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), FixedCylinder: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class VisualCylinder:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), VisualCylinder: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class DynamicSphere:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), DynamicSphere: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class FixedSphere:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), FixedSphere: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...

class VisualSphere:
    """Source: the isaacsim.core.api.objects API reference (Isaac Sim 4.5 and 5.0), VisualSphere: `orientation` / `orientations`: "quaternion is scalar-first (w, x, y, z)"."""

    def __init__(self, prim_path: str, *args: object, orientation: _WXYZ = ..., orientations: _WXYZ = ..., **options: object) -> None: ...
