from geolint.typing import QuaternionWXYZ, Radians, RotationMatrix, RotationVector, VectorArray

class quaternion:
    """The quaternion scalar type: quaternion(w, x, y, z).

    Source: quaternion/__init__.py and src/numpy_quaternion.c (2024.0.13): the constructor takes
    w, x, y, z; `components` is [w, x, y, z].
    """

    def __init__(self, w: float, x: float, y: float, z: float) -> None: ...
    @property
    def components(self) -> QuaternionWXYZ: ...

def from_float_array(a: QuaternionWXYZ) -> quaternion:
    """Source: quaternion/__init__.py (2024.0.13): `from_float_array(a)` returns `as_quat_array(a)`,
    which reads each four components "in that order: `w`, `x`, `y`, `z`"."""

def as_quat_array(a: QuaternionWXYZ) -> quaternion:
    """Source: quaternion/__init__.py (2024.0.13), as_quat_array's docstring: "`w`, `x`, `y`, `z`"."""

def as_float_array(a: quaternion) -> QuaternionWXYZ:
    """Source: quaternion/__init__.py (2024.0.13), as_float_array: the last dimension holds "the scalar
    and vector components" in that order."""

def from_rotation_matrix(rot: RotationMatrix, nonorthogonal: bool = ...) -> quaternion:
    """Source: quaternion/__init__.py (2024.0.13), from_rotation_matrix."""

def as_rotation_matrix(q: quaternion) -> RotationMatrix:
    """Source: quaternion/__init__.py (2024.0.13), as_rotation_matrix."""

def from_rotation_vector(rot: RotationVector) -> quaternion:
    """Source: quaternion/__init__.py (2024.0.13), from_rotation_vector: axis times angle in radians."""

def as_rotation_vector(q: quaternion) -> RotationVector:
    """Source: quaternion/__init__.py (2024.0.13), as_rotation_vector."""

def from_euler_angles(alpha_beta_gamma: Radians, beta: Radians | None = ..., gamma: Radians | None = ...) -> quaternion:
    """Source: quaternion/__init__.py (2024.0.13), from_euler_angles: z-y-z Euler angles, "The angles
    naturally must be in radians"."""

def as_euler_angles(q: quaternion) -> Radians:
    """Source: quaternion/__init__.py (2024.0.13), as_euler_angles: radians."""

def rotate_vectors(R: quaternion, v: VectorArray, axis: int = ...) -> VectorArray:
    """Source: quaternion/__init__.py (2024.0.13), rotate_vectors: rotates vectors (no translation)."""
