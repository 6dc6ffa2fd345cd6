from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ, Radians, RotationMatrix
from typing_extensions import Annotated

_Quaternions = Annotated[QuaternionWXYZ, STACKED]

def quat_to_mat(quat_wxyz: _Quaternions) -> RotationMatrix:
    """Source: av2/geometry/geometry.py (0.3.6), quat_to_mat: "NOTE: SciPy uses the scalar last quaternion notation.
    Throughout this repository, we use the scalar FIRST convention.", "quat_wxyz: (...,4) array of quaternions in scalar
    first order"; it reorders them for scipy: `quat_xyzw = quat_wxyz[..., [1, 2, 3, 0]]`, then
    `Rotation.from_quat(quat_xyzw).as_matrix()`. Checked numerically (tests/knowledge/test_image_and_scene_facts.py)."""

def mat_to_quat(mat: RotationMatrix) -> _Quaternions:
    """Source: av2/geometry/geometry.py (0.3.6), mat_to_quat: "Convert a 3D rotation matrix to a scalar _first_
    quaternion", `quat_wxyz = quat_xyzw[..., [3, 0, 1, 2]]` of scipy's `as_quat()`."""

def mat_to_xyz(mat: RotationMatrix) -> Radians:
    """Source: av2/geometry/geometry.py (0.3.6), mat_to_xyz: "(...,3) Tait-Bryan angles (in radians) formulated for a
    sequence of extrinsic rotations", `Rotation.from_matrix(mat).as_euler("xyz", degrees=False)`."""

def xyz_to_mat(xyz_rad: Radians) -> RotationMatrix:
    """Source: av2/geometry/geometry.py (0.3.6), xyz_to_mat: "xyz_rad: (...,3) Tait-Bryan angles (in radians) of
    extrinsic rotations", `Rotation.from_euler("xyz", xyz_rad, degrees=False).as_matrix()`."""

def wrap_angles(angles: Radians, period: float = ...) -> Radians:
    """Source: av2/geometry/geometry.py (0.3.6), wrap_angles: "Map angles (in radians) from domain [-inf, inf] to [0,
    pi)", "Angles (in radians) mapped to the interval [0, pi)"."""
