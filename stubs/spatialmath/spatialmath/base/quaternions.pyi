from typing import Literal, overload

from geolint.typing import QuaternionWXYZ, QuaternionXYZW, RotationMatrix, VectorArray

# spatialmath.base.quaternions (1.1.18): "a quaternion is represented by a 4-element NumPy array ...
# the scalar part first", (s, vx, vy, vz); `order="xyzs"` selects scalar last where a function has it.

@overload
def q2r(q: QuaternionWXYZ, order: Literal["sxyz"] = ...) -> RotationMatrix: ...
@overload
def q2r(q: QuaternionXYZW, order: Literal["xyzs"]) -> RotationMatrix:
    """Source: spatialmath/base/quaternions.py (1.1.18), q2r: "order: the order of the quaternion elements. Must be 'sxyz' or 'xyzs'.
    Defaults to 'sxyz'"."""
@overload
def r2q(R: RotationMatrix, check: bool = ..., tol: float = ..., order: Literal["sxyz"] = ..., shortest: bool = ...) -> QuaternionWXYZ: ...
@overload
def r2q(R: RotationMatrix, check: bool = ..., tol: float = ..., *, order: Literal["xyzs"], shortest: bool = ...) -> QuaternionXYZW:
    """Source: spatialmath/base/quaternions.py (1.1.18), r2q: "order: the order of the returned quaternion elements. Must be 'sxyz' or
    'xyzs'. Defaults to 'sxyz'"."""

def qqmul(q1: QuaternionWXYZ, q2: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: spatialmath/base/quaternions.py (1.1.18), qqmul: the Hamilton product, `s1, v1 = q1[0], q1[1:4]`."""

def qvmul(q: QuaternionWXYZ, v: VectorArray) -> VectorArray:
    """Source: spatialmath/base/quaternions.py (1.1.18), qvmul: "Vector rotation" (a rotation only)."""

def qconj(q: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: spatialmath/base/quaternions.py (1.1.18), qconj: `np.r_[q[0], -q[1:4]]`."""

def qunit(q: QuaternionWXYZ, tol: float = ...) -> QuaternionWXYZ:
    """Source: spatialmath/base/quaternions.py (1.1.18), qunit (scalar part first, made non-negative)."""

def qslerp(q0: QuaternionWXYZ, q1: QuaternionWXYZ, s: float, shortest: bool = ..., tol: float = ...) -> QuaternionWXYZ:
    """Source: spatialmath/base/quaternions.py (1.1.18), qslerp."""

def q2v(q: QuaternionWXYZ) -> VectorArray:
    """Source: spatialmath/base/quaternions.py (1.1.18), q2v: the vector part of a unit quaternion whose scalar part is made non-negative."""

def v2q(v: VectorArray) -> QuaternionWXYZ:
    """Source: spatialmath/base/quaternions.py (1.1.18), v2q: the unit quaternion of a vector part, `np.r_[s, v]`."""
