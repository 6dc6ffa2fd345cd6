from typing import Annotated, Literal

from geolint.knowledge.markers import CameraAxes
from geolint.typing import TransformMatrix

# TSDF volumes take the camera's extrinsic (world-to-camera) for each frame they integrate, in OpenCV camera axes:
# cpp/open3d/pipelines/integration/UniformTSDFVolume.cpp (commit 0c9bef0) keeps voxels with `pt_camera(2) > 0` (z
# forward) and projects them to `u = x * fx / z + cx`, `v = y * fy / z + cy` (y down, the image's rows).
_Extrinsic = Annotated[TransformMatrix[Literal["camera"], Literal["world"]], CameraAxes.OPENCV]

class UniformTSDFVolume:
    """Source: open3d.pipelines.integration.UniformTSDFVolume (0.20.0 docs), integrate(image, intrinsic, extrinsic): "Function
    to integrate an RGB-D image into the volume"; the Open3D tutorial (pipelines/rgbd_integration) passes
    `np.linalg.inv(camera_poses[i].pose)`, the inverse of a camera-to-world pose."""

    def integrate(self, image: object, intrinsic: object, extrinsic: _Extrinsic) -> None: ...

class ScalableTSDFVolume:
    """Source: open3d.pipelines.integration.ScalableTSDFVolume (0.20.0 docs), integrate(image, intrinsic, extrinsic), as for
    UniformTSDFVolume."""

    def integrate(self, image: object, intrinsic: object, extrinsic: _Extrinsic) -> None: ...
