from geolint.typing import QuaternionWXYZ, Radians, RotationMatrix, VectorArray

from transforms3d.axangles import axangle2mat as axangle2mat

def euler2mat(ai: Radians, aj: Radians, ak: Radians, axes: str = ...) -> RotationMatrix:
    """Source: transforms3d/euler.py (0.4.2), euler2mat: "ai : float, First rotation angle (according
    to `axes`)", radians (`math.sin(ai)` and friends)."""

def euler2quat(ai: Radians, aj: Radians, ak: Radians, axes: str = ...) -> QuaternionWXYZ:
    """Source: transforms3d/euler.py (0.4.2), euler2quat: "quat : array shape (4,) Quaternion in
    w, x, y z (real, then vector) format"."""

def mat2euler(mat: RotationMatrix, axes: str = ...) -> tuple[Radians, Radians, Radians]:
    """Source: transforms3d/euler.py (0.4.2), mat2euler: angles in radians."""

def quat2euler(quaternion: QuaternionWXYZ, axes: str = ...) -> tuple[Radians, Radians, Radians]:
    """Source: transforms3d/euler.py (0.4.2), quat2euler: "quaternion : array shape (4,) ... w, x, y, z"."""

def euler2axangle(ai: Radians, aj: Radians, ak: Radians, axes: str = ...) -> tuple[VectorArray, Radians]:
    """Source: transforms3d/euler.py (0.4.2), euler2axangle."""

def axangle2euler(vector: VectorArray, theta: Radians, axes: str = ...) -> tuple[Radians, Radians, Radians]:
    """Source: transforms3d/euler.py (0.4.2), axangle2euler."""
