"""`FrameTree`: named frames joined by poses, with lookups between any two frames (a small tf2).

Each edge joins a parent (``T.dst``) to a child (``T.src``); every frame has at most one parent. A lookup
walks up from both frames to their nearest common ancestor and back down, composing poses, as the design
text describes. Edges may hold time-stamped samples; a lookup between samples interpolates (linear
translation, slerp rotation) and a lookup outside them raises `ExtrapolationError` rather than guess.

``tree.transform(value, to=...)`` uses the value's own frame as the source (tf2's ``do_transform_point``
trusts the transform's header and ignores the input's; we don't).
"""

from __future__ import annotations

import bisect
import difflib
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, TypeVar, overload

import numpy as np

from geolint.runtime import rotation as _rotation
from geolint.runtime.errors import (
    DisconnectedFramesError,
    ExtrapolationError,
    FrameCycleError,
    GeometryTypeError,
    GeometryValueError,
    MissingStampError,
    SecondParentError,
    UnknownFrameError,
)
from geolint.runtime.frames import frame_name
from geolint.runtime.primitives import describe
from geolint.runtime.transform import Transform

if TYPE_CHECKING:
    from geolint.runtime.cloud import PointCloud
    from geolint.runtime.primitives import Direction, Point, Vector
    from geolint.runtime.spatial import Covariance, Twist, Wrench

__all__ = ["FrameTree"]

_A = TypeVar("_A")
_B = TypeVar("_B")


@dataclass
class _Edge:
    """The pose of ``child`` in ``parent``: one static transform, or samples sorted by stamp."""

    parent: str
    child: str
    static: Transform[Any, Any] | None = None
    stamps: list[float] = field(default_factory=list)
    samples: list[Transform[Any, Any]] = field(default_factory=list)

    def at(self, stamp: float | None) -> np.ndarray:
        """The 4x4 matrix T_parent_child at ``stamp`` (interpolated between samples)."""
        if self.static is not None:
            return self.static._m
        if stamp is None:
            raise MissingStampError(
                f"the edge {self.parent} -> {self.child} is time-stamped "
                f"({len(self.stamps)} samples, {self.stamps[0]:g} .. {self.stamps[-1]:g}); pass at=<time>"
            )
        first, last = self.stamps[0], self.stamps[-1]
        if stamp < first or stamp > last:
            gap = first - stamp if stamp < first else stamp - last
            side = "before the first" if stamp < first else "after the last"
            raise ExtrapolationError(
                f"lookup at {stamp:g} on the edge {self.parent} -> {self.child} is {gap:g} {side} sample "
                f"(samples cover {first:g} .. {last:g}); FrameTree interpolates but never extrapolates"
            )
        i = bisect.bisect_left(self.stamps, stamp)
        if self.stamps[i] == stamp:
            return self.samples[i]._m
        t0, t1 = self.stamps[i - 1], self.stamps[i]
        return _interpolate(self.samples[i - 1]._m, self.samples[i]._m, (stamp - t0) / (t1 - t0))


def _interpolate(m0: np.ndarray, m1: np.ndarray, fraction: float) -> np.ndarray:
    q0 = _rotation.matrix_to_quat(m0[:3, :3], "xyzw")
    q1 = _rotation.matrix_to_quat(m1[:3, :3], "xyzw")
    out = np.eye(4)
    out[:3, :3] = _rotation.quat_to_matrix(_rotation.slerp(q0, q1, fraction), "xyzw", normalize=True)
    out[:3, 3] = (1 - fraction) * m0[:3, 3] + fraction * m1[:3, 3]
    out.flags.writeable = False
    return out


