from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ, QuaternionXYZW, RotationMatrix
from typing_extensions import Annotated

# pytransform3d.batch_rotations: the stacked forms of pytransform3d.rotations, the same (w, x, y, z) order.

def matrices_from_quaternions(Q: Annotated[QuaternionWXYZ, STACKED], normalize_quaternions: bool = ..., out: object = ...) -> Annotated[RotationMatrix, STACKED]:
    """Source: pytransform3d/batch_rotations/_quaternion.py (3.17.0), matrices_from_quaternions: "Unit
    quaternions to represent rotations: (w, x, y, z)"."""

def quaternions_from_matrices(Rs: Annotated[RotationMatrix, STACKED], out: object = ...) -> Annotated[QuaternionWXYZ, STACKED]:
    """Source: pytransform3d/batch_rotations/_matrix.py (3.17.0), quaternions_from_matrices: returns "Unit
    quaternions to represent rotations: (w, x, y, z)"."""

def axis_angles_from_quaternions(qs: Annotated[QuaternionWXYZ, STACKED]) -> object:
    """Source: pytransform3d/batch_rotations/_quaternion.py (3.17.0), axis_angles_from_quaternions: "Unit
    quaternion to represent rotation: (w, x, y, z)"."""

def batch_concatenate_quaternions(Q1: Annotated[QuaternionWXYZ, STACKED], Q2: Annotated[QuaternionWXYZ, STACKED], out: object = ...) -> Annotated[QuaternionWXYZ, STACKED]:
    """Source: pytransform3d/batch_rotations/_quaternion.py (3.17.0), batch_concatenate_quaternions: both
    "(w, x, y, z)"."""

def batch_quaternion_wxyz_from_xyzw(Q_xyzw: Annotated[QuaternionXYZW, STACKED], out: object = ...) -> Annotated[QuaternionWXYZ, STACKED]:
    """Source: pytransform3d/batch_rotations/_quaternion.py (3.17.0), batch_quaternion_wxyz_from_xyzw:
    "Converts from x, y, z, w to w, x, y, z convention"."""

def batch_quaternion_xyzw_from_wxyz(Q_wxyz: Annotated[QuaternionWXYZ, STACKED], out: object = ...) -> Annotated[QuaternionXYZW, STACKED]:
    """Source: pytransform3d/batch_rotations/_quaternion.py (3.17.0), batch_quaternion_xyzw_from_wxyz:
    "Converts from w, x, y, z to x, y, z, w convention"."""
