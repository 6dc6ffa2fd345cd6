from geolint.typing import (
    Dst, From, HomogeneousPoints, HomogeneousVectors, In, PointArray, RotationMatrix, Src, To, TransformMatrix, Translation,
    VectorArray,
)

# pytransform3d.transformations: 4x4 poses named `A2B` ("Transform from frame A to frame B"), composed
# in the extrinsic convention.

def concat(A2B: TransformMatrix[In, From], B2C: TransformMatrix[To, In], strict_check: bool = ..., check: bool = ...) -> TransformMatrix[To, From]:
    """Source: pytransform3d/transformations/_transform_operations.py (3.17.0), concat: "We use the
    extrinsic convention, which means that B2C is left-multiplied to A2B", T_CB T_BA = T_CA."""

def invert_transform(A2B: TransformMatrix[Dst, Src], strict_check: bool = ..., check: bool = ...) -> TransformMatrix[Src, Dst]:
    """Source: pytransform3d/transformations/_transform_operations.py (3.17.0), invert_transform:
    "Invert transform from frame A to frame B"."""

def transform_from(R: RotationMatrix[Dst, Src], p: Translation[Dst, Src], strict_check: bool = ...) -> TransformMatrix[Dst, Src]:
    """Source: pytransform3d/transformations/_transform.py (3.17.0), transform_from: "Make transformation
    from rotation matrix and translation"."""

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
