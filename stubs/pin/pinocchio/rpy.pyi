from typing import overload

from geolint.typing import Radians, RotationMatrix

@overload
def rpyToMatrix(roll: Radians, pitch: Radians, yaw: Radians) -> RotationMatrix: ...
@overload
def rpyToMatrix(rpy: Radians) -> RotationMatrix:
    """Source: pinocchio 4.1.0, pinocchio.rpy.rpyToMatrix.__doc__: "Given (r, p, y), the rotation is given as
    R = R_z(y)R_y(p)R_x(r), where R_a(theta) denotes the rotation of theta radians axis a"."""

def matrixToRpy(R: RotationMatrix) -> tuple[Radians, Radians, Radians]:
    """Source: pinocchio 4.1.0, pinocchio.rpy.matrixToRpy.__doc__: "the angles (r, p, y) are given so that
    R = R_z(y)R_y(p)R_x(r) ... r in [-pi,pi], p in[-pi/2,pi/2], y in [-pi,pi]" (an array of shape (3,))."""
