from geolint.typing import QuaternionWXYZ, Radians, RotationMatrix, VectorArray

def quat2mat(q: QuaternionWXYZ) -> RotationMatrix:
    """Source: transforms3d/quaternions.py (0.4.2), quat2mat: "q : 4 element array-like", w, x, y, z."""

def mat2quat(M: RotationMatrix) -> QuaternionWXYZ:
    """Source: transforms3d/quaternions.py (0.4.2), mat2quat: "q : (4,) array ... w, x, y, z"."""

def qmult(q1: QuaternionWXYZ, q2: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: transforms3d/quaternions.py (0.4.2), qmult: `w1, x1, y1, z1 = q1`."""

def qconjugate(q: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: transforms3d/quaternions.py (0.4.2), qconjugate: `q * np.array([1.0, -1, -1, -1])`."""

def qinverse(q: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: transforms3d/quaternions.py (0.4.2), qinverse: the conjugate over the squared norm."""

def qeye(dtype: object = ...) -> QuaternionWXYZ:
    """Source: transforms3d/quaternions.py (0.4.2), qeye: `np.array([1, 0, 0, 0])`."""

def axangle2quat(vector: VectorArray, theta: Radians, is_normalized: bool = ...) -> QuaternionWXYZ:
    """Source: transforms3d/quaternions.py (0.4.2), axangle2quat: "theta : scalar, angle of rotation"
    (radians), the result w, x, y, z."""

def quat2axangle(quat: QuaternionWXYZ, identity_thresh: float | None = ...) -> tuple[VectorArray, Radians]:
    """Source: transforms3d/quaternions.py (0.4.2), quat2axangle."""

def rotate_vector(v: VectorArray, q: QuaternionWXYZ, is_normalized: bool = ...) -> VectorArray:
    """Source: transforms3d/quaternions.py (0.4.2), rotate_vector: "Apply transformation in quaternion
    `q` to vector `v`" (a rotation only)."""
