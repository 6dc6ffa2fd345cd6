"""Exceptions raised by the geolint runtime.

Every runtime error derives from `GeolintError`, so ``except GeolintError`` catches them all. Each one also
derives from the matching builtin (`TypeError`, `ValueError`, `LookupError`) so code written against plain
numpy's exceptions keeps working.
"""

from __future__ import annotations

__all__ = [
    "GeolintError",
    "GeometryTypeError",
    "GeometryValueError",
    "FrameMismatchError",
    "InvalidRotationError",
    "FrameTreeError",
    "UnknownFrameError",
    "DisconnectedFramesError",
    "SecondParentError",
    "FrameCycleError",
    "MissingStampError",
    "ExtrapolationError",
]


class GeolintError(Exception):
    """Base class of every error the geolint runtime raises."""


class GeometryTypeError(GeolintError, TypeError):
    """An operation that is not valid algebra for these kinds (point + point, a raw ndarray where a typed value
    is required, a value without a frame)."""


class GeometryValueError(GeolintError, ValueError):
    """Coordinates of the wrong shape, NaN or infinite entries, a zero-length direction."""


class FrameMismatchError(GeolintError, ValueError):
    """Two values that must share a frame do not, e.g. ``Transform[World <- Camera] applied to Point[Base]``."""


class InvalidRotationError(GeolintError, ValueError):
    """A matrix or quaternion that is not a proper rotation within tolerance (the message says by how much)."""


class FrameTreeError(GeolintError, LookupError):
    """Base class of the errors raised by `FrameTree`."""


class UnknownFrameError(FrameTreeError):
    """A frame name the tree has never seen."""


class DisconnectedFramesError(FrameTreeError):
    """Two frames of the tree that share no common ancestor."""


class SecondParentError(FrameTreeError):
    """An edge that would give a frame a second parent (a frame tree has exactly one parent per frame)."""


class FrameCycleError(FrameTreeError):
    """An edge that would close a cycle in the frame tree."""


class MissingStampError(FrameTreeError):
    """A lookup without ``at=`` through an edge that only has time-stamped samples."""


class ExtrapolationError(FrameTreeError, ValueError):
    """A lookup at a time outside the stamped samples of an edge (we interpolate, never extrapolate)."""
