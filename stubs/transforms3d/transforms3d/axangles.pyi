from geolint.typing import Radians, RotationMatrix, TransformMatrix, VectorArray

def axangle2mat(axis: VectorArray, angle: Radians, is_normalized: bool = ...) -> RotationMatrix:
    """Source: transforms3d/axangles.py (0.4.2), axangle2mat: "angle : scalar, angle of rotation" (radians)."""

def mat2axangle(mat: RotationMatrix, unit_thresh: float = ...) -> tuple[VectorArray, Radians]:
    """Source: transforms3d/axangles.py (0.4.2), mat2axangle."""

def axangle2aff(axis: VectorArray, angle: Radians, point: object = ...) -> TransformMatrix:
    """Source: transforms3d/axangles.py (0.4.2), axangle2aff: a 4x4 rotation about an axis through `point`."""
