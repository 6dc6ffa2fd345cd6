from geolint.knowledge.markers import ROW_VECTORS, any_receiver
from geolint.typing import DirectionArray, PointArray, TransformMatrix
from typing_extensions import Annotated

# Recognised on any receiver in a module that imports pytorch3d: a `Transform3d` mostly arrives from a
# camera or a helper (`cameras.get_world_to_view_transform()`) whose type a file does not show.
@any_receiver(when_imported=("pytorch3d",))
class Transform3d:
    """Source: pytorch3d/transforms/transform3d.py (06a76ef), class Transform3d: a batch of 4x4 transforms applied to row
    vectors ("points_out = points @ M"); transform_points(points, eps=None) appends a 1 and divides by the fourth coordinate,
    transform_normals(normals) "Use this transform to transform a set of normal vectors" (the inverse transpose of the
    3x3 block, no translation)."""

    def transform_points(self: Annotated[TransformMatrix, ROW_VECTORS], points: PointArray, eps: float | None = ...) -> PointArray: ...
    def transform_normals(self: Annotated[TransformMatrix, ROW_VECTORS], normals: DirectionArray) -> DirectionArray: ...
