"""Frames: named coordinate systems, spelled as classes (``class World(Frame): pass``) or as strings.

A frame is identified by its name only. ``class World(Frame): pass`` is the frame "World";
``class BaseLink(Frame, name="base_link")`` is the frame "base_link", the same frame as the string
``"base_link"``. `frame_name` turns either spelling into the name every runtime value stores.
"""

from __future__ import annotations

import sys
from typing import Any, ClassVar

from geolint.runtime.errors import GeometryTypeError

__all__ = ["Frame", "frame_name"]


class Frame:
    """Base class of frame classes. Subclass it, never instantiate it.

    Examples
    --------
    >>> class World(Frame): pass
    >>> class BaseLink(Frame, name="base_link"): pass
    >>> frame_name(World), frame_name(BaseLink)
    ('World', 'base_link')
    """

    frame_name: ClassVar[str] = "Frame"

    def __init_subclass__(cls, *, name: str | None = None, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        cls.frame_name = _checked_name(cls.__name__ if name is None else name)

    def __new__(cls, *args: Any, **kwargs: Any) -> Frame:
        raise GeometryTypeError(
            f"{cls.__name__} is a frame, used as a type argument (Point[{cls.__name__}]); it has no instances"
        )


def _checked_name(name: object) -> str:
    if not isinstance(name, str) or not name or name != name.strip():
        raise GeometryTypeError(f"a frame name must be a non-empty string without surrounding spaces, got {name!r}")
    # Interned, so frame comparisons on the hot paths are usually an identity check.
    return sys.intern(name)


def frame_name(frame: object) -> str:
    """The name of a frame given as a `Frame` subclass or a string.

    Parameters
    ----------
    frame : type[Frame] or str
        ``World`` (a subclass of `Frame`) or ``"camera"``.

    Returns
    -------
    str
        The frame's name, e.g. ``"World"`` or ``"camera"``.

    Raises
    ------
    GeometryTypeError
        For anything else (an instance, a number, an empty string, a `typing.TypeVar`).
    """
    if isinstance(frame, str):
        return _checked_name(frame)
    if isinstance(frame, type) and issubclass(frame, Frame) and frame is not Frame:
        return frame.frame_name
    raise GeometryTypeError(
        f"expected a frame (a subclass of geolint.Frame, or a frame name string), got {frame!r}"
    )
