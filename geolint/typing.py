"""Frame annotations for plain numpy arrays, at zero runtime cost.

Teams that keep their geometry in ndarrays annotate them instead of wrapping them::

    from geolint.typing import PointArray, RotationMatrix, Translation, VectorArray, as_points

    def to_world(R: RotationMatrix[World, Camera], t: Translation[World, Camera],
                 p: PointArray[Camera], n: VectorArray[Camera]) -> tuple[PointArray[World], VectorArray[World]]:
        return R @ p + t, R @ n          # `R @ n + t` would be a geo-translation error

Why classes and not ``Annotated[NDArray[np.float64], Point[F]]``: mypy drops ``Annotated`` metadata before any
plugin can see it, and a frame inside metadata is not a type, so nothing could compare two frames. Here each
name is, *for the type checker only*, a generic subclass of ``numpy.ndarray`` (so every numpy function still
accepts it) whose type arguments are the frames. With the ``geolint.mypy`` plugin, ``@``, ``np.dot``,
``np.matmul``, ``+`` and ``-`` check the frames and infer the result's kind and frame; without the plugin the
annotations still document the frames and keep a ``PointArray[World]`` apart from a ``PointArray[Camera]``.

At runtime each name is a tiny object whose subscript returns ``numpy.typing.NDArray[numpy.float64]`` (so
``typing.get_type_hints`` and runtime validators see a plain float array), and the ``as_*`` markers return
their argument unchanged: no copy, no wrapper, no isinstance cost.

Frames are written like the runtime's: a ``Frame`` subclass (``PointArray[World]``), a string with the plugin
(``PointArray["camera"]``), or ``PointArray[Literal["camera"]]`` with any checker. Conventions: column
vectors for ``R @ p`` (a single point or ``(3, N)``); rows for ``pts @ R.T`` (``(N, 3)``), where ``R.T`` of a
``RotationMatrix[A, B]`` is a ``RotationMatrix[B, A]``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Generic, TypeVar, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "PointArray",
    "VectorArray",
    "DirectionArray",
    "RotationMatrix",
    "TransformMatrix",
    "Translation",
    "HomogeneousPoints",
    "HomogeneousVectors",
    "VectorWithW1",
    "OriginOffset",
    "NegatedRotation",
    "QuaternionXYZW",
    "QuaternionWXYZ",
    "RotationVector",
    "Radians",
    "Degrees",
    "as_points",
    "as_vectors",
    "as_directions",
    "as_rotation",
    "as_transform",
    "as_translation",
]

F = TypeVar("F")
Dst = TypeVar("Dst")
Src = TypeVar("Src")
In = TypeVar("In")
From = TypeVar("From")
To = TypeVar("To")

if TYPE_CHECKING:

    _Float = np.dtype[np.float64]

    class PointArray(np.ndarray[Any, _Float], Generic[F]):
        """Points (locations) in frame F: shape (3,), (3, N) for ``R @ p``, or (N, 3) for ``p @ R.T``."""

    class VectorArray(np.ndarray[Any, _Float], Generic[F]):
        """Free vectors in frame F (displacements, velocities, forces): rotated, never translated."""

    class DirectionArray(VectorArray[F]):
        """Unit vectors in frame F (normals, axes). A scaled or summed direction is a `VectorArray`."""

    class RotationMatrix(np.ndarray[Any, _Float], Generic[Dst, Src]):
        """A (3, 3) rotation mapping Src coordinates into Dst (``R_dst_src``)."""

        @property
        # numpy's name; for a rotation the transpose is the inverse, with the frames swapped (not Self)
        def T(self) -> RotationMatrix[Src, Dst]: ...  # type: ignore[override]  # noqa: N802

    class TransformMatrix(np.ndarray[Any, _Float], Generic[Dst, Src]):
        """A (4, 4) homogeneous transform mapping Src into Dst (``T_dst_src``).

        With the plugin, ``T[:3, :3]`` is a ``RotationMatrix[Dst, Src]`` and ``T[:3, 3]`` a
        ``Translation[Dst, Src]``.
        """

    class Translation(np.ndarray[Any, _Float], Generic[Dst, Src]):
        """The (3,) translation of a ``TransformMatrix[Dst, Src]``: the origin of Src in Dst. Points only."""

    class HomogeneousPoints(np.ndarray[Any, _Float], Generic[F]):
        """Points with w=1 appended, shape (4,) or (4, N): a 4x4 transform moves them fully."""

    class HomogeneousVectors(np.ndarray[Any, _Float], Generic[F]):
        """Vectors with w=0 appended: a 4x4 transform rotates them and leaves out the translation."""

    class VectorWithW1(np.ndarray[Any, _Float], Generic[F]):
        """What ``np.append(v, 1)`` makes of a vector: a 4x4 transform would translate it (a bug)."""

    class OriginOffset(np.ndarray[Any, _Float], Generic[In, From, To]):
        """The vector from From's origin to To's origin, in In's axes: a step of a hand-written composition.

        ``R[A <- B] @ t[B <- C]`` is an ``OriginOffset[A, B, C]``; adding ``t[A <- B]`` gives the
        ``Translation[A, C]`` (``R_ab @ t_bc + t_ab``). ``Translation[A, B]`` is ``OriginOffset[A, A, B]``, and a
        negated offset runs the other way (``-t[A <- B]`` is ``OriginOffset[A, B, A]``).
        """

    class NegatedRotation(np.ndarray[Any, _Float], Generic[Dst, Src]):
        """``-R`` for a ``RotationMatrix[Dst, Src]``: not a rotation, but ``-R.T @ t`` is the inverse's translation."""

    # Conventions without frames: the component order of a quaternion, the unit of angles. The
    # knowledge base's stubs (``stubs/``) state library APIs with these, and typed code may too.
    class QuaternionXYZW(np.ndarray[Any, _Float]):
        """A quaternion (or a stack of them) stored scalar-last: x, y, z, w."""

    class QuaternionWXYZ(np.ndarray[Any, _Float]):
        """A quaternion (or a stack of them) stored scalar-first: w, x, y, z."""

    class RotationVector(np.ndarray[Any, _Float]):
        """An axis-angle rotation vector: the unit axis times the angle in radians."""

    class Radians(np.ndarray[Any, _Float]):
        """Angles in radians (one or several)."""

    class Degrees(np.ndarray[Any, _Float]):
        """Angles in degrees (one or several)."""


