from geolint.typing import RotationMatrix, TransformMatrix, Translation

def compose(T: Translation, R: RotationMatrix, Z: object, S: object = ...) -> TransformMatrix:
    """Source: transforms3d/affines.py (0.4.2), compose(T, R, Z, S=None): "T : array-like shape (N,)
    Translations", R rotation, Z zooms; the result is the homogeneous affine."""

def decompose44(A44: TransformMatrix) -> tuple[Translation, RotationMatrix, object, object]:
    """Source: transforms3d/affines.py (0.4.2), decompose44: returns T, R, Z, S."""

def decompose(A: TransformMatrix) -> tuple[Translation, RotationMatrix, object, object]:
    """Source: transforms3d/affines.py (0.4.2), decompose: returns T, R, Z, S."""
