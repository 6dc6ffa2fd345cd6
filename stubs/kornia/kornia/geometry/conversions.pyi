from typing import overload

from geolint.knowledge.markers import STACKED, versions
from geolint.typing import QuaternionWXYZ, QuaternionXYZW, RotationMatrix, RotationVector
from typing_extensions import Annotated

# kornia/geometry/conversions.py. Up to 0.6.12 each quaternion function takes `order: QuaternionCoeffOrder =
# QuaternionCoeffOrder.XYZW` ("Note: 'xyzw' will be deprecated in favor of 'wxyz'"); from 0.7.0 the
# keyword is gone and "The quaternion should be in (w, x, y, z) format". Below 0.7 only the default is
# stated: a call that passes `order` matches no stated signature, so nothing is said of it.
_WXYZ = Annotated[QuaternionWXYZ, STACKED]
_XYZW = Annotated[QuaternionXYZW, STACKED]

@overload
@versions(">=0.7")
def quaternion_to_rotation_matrix(quaternion: _WXYZ) -> RotationMatrix:
    """Source: kornia/geometry/conversions.py (0.7.0), quaternion_to_rotation_matrix: "The quaternion should
    be in (w, x, y, z) format"; checked numerically (tests/knowledge/test_kornia_facts.py)."""
@overload
@versions("<0.7")
def quaternion_to_rotation_matrix(quaternion: _XYZW) -> RotationMatrix:
    """Source: kornia/geometry/conversions.py (0.5.11, 0.6.12), quaternion_to_rotation_matrix(quaternion,
    order=QuaternionCoeffOrder.XYZW)."""

@overload
@versions(">=0.7")
def rotation_matrix_to_quaternion(rotation_matrix: RotationMatrix, eps: float = ...) -> _WXYZ:
    """Source: kornia/geometry/conversions.py (0.7.0), rotation_matrix_to_quaternion: "The quaternion vector
    has components in (w, x, y, z) format"."""
@overload
@versions("<0.7")
def rotation_matrix_to_quaternion(rotation_matrix: RotationMatrix, eps: float = ...) -> _XYZW:
    """Source: kornia/geometry/conversions.py (0.5.11, 0.6.12), rotation_matrix_to_quaternion(rotation_matrix,
    eps=1.0e-8, order=QuaternionCoeffOrder.XYZW)."""

@versions(">=0.7")
def quaternion_to_axis_angle(quaternion: _WXYZ) -> RotationVector:
    """Source: kornia/geometry/conversions.py (0.7.0), quaternion_to_axis_angle: "Convert quaternion vector to
    axis angle of rotation in radians", (w, x, y, z)."""

@overload
@versions(">=0.7")
def quaternion_to_angle_axis(quaternion: _WXYZ) -> RotationVector:
    """Source: kornia/geometry/conversions.py (0.7.0), quaternion_to_angle_axis: `quaternion_to_axis_angle(quaternion)`."""
@overload
@versions("<0.7")
def quaternion_to_angle_axis(quaternion: _XYZW) -> RotationVector:
    """Source: kornia/geometry/conversions.py (0.5.11, 0.6.12), quaternion_to_angle_axis(quaternion,
    order=QuaternionCoeffOrder.XYZW)."""

@versions(">=0.7")
def axis_angle_to_quaternion(axis_angle: RotationVector) -> _WXYZ:
    """Source: kornia/geometry/conversions.py (0.7.0), axis_angle_to_quaternion: (w, x, y, z) out."""

@overload
@versions(">=0.7")
def angle_axis_to_quaternion(axis_angle: RotationVector) -> _WXYZ:
    """Source: kornia/geometry/conversions.py (0.7.0), angle_axis_to_quaternion: `axis_angle_to_quaternion(axis_angle)`."""
@overload
@versions("<0.7")
def angle_axis_to_quaternion(angle_axis: RotationVector) -> _XYZW:
    """Source: kornia/geometry/conversions.py (0.5.11, 0.6.12), angle_axis_to_quaternion(angle_axis,
    order=QuaternionCoeffOrder.XYZW)."""
