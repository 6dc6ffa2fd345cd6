# evo/core/transformations.py (evo 1.38.1) is Gohlke's transformations.py, version 2015.07.18: "Quaternions
# w+ix+jy+kz are represented as [w, x, y, z]" (its module docstring), the same API as stubs/transformations.
from transformations.transformations import (
    identity_matrix as identity_matrix,
    translation_matrix as translation_matrix,
    translation_from_matrix as translation_from_matrix,
    rotation_matrix as rotation_matrix,
    rotation_from_matrix as rotation_from_matrix,
    euler_matrix as euler_matrix,
    euler_from_matrix as euler_from_matrix,
    euler_from_quaternion as euler_from_quaternion,
    quaternion_from_euler as quaternion_from_euler,
    quaternion_about_axis as quaternion_about_axis,
    quaternion_matrix as quaternion_matrix,
    quaternion_from_matrix as quaternion_from_matrix,
    quaternion_multiply as quaternion_multiply,
    quaternion_conjugate as quaternion_conjugate,
    quaternion_inverse as quaternion_inverse,
    quaternion_slerp as quaternion_slerp,
    random_quaternion as random_quaternion,
    random_rotation_matrix as random_rotation_matrix,
)
