"""A project module that re-exports geolint's classes (used by string_frames_through_reexports)."""

from geolint import Point as Point
from geolint import Transform as Transform

__all__ = ["Point", "Transform"]
