"""geolint: catch geometric type errors (points vs vectors, frames, quaternion order) in Python.

`import geolint` gives the typed geometry runtime (numpy only). The linter lives in
`geolint.api` / `geolint check`, the mypy plugin in `geolint.mypy`.
"""

from geolint._version import __version__
from geolint.runtime import (
    Covariance,
    Direction,
    DisconnectedFramesError,
    ExtrapolationError,
    Frame,
    FrameCycleError,
    FrameMismatchError,
    FrameTree,
    FrameTreeError,
    GeolintError,
    GeometryTypeError,
    GeometryValueError,
    InvalidRotationError,
    MissingStampError,
    Point,
    PointCloud,
    SecondParentError,
    Transform,
    Twist,
    UnknownFrameError,
    Vector,
    Wrench,
    frame_name,
)

__all__ = [
    "__version__",
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