else:

    class _FramedArrayAnnotation:
        """Runtime stand-in: subscripting gives ``NDArray[np.float64]``, whatever the frames."""

        __slots__ = ("__name__", "_arity")

        def __init__(self, name: str, arity: int) -> None:
            self.__name__ = name
            self._arity = arity

        def __getitem__(self, frames: Any) -> Any:
            count = len(frames) if isinstance(frames, tuple) else 1
            if count != self._arity:
                want = "1 frame" if self._arity == 1 else f"{self._arity} frames"
                raise TypeError(f"{self.__name__} takes {want}, got {count}: {frames!r}")
            return _FLOAT_ARRAY

        def __repr__(self) -> str:
            return f"geolint.typing.{self.__name__}"

    _FLOAT_ARRAY = NDArray[np.float64]

    PointArray = _FramedArrayAnnotation("PointArray", 1)
    VectorArray = _FramedArrayAnnotation("VectorArray", 1)
    DirectionArray = _FramedArrayAnnotation("DirectionArray", 1)
    RotationMatrix = _FramedArrayAnnotation("RotationMatrix", 2)
    TransformMatrix = _FramedArrayAnnotation("TransformMatrix", 2)
    Translation = _FramedArrayAnnotation("Translation", 2)
    HomogeneousPoints = _FramedArrayAnnotation("HomogeneousPoints", 1)
    HomogeneousVectors = _FramedArrayAnnotation("HomogeneousVectors", 1)
    VectorWithW1 = _FramedArrayAnnotation("VectorWithW1", 1)
    OriginOffset = _FramedArrayAnnotation("OriginOffset", 3)
    NegatedRotation = _FramedArrayAnnotation("NegatedRotation", 2)
    QuaternionXYZW = QuaternionWXYZ = RotationVector = Radians = Degrees = _FLOAT_ARRAY


# The markers: identity at runtime, a frame for the type checker. With the plugin a string frame
# (``as_points(a, "camera")``) gives ``PointArray["camera"]``; without it, pass a Frame class.


@overload
def as_points(array: ArrayLike, frame: type[F]) -> PointArray[F]: ...
@overload
def as_points(array: ArrayLike, frame: str) -> PointArray[Any]: ...
def as_points(array: Any, frame: Any) -> Any:
    """Mark `array` as points in `frame` for the type checker; returns `array` itself."""
    return array


@overload
def as_vectors(array: ArrayLike, frame: type[F]) -> VectorArray[F]: ...
@overload
def as_vectors(array: ArrayLike, frame: str) -> VectorArray[Any]: ...
def as_vectors(array: Any, frame: Any) -> Any:
    """Mark `array` as free vectors in `frame` for the type checker; returns `array` itself."""
    return array


@overload
def as_directions(array: ArrayLike, frame: type[F]) -> DirectionArray[F]: ...
@overload
def as_directions(array: ArrayLike, frame: str) -> DirectionArray[Any]: ...
def as_directions(array: Any, frame: Any) -> Any:
    """Mark `array` as unit vectors in `frame` for the type checker; returns `array` itself."""
    return array


@overload
def as_rotation(array: ArrayLike, dst: type[Dst], src: type[Src]) -> RotationMatrix[Dst, Src]: ...
@overload
def as_rotation(array: ArrayLike, dst: type[Any] | str, src: type[Any] | str) -> RotationMatrix[Any, Any]: ...
def as_rotation(array: Any, dst: Any, src: Any) -> Any:
    """Mark `array` as a rotation mapping `src` coordinates into `dst`; returns `array` itself."""
    return array


@overload
def as_transform(array: ArrayLike, dst: type[Dst], src: type[Src]) -> TransformMatrix[Dst, Src]: ...
@overload
def as_transform(array: ArrayLike, dst: type[Any] | str, src: type[Any] | str) -> TransformMatrix[Any, Any]: ...
def as_transform(array: Any, dst: Any, src: Any) -> Any:
    """Mark `array` as a 4x4 transform mapping `src` into `dst`; returns `array` itself."""
    return array


@overload
def as_translation(array: ArrayLike, dst: type[Dst], src: type[Src]) -> Translation[Dst, Src]: ...
@overload
def as_translation(array: ArrayLike, dst: type[Any] | str, src: type[Any] | str) -> Translation[Any, Any]: ...
def as_translation(array: Any, dst: Any, src: Any) -> Any:
    """Mark `array` as the translation of a transform mapping `src` into `dst`; returns `array` itself."""
    return array
