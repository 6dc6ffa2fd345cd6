from typing import Literal, overload

from geolint.typing import Degrees, Radians, RotationMatrix, TransformMatrix, VectorArray

# spatialmath.base.transforms3d (1.1.18): every angle argument goes through `getunit(theta, unit)`:
# "The input value is assumed to be in units of ``unit`` and is converted to radians", unit "rad" (the
# default) or "deg" (spatialmath/base/argcheck.py).

@overload
def rotx(theta: Radians, unit: Literal["rad"] = ...) -> RotationMatrix: ...
@overload
def rotx(theta: Degrees, unit: Literal["deg"]) -> RotationMatrix:
    """Source: spatialmath/base/transforms3d.py (1.1.18), rotx: "theta: rotation angle", "unit: angular units: 'rad' [default], or 'deg'"."""
@overload
def trotx(theta: Radians, unit: Literal["rad"] = ..., t: object = ...) -> TransformMatrix: ...
@overload
def trotx(theta: Degrees, unit: Literal["deg"], t: object = ...) -> TransformMatrix:
    """Source: spatialmath/base/transforms3d.py (1.1.18), trotx: like rotx, with a translation `t`."""
@overload
def roty(theta: Radians, unit: Literal["rad"] = ...) -> RotationMatrix: ...
@overload
def roty(theta: Degrees, unit: Literal["deg"]) -> RotationMatrix:
    """Source: spatialmath/base/transforms3d.py (1.1.18), roty: "theta: rotation angle", "unit: angular units: 'rad' [default], or 'deg'"."""
@overload
def troty(theta: Radians, unit: Literal["rad"] = ..., t: object = ...) -> TransformMatrix: ...
@overload
def troty(theta: Degrees, unit: Literal["deg"], t: object = ...) -> TransformMatrix:
    """Source: spatialmath/base/transforms3d.py (1.1.18), troty: like roty, with a translation `t`."""
@overload
def rotz(theta: Radians, unit: Literal["rad"] = ...) -> RotationMatrix: ...
@overload
def rotz(theta: Degrees, unit: Literal["deg"]) -> RotationMatrix:
    """Source: spatialmath/base/transforms3d.py (1.1.18), rotz: "theta: rotation angle", "unit: angular units: 'rad' [default], or 'deg'"."""
@overload
def trotz(theta: Radians, unit: Literal["rad"] = ..., t: object = ...) -> TransformMatrix: ...
@overload
def trotz(theta: Degrees, unit: Literal["deg"], t: object = ...) -> TransformMatrix:
    """Source: spatialmath/base/transforms3d.py (1.1.18), trotz: like rotz, with a translation `t`."""
@overload
def rpy2r(roll: Radians, pitch: Radians = ..., yaw: Radians = ..., *, unit: Literal["rad"] = ..., order: str = ...) -> RotationMatrix: ...
@overload
def rpy2r(roll: Degrees, pitch: Degrees = ..., yaw: Degrees = ..., *, unit: Literal["deg"], order: str = ...) -> RotationMatrix:
    """Source: spatialmath/base/transforms3d.py (1.1.18), rpy2r: "roll: roll angle or 3-vector of angles", "unit: angular units: 'rad' [default], or 'deg'"."""
@overload
def rpy2tr(roll: Radians, pitch: Radians = ..., yaw: Radians = ..., unit: Literal["rad"] = ..., order: str = ...) -> TransformMatrix: ...
@overload
def rpy2tr(roll: Degrees, pitch: Degrees, yaw: Degrees, unit: Literal["deg"], order: str = ...) -> TransformMatrix: ...
@overload
def rpy2tr(roll: Degrees, pitch: Degrees = ..., yaw: Degrees = ..., *, unit: Literal["deg"], order: str = ...) -> TransformMatrix:
    """Source: spatialmath/base/transforms3d.py (1.1.18), rpy2tr: rpy2r as a 4x4 pose."""
@overload
def eul2r(phi: Radians, theta: Radians = ..., psi: Radians = ..., unit: Literal["rad"] = ...) -> RotationMatrix: ...
@overload
def eul2r(phi: Degrees, theta: Degrees, psi: Degrees, unit: Literal["deg"]) -> RotationMatrix: ...
@overload
def eul2r(phi: Degrees, theta: Degrees = ..., psi: Degrees = ..., *, unit: Literal["deg"]) -> RotationMatrix:
    """Source: spatialmath/base/transforms3d.py (1.1.18), eul2r: ZYZ Euler angles, unit as rpy2r."""
@overload
def eul2tr(phi: Radians, theta: Radians = ..., psi: Radians = ..., unit: Literal["rad"] = ...) -> TransformMatrix: ...
@overload
def eul2tr(phi: Degrees, theta: Degrees, psi: Degrees, unit: Literal["deg"]) -> TransformMatrix: ...
@overload
def eul2tr(phi: Degrees, theta: Degrees = ..., psi: Degrees = ..., *, unit: Literal["deg"]) -> TransformMatrix:
    """Source: spatialmath/base/transforms3d.py (1.1.18), eul2tr: eul2r as a 4x4 pose."""
@overload
def angvec2r(theta: Radians, v: VectorArray, unit: Literal["rad"] = ...) -> RotationMatrix: ...
@overload
def angvec2r(theta: Degrees, v: VectorArray, unit: Literal["deg"]) -> RotationMatrix:
    """Source: spatialmath/base/transforms3d.py (1.1.18), angvec2r(theta, v, unit='rad'): a rotation of `theta` about `v`."""
@overload
def tr2rpy(T: object, unit: Literal["rad"] = ..., order: str = ..., check: bool = ..., tol: float = ...) -> tuple[Radians, Radians, Radians]: ...
@overload
def tr2rpy(T: object, unit: Literal["deg"], order: str = ..., check: bool = ..., tol: float = ...) -> tuple[Degrees, Degrees, Degrees]:
    """Source: spatialmath/base/transforms3d.py (1.1.18), tr2rpy: "unit: angular units: 'rad' [default], or
    'deg'"; returns "Roll-pitch-yaw angles" (an array of shape (3,))."""
@overload
def tr2eul(T: object, unit: Literal["rad"] = ..., flip: bool = ..., check: bool = ..., tol: float = ...) -> tuple[Radians, Radians, Radians]: ...
@overload
def tr2eul(T: object, unit: Literal["deg"], flip: bool = ..., check: bool = ..., tol: float = ...) -> tuple[Degrees, Degrees, Degrees]:
    """Source: spatialmath/base/transforms3d.py (1.1.18), tr2eul: ZYZ Euler angles (an array of shape
    (3,)), unit as tr2rpy."""
