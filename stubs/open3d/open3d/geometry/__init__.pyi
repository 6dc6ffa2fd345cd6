from typing import Annotated, Literal, overload

from geolint.knowledge.markers import CameraAxes
from geolint.typing import PointArray, QuaternionWXYZ, Radians, RotationMatrix, RotationVector, TransformMatrix

# open3d.geometry (0.20.0), the module functions (also static methods of every geometry class).

def get_rotation_matrix_from_quaternion(rotation: QuaternionWXYZ) -> RotationMatrix:
    """Source: open3d 0.20.0, open3d.geometry.get_rotation_matrix_from_quaternion.__doc__: "Returns a
    rotation matrix from a quaternion in [w, x, y, z] order"."""

def get_rotation_matrix_from_axis_angle(rotation: RotationVector) -> RotationMatrix:
    """Source: open3d 0.20.0, open3d.geometry.get_rotation_matrix_from_axis_angle.__doc__: "The input is an
    axis-angle vector in radians"."""

def get_rotation_matrix_from_xyz(rotation: Radians) -> RotationMatrix:
    """Source: open3d 0.20.0, open3d.geometry.get_rotation_matrix_from_xyz.__doc__: "The rotation is
    specified in radians"."""

def get_rotation_matrix_from_xzy(rotation: Radians) -> RotationMatrix:
    """Source: open3d 0.20.0, open3d.geometry.get_rotation_matrix_from_xzy.__doc__: "The rotation is
    specified in radians"."""

def get_rotation_matrix_from_yxz(rotation: Radians) -> RotationMatrix:
    """Source: open3d 0.20.0, open3d.geometry.get_rotation_matrix_from_yxz.__doc__: "The rotation is
    specified in radians"."""

def get_rotation_matrix_from_yzx(rotation: Radians) -> RotationMatrix:
    """Source: open3d 0.20.0, open3d.geometry.get_rotation_matrix_from_yzx.__doc__: "The rotation is
    specified in radians"."""

def get_rotation_matrix_from_zxy(rotation: Radians) -> RotationMatrix:
    """Source: open3d 0.20.0, open3d.geometry.get_rotation_matrix_from_zxy.__doc__: "The rotation is
    specified in radians"."""

def get_rotation_matrix_from_zyx(rotation: Radians) -> RotationMatrix:
    """Source: open3d 0.20.0, open3d.geometry.get_rotation_matrix_from_zyx.__doc__: "The rotation is
    specified in radians"."""

# An Open3D extrinsic maps world into camera: the factories invert it to place the camera
# (`Eigen::Matrix4d camera_pose = extrinsic.inverse();`, cpp/open3d/geometry/PointCloudFactory.cpp), in OpenCV camera
# axes: a pixel (u, v) at depth z is the camera point `((u - cx) * z / fx, (v - cy) * z / fy, z)` (the same file,
# commit 00fa180): x right, y down (the image's rows), z forward.
_Extrinsic = Annotated[TransformMatrix[Literal["camera"], Literal["world"]], CameraAxes.OPENCV]

class PointCloud:
    """Source: open3d.geometry.PointCloud (0.20.0 docs), create_from_rgbd_image(image, intrinsic, extrinsic=identity,
    project_valid_depth_only=True) and create_from_depth_image(depth, intrinsic, extrinsic=identity, depth_scale=1000.0,
    depth_trunc=1000.0, stride=1, project_valid_depth_only=True); cpp/open3d/geometry/PointCloudFactory.cpp places the camera
    at `extrinsic.inverse()`: the extrinsic is world-to-camera, and the cloud it returns holds points."""

    @staticmethod
    def create_from_rgbd_image(image: object, intrinsic: object, extrinsic: _Extrinsic = ..., project_valid_depth_only: bool = ...) -> Annotated[PointCloud, PointArray]: ...
    @staticmethod
    def create_from_depth_image(
        depth: object, intrinsic: object, extrinsic: _Extrinsic = ..., depth_scale: float = ...,
        depth_trunc: float = ..., stride: int = ..., project_valid_depth_only: bool = ...,
    ) -> Annotated[PointCloud, PointArray]: ...

class LineSet:
    """Source: open3d.geometry.LineSet (0.20.0 docs), create_camera_visualization(view_width_px, view_height_px, intrinsic,
    extrinsic, scale=1.0) and create_camera_visualization(intrinsic, extrinsic, scale=1.0): "Factory function to create a
    LineSet from intrinsic and extrinsic camera matrices"; the extrinsic is world-to-camera as in the point cloud factories."""

    @overload
    @staticmethod
    def create_camera_visualization(view_width_px: int, view_height_px: int, intrinsic: object, extrinsic: TransformMatrix[Literal["camera"], Literal["world"]], scale: float = ...) -> LineSet: ...
    @overload
    @staticmethod
    def create_camera_visualization(intrinsic: object, extrinsic: TransformMatrix[Literal["camera"], Literal["world"]], scale: float = ...) -> LineSet: ...
