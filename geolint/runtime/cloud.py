"""`PointCloud[F]`: N points with optional unit normals in one frame, moved as the design text's step 8 says.

A cloud mixes two kinds in one value: positions (w = 1) and surface normals (w = 0). ``T @ cloud``
partitions them by kind, moves the points by rotation and translation and the normals by rotation only,
and merges them back, so a normal can never pick up the translation (the classic ``do_transform_cloud`` bug).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar, Generic, TypeVar

import numpy as np

from geolint.runtime._framed import FramedKind, checked_array, frozen
from geolint.runtime.errors import GeometryTypeError, GeometryValueError
from geolint.runtime.primitives import Direction, Point, _rescaled_unit, _unit, describe, register_kind

if TYPE_CHECKING:
    from numpy.typing import ArrayLike, NDArray

__all__ = ["PointCloud"]

F = TypeVar("F")


class PointCloud(FramedKind, Generic[F]):
    """N points in frame F, each with an optional unit surface normal.

    Parameters
    ----------
    points : array_like, shape (N, 3)
        Positions in F.
    normals : array_like, shape (N, 3), optional
        Surface normals in F, one per point; scaled to unit length (a zero normal is rejected).
    """

    __slots__ = ("_points", "_normals")
    __array_ufunc__ = None
    _frame: ClassVar[str]
    _points: np.ndarray
    _normals: np.ndarray | None

    def __init__(self, points: ArrayLike, normals: ArrayLike | None = None) -> None:
        cls = type(self)
        if "_frames" not in cls.__dict__:
            raise GeometryTypeError("PointCloud needs a frame: PointCloud[World](points=..., normals=...)")
        owner = self._describe()
        self._points = checked_array(points, ((-1, 3),), "points", owner)
        if normals is None:
            self._normals = None
        else:
            raw = checked_array(normals, ((-1, 3),), "normals", owner, float(np.finfo(np.float64).max))
            if raw.shape[0] != self._points.shape[0]:
                raise GeometryValueError(
                    f"{owner}: {self._points.shape[0]} points but {raw.shape[0]} normals; give one normal per point"
                )
            self._normals = _rescaled_unit(raw, f"{owner} normals")

    @classmethod
    def _wrap(cls, frame: str, points: np.ndarray, normals: np.ndarray | None) -> Any:
        try:
            framed = PointCloud._by_frame_name[frame]
        except KeyError:
            framed = PointCloud.framed_class(frame)
        obj: Any = object.__new__(framed)
        obj._points = points
        obj._normals = normals
        return obj

    @property
    def frame(self) -> str:
        """The name of the frame of the points and normals."""
        return self._frame

    @property
    def points(self) -> Point[F]:
        """The positions as a batch `Point[F]` of shape (N, 3)."""
        return Point._wrap(self._frame, self._points)  # type: ignore[no-any-return]

    @property
    def normals(self) -> Direction[F] | None:
        """The normals as a batch `Direction[F]` of shape (N, 3), or None."""
        if self._normals is None:
            return None
        return Direction._wrap(self._frame, self._normals)  # type: ignore[no-any-return]

    def __len__(self) -> int:
        return int(self._points.shape[0])

    def _describe(self) -> str:
        return f"PointCloud[{self._frame}]"

    def __repr__(self) -> str:
        with_normals = "with" if self._normals is not None else "without"
        return f"{self._describe()}(<{len(self)} points {with_normals} normals>)"

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __array__(self, dtype: Any = None, copy: bool | None = None) -> np.ndarray:
            if dtype is None and not copy:
                return frozen(self._points)
            return np.array(self._points, dtype=dtype, copy=True)

    def __reduce__(self) -> tuple[Any, ...]:
        from geolint.runtime.primitives import _rebuild

        return (_rebuild, ("PointCloud", self._frame, self._points, self._normals))

    @classmethod
    def _from_state(cls, frames: tuple[str, ...], points: np.ndarray, normals: np.ndarray | None) -> Any:
        return cls._wrap(frames[0], points, normals)

    def _moved_by(self, transform: Any) -> Any:
        # Step 8 of the design text: partition by kind, transform each part by its own rule, merge.
        points = transform.rotate(self._points)
        points += transform._translation_block()
        normals = None
        if self._normals is not None:
            normals = _unit(transform.rotate(self._normals), "normals")
        return PointCloud._wrap(transform._dst, points, normals)

    def normal_lengths(self) -> NDArray[np.float64]:
        """The length of every normal, shape (N,) (all 1.0 for a correctly transformed cloud)."""
        if self._normals is None:
            raise GeometryValueError(f"{self._describe()} has no normals")
        return np.linalg.norm(self._normals, axis=1)  # type: ignore[no-any-return]

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __matmul__(self, other: object) -> Any:
            raise GeometryTypeError(f"{self._describe()} @ {describe(other)}: a transform goes on the left")

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __rmatmul__(self, other: object) -> Any:
            raise GeometryTypeError(
                f"{describe(other)} @ {self._describe()}: use a Transform[Dst, {self._frame}] so that normals get "
                f"the rotation only"
            )


register_kind(PointCloud)
