"""Every fully qualified name the plugin hooks or builds, in one place.

mypy names a method call after the class of the receiver (``geolint.typing.PointArray.__add__`` even though
the method is inherited from the array class), and a function after the module that defines it (not the one
that re-exports it): the array library's functions are found through the knowledge base
(``KnowledgeBase.api_defined_as``), not named here.
"""

from __future__ import annotations

from typing import Any, cast, get_origin

from geolint import typing as _typing

# --- runtime kinds (geolint.runtime; helper H1's fixed module layout) ---
FRAME = "geolint.runtime.frames.Frame"
POINT = "geolint.runtime.primitives.Point"
VECTOR = "geolint.runtime.primitives.Vector"
DIRECTION = "geolint.runtime.primitives.Direction"
TRANSFORM = "geolint.runtime.transform.Transform"
POINT_CLOUD = "geolint.runtime.cloud.PointCloud"
TWIST = "geolint.runtime.spatial.Twist"
WRENCH = "geolint.runtime.spatial.Wrench"
COVARIANCE = "geolint.runtime.spatial.Covariance"

# --- annotations for plain ndarrays (geolint.typing) ---
TYPING_MODULE = "geolint.typing"
POINT_ARRAY = "geolint.typing.PointArray"
VECTOR_ARRAY = "geolint.typing.VectorArray"
DIRECTION_ARRAY = "geolint.typing.DirectionArray"
ROTATION_MATRIX = "geolint.typing.RotationMatrix"
TRANSFORM_MATRIX = "geolint.typing.TransformMatrix"
TRANSLATION = "geolint.typing.Translation"
HOMOGENEOUS_POINTS = "geolint.typing.HomogeneousPoints"
HOMOGENEOUS_VECTORS = "geolint.typing.HomogeneousVectors"
VECTOR_WITH_W1 = "geolint.typing.VectorWithW1"
ORIGIN_OFFSET = "geolint.typing.OriginOffset"
NEGATED_ROTATION = "geolint.typing.NegatedRotation"
AS_POINTS = "geolint.typing.as_points"
AS_VECTORS = "geolint.typing.as_vectors"
AS_DIRECTIONS = "geolint.typing.as_directions"
AS_ROTATION = "geolint.typing.as_rotation"
AS_TRANSFORM = "geolint.typing.as_transform"
AS_TRANSLATION = "geolint.typing.as_translation"

# --- runtime methods ---
COORDINATE_VALUES = (POINT, VECTOR, DIRECTION)  # batch indexing and is_close

# --- the array class geolint.typing's annotations subclass for the checker (what they are at runtime) ---
def _class_of(annotation: Any) -> Any:
    """The class an annotation stands for, through generic aliases and `type` aliases (numpy defines
    `NDArray` as one on Python 3.12 and later)."""
    for _ in range(8):
        origin = get_origin(annotation)
        if origin is not None:
            annotation = origin
        elif isinstance(annotation, type):
            return annotation
        else:
            annotation = annotation.__value__
    raise TypeError(f"no class behind {annotation!r}")


_ARRAY_CLASS: Any = _class_of(cast(Any, _typing.PointArray)["F"])
NDARRAY = f"{_ARRAY_CLASS.__module__}.{_ARRAY_CLASS.__qualname__}"

# Binary operators the plugin gives frame-aware results.
# The reflected ones matter too: when ``a.__matmul__`` reports a problem, mypy tries ``b.__rmatmul__`` and
# would keep numpy's silent answer unless the plugin reports there as well.
OPERATORS = (
    "__matmul__",
    "__rmatmul__",
    "__add__",
    "__radd__",
    "__sub__",
    "__rsub__",
    "__mul__",
    "__rmul__",
    "__truediv__",
    "__neg__",
)
