"""Spatial velocities, forces and uncertainties in a frame: `Twist[F]`, `Wrench[F]`, `Covariance[F]`.

A pose moves them with the adjoint, not with the point rule:

- twist (linear v, angular w):  w' = R w,  v' = R v + t x (R w)
- wrench (force f, torque tau): f' = R f,  tau' = R tau + t x (R f)
- position covariance S:        S' = R S R^T (translation does not change an uncertainty)

Each part has shape (3,) for one value or (N, 3) for a batch; a covariance is (3, 3) or (N, 3, 3).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar, Generic, TypeVar

import numpy as np

from geolint.runtime._framed import FramedKind, checked_array, checked_tolerance, format_array, frozen, read_only
from geolint.runtime.errors import GeometryTypeError, GeometryValueError
from geolint.runtime.primitives import Vector, check_same_frame, describe, register_kind

if TYPE_CHECKING:
    from numpy.typing import ArrayLike, NDArray

__all__ = ["Twist", "Wrench", "Covariance"]

F = TypeVar("F")

_PART_SHAPES = ((3,), (-1, 3))


class _SixVector(FramedKind):
    """Two 3-vectors of one frame, moved by the adjoint (shared by `Twist` and `Wrench`)."""

    __slots__ = ("_first", "_second")
    __array_ufunc__ = None
    _frame: ClassVar[str]
    # Names of the two parts as the constructor spells them; the first is the one crossed with t.
    _parts: ClassVar[tuple[str, str]]
    _first: np.ndarray  # linear velocity or torque: picks up t x (R second)
    _second: np.ndarray  # angular velocity or force: rotated only

    def _init_parts(self, first: ArrayLike, second: ArrayLike) -> None:
        cls = type(self)
        if "_frames" not in cls.__dict__:
            a, b = self._parts
            raise GeometryTypeError(f"{cls.__name__} needs a frame: {cls.__name__}[World]({a}=..., {b}=...)")
        owner = self._describe()
        self._first = checked_array(first, _PART_SHAPES, self._parts[0], owner)
        self._second = checked_array(second, _PART_SHAPES, self._parts[1], owner)
        if self._first.shape != self._second.shape:
            raise GeometryValueError(
                f"{owner}: {self._parts[0]} has shape {self._first.shape} but {self._parts[1]} has "
                f"{self._second.shape}; they must match"
            )

    @classmethod
    def _wrap(cls, frame: str, first: np.ndarray, second: np.ndarray) -> Any:
        kind = cls._kind
        try:
            framed = kind._by_frame_name[frame]
        except KeyError:
            framed = kind.framed_class(frame)
        obj = object.__new__(framed)
        obj._first = first
        obj._second = second
        return obj

    @property
    def frame(self) -> str:
        """The name of the frame both parts are expressed in (and the reference point: its origin)."""
        return self._frame

    def _describe(self) -> str:
        return f"{self._kind.__name__}[{self._frame}]"

    def __repr__(self) -> str:
        a, b = self._parts
        return f"{self._describe()}({a}={format_array(self._first)}, {b}={format_array(self._second)})"

    def __reduce__(self) -> tuple[Any, ...]:
        from geolint.runtime.primitives import _rebuild

        return (_rebuild, (self._kind.__name__, self._frame, self._first, self._second))

    @classmethod
    def _from_state(cls, frames: tuple[str, ...], first: np.ndarray, second: np.ndarray) -> Any:
        return cls._wrap(frames[0], first, second)

    def _moved_by(self, transform: Any) -> Any:
        second = transform.rotate(self._second)
        first = transform.rotate(self._first)
        first += np.cross(transform._translation_block(), second)
        return type(self)._wrap(transform._dst, first, second)

    def __add__(self, other: Any) -> Any:
        if not isinstance(other, _SixVector) or other._kind is not self._kind:
            raise GeometryTypeError(f"{self._describe()} + {describe(other)}: only values of the same kind add")
        check_same_frame(self, other, "+")
        return type(self)._wrap(self._frame, self._first + other._first, self._second + other._second)

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __rmatmul__(self, other: object) -> Any:
            raise GeometryTypeError(
                f"{describe(other)} @ {self._describe()}: use a Transform[Dst, {self._frame}], which applies the adjoint"
            )


class Twist(_SixVector, Generic[F]):
    """A spatial velocity in frame F, referred to F's origin.

    Parameters
    ----------
    linear : array_like, shape (3,) or (N, 3)
        Linear velocity v of the point at F's origin, in F.
    angular : array_like, shape (3,) or (N, 3)
        Angular velocity w, in F.
    """

    __slots__ = ()
    _parts = ("linear", "angular")

    def __init__(self, linear: ArrayLike, angular: ArrayLike) -> None:
        self._init_parts(linear, angular)

    def __add__(self, other: Twist[F]) -> Twist[F]:
        return super().__add__(other)  # type: ignore[no-any-return]

    @property
    def linear(self) -> Vector[F]:
        """Linear velocity v, a `Vector[F]`."""
        return Vector._wrap(self._frame, self._first)  # type: ignore[no-any-return]

    @property
    def angular(self) -> Vector[F]:
        """Angular velocity w, a `Vector[F]`."""
        return Vector._wrap(self._frame, self._second)  # type: ignore[no-any-return]


class Wrench(_SixVector, Generic[F]):
    """A force and a torque in frame F, the torque taken about F's origin.

    Parameters
    ----------
    force : array_like, shape (3,) or (N, 3)
    torque : array_like, shape (3,) or (N, 3)
    """

    __slots__ = ()
    _parts = ("torque", "force")

    def __init__(self, force: ArrayLike, torque: ArrayLike) -> None:
        self._init_parts(torque, force)

    def __add__(self, other: Wrench[F]) -> Wrench[F]:
        return super().__add__(other)  # type: ignore[no-any-return]

    def __repr__(self) -> str:
        return f"{self._describe()}(force={format_array(self._second)}, torque={format_array(self._first)})"

    @property
    def force(self) -> Vector[F]:
        """Force f, a `Vector[F]`."""
        return Vector._wrap(self._frame, self._second)  # type: ignore[no-any-return]

    @property
    def torque(self) -> Vector[F]:
        """Torque tau about F's origin, a `Vector[F]`."""
        return Vector._wrap(self._frame, self._first)  # type: ignore[no-any-return]


