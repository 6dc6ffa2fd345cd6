from typing import Literal, overload

from geolint.typing import Degrees, PointArray, Radians, TransformMatrix

class SO3:
    """Source: spatialmath/pose3d.py (1.1.18), SO3: a rotation (or a sequence of them); angles in radians unless `unit="deg"`."""

    @overload
    @classmethod
    def Rx(cls, theta: Radians, unit: Literal["rad"] = ...) -> SO3: ...
    @overload
    @classmethod
    def Rx(cls, theta: Degrees, unit: Literal["deg"]) -> SO3:
        """Source: spatialmath/pose3d.py (1.1.18), SO3.Rx: "theta: rotation angle about the x-axis", unit 'rad' [default] or 'deg'."""
    @overload
    @classmethod
    def Ry(cls, theta: Radians, unit: Literal["rad"] = ...) -> SO3: ...
    @overload
    @classmethod
    def Ry(cls, theta: Degrees, unit: Literal["deg"]) -> SO3:
        """Source: spatialmath/pose3d.py (1.1.18), SO3.Ry: "theta: rotation angle about the y-axis", unit 'rad' [default] or 'deg'."""
    @overload
    @classmethod
    def Rz(cls, theta: Radians, unit: Literal["rad"] = ...) -> SO3: ...
    @overload
    @classmethod
    def Rz(cls, theta: Degrees, unit: Literal["deg"]) -> SO3:
        """Source: spatialmath/pose3d.py (1.1.18), SO3.Rz: "theta: rotation angle about the z-axis", unit 'rad' [default] or 'deg'."""
    @overload
    @classmethod
    def RPY(cls, roll: Radians, pitch: Radians = ..., yaw: Radians = ..., *, unit: Literal["rad"] = ..., order: str = ...) -> SO3: ...
    @overload
    @classmethod
    def RPY(cls, roll: Degrees, pitch: Degrees = ..., yaw: Degrees = ..., *, unit: Literal["deg"], order: str = ...) -> SO3:
        """Source: spatialmath/pose3d.py (1.1.18), SO3.RPY(*angles, unit='rad', order='zyx'): three angles, or one 3-vector of them."""
    @overload
    @classmethod
    def Eul(cls, phi: Radians, theta: Radians = ..., psi: Radians = ..., *, unit: Literal["rad"] = ...) -> SO3: ...
    @overload
    @classmethod
    def Eul(cls, phi: Degrees, theta: Degrees = ..., psi: Degrees = ..., *, unit: Literal["deg"]) -> SO3:
        """Source: spatialmath/pose3d.py (1.1.18), SO3.Eul(*angles, unit='rad'): ZYZ Euler angles."""
    @overload
    def rpy(self, unit: Literal["rad"] = ..., order: str = ...) -> tuple[Radians, Radians, Radians]: ...
    @overload
    def rpy(self, unit: Literal["deg"], order: str = ...) -> tuple[Degrees, Degrees, Degrees]:
        """Source: spatialmath/pose3d.py (1.1.18), SO3.rpy: "unit: angular units: 'rad' [default], or 'deg'"
        (tr2rpy of the rotation, an array of shape (3,))."""
    @overload
    def eul(self, unit: Literal["rad"] = ..., flip: bool = ...) -> tuple[Radians, Radians, Radians]: ...
    @overload
    def eul(self, unit: Literal["deg"], flip: bool = ...) -> tuple[Degrees, Degrees, Degrees]:
        """Source: spatialmath/pose3d.py (1.1.18), SO3.eul: ZYZ Euler angles, unit as rpy."""


