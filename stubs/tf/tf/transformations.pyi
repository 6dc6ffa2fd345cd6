"""ROS 1 tf.transformations: Gohlke's transformations.py of 2009 as tf ships it, with quaternions
(x, y, z, w): "Quaternions ix+jy+kz+w are represented as [x, y, z, w]" (its module docstring).
"""

from geolint.typing import PointArray, QuaternionXYZW, Radians, TransformMatrix, Translation, VectorArray

def identity_matrix() -> TransformMatrix:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), identity_matrix: the 4x4 identity."""

def translation_matrix(direction: Translation) -> TransformMatrix:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), translation_matrix: the homogeneous matrix that translates by `direction`."""

def translation_from_matrix(matrix: TransformMatrix) -> Translation:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), translation_from_matrix: `matrix[:3, 3]`."""

def rotation_matrix(angle: Radians, direction: VectorArray, point: PointArray | None = ...) -> TransformMatrix:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), rotation_matrix: "Angles are in radians unless specified otherwise"
    (the module docstring); a 4x4 rotation about the axis through `point`."""

def rotation_from_matrix(matrix: TransformMatrix) -> tuple[Radians, VectorArray, PointArray]:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), rotation_from_matrix: returns angle (an arctangent, radians), direction,
    point."""

def euler_matrix(ai: Radians, aj: Radians, ak: Radians, axes: str = ...) -> TransformMatrix:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), euler_matrix: "ai, aj, ak : Euler's roll, pitch and yaw angles",
    radians (their sines and cosines), a 4x4 homogeneous rotation."""

def euler_from_matrix(matrix: object, axes: str = ...) -> tuple[Radians, Radians, Radians]:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), euler_from_matrix: reads the rotation part of a 3x3 or 4x4
    matrix; each angle is an arctangent (radians)."""

def euler_from_quaternion(quaternion: QuaternionXYZW, axes: str = ...) -> tuple[Radians, Radians, Radians]:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), euler_from_quaternion: `euler_from_matrix(quaternion_matrix(quaternion), axes)`."""

def quaternion_from_euler(ai: Radians, aj: Radians, ak: Radians, axes: str = ...) -> QuaternionXYZW:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), quaternion_from_euler: radians (cosines of the half angles); "Quaternions ... are
    represented as [x, y, z, w]" (the module docstring)."""

def quaternion_about_axis(angle: Radians, axis: VectorArray) -> QuaternionXYZW:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), quaternion_about_axis: the cosine of half the angle (radians) is
    the scalar, in (x, y, z, w) order."""

def quaternion_matrix(quaternion: QuaternionXYZW) -> TransformMatrix:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), quaternion_matrix: a 4x4 homogeneous rotation from a (x, y, z, w) quaternion."""

def quaternion_from_matrix(matrix: object) -> QuaternionXYZW:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), quaternion_from_matrix(matrix): returns (x, y, z, w)."""

def quaternion_multiply(quaternion1: QuaternionXYZW, quaternion0: QuaternionXYZW) -> QuaternionXYZW:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), quaternion_multiply(quaternion1, quaternion0): unpacks each as
    (x, y, z, w)."""

def quaternion_conjugate(quaternion: QuaternionXYZW) -> QuaternionXYZW:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), quaternion_conjugate: negates the three vector components of a (x, y, z, w) quaternion."""

def quaternion_inverse(quaternion: QuaternionXYZW) -> QuaternionXYZW:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), quaternion_inverse: the conjugate over the squared norm."""

def quaternion_slerp(quat0: QuaternionXYZW, quat1: QuaternionXYZW, fraction: float, spin: int = ..., shortestpath: bool = ...) -> QuaternionXYZW:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), quaternion_slerp(quat0, quat1, fraction, spin=0, shortestpath=True):
    interpolates the four components as given, so the result is in their order."""

def random_quaternion(rand: object = ...) -> QuaternionXYZW:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), random_quaternion(rand=None): (x, y, z, w)."""

def random_rotation_matrix(rand: object = ...) -> TransformMatrix:
    """Source: ros/geometry tf/src/tf/transformations.py (commit f7b74502e6491a4f4c9dcae6241379a6225089b0, Gohlke's version 20090418), random_rotation_matrix: `quaternion_matrix(random_quaternion(rand))`."""
