"""Open3D's facts in stubs/, checked against the library where it installs (skipped where it does not:
its wheel is large and needs libusb)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.knowledge.facts_helpers import QUARTER_TURN_Z, _quarter_turn, _stated

geometry = pytest.importorskip("open3d.geometry")
open3d = pytest.importorskip("open3d")


class TestOpen3d:
    geometry = geometry

    def test_quaternion_and_euler_matrices(self) -> None:
        order = _stated("open3d.geometry.get_rotation_matrix_from_quaternion", "get_rotation_matrix_from_quaternion(q)", "rotation")
        assert np.allclose(self.geometry.get_rotation_matrix_from_quaternion(np.array(_quarter_turn(order))), QUARTER_TURN_Z)
        unit = _stated("open3d.geometry.get_rotation_matrix_from_xyz", "get_rotation_matrix_from_xyz(r)", "rotation", "angle_unit")
        assert unit == "radians"
        assert np.allclose(self.geometry.get_rotation_matrix_from_xyz(np.array([0.0, 0.0, math.pi / 2])), QUARTER_TURN_Z)


    def test_extrinsics_are_world_to_camera_in_opencv_axes(self) -> None:
        """A depth image's pixel right of and above the principal point becomes a camera point with x > 0,
        y < 0 and z = depth > 0 (x right, y down, z forward), and the extrinsic is inverted to place it."""
        call = "create_from_depth_image(depth, intrinsic, extrinsic)"
        assert _stated("open3d.geometry.PointCloud.create_from_depth_image", call, "extrinsic", "camera_axes") == "opencv"
        assert _stated("open3d.geometry.PointCloud.create_from_depth_image", call, "extrinsic", "frames") == ("camera", "world")
        width, height, depth_m = 8, 6, 2.0
        pixels = np.zeros((height, width), dtype=np.float32)
        pixels[0, width - 1] = depth_m  # top-right pixel
        intrinsic = open3d.camera.PinholeCameraIntrinsic(width, height, 10.0, 10.0, 3.5, 2.5)
        image = open3d.geometry.Image(pixels)
        cloud = self.geometry.PointCloud.create_from_depth_image(image, intrinsic, depth_scale=1.0)
        x, y, z = np.asarray(cloud.points)[0]
        assert x > 0 and y < 0 and math.isclose(z, depth_m)
        world_to_camera = np.eye(4)
        world_to_camera[:3, 3] = [0.0, 0.0, 5.0]  # the camera 5 m along the world's -z
        moved = self.geometry.PointCloud.create_from_depth_image(image, intrinsic, world_to_camera, depth_scale=1.0)
        assert np.allclose(np.asarray(moved.points)[0], [x, y, z - 5.0])

    def test_tsdf_integration_takes_the_world_to_camera_extrinsic_in_opencv_axes(self) -> None:
        call = "integrate(image, intrinsic, extrinsic)"
        for volume in ("UniformTSDFVolume", "ScalableTSDFVolume"):
            qualified = f"open3d.pipelines.integration.{volume}.integrate"
            assert _stated(qualified, call, "extrinsic", "camera_axes") == "opencv"
            assert _stated(qualified, call, "extrinsic", "frames") == ("camera", "world")