class Covariance(FramedKind, Generic[F]):
    """The covariance of a position (or of any free vector) expressed in frame F: S' = R S R^T under a pose.

    Parameters
    ----------
    matrix : array_like, shape (3, 3) or (N, 3, 3)
        Symmetric positive semi-definite, within ``tolerance`` (default 1e-9, relative to the largest entry).
    """

    __slots__ = ("_s",)
    __array_ufunc__ = None
    _frame: ClassVar[str]
    _s: np.ndarray

    def __init__(self, matrix: ArrayLike, *, tolerance: float = 1e-9) -> None:
        cls = type(self)
        if "_frames" not in cls.__dict__:
            raise GeometryTypeError("Covariance needs a frame: Covariance[World](matrix)")
        owner = self._describe()
        tolerance = checked_tolerance(tolerance, owner)
        s = checked_array(matrix, ((3, 3), (-1, 3, 3)), "matrix", owner)
        if s.size:
            # Relative to each matrix's own largest entry: one large covariance in a batch must not
            # widen the tolerance for the others.
            scale = np.maximum(np.abs(s).max(axis=(-2, -1)), 1.0)
            asymmetry = np.abs(s - np.swapaxes(s, -1, -2)).max(axis=(-2, -1))
            most_asymmetric = int(np.atleast_1d(asymmetry / scale).argmax())
            if np.atleast_1d(asymmetry)[most_asymmetric] > tolerance * np.atleast_1d(scale)[most_asymmetric]:
                where = f" (matrix {most_asymmetric} of the batch)" if s.ndim == 3 else ""
                raise GeometryValueError(
                    f"{owner}: a covariance is symmetric; max |S - S^T| = "
                    f"{np.atleast_1d(asymmetry)[most_asymmetric]:.3g}{where}"
                )
            lowest = np.atleast_1d(np.linalg.eigvalsh(s).min(axis=-1) / scale)
            worst = int(lowest.argmin())
            if lowest[worst] < -tolerance:
                where = f" (matrix {worst} of the batch)" if s.ndim == 3 else ""
                raise GeometryValueError(
                    f"{owner}: a covariance is positive semi-definite; its smallest eigenvalue is "
                    f"{lowest[worst] * np.atleast_1d(scale)[worst]:.3g}{where}"
                )
        self._s = s

    @classmethod
    def _wrap(cls, frame: str, s: np.ndarray) -> Any:
        try:
            framed = Covariance._by_frame_name[frame]
        except KeyError:
            framed = Covariance.framed_class(frame)
        obj: Any = object.__new__(framed)
        obj._s = s
        return obj

    @property
    def frame(self) -> str:
        """The name of the frame the covariance is expressed in."""
        return self._frame

    @property
    def matrix(self) -> NDArray[np.float64]:
        """S, read-only, shape (3, 3) or (N, 3, 3)."""
        return read_only(self._s)

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __array__(self, dtype: Any = None, copy: bool | None = None) -> np.ndarray:
            if dtype is None and not copy:
                return frozen(self._s)
            return np.array(self._s, dtype=dtype, copy=True)

    def _describe(self) -> str:
        return f"Covariance[{self._frame}]"

    def __repr__(self) -> str:
        return f"{self._describe()}({format_array(self._s)})"

    def __reduce__(self) -> tuple[Any, ...]:
        from geolint.runtime.primitives import _rebuild

        return (_rebuild, ("Covariance", self._frame, self._s))

    @classmethod
    def _from_state(cls, frames: tuple[str, ...], s: np.ndarray) -> Any:
        return cls._wrap(frames[0], s)

    def _moved_by(self, transform: Any) -> Any:
        r = transform._rotation_block()
        moved = r @ self._s @ np.swapaxes(r, -1, -2)
        # Symmetrise: R S R^T is symmetric in exact arithmetic; keep it so in floating point.
        moved = 0.5 * (moved + np.swapaxes(moved, -1, -2))
        return Covariance._wrap(transform._dst, moved)

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __rmatmul__(self, other: object) -> Any:
            raise GeometryTypeError(
                f"{describe(other)} @ {self._describe()}: use a Transform[Dst, {self._frame}] (it applies R S R^T)"
            )


for _kind in (Twist, Wrench, Covariance):
    register_kind(_kind)
