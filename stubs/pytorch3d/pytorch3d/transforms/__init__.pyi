from pytorch3d.transforms.rotation_conversions import (
    axis_angle_to_matrix as axis_angle_to_matrix,
    axis_angle_to_quaternion as axis_angle_to_quaternion,
    euler_angles_to_matrix as euler_angles_to_matrix,
    matrix_to_euler_angles as matrix_to_euler_angles,
    matrix_to_quaternion as matrix_to_quaternion,
    quaternion_apply as quaternion_apply,
    quaternion_invert as quaternion_invert,
    quaternion_multiply as quaternion_multiply,
    quaternion_raw_multiply as quaternion_raw_multiply,
    quaternion_to_axis_angle as quaternion_to_axis_angle,
    quaternion_to_matrix as quaternion_to_matrix,
    random_quaternions as random_quaternions,
    standardize_quaternion as standardize_quaternion,
)
from pytorch3d.transforms.transform3d import Transform3d as Transform3d
