from typing import Literal, overload

from geolint.knowledge.markers import STACKED
from geolint.typing import Degrees, Dst, Src, QuaternionWXYZ, QuaternionXYZW, Radians, RotationMatrix, RotationVector, VectorArray
from typing_extensions import Annotated

class Rotation:
    """A rotation or a stack of them.

    Source: scipy/spatial/transform/_rotation.py (1.17.1) and the Rotation reference pages
    (docs.scipy.org, 1.6 to 1.18): quaternions are scalar-last unless `scalar_first=True`; angles are
    radians unless `degrees=True`; `apply` rotates vectors (no translation).
    """

    @overload
    @classmethod
    def from_quat(cls, quat: Annotated[QuaternionXYZW, STACKED], *, scalar_first: Literal[False] = ...) -> Rotation: ...
    @overload
    @classmethod
    def from_quat(cls, quat: Annotated[QuaternionWXYZ, STACKED], *, scalar_first: Literal[True]) -> Rotation: ...
    @overload
    def as_quat(self, canonical: bool = ..., *, scalar_first: Literal[False] = ...) -> QuaternionXYZW: ...
    @overload
    def as_quat(self, canonical: bool = ..., *, scalar_first: Literal[True]) -> QuaternionWXYZ: ...
    @overload
    @classmethod
    def from_euler(cls, seq: str, angles: Radians, degrees: Literal[False] = ...) -> Rotation: ...
    @overload
    @classmethod
    def from_euler(cls, seq: str, angles: Degrees, degrees: Literal[True]) -> Rotation: ...
    @overload
    def as_euler(self, seq: str, degrees: Literal[False] = ..., *, suppress_warnings: bool = ...) -> Radians: ...
    @overload
    def as_euler(self, seq: str, degrees: Literal[True], *, suppress_warnings: bool = ...) -> Degrees: ...
    @overload
    @classmethod
    def from_rotvec(cls, rotvec: RotationVector, degrees: Literal[False] = ...) -> Rotation: ...
    @overload
    @classmethod
    def from_rotvec(cls, rotvec: Degrees, degrees: Literal[True]) -> Rotation: ...
    @overload
    def as_rotvec(self, degrees: Literal[False] = ...) -> RotationVector: ...
    @overload
    def as_rotvec(self, degrees: Literal[True]) -> Degrees: ...
    @classmethod
    def from_matrix(cls, matrix: RotationMatrix[Dst, Src], *, assume_valid: bool = ...) -> Rotation: ...
    def as_matrix(self) -> RotationMatrix[Dst, Src]: ...
    def apply(self, vectors: VectorArray[Src], inverse: bool = ...) -> VectorArray[Dst]: ...
    def inv(self) -> Rotation: ...

class Slerp:
    """Spherical linear interpolation of rotations.

    Source: scipy/spatial/transform/_rotation.py (1.17.1), Slerp(times, rotations).
    """

    def __init__(self, times: object, rotations: Rotation) -> None: ...
