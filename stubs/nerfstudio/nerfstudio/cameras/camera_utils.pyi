from typing import Annotated, Literal, overload

from geolint.knowledge.markers import STACKED, CameraAxes
from geolint.typing import QuaternionWXYZ, RotationMatrix, TransformMatrix

def quaternion_from_matrix(matrix: object, isprecise: bool = ...) -> QuaternionWXYZ:
    """Source: nerfstudio 1.1.5 (commit 50e0e3c7), nerfstudio/cameras/camera_utils.py, quaternion_from_matrix (line 50):
    the scalar is component 0 (`q[0] = t`, the trace, when isprecise; `q = V[np.array([3, 0, 1, 2]), ...]`, the
    eigenvector's scalar moved first, otherwise; `if q[0] < 0.0: np.negative(q, q)`, lines 62, 99-101)."""

def quaternion_matrix(quaternion: QuaternionWXYZ) -> TransformMatrix:
    """Source: nerfstudio 1.1.5 (commit 50e0e3c7), nerfstudio/cameras/camera_utils.py, quaternion_matrix (line 141):
    "Return homogeneous rotation matrix from quaternion", a 4x4 whose [0, 0] entry is `1 - q[2, 2] - q[3, 3]` of the
    outer product, so component 0 is the scalar."""

@overload
def auto_orient_and_center_poses(
    poses: Annotated[TransformMatrix[Literal["world"], Literal["camera"]], CameraAxes.OPENGL, STACKED],
    method: Literal["pca", "up", "vertical", "none"] = ...,
    center_method: Literal["poses", "focus"] = ...,
) -> object:
    """Source: nerfstudio 1.1.5 (commit 50e0e3c7), nerfstudio/cameras/camera_utils.py, auto_orient_and_center_poses
    (line 552): reads `origins = poses[..., :3, 3]` as the camera centres and, for method="up", the mean of the
    poses' second columns (camera +Y, up in OpenGL axes) as the up vector to rotate onto +Z, so `poses` are
    (N, 4, 4) camera-to-world in OpenGL axes (docs/quickstart/data_conventions.md: "We use the OpenGL/Blender ...
    coordinate convention for cameras. +X is right, +Y is up, and +Z is pointing back"). It returns "Tuple of the
    oriented poses and the transform matrix", both 3x4 (`transform @ poses`), which the vocabulary's 4x4
    TransformMatrix does not state. The transform's translation is `-R @ translation` of the centre the method
    picks; with center_method="none" that centre is zeros, so the transform is its rotation alone (the second
    overload)."""

@overload
def auto_orient_and_center_poses(
    poses: Annotated[TransformMatrix[Literal["world"], Literal["camera"]], CameraAxes.OPENGL, STACKED],
    method: Literal["pca", "up", "vertical", "none"] = ...,
    *,
    center_method: Literal["none"],
) -> tuple[object, RotationMatrix]: ...
@overload
def auto_orient_and_center_poses(
    poses: Annotated[TransformMatrix[Literal["world"], Literal["camera"]], CameraAxes.OPENGL, STACKED],
    method: Literal["pca", "up", "vertical", "none"],
    center_method: Literal["none"],
) -> tuple[object, RotationMatrix]: ...
