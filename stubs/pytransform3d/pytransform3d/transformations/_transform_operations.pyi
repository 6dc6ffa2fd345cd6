from typing import overload

from geolint.typing import Dst, HomogeneousPoints, HomogeneousVectors, PointArray, Src, TransformMatrix, VectorArray

# Where pytransform3d defines them (mypy names a call after the defining module); the package
# re-exports them.
def vector_to_point(v: PointArray) -> HomogeneousPoints:
    """Source: pytransform3d/transformations/_transform_operations.py (3.17.0), vector_to_point: "A point (x, y, z) ... will be
    represented by [x, y, z, 1] in homogeneous coordinates to which we can apply a transformation"."""

def vectors_to_points(V: PointArray) -> HomogeneousPoints:
    """Source: pytransform3d/transformations/_transform_operations.py (3.17.0), vectors_to_points: each row gets a 1 appended."""

def vector_to_direction(v: VectorArray) -> HomogeneousVectors:
    """Source: pytransform3d/transformations/_transform_operations.py (3.17.0), vector_to_direction: "A direction (x, y, z) ...
    will be represented by [x, y, z, 0] in homogeneous coordinates"."""

def vectors_to_directions(V: VectorArray) -> HomogeneousVectors:
    """Source: pytransform3d/transformations/_transform_operations.py (3.17.0), vectors_to_directions: each row gets a 0 appended."""

@overload
def transform(A2B: TransformMatrix[Dst, Src], PA: HomogeneousPoints[Src], strict_check: bool = ...) -> HomogeneousPoints[Dst]: ...
@overload
def transform(A2B: TransformMatrix[Dst, Src], PA: HomogeneousVectors[Src], strict_check: bool = ...) -> HomogeneousVectors[Dst]:
    """Source: pytransform3d/transformations/_transform_operations.py (3.17.0), transform(A2B, PA, strict_check=True):
    "Transform point or list of points or directions"; PA "represented by homogeneous coordinates" in frame A."""
