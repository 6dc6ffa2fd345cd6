"""Shared machinery of the runtime's framed values: subscripting a kind with frames, and checked input arrays.

``Point[World]`` builds (once, then caches) a subclass of `Point` whose class attribute ``_frame`` is
``"World"``; the instances of that subclass are the points in World. ``Point["World"]`` is the same class.
Type variables (``Point[F]`` in a generic signature evaluated at runtime) are handed to `typing.Generic`, so
the classes stay ordinary generics for type checkers and for ``typing.get_type_hints``.

The frame lives on the class, not the instance: a value's frame costs no memory and a frame comparison is a
comparison of two interned strings.
"""

from __future__ import annotations

import typing
from typing import Any, ClassVar

import numpy as np

from geolint.runtime.errors import GeometryTypeError, GeometryValueError
from geolint.runtime.frames import Frame, frame_name

__all__ = [
    "FramedKind",
    "LARGEST_COORDINATE",
    "ReadOnlyArray",
    "is_frame_argument",
    "resolve_frame",
    "checked_array",
    "checked_tolerance",
    "frozen",
    "read_only",
    "format_array",
]

# Inputs beyond this magnitude are refused: squares (norms) and a few sums and products of such values
# stay finite, so no operation of the runtime can overflow to inf without an error.
LARGEST_COORDINATE = 1e150


def is_frame_argument(item: object) -> bool:
    """True for what names a frame at runtime: a string, a `Frame` subclass, or ``Literal["name"]``."""
    if isinstance(item, str):
        return True
    if isinstance(item, type) and issubclass(item, Frame):
        return True
    return typing.get_origin(item) is typing.Literal


def resolve_frame(item: object) -> str:
    """The frame name of a subscript argument (see `is_frame_argument`)."""
    if typing.get_origin(item) is typing.Literal:
        args = typing.get_args(item)
        if len(args) != 1:
            raise GeometryTypeError(f"a frame literal names one frame, got {item!r}")
        item = args[0]
    return frame_name(item)


class FramedKind:
    """Mixin for the value kinds subscripted by frames (`Point`, `Transform`, ...).

    Each kind class (a direct user-facing class such as `Point`) owns a cache ``_framed_classes`` from frame
    names to its framed subclasses, created lazily by `framed_class`.
    """

    __slots__ = ()

    # Set on each kind class by __init_subclass__; the framed subclasses share their kind's cache.
    _kind: ClassVar[Any]
    _framed_classes: ClassVar[dict[Any, type]]
    # For one-frame kinds, the same classes keyed by the bare name (a hot-path lookup without a tuple).
    _by_frame_name: ClassVar[dict[str, type]]
    _by_argument: ClassVar[dict[Any, type]]
    # How many frames the kind is subscripted with: 1 for Point[F], 2 for Transform[Dst, Src].
    _frame_arity: ClassVar[int] = 1

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        if "_frames" not in cls.__dict__:  # a kind class, not one of its framed subclasses
            cls._kind = cls
            cls._framed_classes = {}
            cls._by_frame_name = {}
            cls._by_argument = {}

    def __class_getitem__(cls, item: Any) -> Any:  # implicitly a classmethod
        if "_frames" in cls.__dict__:
            raise GeometryTypeError(f"{cls.__name__} already has its frames; it cannot be subscripted again")
        try:
            return cls._by_argument[item]
        except (KeyError, TypeError):
            pass
        items = item if isinstance(item, tuple) else (item,)
        if not all(is_frame_argument(one) for one in items):
            if any(isinstance(one, (typing.TypeVar, typing.ForwardRef)) or one is typing.Any for one in items):
                # A generic signature evaluated at runtime: let typing build the usual alias.
                return super(FramedKind, cls).__class_getitem__(item)  # type: ignore[misc]  # pyright: ignore  # Generic's
        if len(items) != cls._frame_arity:
            want = "one frame" if cls._frame_arity == 1 else f"{cls._frame_arity} frames"
            example = f"{cls.__name__}[World]" if cls._frame_arity == 1 else f"{cls.__name__}[World, Camera]"
            raise GeometryTypeError(f"{cls.__name__} takes {want} ({example}), got {item!r}")
        framed = cls.framed_class(*(resolve_frame(one) for one in items))
        try:
            cls._by_argument[item] = framed
        except TypeError:
            pass
        return framed

    @classmethod
    def framed_class(cls, *frames: str) -> Any:
        """The subclass of this kind for the given frame names (created once, then cached)."""
        try:
            return cls._framed_classes[frames]
        except KeyError:
            pass
        kind = cls._kind
        label = kind._label(*frames)
        namespace: dict[str, Any] = {
            "__slots__": (),
            "__module__": kind.__module__,
            "__qualname__": label,
            "_frames": frames,
        }
        namespace.update(kind._frame_attributes(*frames))
        created = type(kind)(label, (kind,), namespace)
        # setdefault: if two threads race here, both get the first class, so `type(p) is Point[World]` holds.
        framed = kind._framed_classes.setdefault(frames, created)
        if len(frames) == 1:
            kind._by_frame_name.setdefault(frames[0], framed)
        return framed

    @classmethod
    def _label(cls, *frames: str) -> str:
        return f"{cls.__name__}[{', '.join(frames)}]"

    @classmethod
    def _frame_attributes(cls, *frames: str) -> dict[str, Any]:
        return {"_frame": frames[0]}


def frozen(array: np.ndarray) -> np.ndarray:
    """``array`` made read-only (in place) before it is handed to the user.

    Values the runtime computes keep a writeable array on the hot paths (setting the flag costs about as
    much as moving one point); every accessor that returns the coordinates freezes them first, so no
    caller can change a value after the fact.
    """
    if array.flags.writeable:
        array.flags.writeable = False
    return array


