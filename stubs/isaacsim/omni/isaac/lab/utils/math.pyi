from typing import Literal, overload

from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ, QuaternionXYZW
from typing_extensions import Annotated

# IsaacLab source/extensions/omni.isaac.lab/omni/isaac/lab/utils/math.py: every docstring says "(w, x, y, z)".
# Only the quaternion each function reads first (its first argument) and the one it returns are stated.
_WXYZ = Annotated[QuaternionWXYZ, STACKED]
_XYZW = Annotated[QuaternionXYZW, STACKED]

def axis_angle_from_quat(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), axis_angle_from_quat."""

def euler_xyz_from_quat(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), euler_xyz_from_quat."""

def matrix_from_quat(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), matrix_from_quat."""

def quat_apply(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), quat_apply."""

def quat_apply_yaw(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), quat_apply_yaw."""

def quat_box_minus(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), quat_box_minus."""

def quat_conjugate(q: _WXYZ, *args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), quat_conjugate."""

def quat_from_angle_axis(*args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), quat_from_angle_axis."""

def quat_from_euler_xyz(*args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), quat_from_euler_xyz."""

def quat_from_matrix(*args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), quat_from_matrix."""

def quat_inv(q: _WXYZ, *args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), quat_inv."""

def quat_mul(q: _WXYZ, *args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), quat_mul."""

def quat_rotate(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), quat_rotate."""

def quat_rotate_inverse(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), quat_rotate_inverse."""

def quat_unique(q: _WXYZ, *args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), quat_unique."""

def yaw_quat(q: _WXYZ, *args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/lab/utils/math.py (IsaacLab, omni.isaac.lab), yaw_quat."""

@overload
def convert_quat(quat: _WXYZ, to: Literal["xyzw"] = ...) -> _XYZW: ...
@overload
def convert_quat(quat: _XYZW, to: Literal["wxyz"]) -> _WXYZ:
    """Source: IsaacLab source/extensions/omni.isaac.lab/omni/isaac/lab/utils/math.py, convert_quat(quat, to="xyzw"): `to`
    names the order it returns and it reads the other, the same in every Isaac Lab version."""
