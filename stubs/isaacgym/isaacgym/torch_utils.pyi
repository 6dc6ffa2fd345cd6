from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionXYZW, Radians, VectorArray
from typing_extensions import Annotated

# isaacgym/python/isaacgym/torch_utils.py (Isaac Gym Preview 4), which tasks import with `from
# isaacgym.torch_utils import *`: `quat_mul` unpacks `x1, y1, z1, w1 = a[:, 0], a[:, 1], a[:, 2], a[:, 3]`,
# `quat_from_euler_xyz` returns `torch.stack([qx, qy, qz, qw], dim=-1)`, `quat_rotate` takes `q_w = q[:, -1]`.
# Every function takes (N, 4) stacks.
_Q = Annotated[QuaternionXYZW, STACKED]

def quat_mul(a: _Q, b: _Q) -> _Q:
    """Source: isaacgym torch_utils.py (Preview 4), quat_mul: `x1, y1, z1, w1 = a[:, 0], ...`, returns
    `torch.stack([x, y, z, w], dim=-1)`."""

def quat_conjugate(a: _Q) -> _Q:
    """Source: isaacgym torch_utils.py (Preview 4), quat_conjugate: `torch.cat((-a[:, :3], a[:, -1:]), dim=-1)`."""

def quat_unit(a: _Q) -> _Q:
    """Source: isaacgym torch_utils.py (Preview 4), quat_unit: `normalize(a)`."""

def quat_apply(a: _Q, b: VectorArray) -> VectorArray:
    """Source: isaacgym torch_utils.py (Preview 4), quat_apply: `xyz = a[:, :3]`, `a[:, 3:]` the scalar part;
    rotates b (no translation)."""

def quat_rotate(q: _Q, v: VectorArray) -> VectorArray:
    """Source: isaacgym torch_utils.py (Preview 4), quat_rotate: `q_w = q[:, -1]`."""

def quat_rotate_inverse(q: _Q, v: VectorArray) -> VectorArray:
    """Source: isaacgym torch_utils.py (Preview 4), quat_rotate_inverse: `q_w = q[:, -1]`."""

def quat_from_angle_axis(angle: Radians, axis: VectorArray) -> _Q:
    """Source: isaacgym torch_utils.py (Preview 4), quat_from_angle_axis: `theta = (angle / 2)`,
    `theta.sin()`, returns `torch.cat([xyz, w], dim=-1)`."""

def quat_from_euler_xyz(roll: Radians, pitch: Radians, yaw: Radians) -> _Q:
    """Source: isaacgym torch_utils.py (Preview 4), quat_from_euler_xyz: `torch.cos(yaw * 0.5)`..., returns
    `torch.stack([qx, qy, qz, qw], dim=-1)`."""

def get_euler_xyz(q: _Q) -> tuple[Radians, Radians, Radians]:
    """Source: isaacgym torch_utils.py (Preview 4), get_euler_xyz: `qx, qy, qz, qw = 0, 1, 2, 3`; returns
    roll, pitch and yaw from `torch.atan2`, each `% (2 * np.pi)`."""

def get_basis_vector(q: _Q, v: VectorArray) -> VectorArray:
    """Source: isaacgym torch_utils.py (Preview 4), get_basis_vector: `quat_rotate(q, v)`."""

def tf_inverse(q: _Q, t: VectorArray) -> tuple[_Q, VectorArray]:
    """Source: isaacgym torch_utils.py (Preview 4), tf_inverse: `q_inv, -quat_apply(q_inv, t)`."""

def tf_apply(q: _Q, t: VectorArray, v: object) -> object:
    """Source: isaacgym torch_utils.py (Preview 4), tf_apply: `quat_apply(q, v) + t` (v is a point)."""

def tf_vector(q: _Q, v: VectorArray) -> VectorArray:
    """Source: isaacgym torch_utils.py (Preview 4), tf_vector: `quat_apply(q, v)`."""

def tf_combine(q1: _Q, t1: VectorArray, q2: _Q, t2: VectorArray) -> tuple[_Q, VectorArray]:
    """Source: isaacgym torch_utils.py (Preview 4), tf_combine: `quat_mul(q1, q2), quat_apply(q1, t2) + t1`."""
