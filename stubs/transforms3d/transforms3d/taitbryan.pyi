from geolint.typing import QuaternionWXYZ, Radians, RotationMatrix, VectorArray

from transforms3d.axangles import axangle2mat as axangle2mat

def euler2mat(z: Radians, y: Radians, x: Radians) -> RotationMatrix:
    """Source: transforms3d/taitbryan.py (0.4.2), euler2mat: "z : scalar Rotation angle in radians
    around z-axis (performed first)", y and x likewise."""

def euler2quat(z: Radians, y: Radians, x: Radians) -> QuaternionWXYZ:
    """Source: transforms3d/taitbryan.py (0.4.2), euler2quat: "quat : array shape (4,) Quaternion in
    w, x, y z (real, then vector) format"."""

def mat2euler(M: RotationMatrix, cy_thresh: float | None = ...) -> tuple[Radians, Radians, Radians]:
    """Source: transforms3d/taitbryan.py (0.4.2), mat2euler: "z : scalar, y : scalar, x : scalar
    Rotations in radians around z, y, x axes, respectively"."""

def quat2euler(q: QuaternionWXYZ) -> tuple[Radians, Radians, Radians]:
    """Source: transforms3d/taitbryan.py (0.4.2), quat2euler: `mat2euler(nq.quat2mat(q))`."""

def euler2axangle(z: Radians, y: Radians, x: Radians) -> tuple[VectorArray, Radians]:
    """Source: transforms3d/taitbryan.py (0.4.2), euler2axangle: `nq.quat2axangle(euler2quat(z, y, x))`."""

def axangle2euler(vector: VectorArray, theta: Radians) -> tuple[Radians, Radians, Radians]:
    """Source: transforms3d/taitbryan.py (0.4.2), axangle2euler: "theta : scalar angle of rotation"
    (radians, through axangle2mat)."""
