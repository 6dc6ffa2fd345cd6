from typing import Literal, overload

from geolint.typing import Degrees, QuaternionWXYZ, QuaternionXYZW, Radians, VectorArray

class Quaternion:
    """Source: spatialmath/quaternion.py (1.1.18), Quaternion.__init__: "Quaternion(v) is a new
    quaternion with value specified by the 4-vector v"; "Quaternion(s, v) ... scalar s and vector v":
    the scalar part first."""

    @overload
    def __init__(self, s: QuaternionWXYZ, *, check: bool = ...) -> None: ...
    @overload
    def __init__(self, s: float, v: VectorArray, check: bool = ...) -> None: ...


class UnitQuaternion(Quaternion):
    """Source: spatialmath/quaternion.py (1.1.18), UnitQuaternion.__init__: "UnitQuaternion(v) is a new unit
    quaternion with the elements specified by the 4-vector v", "UnitQuaternion(s, v) ... scalar s and
    vector v"; `.vec` is (s, vx, vy, vz), `.vec_xyzs` scalar last. Angles in radians unless `unit="deg"`."""

    @overload
    def __init__(self, s: QuaternionWXYZ, *, norm: bool = ..., check: bool = ...) -> None: ...
    @overload
    def __init__(self, s: float, v: VectorArray, norm: bool = ..., check: bool = ...) -> None: ...
    @property
    def vec(self) -> QuaternionWXYZ: ...
    @property
    def vec_xyzs(self) -> QuaternionXYZW: ...

    @overload
    @classmethod
    def Rx(cls, angles: Radians, unit: Literal["rad"] = ...) -> UnitQuaternion: ...
    @overload
    @classmethod
    def Rx(cls, angles: Degrees, unit: Literal["deg"]) -> UnitQuaternion:
        """Source: spatialmath/quaternion.py (1.1.18), UnitQuaternion.Rx: "angle: rotation angle", unit 'rad' [default] or 'deg'."""
    @overload
    @classmethod
    def Ry(cls, angles: Radians, unit: Literal["rad"] = ...) -> UnitQuaternion: ...
    @overload
    @classmethod
    def Ry(cls, angles: Degrees, unit: Literal["deg"]) -> UnitQuaternion:
        """Source: spatialmath/quaternion.py (1.1.18), UnitQuaternion.Ry: "angle: rotation angle", unit 'rad' [default] or 'deg'."""
    @overload
    @classmethod
    def Rz(cls, angles: Radians, unit: Literal["rad"] = ...) -> UnitQuaternion: ...
    @overload
    @classmethod
    def Rz(cls, angles: Degrees, unit: Literal["deg"]) -> UnitQuaternion:
        """Source: spatialmath/quaternion.py (1.1.18), UnitQuaternion.Rz: "angle: rotation angle", unit 'rad' [default] or 'deg'."""
    @overload
    @classmethod
    def RPY(cls, roll: Radians, pitch: Radians = ..., yaw: Radians = ..., *, unit: Literal["rad"] = ..., order: str = ...) -> UnitQuaternion: ...
    @overload
    @classmethod
    def RPY(cls, roll: Degrees, pitch: Degrees = ..., yaw: Degrees = ..., *, unit: Literal["deg"], order: str = ...) -> UnitQuaternion:
        """Source: spatialmath/quaternion.py (1.1.18), UnitQuaternion.RPY(*angles, order='zyx', unit='rad')."""
    @overload
    @classmethod
    def Eul(cls, phi: Radians, theta: Radians = ..., psi: Radians = ..., *, unit: Literal["rad"] = ...) -> UnitQuaternion: ...
    @overload
    @classmethod
    def Eul(cls, phi: Degrees, theta: Degrees = ..., psi: Degrees = ..., *, unit: Literal["deg"]) -> UnitQuaternion:
        """Source: spatialmath/quaternion.py (1.1.18), UnitQuaternion.Eul(*angles, unit='rad')."""
    @overload
    def rpy(self, unit: Literal["rad"] = ..., order: str = ...) -> tuple[Radians, Radians, Radians]: ...
    @overload
    def rpy(self, unit: Literal["deg"], order: str = ...) -> tuple[Degrees, Degrees, Degrees]:
        """Source: spatialmath/quaternion.py (1.1.18), UnitQuaternion.rpy: "unit: angular units: 'rad'
        [default], or 'deg'"."""
