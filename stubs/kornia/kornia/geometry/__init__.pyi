# `from .conversions import *` in kornia/geometry/__init__.py (0.5 to 0.9)
from kornia.geometry.conversions import (
    angle_axis_to_quaternion as angle_axis_to_quaternion,
    axis_angle_to_quaternion as axis_angle_to_quaternion,
    quaternion_to_angle_axis as quaternion_to_angle_axis,
    quaternion_to_axis_angle as quaternion_to_axis_angle,
    quaternion_to_rotation_matrix as quaternion_to_rotation_matrix,
    rotation_matrix_to_quaternion as rotation_matrix_to_quaternion,
)
