from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ, QuaternionXYZW
from typing_extensions import Annotated

# omni.isaac.core/omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1): `quat_mul` unpacks `w1, x1, y1, z1`,
# `euler_angles_to_quats` returns "scalar first", `xyzw2wxyz` is `torch.roll(q, 1, -1)`.
# Only the quaternion each function reads first (its first argument) and the one it returns are stated.
_WXYZ = Annotated[QuaternionWXYZ, STACKED]
_XYZW = Annotated[QuaternionXYZW, STACKED]

def euler_angles_to_quats(*args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), euler_angles_to_quats."""

def get_basis_vector(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), get_basis_vector."""

def get_euler_xyz(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), get_euler_xyz."""

def gf_quat_to_tensor(*args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), gf_quat_to_tensor."""

def quat_apply(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), quat_apply."""

def quat_axis(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), quat_axis."""

def quat_conjugate(q: _WXYZ, *args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), quat_conjugate."""

def quat_diff_rad(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), quat_diff_rad."""

def quat_from_angle_axis(*args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), quat_from_angle_axis."""

def quat_from_euler_xyz(*args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), quat_from_euler_xyz."""

def quat_mul(q: _WXYZ, *args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), quat_mul."""

def quat_rotate(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), quat_rotate."""

def quat_rotate_inverse(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), quat_rotate_inverse."""

def quat_unit(q: _WXYZ, *args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), quat_unit."""

def quats_to_rot_matrices(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), quats_to_rot_matrices."""

def rot_matrices_to_quats(*args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), rot_matrices_to_quats."""

def wxyz2xyzw(q: _WXYZ, *args: object, **kwargs: object) -> _XYZW:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), wxyz2xyzw."""

def xyzw2wxyz(q: _XYZW, *args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/core/utils/torch/rotations.py (Isaac Sim 4.1), xyzw2wxyz."""