class FrameTree:
    """A tree of frames; each edge holds the pose of a child frame in its parent, static or time-stamped.

    Examples
    --------
    >>> tree = FrameTree()
    >>> tree.add(T_world_base)                 # edge World -> Base
    >>> tree.add(T_base_cam)                   # edge Base -> Camera
    >>> tree.lookup(World, Camera)             # Transform[World, Camera]
    >>> tree.transform(p_cam, to=World)        # uses p_cam.frame as the source
    """

    def __init__(self) -> None:
        self._edges: dict[str, _Edge] = {}  # child name -> edge to its parent
        self._frames: set[str] = set()

    # ---- building -----------------------------------------------------------------------------------------

    def add(self, transform: Transform[Any, Any], stamp: float | None = None) -> None:
        """Add the edge parent = ``transform.dst`` -> child = ``transform.src``.

        Parameters
        ----------
        transform : Transform
            One pose (not a batch).
        stamp : float, optional
            Time of this sample. Without it the edge is static (adding again replaces it); with it, samples
            accumulate and lookups interpolate between them. An edge is either static or stamped.

        Raises
        ------
        SecondParentError
            The child already has a different parent.
        FrameCycleError
            The parent is the child or one of its descendants.
        """
        if not isinstance(transform, Transform):
            raise GeometryTypeError(f"FrameTree.add expects a Transform, got {describe(transform)}")
        if transform.is_batch:
            raise GeometryValueError("FrameTree.add takes one pose; add a batch as stamped samples one by one")
        stamp = _checked_stamp(stamp, "FrameTree.add: stamp")
        parent, child = transform.dst, transform.src
        edge = self._edges.get(child)
        if edge is not None and edge.parent != parent:
            raise SecondParentError(
                f"{child} already has the parent {edge.parent}; it cannot also be a child of {parent} "
                f"(a frame tree has one parent per frame; add the inverse, Transform[{child}, {parent}], "
                f"if {parent} should hang below {child})"
            )
        if edge is None:
            if parent == child or parent in self._frames and self._is_ancestor(child, parent):
                path = " -> ".join(reversed(self._path_to_root(parent)[: self._path_to_root(parent).index(child) + 1]))
                raise FrameCycleError(
                    f"adding {parent} -> {child} would close a cycle ({path} -> {child})"
                    if parent != child
                    else f"a frame cannot be its own parent ({parent})"
                )
            edge = self._edges[child] = _Edge(parent, child)
        if stamp is None:
            if edge.stamps:
                raise GeometryValueError(
                    f"the edge {parent} -> {child} holds time-stamped samples; add this one with stamp="
                )
            edge.static = transform
        else:
            if edge.static is not None:
                raise GeometryValueError(f"the edge {parent} -> {child} is static; it takes no stamped samples")
            stamp = float(stamp)
            i = bisect.bisect_left(edge.stamps, stamp)
            if i < len(edge.stamps) and edge.stamps[i] == stamp:
                edge.samples[i] = transform
            else:
                edge.stamps.insert(i, stamp)
                edge.samples.insert(i, transform)
        self._frames.update((parent, child))

    def _path_to_root(self, frame: str) -> list[str]:
        path = [frame]
        while frame in self._edges:
            frame = self._edges[frame].parent
            path.append(frame)
        return path

    def _is_ancestor(self, ancestor: str, frame: str) -> bool:
        return ancestor in self._path_to_root(frame)

    # ---- queries ------------------------------------------------------------------------------------------

    @property
    def frames(self) -> tuple[str, ...]:
        """Every frame name, sorted."""
        return tuple(sorted(self._frames))

    def __contains__(self, frame: object) -> bool:
        return frame_name(frame) in self._frames

    def parent(self, frame: Any) -> str | None:
        """The parent of a frame, or None for a root."""
        name = self._known(frame)
        edge = self._edges.get(name)
        return edge.parent if edge else None

    def _known(self, frame: Any) -> str:
        name = frame_name(frame)
        if name not in self._frames:
            close = difflib.get_close_matches(name, self._frames, n=3)
            hint = f"; did you mean {', '.join(close)}?" if close else ""
            known = ", ".join(sorted(self._frames)) or "none yet"
            raise UnknownFrameError(f"unknown frame {name!r} (known frames: {known}){hint}")
        return name

    # Frame classes give typed results; a frame given by name is Any on that side. No catch-all overload:
    # it would let a checker pick it whenever the typed one fails in context, hiding frame errors.
    @overload
    def lookup(self, dst: type[_A], src: type[_B], at: float | None = None) -> Transform[_A, _B]: ...
    @overload
    def lookup(self, dst: type[_A], src: str, at: float | None = None) -> Transform[_A, Any]: ...
    @overload
    def lookup(self, dst: str, src: type[_B], at: float | None = None) -> Transform[Any, _B]: ...
    @overload
    def lookup(self, dst: str, src: str, at: float | None = None) -> Transform[Any, Any]: ...
    def lookup(self, dst: Any, src: Any, at: float | None = None) -> Transform[Any, Any]:
        """The pose of ``src`` in ``dst`` (a ``Transform[dst, src]``), at time ``at`` for stamped edges.

        Walks up from both frames to their nearest common ancestor, composing poses on each side, then
        returns ``inv(T_ancestor_dst) @ T_ancestor_src``.

        Raises
        ------
        UnknownFrameError, DisconnectedFramesError, MissingStampError, ExtrapolationError
        """
        at = _checked_stamp(at, "FrameTree.lookup: at")
        dst_name, src_name = self._known(dst), self._known(src)
        up_from_src = self._path_to_root(src_name)
        up_from_dst = self._path_to_root(dst_name)
        on_src_path = set(up_from_src)
        ancestor = next((frame for frame in up_from_dst if frame in on_src_path), None)
        if ancestor is None:
            raise DisconnectedFramesError(
                f"no path between {dst_name} and {src_name}: they are in different trees "
                f"(rooted at {up_from_dst[-1]} and {up_from_src[-1]}); add an edge that connects them"
            )
        ancestor_from_src = self._chain(up_from_src, ancestor, at)
        ancestor_from_dst = self._chain(up_from_dst, ancestor, at)
        matrix = _inverse(ancestor_from_dst) @ ancestor_from_src
        matrix.flags.writeable = False
        return Transform._wrap(dst_name, src_name, matrix)  # type: ignore[no-any-return]

    def _chain(self, path: list[str], ancestor: str, at: float | None) -> np.ndarray:
        """T_ancestor_frame for ``path[0]``, composing edges up to ``ancestor``."""
        matrix = np.eye(4)
        for frame in path:
            if frame == ancestor:
                break
            matrix = self._edges[frame].at(at) @ matrix
        return matrix

    @overload
    def transform(self, value: Point[Any], to: type[_A], at: float | None = None) -> Point[_A]: ...
    @overload
    def transform(self, value: Direction[Any], to: type[_A], at: float | None = None) -> Direction[_A]: ...
    @overload
    def transform(self, value: Vector[Any], to: type[_A], at: float | None = None) -> Vector[_A]: ...
    @overload
    def transform(self, value: PointCloud[Any], to: type[_A], at: float | None = None) -> PointCloud[_A]: ...
    @overload
    def transform(self, value: Twist[Any], to: type[_A], at: float | None = None) -> Twist[_A]: ...
    @overload
    def transform(self, value: Wrench[Any], to: type[_A], at: float | None = None) -> Wrench[_A]: ...
    @overload
    def transform(self, value: Covariance[Any], to: type[_A], at: float | None = None) -> Covariance[_A]: ...
    @overload
    def transform(self, value: Any, to: str, at: float | None = None) -> Any: ...
    def transform(self, value: Any, to: Any, at: float | None = None) -> Any:
        """``value`` expressed in frame ``to``; the source frame is ``value.frame`` (never a separate argument)."""
        source = getattr(value, "_frame", None)
        if source is None:
            raise GeometryTypeError(
                f"FrameTree.transform needs a framed value (Point, Vector, Direction, PointCloud, Twist, Wrench, "
                f"Covariance), got {describe(value)}; wrap arrays first, e.g. Point['camera'](xyz)"
            )
        return self.lookup(to, source, at) @ value

    # ---- drawing ------------------------------------------------------------------------------------------

    def to_graph(self) -> Any:
        """The tree as a `geolint.render.FrameGraph` (edges parent -> child, labelled T_parent_child)."""
        from geolint.render import FrameEdge, FrameGraph

        edges = tuple(
            FrameEdge(
                parent=edge.parent,
                child=edge.child,
                label=f"T_{edge.parent}_{edge.child}"
                + ("" if edge.static is not None else f" ({len(edge.stamps)} stamped samples)"),
            )
            for edge in self._edges.values()
        )
        return FrameGraph(edges=edges, frames=self.frames, name="frame_tree")

    def to_dot(self) -> str:
        """The tree in Graphviz DOT (drawn by the shared renderer `geolint.render.render_dot`)."""
        from geolint.render import render_dot

        return render_dot(self.to_graph())

    def __repr__(self) -> str:
        return f"FrameTree(<{len(self._frames)} frames, {len(self._edges)} edges>)"


def _checked_stamp(stamp: Any, what: str) -> float | None:
    """A time stamp given by the user: None, or a finite real number (not a bool, a string or a list)."""
    if stamp is None:
        return None
    if isinstance(stamp, (bool, np.bool_)) or not isinstance(stamp, (int, float, np.integer, np.floating)):
        raise GeometryTypeError(f"{what} must be a number (a time), got {type(stamp).__name__} {stamp!r}")
    if not np.isfinite(stamp):
        raise GeometryValueError(f"{what} must be a finite number (a time), got {stamp!r}")
    return float(stamp)


def _inverse(matrix: np.ndarray) -> np.ndarray:
    rt = matrix[:3, :3].T
    out = np.eye(4)
    out[:3, :3] = rt
    out[:3, 3] = -rt @ matrix[:3, 3]
    return out
