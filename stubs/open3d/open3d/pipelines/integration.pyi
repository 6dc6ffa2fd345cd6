from typing import Literal

from geolint.typing import TransformMatrix

# TSDF volumes take the camera's extrinsic (world-to-camera) for each frame they integrate.

class UniformTSDFVolume:
    """Source: open3d.pipelines.integration.UniformTSDFVolume (0.20.0 docs), integrate(image, intrinsic, extrinsic): "Function
    to integrate an RGB-D image into the volume"; the Open3D tutorial (pipelines/rgbd_integration) passes
    `np.linalg.inv(camera_poses[i].pose)`, the inverse of a camera-to-world pose."""

    def integrate(self, image: object, intrinsic: object, extrinsic: TransformMatrix[Literal["camera"], Literal["world"]]) -> None: ...

class ScalableTSDFVolume:
    """Source: open3d.pipelines.integration.ScalableTSDFVolume (0.20.0 docs), integrate(image, intrinsic, extrinsic), as for
    UniformTSDFVolume."""

    def integrate(self, image: object, intrinsic: object, extrinsic: TransformMatrix[Literal["camera"], Literal["world"]]) -> None: ...