class SE3:
    """Source: spatialmath/pose3d.py (1.1.18), SE3: a pose (or a sequence of them); angles in radians unless `unit="deg"`."""

    def __init__(self, *args: object, **kwargs: object) -> None: ...
    @classmethod
    def Trans(cls, x: object, y: float = ..., z: float = ...) -> SE3:
        """Source: spatialmath/pose3d.py (1.1.18), SE3.Trans: "Create SE(3) from translation vector"."""
    @classmethod
    def Tx(cls, x: float) -> SE3: ...
    @classmethod
    def Ty(cls, y: float) -> SE3: ...
    @classmethod
    def Tz(cls, z: float) -> SE3: ...
    def inv(self) -> SE3: ...
    @overload
    def __mul__(self: TransformMatrix, right: SE3) -> SE3: ...
    @overload
    def __mul__(self: TransformMatrix, right: PointArray) -> PointArray:
        """Source: spatialmath/baseposematrix.py (1.1.18), BasePoseMatrix.__mul__: "Pose * Pose: matrix product",
        "Pose * N-vector: vector transform", "Pose * NxM matrix: transform each column"; for an SE3 the vector is
        made homogeneous with a 1 (checked: `SE3.Trans(1, 0, 0) * SE3.Rz(pi / 2) * [1, 0, 0]` is [1, 1, 0]):
        the translation is applied, as to a point."""

    @overload
    @classmethod
    def Rx(cls, theta: Radians, unit: Literal["rad"] = ..., t: object = ...) -> SE3: ...
    @overload
    @classmethod
    def Rx(cls, theta: Degrees, unit: Literal["deg"], t: object = ...) -> SE3:
        """Source: spatialmath/pose3d.py (1.1.18), SE3.Rx: "theta: rotation angle about the x-axis", unit 'rad' [default] or 'deg'."""
    @overload
    @classmethod
    def Ry(cls, theta: Radians, unit: Literal["rad"] = ..., t: object = ...) -> SE3: ...
    @overload
    @classmethod
    def Ry(cls, theta: Degrees, unit: Literal["deg"], t: object = ...) -> SE3:
        """Source: spatialmath/pose3d.py (1.1.18), SE3.Ry: "theta: rotation angle about the y-axis", unit 'rad' [default] or 'deg'."""
    @overload
    @classmethod
    def Rz(cls, theta: Radians, unit: Literal["rad"] = ..., t: object = ...) -> SE3: ...
    @overload
    @classmethod
    def Rz(cls, theta: Degrees, unit: Literal["deg"], t: object = ...) -> SE3:
        """Source: spatialmath/pose3d.py (1.1.18), SE3.Rz: "theta: rotation angle about the z-axis", unit 'rad' [default] or 'deg'."""
    @overload
    @classmethod
    def RPY(cls, roll: Radians, pitch: Radians = ..., yaw: Radians = ..., *, unit: Literal["rad"] = ..., order: str = ...) -> SE3: ...
    @overload
    @classmethod
    def RPY(cls, roll: Degrees, pitch: Degrees = ..., yaw: Degrees = ..., *, unit: Literal["deg"], order: str = ...) -> SE3:
        """Source: spatialmath/pose3d.py (1.1.18), SE3.RPY(*angles, unit='rad', order='zyx'): three angles, or one 3-vector of them."""
    @overload
    @classmethod
    def Eul(cls, phi: Radians, theta: Radians = ..., psi: Radians = ..., *, unit: Literal["rad"] = ...) -> SE3: ...
    @overload
    @classmethod
    def Eul(cls, phi: Degrees, theta: Degrees = ..., psi: Degrees = ..., *, unit: Literal["deg"]) -> SE3:
        """Source: spatialmath/pose3d.py (1.1.18), SE3.Eul(*angles, unit='rad'): ZYZ Euler angles."""
    @overload
    def rpy(self, unit: Literal["rad"] = ..., order: str = ...) -> tuple[Radians, Radians, Radians]: ...
    @overload
    def rpy(self, unit: Literal["deg"], order: str = ...) -> tuple[Degrees, Degrees, Degrees]:
        """Source: spatialmath/pose3d.py (1.1.18), SE3.rpy: "unit: angular units: 'rad' [default], or 'deg'"
        (tr2rpy of the rotation, an array of shape (3,))."""
    @overload
    def eul(self, unit: Literal["rad"] = ..., flip: bool = ...) -> tuple[Radians, Radians, Radians]: ...
    @overload
    def eul(self, unit: Literal["deg"], flip: bool = ...) -> tuple[Degrees, Degrees, Degrees]:
        """Source: spatialmath/pose3d.py (1.1.18), SE3.eul: ZYZ Euler angles, unit as rpy."""
