from pytransform3d.transformations._transform_operations import (
    transform as transform,
    vector_to_direction as vector_to_direction,
    vector_to_point as vector_to_point,
    vectors_to_directions as vectors_to_directions,
    vectors_to_points as vectors_to_points,
)

from geolint.typing import Dst, From, In, RotationMatrix, Src, To, TransformMatrix, Translation

# pytransform3d.transformations: 4x4 poses named `A2B` ("Transform from frame A to frame B"), composed
# in the extrinsic convention.

def concat(A2B: TransformMatrix[In, From], B2C: TransformMatrix[To, In], strict_check: bool = ..., check: bool = ...) -> TransformMatrix[To, From]:
    """Source: pytransform3d/transformations/_transform_operations.py (3.17.0), concat: "We use the
    extrinsic convention, which means that B2C is left-multiplied to A2B", T_CB T_BA = T_CA."""

def invert_transform(A2B: TransformMatrix[Dst, Src], strict_check: bool = ..., check: bool = ...) -> TransformMatrix[Src, Dst]:
    """Source: pytransform3d/transformations/_transform_operations.py (3.17.0), invert_transform:
    "Invert transform from frame A to frame B"."""

def transform_from_pq(pq: object) -> TransformMatrix:
    """Source: pytransform3d/transformations/_pq.py (3.17.0), transform_from_pq: "Position and
    orientation quaternion: (x, y, z, qw, qx, qy, qz)", returns "A2B : array, shape (4, 4)"."""

def transform_from(R: RotationMatrix[Dst, Src], p: Translation[Dst, Src], strict_check: bool = ...) -> TransformMatrix[Dst, Src]:
    """Source: pytransform3d/transformations/_transform.py (3.17.0), transform_from: "Make transformation
    from rotation matrix and translation"."""
