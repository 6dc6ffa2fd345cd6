"""Points, vectors and directions expressed in a frame: `Point[F]`, `Vector[F]`, `Direction[F]`.

The three kinds differ in how a pose moves them (the design text's point-versus-vector contract):
a point (a location, homogeneous w = 1) gets rotation and translation, a vector (a displacement, w = 0)
gets rotation only, a direction is a unit vector and stays one. Only valid algebra has an operator,
as in Rust's euclid: point - point is a vector, point + vector a point, point + point raises
`GeometryTypeError`. Mixing frames raises `FrameMismatchError`.

Coordinates are float64, shape (3,) for one value or (N, 3) for a batch; they are copied and made
read-only on construction. ``np.asarray(value)`` gives them back. Operators between a value and a raw
ndarray are refused (``__array_ufunc__ = None`` stops numpy from treating a value as a plain array), so a
wrapped value never silently loses its kind or frame.

Hidden from type checkers: the dunders that only exist to refuse an operation with a helpful message
(``__rmatmul__``, ``Point.__mul__``, ``__array__``...) are defined under ``if not TYPE_CHECKING``, so mypy and
pyright see no such operator and reject ``R @ p``, ``2 * p`` or ``T @ p_wrong_frame`` statically instead of
falling back to a permissive reflected operator.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar, Generic, TypeVar, overload

import numpy as np

from geolint.runtime._framed import LARGEST_COORDINATE, FramedKind, checked_array, format_array, frozen, read_only
from geolint.runtime.errors import FrameMismatchError, GeometryTypeError, GeometryValueError

if TYPE_CHECKING:
    from numpy.typing import ArrayLike, NDArray

__all__ = ["Point", "Vector", "Direction", "F"]

F = TypeVar("F")

_COORD_SHAPES = ((3,), (-1, 3))


def describe(value: object) -> str:
    """How a value is named in error messages: ``Point[World]``, ``Transform[World <- Camera]``, ``ndarray``."""
    describer = getattr(value, "_describe", None)
    if describer is not None:
        return describer()  # type: ignore[no-any-return]
    if isinstance(value, np.ndarray):
        return f"ndarray of shape {value.shape}"
    return type(value).__name__


def check_same_frame(left: Any, right: Any, operation: str) -> None:
    """Raise `FrameMismatchError` unless two values share a frame (names the operation and both frames)."""
    if left._frame is not right._frame and left._frame != right._frame:
        raise FrameMismatchError(
            f"{describe(left)} {operation} {describe(right)}: the frames differ ({left._frame} vs {right._frame}); "
            f"move one of them first (T_{left._frame}_{right._frame} @ value)"
        )


def _scalar_factor(value: object, owner: Any, operation: str) -> Any:
    """A real scalar (or a (N,) array of per-row factors for a batch), checked finite."""
    if isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool):
        if not np.isfinite(value):
            raise GeometryValueError(f"{describe(owner)} {operation} {value}: the factor must be finite")
        return value
    if isinstance(value, np.ndarray) and value.ndim == 1 and owner._xyz.ndim == 2:
        if value.shape[0] != owner._xyz.shape[0] or value.dtype.kind not in "iuf":
            raise GeometryValueError(
                f"{describe(owner)} {operation} array: per-row factors need shape ({owner._xyz.shape[0]},) "
                f"and real numbers, got {value.shape} {value.dtype}"
            )
        if not np.isfinite(value).all():
            raise GeometryValueError(f"{describe(owner)} {operation} array: the factors must be finite")
        return value[:, None]
    raise GeometryTypeError(
        f"{describe(owner)} {operation} {describe(value)}: a vector scales by a real number only"
    )


class _Coordinates(FramedKind):
    """Storage and conversions shared by the three kinds (one slot: the coordinates)."""

    __slots__ = ("_xyz",)
    # Stops numpy from treating a value as an array in ufuncs and operators, so `R @ p` with a raw R
    # reaches our __rmatmul__ (which refuses) instead of silently returning a bare ndarray.
    __array_ufunc__ = None
    _frame: ClassVar[str]
    _xyz: np.ndarray
    # Largest accepted input magnitude (a direction is rescaled, so any finite length will do).
    _largest_input: ClassVar[float] = LARGEST_COORDINATE

    def __init__(self, xyz: ArrayLike) -> None:
        cls = type(self)
        if "_frames" not in cls.__dict__:
            raise GeometryTypeError(
                f"{cls.__name__} needs a frame: write {cls.__name__}[World](xyz) with a Frame class, "
                f"or {cls.__name__}['camera'](xyz) with a frame name"
            )
        self._xyz = self._prepared(checked_array(xyz, _COORD_SHAPES, "xyz", cls.__name__, self._largest_input))

    def _prepared(self, xyz: np.ndarray) -> np.ndarray:
        return xyz

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __radd__(self, other: object) -> Any:
            if isinstance(other, np.ndarray):
                raise _refuse_with_ndarray(self, other, "+", "Vector")
            return NotImplemented

    @classmethod
    def _wrap(cls, frame: str, xyz: np.ndarray) -> Any:
        """A value of this kind in ``frame`` around computed coordinates (no validation, no copy)."""
        try:
            framed = cls._by_frame_name[frame]
        except KeyError:
            framed = cls.framed_class(frame)
        obj: Any = object.__new__(framed)
        obj._xyz = xyz
        return obj

    # ---- introspection ------------------------------------------------------------------------------------

    @property
    def frame(self) -> str:
        """The name of the frame the coordinates are expressed in."""
        return self._frame

    @property
    def xyz(self) -> NDArray[np.float64]:
        """The coordinates, read-only, shape (3,) or (N, 3)."""
        return read_only(self._xyz)

    @property
    def shape(self) -> tuple[int, ...]:
        """(3,) for one value, (N, 3) for a batch."""
        return self._xyz.shape

    @property
    def is_batch(self) -> bool:
        """True for a batch of N values, shape (N, 3)."""
        return self._xyz.ndim == 2

    def __len__(self) -> int:
        if self._xyz.ndim != 2:
            raise GeometryTypeError(f"{describe(self)} is a single value; len() is for batches of shape (N, 3)")
        return int(self._xyz.shape[0])

    def __getitem__(self, index: Any) -> Any:
        if self._xyz.ndim != 2:
            raise GeometryTypeError(
                f"{describe(self)} is a single value; index its coordinates with np.asarray(value)[i]"
            )
        if isinstance(index, tuple):
            raise GeometryTypeError(
                f"{describe(self)}[{', '.join(map(_index_text, index))}]: a batch is indexed by value only (b[i], b[a:b], b[mask]); "
                f"index the coordinates with np.asarray(batch)[...]"
            )
        rows = self._xyz[index]
        if rows.shape[-1:] != (3,) or rows.ndim > 2:  # e.g. b[None]
            raise GeometryTypeError(f"{describe(self)}[{_index_text(index)}] does not select whole values")
        return type(self)._wrap(self._frame, rows)

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __array__(self, dtype: Any = None, copy: bool | None = None) -> np.ndarray:
            if dtype is None and not copy:
                return frozen(self._xyz)
            return np.array(self._xyz, dtype=dtype, copy=True)

    def is_close(self, other: object, atol: float = 1e-9) -> bool:
        """True when ``other`` is the same kind in the same frame with coordinates within ``atol``.

        (``==`` is identity, as for any object: coordinates are floats, compare them with a tolerance.)
        """
        if not isinstance(other, _Coordinates) or other._kind is not self._kind or other._frame != self._frame:
            return False
        return self._xyz.shape == other._xyz.shape and bool(np.allclose(self._xyz, other._xyz, rtol=0.0, atol=atol))

    def _describe(self) -> str:
        return f"{self._kind.__name__}[{self._frame}]"

    @classmethod
    def _from_state(cls, frames: tuple[str, ...], xyz: np.ndarray) -> Any:
        return cls._wrap(frames[0], xyz)

    def __repr__(self) -> str:
        return f"{self._describe()}({format_array(self._xyz)})"

    def __reduce__(self) -> tuple[Any, ...]:
        return (_rebuild, (self._kind.__name__, self._frame, self._xyz))

    # ---- refused operations, with the reason ---------------------------------------------------------------

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __rmatmul__(self, other: object) -> Any:
            raise GeometryTypeError(
                f"{describe(other)} @ {describe(self)}: a raw matrix does not know the kind or frame of the value; "
                f"use a Transform[Dst, {self._frame}] (it applies the translation only to points), or "
                f"np.asarray(value) if you mean plain array math"
            )

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __matmul__(self, other: object) -> Any:
            raise GeometryTypeError(
                f"{describe(self)} @ {describe(other)}: a transform goes on the left (T_dst_src @ value)"
            )

    def __bool__(self) -> bool:
        raise GeometryTypeError(f"the truth value of {describe(self)} is ambiguous; compare np.asarray(value)")


def _index_text(part: Any) -> str:
    """An index as it was written: `:3`, `...`, `0`."""
    if isinstance(part, slice):
        text = ":".join("" if bound is None else repr(bound) for bound in (part.start, part.stop))
        return text + (f":{part.step!r}" if part.step is not None else "")
    return "..." if part is Ellipsis else repr(part)


def _refuse_with_ndarray(value: Any, other: object, operation: str, wrap_as: str) -> GeometryTypeError:
    return GeometryTypeError(
        f"{describe(value)} {operation} {describe(other)}: wrap the array first, e.g. "
        f"{wrap_as}[{value._frame}](array), so its kind and frame are checked"
    )


class Point(_Coordinates, Generic[F]):
    """A location expressed in frame F (homogeneous w = 1): a pose moves it by rotation and translation.

    Parameters
    ----------
    xyz : array_like, shape (3,) or (N, 3)
        Coordinates in F. Copied, checked finite, stored read-only.

    Examples
    --------
    >>> p = Point[World]([0.2, 0.0, 0.0])
    >>> p.frame
    'World'
    >>> q - p                      # Vector[World]
    >>> p + Vector[World]([0, 0, 1])   # Point[World]
    """

    __slots__ = ()

    @overload
    def __sub__(self, other: Point[F]) -> Vector[F]: ...
    @overload
    def __sub__(self, other: Vector[F]) -> Point[F]: ...
    def __sub__(self, other: Point[F] | Vector[F]) -> Vector[F] | Point[F]:
        if isinstance(other, Point):
            check_same_frame(self, other, "-")
            return Vector._wrap(self._frame, self._xyz - other._xyz)  # type: ignore[no-any-return]
        if isinstance(other, Vector):
            check_same_frame(self, other, "-")
            return Point._wrap(self._frame, self._xyz - other._xyz)  # type: ignore[no-any-return]
        if isinstance(other, np.ndarray):
            raise _refuse_with_ndarray(self, other, "-", "Vector")
        return NotImplemented

    def __add__(self, other: Vector[F]) -> Point[F]:
        if isinstance(other, Vector):
            check_same_frame(self, other, "+")
            return Point._wrap(self._frame, self._xyz + other._xyz)  # type: ignore[no-any-return]
        if isinstance(other, Point):
            raise GeometryTypeError(
                f"{describe(self)} + {describe(other)}: adding two points is not defined (the sum depends on "
                f"where the origin is); did you mean p - q (a Vector) or p + (q - p) * 0.5 (a midpoint)?"
            )
        if isinstance(other, np.ndarray):
            raise _refuse_with_ndarray(self, other, "+", "Vector")
        return NotImplemented

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __mul__(self, other: object) -> Any:
            raise GeometryTypeError(
                f"{describe(self)} * {describe(other)}: scaling a point depends on where the origin is; "
                f"scale the vector from a reference point instead: ref + (p - ref) * s"
            )

    if not TYPE_CHECKING:
        __rmul__ = __mul__

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __neg__(self) -> Any:
            raise GeometryTypeError(f"-{describe(self)}: negating a point is not defined; negate a Vector")

    def distance_to(self, other: Point[F]) -> Any:
        """Euclidean distance to another point of the same frame: float, or (N,) for batches."""
        return (other - self).norm()


class Vector(_Coordinates, Generic[F]):
    """A free vector (displacement, velocity, force...) in frame F (homogeneous w = 0): a pose only rotates it.

    Parameters
    ----------
    xyz : array_like, shape (3,) or (N, 3)
        Components in F. Copied, checked finite, stored read-only.
    """

    __slots__ = ()

    @overload
    def __add__(self, other: Point[F]) -> Point[F]: ...
    @overload
    def __add__(self, other: Vector[F]) -> Vector[F]: ...
    def __add__(self, other: Point[F] | Vector[F]) -> Point[F] | Vector[F]:
        if isinstance(other, Vector):
            check_same_frame(self, other, "+")
            return Vector._wrap(self._frame, self._xyz + other._xyz)  # type: ignore[no-any-return]
        if isinstance(other, Point):
            check_same_frame(self, other, "+")
            return Point._wrap(self._frame, self._xyz + other._xyz)  # type: ignore[no-any-return]
        if isinstance(other, np.ndarray):
            raise _refuse_with_ndarray(self, other, "+", "Vector")
        return NotImplemented

    def __sub__(self, other: Vector[F]) -> Vector[F]:
        if isinstance(other, Vector):
            check_same_frame(self, other, "-")
            return Vector._wrap(self._frame, self._xyz - other._xyz)  # type: ignore[no-any-return]
        if isinstance(other, Point):
            raise GeometryTypeError(
                f"{describe(self)} - {describe(other)}: a vector minus a point is not defined; "
                f"did you mean point - vector?"
            )
        if isinstance(other, np.ndarray):
            raise _refuse_with_ndarray(self, other, "-", "Vector")
        return NotImplemented

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __rsub__(self, other: object) -> Any:
            if isinstance(other, np.ndarray):
                raise _refuse_with_ndarray(self, other, "-", "Vector")
            return NotImplemented

    def __neg__(self) -> Vector[F]:
        return Vector._wrap(self._frame, -self._xyz)  # type: ignore[no-any-return]

    # A factor is a real scalar, or for a batch an (N,) array of per-row factors.
    def __mul__(self, factor: float | NDArray[Any]) -> Vector[F]:
        return Vector._wrap(self._frame, _within_range(self._xyz * _scalar_factor(factor, self, "*"), self, "*"))  # type: ignore[no-any-return]

    def __rmul__(self, factor: float | NDArray[Any]) -> Vector[F]:
        return self.__mul__(factor)

    def __truediv__(self, divisor: float | NDArray[Any]) -> Vector[F]:
        factor = _scalar_factor(divisor, self, "/")
        if np.any(factor == 0):
            raise GeometryValueError(f"{describe(self)} / 0: division by zero")
        return Vector._wrap(self._frame, _within_range(self._xyz / factor, self, "/"))  # type: ignore[no-any-return]

    def norm(self) -> Any:
        """Euclidean length: a float for one vector, an (N,) array for a batch."""
        lengths = np.linalg.norm(self._xyz, axis=-1)
        return float(lengths) if lengths.ndim == 0 else lengths

    def dot(self, other: Vector[F]) -> Any:
        """Dot product with a vector of the same frame: float, or (N,) for batches."""
        check_same_frame(self, other, "dot")
        products = np.einsum("...i,...i->...", self._xyz, other._xyz)
        return float(products) if np.ndim(products) == 0 else products

    def cross(self, other: Vector[F]) -> Vector[F]:
        """Cross product with a vector of the same frame, a `Vector[F]`."""
        check_same_frame(self, other, "cross")
        return Vector._wrap(self._frame, np.cross(self._xyz, other._xyz))  # type: ignore[no-any-return]

    def _moved_by(self, transform: Any) -> Any:
        # w = 0: rotation only, never the translation.
        return Vector._wrap(transform._dst, transform.rotate(self._xyz))

    def direction(self) -> Direction[F]:
        """This vector scaled to unit length (raises `GeometryValueError` for a zero vector)."""
        return Direction._wrap(self._frame, _unit(self._xyz, "Direction"))  # type: ignore[no-any-return]


def _within_range(xyz: np.ndarray, owner: Any, operation: str) -> np.ndarray:
    """``xyz`` if its magnitude stays within `LARGEST_COORDINATE` (scaling is how a value can grow past it)."""
    if not (np.abs(xyz) <= LARGEST_COORDINATE).all():
        raise GeometryValueError(
            f"{describe(owner)} {operation} factor: the result would reach {np.abs(xyz).max():.3g}, beyond "
            f"{LARGEST_COORDINATE:g}, where transforms and norms overflow to inf"
        )
    return xyz


def _rescaled_unit(xyz: np.ndarray, owner: str) -> np.ndarray:
    """`_unit` for user input of any finite magnitude: divided by its largest entry first, so squaring
    neither overflows (1e200) nor underflows; the zero-length threshold applies to the true length."""
    largest = np.abs(xyz).max(axis=-1, keepdims=True)
    safe = np.where(largest > 0, largest, 1.0)
    scaled = xyz / safe
    scaled_lengths = np.linalg.norm(scaled, axis=-1, keepdims=True)
    too_short = scaled_lengths < 1e-12 / safe  # the true length below 1e-12, without forming it
    if np.any(too_short):
        where = "" if xyz.ndim == 1 else f" (row {int(np.argmax(too_short[:, 0]))})"
        raise GeometryValueError(f"{owner}: a zero-length vector has no direction{where}")
    unit = scaled / scaled_lengths
    unit.flags.writeable = False
    return unit  # type: ignore[no-any-return]


def _unit(xyz: np.ndarray, owner: str) -> np.ndarray:
    lengths = np.linalg.norm(xyz, axis=-1, keepdims=True)
    if np.any(lengths < 1e-12):
        where = "" if xyz.ndim == 1 else f" (row {int(np.argmin(lengths[:, 0]))})"
        raise GeometryValueError(f"{owner}: a zero-length vector has no direction{where}")
    unit = xyz / lengths
    unit.flags.writeable = False
    return unit  # type: ignore[no-any-return]


class Direction(Vector[F]):
    """A unit vector in frame F (an axis, a surface normal): normalised on construction, rotated only by poses.

    Parameters
    ----------
    xyz : array_like, shape (3,) or (N, 3)
        Any non-zero vector(s); stored scaled to unit length. A zero vector raises `GeometryValueError`.

    Arithmetic returns plain `Vector` values (a sum of two directions is not unit length); negation keeps a `Direction`.
    """

    __slots__ = ()
    _largest_input = float(np.finfo(np.float64).max)

    def _prepared(self, xyz: np.ndarray) -> np.ndarray:
        return _rescaled_unit(xyz, type(self).__name__)

    def __neg__(self) -> Direction[F]:
        # The opposite unit direction is still a unit direction (geolint.algebra.negate).
        return Direction._wrap(self._frame, -self._xyz)  # type: ignore[no-any-return]

    def _moved_by(self, transform: Any) -> Any:
        # Re-normalised so that long chains of (tolerance-limited) rotations cannot drift off unit length.
        return Direction._wrap(transform._dst, _unit(transform.rotate(self._xyz), "Direction"))


_KINDS: dict[str, Any] = {"Point": Point, "Vector": Vector, "Direction": Direction}


def register_kind(kind: type) -> None:
    """Let `pickle` rebuild values of a kind defined in another runtime module."""
    _KINDS[kind.__name__] = kind


def _rebuild(kind_name: str, frames: Any, *state: Any) -> Any:
    kind = _KINDS[kind_name]
    if isinstance(frames, str):
        frames = (frames,)
    return kind._from_state(frames, *state)

