from geolint.typing import QuaternionWXYZ, Radians, RotationMatrix, RotationVector

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