class ReadOnlyArray(np.ndarray):
    """The arrays a value hands out (``T.matrix``, ``p.xyz``...): writing into one says the value is immutable.

    Results computed from one (``T.matrix * 2``) are plain, writeable ndarrays.
    """

    def __setitem__(self, index: Any, value: Any) -> None:
        if not self.flags.writeable:
            raise _immutable()
        super().__setitem__(index, value)

    def __array_wrap__(self, array: Any, context: Any = None, return_scalar: bool = False) -> Any:
        if return_scalar:
            return array[()]
        return array.view(np.ndarray) if isinstance(array, np.ndarray) else array


def _refuse_in_place(name: str) -> Any:
    def in_place(self: ReadOnlyArray, other: Any) -> Any:
        if not self.flags.writeable:
            raise _immutable()
        return getattr(np.ndarray, name)(self, other)

    in_place.__name__ = name
    return in_place


for _name in ("__iadd__", "__isub__", "__imul__", "__itruediv__", "__ifloordiv__", "__imod__", "__ipow__",
              "__imatmul__", "__iand__", "__ior__", "__ixor__", "__ilshift__", "__irshift__"):
    setattr(ReadOnlyArray, _name, _refuse_in_place(_name))


def _immutable() -> GeometryValueError:
    return GeometryValueError(
        "geolint values are immutable: this array is a read-only view of one; copy it first "
        "(np.array(T.matrix), np.array(p.xyz)) or build a new value"
    )


def read_only(array: np.ndarray) -> ReadOnlyArray:
    """``array`` frozen and viewed as a `ReadOnlyArray`, for an accessor to hand out."""
    if array.flags.writeable:
        array.flags.writeable = False
    return array.view(ReadOnlyArray)


def checked_tolerance(tolerance: Any, owner: str) -> float:
    """A tolerance given by the user: a finite real number >= 0 (NaN would make every check pass)."""
    if isinstance(tolerance, bool) or not isinstance(tolerance, (int, float, np.integer, np.floating)):
        raise GeometryTypeError(f"{owner}: tolerance must be a real number, got {type(tolerance).__name__}")
    if not (0 <= tolerance < np.inf):
        raise GeometryValueError(f"{owner}: tolerance must be a finite number >= 0, got {tolerance!r}")
    return float(tolerance)


def checked_array(
    value: Any, shapes: tuple[tuple[int, ...], ...], what: str, owner: str, largest: float = LARGEST_COORDINATE
) -> np.ndarray:
    """A read-only float64 copy of ``value`` after checking its shape and that every entry is finite
    with a magnitude of at most ``largest`` (default `LARGEST_COORDINATE`).

    Parameters
    ----------
    value : array_like
        The user's input.
    shapes : tuple of shape patterns
        Accepted shapes; ``-1`` stands for the batch size N, e.g. ``((3,), (-1, 3))``.
    what, owner : str
        Names for the error message, e.g. ``"xyz"`` and ``"Point[World]"``.
    """
    if isinstance(value, FramedKind):
        raise GeometryTypeError(
            f"{owner} was given a {type(value).__name__} as {what}; converting between kinds or frames is "
            f"explicit: pass np.asarray(value) if you really mean to relabel it"
        )
    try:
        array = np.asarray(value)
    except (TypeError, ValueError) as error:
        raise GeometryValueError(f"{owner}: {what} is not a numeric array ({error})") from None
    if array.dtype.kind not in "iuf":
        raise GeometryValueError(f"{owner}: {what} must hold real numbers, got dtype {array.dtype}")
    if not any(_shape_matches(array.shape, shape) for shape in shapes):
        accepted = " or ".join(_shape_text(shape) for shape in shapes)
        raise GeometryValueError(f"{owner}: {what} must have shape {accepted}, got {array.shape}")
    array = np.array(array, dtype=np.float64, copy=True)
    if not (np.abs(array) <= largest).all():  # one pass catches NaN, inf and overflow-prone magnitudes
        if not np.isfinite(array).all():
            bad = np.argwhere(~np.isfinite(array))[0]
            raise GeometryValueError(
                f"{owner}: {what} has a non-finite entry ({array[tuple(bad)]} at index {tuple(int(i) for i in bad)})"
            )
        bad = np.argwhere(np.abs(array) > largest)[0]
        raise GeometryValueError(
            f"{owner}: {what} has an entry of magnitude {abs(array[tuple(bad)]):.3g} at index "
            f"{tuple(int(i) for i in bad)}, beyond {largest:g}; values that large overflow to inf in "
            f"transforms and norms (rescale the units)"
        )
    array.flags.writeable = False
    return array


def _shape_matches(actual: tuple[int, ...], pattern: tuple[int, ...]) -> bool:
    return len(actual) == len(pattern) and all(p == -1 or a == p for a, p in zip(actual, pattern))


def _shape_text(pattern: tuple[int, ...]) -> str:
    return "(" + ", ".join("N" if p == -1 else str(p) for p in pattern) + (",)" if len(pattern) == 1 else ")")


def format_array(array: np.ndarray) -> str:
    """Coordinates as in a repr: ``[0.3, 0.3, 0.5]``; long batches are summarised by numpy."""
    return np.array2string(
        np.round(array, 9) + 0.0,  # no "-0.0" for rounding noise
        separator=", ",
        threshold=24,
        formatter={"float_kind": _format_float},  # type: ignore[arg-type]  # pyright: ignore[reportArgumentType]
    ).replace("\n", "")


def _format_float(x: float) -> str:
    return np.format_float_positional(x, precision=6, trim="0", unique=True)
