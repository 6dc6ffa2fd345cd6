from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ, QuaternionXYZW
from typing_extensions import Annotated

# omni.isaac.core/omni/isaac/core/utils/rotations.py (Isaac Sim 4.1): every docstring says "quaternion (w, x, y, z)".
# Only the quaternion each function reads first (its first argument) and the one it returns are stated.
_WXYZ = Annotated[QuaternionWXYZ, STACKED]
_XYZW = Annotated[QuaternionXYZW, STACKED]

def euler_angles_to_quat(*args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/core/utils/rotations.py (Isaac Sim 4.1), euler_angles_to_quat."""

def gf_quat_to_np_array(*args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/core/utils/rotations.py (Isaac Sim 4.1), gf_quat_to_np_array."""

def gf_rotation_to_np_array(*args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/core/utils/rotations.py (Isaac Sim 4.1), gf_rotation_to_np_array."""

def quat_to_euler_angles(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/core/utils/rotations.py (Isaac Sim 4.1), quat_to_euler_angles."""

def quat_to_rot_matrix(q: _WXYZ, *args: object, **kwargs: object) -> object:
    """Source: omni/isaac/core/utils/rotations.py (Isaac Sim 4.1), quat_to_rot_matrix."""

def rot_matrix_to_quat(*args: object, **kwargs: object) -> _WXYZ:
    """Source: omni/isaac/core/utils/rotations.py (Isaac Sim 4.1), rot_matrix_to_quat."""
