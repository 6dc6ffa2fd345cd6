from typing import Annotated, Literal

from geolint.knowledge.markers import CameraAxes
from geolint.typing import TransformMatrix
from av2.geometry.se3 import SE3

class PinholeCamera:
    """Source: av2/geometry/camera/pinhole_camera.py (0.3.6), PinholeCamera(ego_SE3_cam, intrinsics, cam_name): "ego_SE3_cam:
    pose of camera in the egovehicle frame (inverse of extrinsics matrix)"; extrinsics: "Return the camera extrinsics",
    `self.ego_SE3_cam.inverse().transform_matrix` (egovehicle to camera); cull_to_view_frustum keeps points with
    `points_cam[:, 2] > 0` and uv = K p with K = [[fx, 0, cx], [0, fy, cy], [0, 0, 1]] in image rows and columns:
    OpenCV camera axes (x right, y down, z forward)."""

    ego_SE3_cam: SE3
    def __init__(self, ego_SE3_cam: SE3, intrinsics: object, cam_name: str) -> None: ...
    @property
    def extrinsics(self) -> Annotated[TransformMatrix[Literal["camera"], Literal["egovehicle"]], CameraAxes.OPENCV]: ...
