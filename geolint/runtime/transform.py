"""`Transform[Dst, Src]`: a rigid pose that maps coordinates in Src into Dst (it reads like ``T_dst_src``).

Stored as one float64 4x4 matrix (or a batch (N, 4, 4)), validated once on construction: rotation block
orthonormal with det +1 (see `geolint.runtime.rotation`), bottom row (0, 0, 0, 1), every entry finite.
Values computed by the runtime (compositions, inverses) skip re-validation.

``T @ value`` applies the point-versus-vector contract: points get R p + t, vectors and directions R v,
point clouds move points by (R, t) and normals by R, twists and wrenches by the adjoint. ``T_ab @ T_bc`` is a
``Transform[A, C]``. Any frame disagreement raises `FrameMismatchError` naming both frames, e.g.
``Transform[World <- Camera] applied to Point[Base]: expected a Point[Camera]``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar, Generic, TypeVar, overload

import numpy as np

from geolint.runtime import rotation as _rotation
from geolint.runtime._framed import FramedKind, checked_array, checked_tolerance, format_array, frozen, read_only
from geolint.runtime.errors import FrameMismatchError, GeometryTypeError, GeometryValueError
from geolint.runtime.frames import frame_name
from geolint.runtime.primitives import Direction, Point, Vector, describe, register_kind

if TYPE_CHECKING:
    from numpy.typing import ArrayLike, NDArray

    from geolint.runtime.cloud import PointCloud
    from geolint.runtime.rotation import QuatOrder
    from geolint.runtime.spatial import Covariance, Twist, Wrench

__all__ = ["Transform", "Dst", "Src"]

Dst = TypeVar("Dst")
Src = TypeVar("Src")
_Mid = TypeVar("_Mid")
_F = TypeVar("_F")

_EYE4 = np.eye(4)
_EYE4.flags.writeable = False


class Transform(FramedKind, Generic[Dst, Src]):
    """The pose of frame Src in frame Dst: maps Src coordinates into Dst (``T_dst_src``).

    Parameters
    ----------
    rotation : array_like, shape (3, 3) or (N, 3, 3), optional
        R_dst_src. Identity when omitted.
    translation : array_like, shape (3,) or (N, 3), optional
        t_dst_src, the origin of Src expressed in Dst. Zero when omitted.
    tolerance : float, optional
        Largest accepted max |R^T R - I| (default `geolint.runtime.rotation.DEFAULT_TOLERANCE`, 1e-6).
    orthonormalize : bool, default False
        Project a slightly-off rotation onto SO(3) instead of rejecting it.

    Examples
    --------
    >>> T_world_cam = Transform[World, Camera](rotation=R, translation=[0.3, 0.1, 0.5])
    >>> T_world_cam @ Point[Camera]([0.2, 0, 0])        # Point[World]
    >>> T_world_cam.inverse()                           # Transform[Camera, World]
    """

    # _r and _t are views of _m made on first use (left unset until then: a fresh composition pays nothing).
    __slots__ = ("_m", "_r", "_t")
    __array_ufunc__ = None  # `ndarray @ T` must reach __rmatmul__, which explains what to do
    _frame_arity: ClassVar[int] = 2
    _dst: ClassVar[str]
    _src: ClassVar[str]
    _m: np.ndarray
    _r: np.ndarray
    _t: np.ndarray
    # Transform is not a framed value: `getattr(T, "_frame", None)` in dispatch must find None quickly.
    _frame: ClassVar[None] = None

    @classmethod
    def _label(cls, *frames: str) -> str:
        return f"Transform[{frames[0]}, {frames[1]}]"

    @classmethod
    def _frame_attributes(cls, *frames: str) -> dict[str, Any]:
        return {"_dst": frames[0], "_src": frames[1]}

    def __init__(
        self,
        rotation: ArrayLike | None = None,
        translation: ArrayLike | None = None,
        *,
        tolerance: float | None = None,
        orthonormalize: bool = False,
    ) -> None:
        owner = self._owner_name()
        r = _EYE4[:3, :3] if rotation is None else checked_array(rotation, ((3, 3), (-1, 3, 3)), "rotation", owner)
        t = np.zeros(3) if translation is None else checked_array(translation, ((3,), (-1, 3)), "translation", owner)
        batch = max(r.ndim - 2, t.ndim - 1)
        if batch:
            n_r = r.shape[0] if r.ndim == 3 else None
            n_t = t.shape[0] if t.ndim == 2 else None
            if n_r is not None and n_t is not None and n_r != n_t:
                raise GeometryValueError(
                    f"{owner}: {n_r} rotations but {n_t} translations; a batch needs one of each per pose"
                )
            n = n_r if n_r is not None else n_t
            matrix: np.ndarray = np.zeros((n or 0, 4, 4))
        else:
            matrix = np.zeros((4, 4))
        matrix[..., :3, :3] = self._checked_rotation(r, tolerance, orthonormalize, owner)
        matrix[..., :3, 3] = t
        matrix[..., 3, 3] = 1.0
        self._set_matrix(matrix)

    def _owner_name(self) -> str:
        cls = type(self)
        if "_frames" not in cls.__dict__:
            raise GeometryTypeError(
                "Transform needs its two frames: Transform[World, Camera](...) maps Camera coordinates into World"
            )
        return self._describe()

    @staticmethod
    def _checked_rotation(r: np.ndarray, tolerance: float | None, orthonormalize: bool, owner: str) -> np.ndarray:
        if orthonormalize:
            return _rotation.orthonormalize(r, owner)
        tolerance = _rotation.DEFAULT_TOLERANCE if tolerance is None else checked_tolerance(tolerance, owner)
        _rotation.validate_rotation(r, tolerance, owner)
        return r

    def _set_matrix(self, matrix: np.ndarray) -> None:
        matrix.flags.writeable = False
        self._m = matrix

    @classmethod
    def _wrap(cls, dst: str, src: str, matrix: np.ndarray) -> Any:
        """A transform around a matrix the runtime computed (no validation, no copy)."""
        try:
            framed = Transform._framed_classes[(dst, src)]
        except KeyError:
            framed = Transform.framed_class(dst, src)
        obj: Any = object.__new__(framed)
        obj._m = matrix
        return obj

    # ---- constructors -----------------------------------------------------------------------------------

    @classmethod
    def from_matrix(
        cls, matrix: ArrayLike, *, tolerance: float | None = None, orthonormalize: bool = False
    ) -> Transform[Dst, Src]:
        """A transform from a homogeneous matrix.

        Parameters
        ----------
        matrix : array_like, shape (4, 4) or (N, 4, 4)
            [[R, t], [0, 0, 0, 1]] mapping Src coordinates into Dst.
        tolerance, orthonormalize
            As for the constructor.
        """
        self = object.__new__(cls)
        owner = self._owner_name()
        m = checked_array(matrix, ((4, 4), (-1, 4, 4)), "matrix", owner)
        bottoms = m[..., 3, :].reshape(-1, 4)
        wrong = np.flatnonzero((bottoms != (0.0, 0.0, 0.0, 1.0)).any(axis=1))
        if wrong.size:
            where = f" (matrix {wrong[0]} of the batch)" if m.ndim == 3 else ""
            raise GeometryValueError(
                f"{owner}: the bottom row of a homogeneous transform must be [0, 0, 0, 1], got "
                f"{format_array(bottoms[wrong[0]])}{where}"
            )
        out = np.array(m)
        out[..., :3, :3] = self._checked_rotation(m[..., :3, :3], tolerance, orthonormalize, owner)
        self._set_matrix(out)
        return self

    @classmethod
    def from_quat(
        cls,
        quat: ArrayLike,
        translation: ArrayLike | None = None,
        *,
        order: QuatOrder,
        tolerance: float | None = None,
        normalize: bool = False,
    ) -> Transform[Dst, Src]:
        """A transform from unit quaternion(s) and translation(s).

        Parameters
        ----------
        quat : array_like, shape (4,) or (N, 4)
            The rotation R_dst_src.
        translation : array_like, shape (3,) or (N, 3), optional
            t_dst_src (zero when omitted).
        order : {"xyzw", "wxyz"}
            Required, no default: scipy and ROS messages use "xyzw", pytransform3d and Eigen's constructor "wxyz".
        tolerance : float, optional
            Largest accepted | |q| - 1 | (default 1e-6) unless ``normalize``.
        normalize : bool, default False
            Scale non-unit quaternions instead of rejecting them.
        """
        owner = object.__new__(cls)._owner_name()
        q = checked_array(quat, ((4,), (-1, 4)), "quat", owner)
        tol = _rotation.DEFAULT_TOLERANCE if tolerance is None else checked_tolerance(tolerance, owner)
        r = _rotation.quat_to_matrix(q, order, tol, normalize, owner)
        return cls(rotation=r, translation=translation)

    @classmethod
    def from_scipy(cls, rotation: Any, translation: ArrayLike | None = None) -> Transform[Dst, Src]:
        """A transform from a ``scipy.spatial.transform.Rotation`` (plus ``translation``) or ``RigidTransform``."""
        if hasattr(rotation, "as_matrix") and type(rotation).__name__ == "RigidTransform":
            if translation is not None:
                raise GeometryValueError("a RigidTransform already holds its translation; do not pass translation=")
            return cls.from_matrix(rotation.as_matrix())
        if type(rotation).__name__ != "Rotation":
            raise GeometryTypeError(f"from_scipy expects a scipy Rotation or RigidTransform, got {describe(rotation)}")
        return cls(rotation=rotation.as_matrix(), translation=translation)

    @overload
    @staticmethod
    def identity(frame: type[_F]) -> Transform[_F, _F]: ...
    @overload
    @staticmethod
    def identity(frame: str) -> Transform[Any, Any]: ...
    @staticmethod
    def identity(frame: Any) -> Transform[Any, Any]:
        """The identity transform of a frame, ``Transform[F, F]``."""
        name = frame_name(frame)
        return Transform._wrap(name, name, _EYE4)  # type: ignore[no-any-return]

    # ---- parts --------------------------------------------------------------------------------------------

    @property
    def dst(self) -> str:
        """The destination frame (where results are expressed), the first type argument."""
        return self._dst

    @property
    def src(self) -> str:
        """The source frame (what the transform accepts), the second type argument."""
        return self._src

    @property
    def matrix(self) -> NDArray[np.float64]:
        """The homogeneous matrix, read-only, shape (4, 4) or (N, 4, 4)."""
        return read_only(self._m)

    @property
    def rotation(self) -> NDArray[np.float64]:
        """R_dst_src, read-only, shape (3, 3) or (N, 3, 3)."""
        return read_only(self._rotation_block())

    @property
    def translation(self) -> NDArray[np.float64]:
        """t_dst_src (the origin of Src in Dst), read-only, shape (3,) or (N, 3)."""
        return read_only(self._translation_block())

    def _rotation_block(self) -> np.ndarray:
        """R as a plain view of the matrix, made once (the runtime's own arithmetic uses these)."""
        try:
            return self._r
        except AttributeError:
            r = self._r = self._m[..., :3, :3]
            return r

    def _translation_block(self) -> np.ndarray:
        try:
            return self._t
        except AttributeError:
            t = self._t = self._m[..., :3, 3]
            return t

    @property
    def is_batch(self) -> bool:
        """True for a batch of N poses, matrix shape (N, 4, 4)."""
        return self._m.ndim == 3

    def __len__(self) -> int:
        if self._m.ndim != 3:
            raise GeometryTypeError(f"{self._describe()} is a single pose; len() is for batches")
        return int(self._m.shape[0])

    def __getitem__(self, index: Any) -> Transform[Dst, Src]:
        if self._m.ndim != 3:
            raise GeometryTypeError(f"{self._describe()} is a single pose; only batches can be indexed")
        if isinstance(index, tuple):
            raise GeometryTypeError(
                f"{self._describe()}[{', '.join(map(_index_text, index))}]: a batch of poses is indexed by pose only "
                f"(T[i], T[a:b], T[mask], T[[i, j]]); for the numbers use T.matrix[...], T.rotation or T.translation"
            )
        matrices = self._m[index]
        if matrices.shape[-2:] != (4, 4) or matrices.ndim > 3:  # e.g. T[None]
            raise GeometryTypeError(f"{self._describe()}[{_index_text(index)}] does not select whole poses")
        return Transform._wrap(self._dst, self._src, matrices)  # type: ignore[no-any-return]

    def _describe(self) -> str:
        return f"Transform[{self._dst} <- {self._src}]"

    def __repr__(self) -> str:
        head = f"Transform[{self._dst}, {self._src}]"
        if self._m.ndim == 3:
            return f"{head}(<batch of {self._m.shape[0]} poses>)"
        return f"{head}(rotation={format_array(self._rotation_block())}, translation={format_array(self._translation_block())})"

    def __reduce__(self) -> tuple[Any, ...]:
        from geolint.runtime.primitives import _rebuild

        return (_rebuild, ("Transform", (self._dst, self._src), self._m))

    @classmethod
    def _from_state(cls, frames: tuple[str, str], matrix: np.ndarray) -> Any:
        return cls._wrap(frames[0], frames[1], matrix)

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __array__(self, dtype: Any = None, copy: bool | None = None) -> np.ndarray:
            if dtype is None and not copy:
                return frozen(self._m)
            return np.array(self._m, dtype=dtype, copy=True)

    # ---- conversions --------------------------------------------------------------------------------------

    def as_quat(self, order: QuatOrder) -> NDArray[np.float64]:
        """The rotation as unit quaternion(s) with non-negative scalar part, in the required ``order``."""
        return _rotation.matrix_to_quat(self._rotation_block(), order)

    def as_scipy(self) -> Any:
        """A ``scipy.spatial.transform.RigidTransform`` (scipy >= 1.16) of the same pose(s)."""
        try:
            from scipy.spatial.transform import RigidTransform  # type: ignore[import-untyped, unused-ignore]
        except ImportError as error:  # pragma: no cover - depends on the installed scipy
            raise ImportError(
                "as_scipy() needs scipy >= 1.16 (RigidTransform); use as_scipy_rotation() and .translation"
            ) from error
        return RigidTransform.from_matrix(self._m)

    def as_scipy_rotation(self) -> Any:
        """The rotation part as a ``scipy.spatial.transform.Rotation``."""
        from scipy.spatial.transform import Rotation  # type: ignore[import-untyped, unused-ignore]

        return Rotation.from_matrix(self.rotation)

    # ---- algebra ------------------------------------------------------------------------------------------

    def inverse(self) -> Transform[Src, Dst]:
        """The inverse pose ``T_src_dst``: rotation R^T, translation -R^T t."""
        m = self._m
        rt = np.swapaxes(m[..., :3, :3], -1, -2)
        inv = np.zeros(m.shape)
        inv[..., :3, :3] = rt
        inv[..., :3, 3] = -(rt @ m[..., :3, 3, None])[..., 0]
        inv[..., 3, 3] = 1.0
        inv.flags.writeable = False
        return Transform._wrap(self._src, self._dst, inv)  # type: ignore[no-any-return]

    @overload
    def __matmul__(self, other: Transform[Src, _Mid]) -> Transform[Dst, _Mid]: ...
    @overload
    def __matmul__(self, other: Point[Src]) -> Point[Dst]: ...
    @overload
    def __matmul__(self, other: Direction[Src]) -> Direction[Dst]: ...
    @overload
    def __matmul__(self, other: Vector[Src]) -> Vector[Dst]: ...
    @overload
    def __matmul__(self, other: PointCloud[Src]) -> PointCloud[Dst]: ...
    @overload
    def __matmul__(self, other: Twist[Src]) -> Twist[Dst]: ...
    @overload
    def __matmul__(self, other: Wrench[Src]) -> Wrench[Dst]: ...
    @overload
    def __matmul__(self, other: Covariance[Src]) -> Covariance[Dst]: ...
    def __matmul__(self, other: Any) -> Any:
        frame = getattr(other, "_frame", None)
        if frame is None:
            if isinstance(other, Transform):
                # Composition, inlined like the point path below.
                if other._dst is not self._src and other._dst != self._src:
                    raise self._composition_mismatch(other)
                try:
                    matrix = self._m @ other._m
                except ValueError:  # only batches of different sizes get here
                    raise self._batch_mismatch(other) from None
                if matrix.ndim == 3 and self._m.ndim == other._m.ndim and self._m.shape[0] != other._m.shape[0]:
                    raise self._batch_mismatch(other)  # numpy broadcast a batch of 1 against a batch of N
                try:
                    cls = _TRANSFORM_CLASSES[(self._dst, other._src)]
                except KeyError:
                    cls = Transform.framed_class(self._dst, other._src)
                composed: Any = _new(cls)
                composed._m = matrix
                return composed
            raise self._refusal(other)
        if frame is not self._src and frame != self._src:
            raise FrameMismatchError(
                f"{self._describe()} applied to {describe(other)}: expected a {other._kind.__name__}[{self._src}]"
            )
        if isinstance(other, Point):
            # The hot path: inlined (no helper calls) because one point costs only ~1 us in plain numpy.
            xyz = other._xyz
            if self._m.ndim == 2:
                try:
                    r = self._r
                    t = self._t
                except AttributeError:
                    r = self._rotation_block()
                    t = self._translation_block()
                # (R @ X.T).T is numpy's fastest kernel for (N, 3) input (see benchmarks/bench_runtime.py).
                out = r @ xyz if xyz.ndim == 1 else (r @ xyz.T).T
                out += t
            else:
                out = self._apply_batch(xyz, translate=True)
            try:
                cls = _POINT_CLASSES[self._dst]
            except KeyError:
                cls = Point.framed_class(self._dst)
            result: Any = _new(cls)
            result._xyz = out
            return result
        moved_by = getattr(other, "_moved_by", None)
        if moved_by is None:
            raise self._refusal(other)
        return moved_by(self)

    def rotate(self, xyz: np.ndarray) -> np.ndarray:
        """R x for coordinates of shape (3,) or (N, 3) (pose i to row i for a batch); no frame checks."""
        if self._m.ndim == 2:
            r = self._rotation_block()
            return r @ xyz if xyz.ndim == 1 else (r @ xyz.T).T  # type: ignore[no-any-return]
        return self._apply_batch(xyz, translate=False)

    def _apply_batch(self, xyz: np.ndarray, translate: bool) -> np.ndarray:
        m = self._m
        n = m.shape[0]
        if xyz.ndim == 2 and xyz.shape[0] != n:
            raise GeometryValueError(
                f"{self._describe()} is a batch of {n} poses but the value has {xyz.shape[0]} rows; "
                f"pose i applies to row i, so the counts must match (or pass one value for all poses)"
            )
        out = (m[:, :3, :3] @ np.broadcast_to(xyz, (n, 3))[:, :, None])[:, :, 0]
        if translate:
            out += m[:, :3, 3]
        return out  # type: ignore[no-any-return]

    def _composition_mismatch(self, other: Transform[Any, Any]) -> FrameMismatchError:
        return FrameMismatchError(
            f"{self._describe()} @ {other._describe()}: composing needs the inner frames to match; "
            f"expected a Transform[{self._src} <- ...]"
        )

    def _batch_mismatch(self, other: Transform[Any, Any]) -> GeometryValueError:
        return GeometryValueError(
            f"{self._describe()} @ {other._describe()}: batches of {self._m.shape[0]} and {other._m.shape[0]} "
            f"poses; composition pairs pose i with pose i, so the counts must match"
        )

    def _refusal(self, other: object) -> GeometryTypeError:
        if isinstance(other, np.ndarray):
            return GeometryTypeError(
                f"{self._describe()} @ {describe(other)}: a raw array does not say whether it holds points or "
                f"vectors; wrap it as Point[{self._src}](array) (rotation and translation) or "
                f"Vector[{self._src}](array) (rotation only), or use T.matrix for plain array math"
            )
        return GeometryTypeError(f"{self._describe()} @ {describe(other)}: not a geometric value of geolint")

    if not TYPE_CHECKING:  # see "Hidden from type checkers" in the module docstring
        def __rmatmul__(self, other: object) -> Any:
            raise GeometryTypeError(
                f"{describe(other)} @ {self._describe()}: write T.matrix for plain array math, or compose Transforms"
            )

    def __bool__(self) -> bool:
        raise GeometryTypeError(f"the truth value of {self._describe()} is ambiguous")

    def is_close(self, other: Transform[Dst, Src], atol: float = 1e-9) -> bool:
        """True when the frames match and every matrix entry agrees within ``atol``."""
        if (self._dst, self._src) != (other._dst, other._src):
            return False
        return bool(np.allclose(self._m, other._m, rtol=0.0, atol=atol))


def _index_text(part: Any) -> str:
    """An index as it was written: `:3`, `...`, `0`."""
    if isinstance(part, slice):
        text = ":".join("" if bound is None else repr(bound) for bound in (part.start, part.stop))
        return text + (f":{part.step!r}" if part.step is not None else "")
    return "..." if part is Ellipsis else repr(part)


register_kind(Transform)
# Module-level aliases for the hot paths in Transform.__matmul__ (saves attribute lookups per call).
_POINT_CLASSES = Point._by_frame_name
_TRANSFORM_CLASSES = Transform._framed_classes
_new = object.__new__

