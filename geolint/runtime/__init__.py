"""The typed geometry runtime: points, vectors, directions, transforms, clouds, twists, wrenches, frame trees.

Depends on numpy only (scipy is imported inside the interop methods). Every public name is re-exported
from `geolint`.
"""

from geolint.runtime.cloud import PointCloud
from geolint.runtime.errors import (
    DisconnectedFramesError,
    ExtrapolationError,
    FrameCycleError,
    FrameMismatchError,
    FrameTreeError,
    GeolintError,
    GeometryTypeError,
    GeometryValueError,
    InvalidRotationError,
    MissingStampError,
    SecondParentError,
    UnknownFrameError,
)
from geolint.runtime.frames import Frame, frame_name
from geolint.runtime.frametree import FrameTree
from geolint.runtime.primitives import Direction, Point, Vector
from geolint.runtime.spatial import Covariance, Twist, Wrench
from geolint.runtime.transform import Transform

__all__ = [
    "Frame",
    "frame_name",
    "Point",
    "Vector",
    "Direction",
    "Transform",
    "PointCloud",
    "Twist",
    "Wrench",
    "Covariance",
    "FrameTree",
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
