"""geolint: catch geometric type errors (points vs vectors, frames, quaternion order) in Python.

`import geolint` gives the typed geometry runtime (numpy only). The linter lives in
`geolint.api` / `geolint check`, the mypy plugin in `geolint.mypy`.
"""

from typing import TYPE_CHECKING

from geolint._version import __version__

if TYPE_CHECKING:  # checkers see plain imports; at run time the runtime loads on first use
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


if not TYPE_CHECKING:  # a module __getattr__ would make checkers accept any misspelt name

    def __getattr__(name: str) -> object:
        """Import the numpy runtime only when one of its names is used.

        `geolint check`, the language server and the mypy plugin import this package too; loading numpy
        for them would add ~0.15 s to every pre-commit run for nothing.
        """
        if name in __all__ and name != "__version__":
            import geolint.runtime

            value = getattr(geolint.runtime, name)
            globals()[name] = value
            return value
        raise AttributeError(f"module 'geolint' has no attribute {name!r}")
