"""Christoph Gohlke's transformations (PyPI `transformations`): quaternions (w, x, y, z), angles in radians.

The package's __init__.py star-imports this module. On import, the module replaces many functions
with the C versions of its `_transformations` extension and keeps the Python ones under a `_py`
suffix (`_import_module('_transformations', __package__)`, postfix '_py'): the same API, the same
order (checked numerically in tests/knowledge/test_gohlke_facts.py).
"""

from geolint.typing import PointArray, QuaternionWXYZ, Radians, TransformMatrix, Translation, VectorArray

def identity_matrix() -> TransformMatrix:
    """Source: transformations/transformations.py (2026.1.18), identity_matrix: the 4x4 identity."""

def translation_matrix(direction: Translation) -> TransformMatrix:
    """Source: transformations/transformations.py (2026.1.18), translation_matrix: the homogeneous matrix that translates by `direction`."""

def translation_from_matrix(matrix: TransformMatrix) -> Translation:
    """Source: transformations/transformations.py (2026.1.18), translation_from_matrix: `matrix[:3, 3]`."""

def rotation_matrix(angle: Radians, direction: VectorArray, point: PointArray | None = ...) -> TransformMatrix:
    """Source: transformations/transformations.py (2026.1.18), rotation_matrix: "Angles are in radians unless specified otherwise"
    (the module docstring); a 4x4 rotation about the axis through `point`."""

def rotation_from_matrix(matrix: TransformMatrix) -> tuple[Radians, VectorArray, PointArray]:
    """Source: transformations/transformations.py (2026.1.18), rotation_from_matrix: returns angle (an arctangent, radians), direction,
    point."""

def euler_matrix(ai: Radians, aj: Radians, ak: Radians, axes: str = ...) -> TransformMatrix:
    """Source: transformations/transformations.py (2026.1.18), euler_matrix: "ai, aj, ak : Euler's roll, pitch and yaw angles",
    radians (their sines and cosines), a 4x4 homogeneous rotation."""

def euler_from_matrix(matrix: object, axes: str = ...) -> tuple[Radians, Radians, Radians]:
    """Source: transformations/transformations.py (2026.1.18), euler_from_matrix: reads the rotation part of a 3x3 or 4x4
    matrix; each angle is an arctangent (radians)."""

def euler_from_quaternion(quaternion: QuaternionWXYZ, axes: str = ...) -> tuple[Radians, Radians, Radians]:
    """Source: transformations/transformations.py (2026.1.18), euler_from_quaternion: `euler_from_matrix(quaternion_matrix(quaternion), axes)`."""

def quaternion_from_euler(ai: Radians, aj: Radians, ak: Radians, axes: str = ...) -> QuaternionWXYZ:
    """Source: transformations/transformations.py (2026.1.18), quaternion_from_euler: radians (cosines of the half angles); "Quaternions ... are
    represented as [w, x, y, z]" (the module docstring)."""

def quaternion_about_axis(angle: Radians, axis: VectorArray) -> QuaternionWXYZ:
    """Source: transformations/transformations.py (2026.1.18), quaternion_about_axis: the cosine of half the angle (radians) is
    the scalar, in (w, x, y, z) order."""

def quaternion_matrix(quaternion: QuaternionWXYZ) -> TransformMatrix:
    """Source: transformations/transformations.py (2026.1.18), quaternion_matrix: a 4x4 homogeneous rotation from a (w, x, y, z) quaternion."""

def quaternion_from_matrix(matrix: object, *, isprecise: bool = ...) -> QuaternionWXYZ:
    """Source: transformations/transformations.py (2026.1.18), quaternion_from_matrix(matrix, *, isprecise=False): returns
    (w, x, y, z)."""

def quaternion_multiply(quaternion1: QuaternionWXYZ, quaternion0: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: transformations/transformations.py (2026.1.18), quaternion_multiply(quaternion1, quaternion0): unpacks each as
    (w, x, y, z)."""

def quaternion_conjugate(quaternion: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: transformations/transformations.py (2026.1.18), quaternion_conjugate: negates the three vector components of a (w, x, y, z) quaternion."""

def quaternion_inverse(quaternion: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: transformations/transformations.py (2026.1.18), quaternion_inverse: the conjugate over the squared norm."""

def quaternion_real(quaternion: QuaternionWXYZ) -> float:
    """Source: transformations/transformations.py (2026.1.18), quaternion_real: the scalar, `quaternion[0]`."""

def quaternion_imag(quaternion: QuaternionWXYZ) -> VectorArray:
    """Source: transformations/transformations.py (2026.1.18), quaternion_imag: the vector part, `quaternion[1:4]`."""

def quaternion_slerp(quat0: QuaternionWXYZ, quat1: QuaternionWXYZ, fraction: float, spin: int = ..., *, shortestpath: bool = ...) -> QuaternionWXYZ:
    """Source: transformations/transformations.py (2026.1.18), quaternion_slerp(quat0, quat1, fraction, spin=0, *, shortestpath=True):
    interpolates the four components as given, so the result is in their order."""

def random_quaternion(rand: object = ...) -> QuaternionWXYZ:
    """Source: transformations/transformations.py (2026.1.18), random_quaternion(rand=None): (w, x, y, z)."""

def random_rotation_matrix(rand: object = ...) -> TransformMatrix:
    """Source: transformations/transformations.py (2026.1.18), random_rotation_matrix: `quaternion_matrix(random_quaternion(rand))`."""

quaternion_about_axis_py = quaternion_about_axis
quaternion_conjugate_py = quaternion_conjugate
quaternion_from_euler_py = quaternion_from_euler
quaternion_from_matrix_py = quaternion_from_matrix
quaternion_inverse_py = quaternion_inverse
quaternion_matrix_py = quaternion_matrix
quaternion_multiply_py = quaternion_multiply
quaternion_slerp_py = quaternion_slerp
random_quaternion_py = random_quaternion
euler_matrix_py = euler_matrix
euler_from_matrix_py = euler_from_matrix
rotation_matrix_py = rotation_matrix
translation_matrix_py = translation_matrix
identity_matrix_py = identity_matrix
random_rotation_matrix_py = random_rotation_matrix
