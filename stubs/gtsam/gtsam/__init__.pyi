from geolint.typing import Radians

class Rot3:
    """Source: gtsam/geometry/Rot3.h and the wrapper's docstrings (gtsam 4.3.0): a rotation; every angle
    in radians (checked numerically, tests/knowledge/test_simulator_facts.py)."""

    @staticmethod
    def Quaternion(w: float, x: float, y: float, z: float) -> Rot3:
        """Source: gtsam 4.3.0, Rot3.Quaternion.__doc__: "Quaternion(w, x, y, z) ... Create from
        Quaternion coefficients"."""
    @staticmethod
    def Ypr(y: Radians, p: Radians, r: Radians) -> Rot3:
        """Source: gtsam 4.3.0, Rot3.Ypr.__doc__: "Returns rotation nRb from body to nav frame", yaw,
        pitch, roll."""
    @staticmethod
    def RzRyRx(x: Radians, y: Radians, z: Radians) -> Rot3:
        """Source: gtsam 4.3.0, Rot3.RzRyRx.__doc__: "Rotations around Z, Y, then X axes"."""
    @staticmethod
    def Rx(t: Radians) -> Rot3:
        """Source: gtsam/geometry/Rot3.h (4.3.0), Rx: "Rotation around X axis"."""
    @staticmethod
    def Ry(t: Radians) -> Rot3:
        """Source: gtsam/geometry/Rot3.h (4.3.0), Ry: "Rotation around Y axis"."""
    @staticmethod
    def Rz(t: Radians) -> Rot3:
        """Source: gtsam/geometry/Rot3.h (4.3.0), Rz: "Rotation around Z axis"."""
    def ypr(self) -> tuple[Radians, Radians, Radians]:
        """Source: gtsam/geometry/Rot3.h (4.3.0), ypr: "yaw, pitch, roll" (an array of shape (3,))."""
    def rpy(self) -> tuple[Radians, Radians, Radians]:
        """Source: gtsam/geometry/Rot3.h (4.3.0), rpy: "roll, pitch, yaw" (an array of shape (3,))."""
