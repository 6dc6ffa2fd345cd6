from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ, QuaternionXYZW, Radians, RotationMatrix
from typing_extensions import Annotated

def quat2rotmat(q: QuaternionWXYZ) -> RotationMatrix:
    """Source: argoverse/utils/transform.py (argoverse-api 1.1.0, commit f886ac5), quat2rotmat: "Note that libraries such as
    Scipy expect a quaternion in scalar-last [x, y, z, w] format, whereas at Argo we work with scalar-first [w, x, y, z]
    format", "q: Array of shape (4,) representing (w, x, y, z) coordinates"; it calls `quat_argo2scipy(q)`, then
    `Rotation.from_quat(quat_xyzw).as_matrix()`. Checked numerically, where argoverse imports
    (tests/knowledge/test_image_and_scene_facts.py)."""

def rotmat2quat(R: RotationMatrix) -> QuaternionWXYZ:
    """Source: argoverse/utils/transform.py (commit f886ac5), rotmat2quat: "Convert a rotation-matrix to a quaternion in
    Argo's scalar-first notation (w, x, y, z)"."""

def yaw_to_quaternion3d(yaw: Radians) -> QuaternionWXYZ:
    """Source: argoverse/utils/transform.py (commit f886ac5), yaw_to_quaternion3d: "yaw: angle to rotate about the z-axis,
    representing an Euler angle, in radians", "array w/ quaternion coefficients (qw,qx,qy,qz) in scalar-first order, per
    Argoverse convention"."""

def quat_argo2scipy(q: QuaternionWXYZ) -> QuaternionXYZW:
    """Source: argoverse/utils/transform.py (commit f886ac5), quat_argo2scipy: "Re-order Argoverse's scalar-first [w,x,y,z]
    quaternion order to Scipy's scalar-last [x,y,z,w]"."""

def quat_scipy2argo(q: QuaternionXYZW) -> QuaternionWXYZ:
    """Source: argoverse/utils/transform.py (commit f886ac5), quat_scipy2argo: "Re-order Scipy's scalar-last [x,y,z,w]
    quaternion order to Argoverse's scalar-first [w,x,y,z]"."""

def quat_argo2scipy_vectorized(q: Annotated[QuaternionWXYZ, STACKED]) -> Annotated[QuaternionXYZW, STACKED]:
    """Source: argoverse/utils/transform.py (commit f886ac5), quat_argo2scipy_vectorized: `q[..., [1, 2, 3, 0]]`."""

def quat_scipy2argo_vectorized(q: Annotated[QuaternionXYZW, STACKED]) -> Annotated[QuaternionWXYZ, STACKED]:
    """Source: argoverse/utils/transform.py (commit f886ac5), quat_scipy2argo_vectorized: `q[..., [3, 0, 1, 2]]`."""
