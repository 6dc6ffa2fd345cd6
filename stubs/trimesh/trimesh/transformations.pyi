"""trimesh.transformations: trimesh's copy of Gohlke's transformations.py, quaternions (w, x, y, z)
("Quaternions w+ix+jy+kz are represented as [w, x, y, z]", its module docstring), angles in radians.
"""

from typing import Literal, overload

from geolint.typing import Dst, PointArray, QuaternionWXYZ, Radians, Src, TransformMatrix, Translation, VectorArray

def identity_matrix() -> TransformMatrix:
    """Source: trimesh/transformations.py (trimesh 5.2.0), identity_matrix: the 4x4 identity."""

def translation_matrix(direction: Translation) -> TransformMatrix:
    """Source: trimesh/transformations.py (trimesh 5.2.0), translation_matrix: the homogeneous matrix that translates by `direction`."""

def translation_from_matrix(matrix: TransformMatrix) -> Translation:
    """Source: trimesh/transformations.py (trimesh 5.2.0), translation_from_matrix: `matrix[:3, 3]`."""

def rotation_matrix(angle: Radians, direction: VectorArray, point: PointArray | None = ...) -> TransformMatrix:
    """Source: trimesh/transformations.py (trimesh 5.2.0), rotation_matrix: "Angles are in radians unless specified otherwise"
    (the module docstring); a 4x4 rotation about the axis through `point`."""

def rotation_from_matrix(matrix: TransformMatrix) -> tuple[Radians, VectorArray, PointArray]:
    """Source: trimesh/transformations.py (trimesh 5.2.0), rotation_from_matrix: returns angle (an arctangent, radians), direction,
    point."""

def euler_matrix(ai: Radians, aj: Radians, ak: Radians, axes: str = ...) -> TransformMatrix:
    """Source: trimesh/transformations.py (trimesh 5.2.0), euler_matrix: "ai, aj, ak : Euler's roll, pitch and yaw angles",
    radians (their sines and cosines), a 4x4 homogeneous rotation."""

def euler_from_matrix(matrix: object, axes: str = ...) -> tuple[Radians, Radians, Radians]:
    """Source: trimesh/transformations.py (trimesh 5.2.0), euler_from_matrix: reads the rotation part of a 3x3 or 4x4
    matrix; each angle is an arctangent (radians)."""

def euler_from_quaternion(quaternion: QuaternionWXYZ, axes: str = ...) -> tuple[Radians, Radians, Radians]:
    """Source: trimesh/transformations.py (trimesh 5.2.0), euler_from_quaternion: `euler_from_matrix(quaternion_matrix(quaternion), axes)`."""

def quaternion_from_euler(ai: Radians, aj: Radians, ak: Radians, axes: str = ...) -> QuaternionWXYZ:
    """Source: trimesh/transformations.py (trimesh 5.2.0), quaternion_from_euler: radians (cosines of the half angles); "Quaternions ... are
    represented as [w, x, y, z]" (the module docstring)."""

def quaternion_about_axis(angle: Radians, axis: VectorArray) -> QuaternionWXYZ:
    """Source: trimesh/transformations.py (trimesh 5.2.0), quaternion_about_axis: the cosine of half the angle (radians) is
    the scalar, in (w, x, y, z) order."""

def quaternion_matrix(quaternion: QuaternionWXYZ) -> TransformMatrix:
    """Source: trimesh/transformations.py (trimesh 5.2.0), quaternion_matrix: a 4x4 homogeneous rotation from a (w, x, y, z) quaternion."""

def quaternion_from_matrix(matrix: object, isprecise: bool = ...) -> QuaternionWXYZ:
    """Source: trimesh/transformations.py (trimesh 5.2.0), quaternion_from_matrix(matrix, isprecise=False): returns (w, x, y, z)."""

def quaternion_multiply(quaternion1: QuaternionWXYZ, quaternion0: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: trimesh/transformations.py (trimesh 5.2.0), quaternion_multiply(quaternion1, quaternion0): unpacks each as
    (w, x, y, z)."""

def quaternion_conjugate(quaternion: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: trimesh/transformations.py (trimesh 5.2.0), quaternion_conjugate: negates the three vector components of a (w, x, y, z) quaternion."""

def quaternion_inverse(quaternion: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: trimesh/transformations.py (trimesh 5.2.0), quaternion_inverse: the conjugate over the squared norm."""

def quaternion_real(quaternion: QuaternionWXYZ) -> float:
    """Source: trimesh/transformations.py (trimesh 5.2.0), quaternion_real: the scalar, `quaternion[0]`."""

def quaternion_imag(quaternion: QuaternionWXYZ) -> VectorArray:
    """Source: trimesh/transformations.py (trimesh 5.2.0), quaternion_imag: the vector part, `quaternion[1:4]`."""

def quaternion_slerp(quat0: QuaternionWXYZ, quat1: QuaternionWXYZ, fraction: float, spin: int = ..., shortestpath: bool = ...) -> QuaternionWXYZ:
    """Source: trimesh/transformations.py (trimesh 5.2.0), quaternion_slerp(quat0, quat1, fraction, spin=0, shortestpath=True):
    interpolates the four components as given, so the result is in their order."""

def random_quaternion(rand: object = ..., num: int = ..., seed: object = ...) -> QuaternionWXYZ:
    """Source: trimesh/transformations.py (trimesh 5.2.0), random_quaternion(rand=None, num=1, seed=None): (w, x, y, z)."""

def random_rotation_matrix(rand: object = ...) -> TransformMatrix:
    """Source: trimesh/transformations.py (trimesh 5.2.0), random_rotation_matrix: `quaternion_matrix(random_quaternion(rand))`."""

@overload
def transform_points(points: PointArray[Src], matrix: TransformMatrix[Dst, Src], translate: Literal[True] = ...) -> PointArray[Dst]: ...
@overload
def transform_points(points: VectorArray[Src], matrix: TransformMatrix[Dst, Src], translate: Literal[False]) -> VectorArray[Dst]:
    """Source: trimesh/transformations.py (trimesh 5.2.0), transform_points(points, matrix, translate=True): "translate : bool
    If True points will be translated, if False only the rotation is applied"; with a translation of
    (1, 0, 0), (0, 0, 1) becomes (1, 0, 1), and (0, 0, 1) with translate=False (checked numerically)."""
