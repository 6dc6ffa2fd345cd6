from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ, Radians, RotationMatrix, RotationVector, VectorArray
from typing_extensions import Annotated

# pytorch3d/transforms/rotation_conversions.py (commit 06a76ef8): "quaternions with real part first, as
# tensor of shape (..., 4)"; "Euler angles in radians as tensor of shape (..., 3)". PyTorch3D is not on
# PyPI for this machine's Python, so these facts are cited from the source, not run.
_Q = Annotated[QuaternionWXYZ, STACKED]

def quaternion_to_matrix(quaternions: _Q) -> RotationMatrix:
    """Source: rotation_conversions.py (06a76ef8), quaternion_to_matrix: "quaternions with real part first"
    (`r, i, j, k = torch.unbind(quaternions, -1)`)."""

def matrix_to_quaternion(matrix: RotationMatrix) -> _Q:
    """Source: rotation_conversions.py (06a76ef8), matrix_to_quaternion: "quaternions with real part first"."""

def quaternion_to_axis_angle(quaternions: _Q) -> RotationVector:
    """Source: rotation_conversions.py (06a76ef8), quaternion_to_axis_angle: "quaternions with real part first"."""

def axis_angle_to_quaternion(axis_angle: RotationVector) -> _Q:
    """Source: rotation_conversions.py (06a76ef8), axis_angle_to_quaternion: "the magnitude is the angle turned
    anticlockwise in radians"; returns "quaternions with real part first"."""

def axis_angle_to_matrix(axis_angle: RotationVector, fast: bool = ...) -> RotationMatrix:
    """Source: rotation_conversions.py (06a76ef8), axis_angle_to_matrix: "the magnitude is the angle turned
    anticlockwise in radians"."""

def euler_angles_to_matrix(euler_angles: Radians, convention: str) -> RotationMatrix:
    """Source: rotation_conversions.py (06a76ef8), euler_angles_to_matrix: "Euler angles in radians as tensor of
    shape (..., 3)"."""

def matrix_to_euler_angles(matrix: RotationMatrix, convention: str) -> Radians:
    """Source: rotation_conversions.py (06a76ef8), matrix_to_euler_angles: "Euler angles in radians as tensor of
    shape (..., 3)"."""

def quaternion_raw_multiply(a: _Q, b: _Q) -> _Q:
    """Source: rotation_conversions.py (06a76ef8), quaternion_raw_multiply: "Quaternions as tensor of shape
    (..., 4), real part first"."""

def quaternion_multiply(a: _Q, b: _Q) -> _Q:
    """Source: rotation_conversions.py (06a76ef8), quaternion_multiply: "real part first"."""

def quaternion_invert(quaternion: _Q) -> _Q:
    """Source: rotation_conversions.py (06a76ef8), quaternion_invert: "with real part first"."""

def standardize_quaternion(quaternions: _Q) -> _Q:
    """Source: rotation_conversions.py (06a76ef8), standardize_quaternion: "Quaternions with real part first"."""

def quaternion_apply(quaternion: _Q, point: VectorArray) -> VectorArray:
    """Source: rotation_conversions.py (06a76ef8), quaternion_apply: "Apply the rotation given by a quaternion
    to a 3D point", "real part first" (a rotation only: no translation)."""

def random_quaternions(n: int, dtype: object = ..., device: object = ...) -> _Q:
    """Source: rotation_conversions.py (06a76ef8), random_quaternions: "versors with nonnegative real part"
    (`o[:, 0]` is the real part)."""
