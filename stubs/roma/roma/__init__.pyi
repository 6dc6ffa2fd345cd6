from typing import Literal, overload

from geolint.knowledge.markers import STACKED
from geolint.typing import Degrees, QuaternionWXYZ, QuaternionXYZW, Radians, RotationMatrix, RotationVector, VectorArray
from typing_extensions import Annotated

# RoMa 1.8.0: every quaternion argument and result is "(...x4 tensor, XYZW convention)" (roma/mappings.py,
# roma/utils.py docstrings): a batch (..., 4) is accepted everywhere.
_Q = Annotated[QuaternionXYZW, STACKED]

def unitquat_to_rotmat(quat: _Q) -> RotationMatrix:
    """Source: roma/mappings.py (1.8.0), unitquat_to_rotmat: "quat (...x4 tensor, XYZW convention)"."""

def unitquat_to_rotvec(quat: _Q, shortest_arc: bool = ...) -> RotationVector:
    """Source: roma/mappings.py (1.8.0), unitquat_to_rotvec: "quat (...x4 tensor, XYZW convention)"."""

def rotmat_to_unitquat(R: RotationMatrix) -> _Q:
    """Source: roma/mappings.py (1.8.0), rotmat_to_unitquat: "batch of unit quaternions (...x4 tensor,
    XYZW convention)"."""

def rotvec_to_unitquat(rotvec: RotationVector) -> _Q:
    """Source: roma/mappings.py (1.8.0), rotvec_to_unitquat: "batch of unit quaternions (...x4 tensor,
    XYZW convention)"."""

def quat_xyzw_to_wxyz(xyzw: _Q) -> Annotated[QuaternionWXYZ, STACKED]:
    """Source: roma/mappings.py (1.8.0), quat_xyzw_to_wxyz: "Convert quaternion from XYZW to WXYZ convention"."""

def quat_wxyz_to_xyzw(wxyz: Annotated[QuaternionWXYZ, STACKED]) -> _Q:
    """Source: roma/mappings.py (1.8.0), quat_wxyz_to_xyzw: "Convert quaternion from WXYZ to XYZW convention"."""

def quat_product(p: _Q, q: _Q) -> _Q:
    """Source: roma/utils.py (1.8.0), quat_product: "p, q (...x4 tensor, XYZW convention)"."""

def quat_action(q: _Q, v: VectorArray, is_normalized: bool = ...) -> VectorArray:
    """Source: roma/utils.py (1.8.0), quat_action: "Rotate a 3D vector v=(x,y,z) by a rotation represented by
    a quaternion q" (a rotation only)."""

def quat_conjugation(quat: _Q) -> _Q:
    """Source: roma/utils.py (1.8.0), quat_conjugation: "quat (...x4 tensor, XYZW convention)"."""

def quat_inverse(quat: _Q) -> _Q:
    """Source: roma/utils.py (1.8.0), quat_inverse: "quat (...x4 tensor, XYZW convention)"."""

def quat_normalize(quat: _Q) -> _Q:
    """Source: roma/utils.py (1.8.0), quat_normalize."""

def unitquat_slerp(q0: _Q, q1: _Q, steps: object, shortest_arc: bool = ...) -> _Q:
    """Source: roma/utils.py (1.8.0), unitquat_slerp: XYZW, like every quaternion of roma/utils.py."""

def random_unitquat(size: object = ..., dtype: object = ..., device: object = ..., generator: object = ...) -> _Q:
    """Source: roma/utils.py (1.8.0), random_unitquat: XYZW, like every quaternion of roma/utils.py."""

@overload
def euler_to_unitquat(convention: str, angles: Radians, degrees: Literal[False] = ..., normalize: bool = ..., dtype: object = ..., device: object = ...) -> _Q: ...
@overload
def euler_to_unitquat(convention: str, angles: Degrees, degrees: Literal[True], normalize: bool = ..., dtype: object = ..., device: object = ...) -> _Q:
    """Source: roma/euler.py (1.8.0), euler_to_unitquat: "degrees (bool): if True, input angles are assumed to
    be expressed in degrees"; returns XYZW."""
@overload
def euler_to_rotmat(convention: str, angles: Radians, degrees: Literal[False] = ..., dtype: object = ..., device: object = ...) -> RotationMatrix: ...
@overload
def euler_to_rotmat(convention: str, angles: Degrees, degrees: Literal[True], dtype: object = ..., device: object = ...) -> RotationMatrix:
    """Source: roma/euler.py (1.8.0), euler_to_rotmat: degrees as euler_to_unitquat."""
@overload
def unitquat_to_euler(convention: str, quat: _Q, as_tuple: bool = ..., degrees: Literal[False] = ..., epsilon: float = ...) -> Radians: ...
@overload
def unitquat_to_euler(convention: str, quat: _Q, as_tuple: bool = ..., *, degrees: Literal[True], epsilon: float = ...) -> Degrees:
    """Source: roma/euler.py (1.8.0), unitquat_to_euler(convention, quat, as_tuple=False, degrees=False): the
    quaternion is the second argument, XYZW."""
@overload
def rotmat_to_euler(convention: str, rotmat: RotationMatrix, as_tuple: bool = ..., degrees: Literal[False] = ..., epsilon: float = ...) -> Radians: ...
@overload
def rotmat_to_euler(convention: str, rotmat: RotationMatrix, as_tuple: bool = ..., *, degrees: Literal[True], epsilon: float = ...) -> Degrees:
    """Source: roma/euler.py (1.8.0), rotmat_to_euler: degrees as unitquat_to_euler."""
