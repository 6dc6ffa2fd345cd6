"""genesis.utils.geom: quaternions are (qw, qx, qy, qz) ("last dimension gathers the 4 quaternion coordinates
(qw, qx, qy, qz)", `_np_quat_to_R`'s docstring, line 589); Euler angles in radians unless `degrees=True`.
"""

from typing import Literal, overload

from geolint.typing import Degrees, QuaternionWXYZ, Radians, RotationMatrix, RotationVector, TransformMatrix, VectorArray

@overload
def xyz_to_quat(xyz: Radians, rpy: bool = ..., degrees: Literal[False] = ...) -> QuaternionWXYZ: ...
@overload
def xyz_to_quat(xyz: Degrees, rpy: bool = ..., *, degrees: Literal[True]) -> QuaternionWXYZ: ...
@overload
def xyz_to_quat(xyz: Degrees, rpy: bool, degrees: Literal[True]) -> QuaternionWXYZ:
    """Source: genesis/utils/geom.py (0.4.5, 7bf5f6a), xyz_to_quat(xyz, rpy=False, degrees=False), line 572: `if degrees:
    xyz = np.deg2rad(xyz)` (574-579); returns (w, x, y, z)."""

@overload
def quat_to_xyz(quat: QuaternionWXYZ, rpy: bool = ..., degrees: Literal[False] = ...) -> Radians: ...
@overload
def quat_to_xyz(quat: QuaternionWXYZ, rpy: bool = ..., *, degrees: Literal[True]) -> Degrees: ...
@overload
def quat_to_xyz(quat: QuaternionWXYZ, rpy: bool, degrees: Literal[True]) -> Degrees:
    """Source: genesis/utils/geom.py (0.4.5), quat_to_xyz(quat, rpy=False, degrees=False), line 767: radians, `np.rad2deg`
    when `degrees=True` (770-775)."""

def euler_to_quat(euler_xyz: Degrees) -> QuaternionWXYZ:
    """Source: genesis/utils/geom.py (0.4.5), euler_to_quat, line 1701: `return xyz_to_quat(np.asarray(euler_xyz), rpy=True,
    degrees=True)`."""

def euler_to_R(euler_xyz: Degrees) -> RotationMatrix:
    """Source: genesis/utils/geom.py (0.4.5), euler_to_R, line 1737: `return _np_euler_to_R(np.deg2rad(euler_xyz))`."""

def quat_to_R(quat: QuaternionWXYZ) -> RotationMatrix:
    """Source: genesis/utils/geom.py (0.4.5), quat_to_R, line 652; `q_w, q_x, q_y, q_z = quat[..., 0], quat[..., 1], ...` (601)."""

def R_to_quat(R: RotationMatrix) -> QuaternionWXYZ:
    """Source: genesis/utils/geom.py (0.4.5), R_to_quat, line 871: `torch.stack([0.25 * s, (r32 - r23) / s, ...])`, w first (856)."""

def trans_quat_to_T(trans: VectorArray | None = ..., quat: QuaternionWXYZ | None = ...) -> TransformMatrix:
    """Source: genesis/utils/geom.py (0.4.5), trans_quat_to_T, line 925: `quat_to_R(quat, out=T[..., :3, :3])`."""

def T_to_quat(T: TransformMatrix) -> QuaternionWXYZ:
    """Source: genesis/utils/geom.py (0.4.5), T_to_quat, line 959: `return R_to_quat(T[..., :3, :3])`."""

def inv_quat(quat: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: genesis/utils/geom.py (0.4.5), inv_quat, line 432: the conjugate, `_quat[..., 1:] *= -1`."""

def transform_by_quat(v: VectorArray, quat: QuaternionWXYZ) -> VectorArray:
    """Source: genesis/utils/geom.py (0.4.5), transform_by_quat(v, quat), line 1081: rotates v by a (w, x, y, z) quaternion
    (`q_w, q_x, q_y, q_z = quat[..., :1], ...`, 1061)."""

def transform_quat_by_quat(v: QuaternionWXYZ, u: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: genesis/utils/geom.py (0.4.5), transform_quat_by_quat(v, u), line 1017: "equivalent to quatmul(quat_u, quat_v)
    or R_u @ R_v"."""

def axis_angle_to_quat(angle: Radians, axis: VectorArray) -> QuaternionWXYZ:
    """Source: genesis/utils/geom.py (0.4.5), axis_angle_to_quat(angle, axis), line 1097: `theta = (0.5 * angle)`,
    `np.concatenate([w, xyz], axis=-1)`."""

def quat_to_rotvec(quat: QuaternionWXYZ) -> RotationVector:
    """Source: genesis/utils/geom.py (0.4.5), quat_to_rotvec, line 1742: "quaternions (qw, qx, qy, qz)"."""

def rotvec_to_quat(rotvec: RotationVector) -> QuaternionWXYZ:
    """Source: genesis/utils/geom.py (0.4.5), rotvec_to_quat, line 1773: "the quaternion representation (qw, qx, qy, qz)"."""

def slerp(q0: QuaternionWXYZ, q1: QuaternionWXYZ, t: object) -> QuaternionWXYZ:
    """Source: genesis/utils/geom.py (0.4.5), slerp(q0, q1, t), line 1528: "The start quaternion (w, x, y, z)"."""
