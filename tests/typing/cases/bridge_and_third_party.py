"""Runtime values through raw numpy, and the third-party calls with frame-aware signatures."""

import numpy as np
import pytransform3d.transformations as pt
import trimesh

from geolint import Frame, Point, Transform, Vector
from geolint.typing import PointArray, TransformMatrix, VectorArray


class World(Frame):
    pass


class Cam(Frame):
    pass


def through_matrix(T: Transform[World, Cam], p: Point[Cam], v: Vector[Cam]) -> None:
    reveal_type(np.asarray(p))  # N: geolint.typing.PointArray[bridge_and_third_party.Cam]
    reveal_type(T.matrix)  # N: geolint.typing.TransformMatrix[bridge_and_third_party.World, bridge_and_third_party.Cam]
    reveal_type(T.matrix @ np.append(np.asarray(p), 1))  # N: geolint.typing.HomogeneousPoints[bridge_and_third_party.World]
    T.matrix @ np.append(np.asarray(v), 1)  # E: geo-translation: TransformMatrix[World <- Cam] applied to VectorWithW1[Cam]
    reveal_type(T.rotation @ np.asarray(v))  # N: geolint.typing.VectorArray[bridge_and_third_party.World]
    T.rotation @ np.asarray(v) + T.translation  # E: geo-translation


def with_trimesh(T: TransformMatrix[World, Cam], pts: PointArray[Cam], normals: VectorArray[Cam], elsewhere: PointArray[World]) -> None:
    reveal_type(trimesh.transform_points(pts, T))  # N: geolint.typing.PointArray[bridge_and_third_party.World]
    trimesh.transform_points(normals, T)  # E: geo-translation: trimesh.transform_points translates its input
    reveal_type(trimesh.transform_points(normals, T, translate=False))  # N: geolint.typing.VectorArray[bridge_and_third_party.World]
    trimesh.transform_points(elsewhere, T)  # E: geo-frame: TransformMatrix[World <- Cam] applied to PointArray[World]


def with_pytransform3d(A2B: TransformMatrix[World, Cam], p: PointArray[Cam], v: VectorArray[Cam]) -> None:
    reveal_type(pt.vector_to_point(p))  # N: geolint.typing.HomogeneousPoints[bridge_and_third_party.Cam]
    pt.vector_to_point(v)  # E: geo-translation: vector_to_point gives VectorArray[Cam] w=1
    reveal_type(pt.vector_to_direction(v))  # N: geolint.typing.HomogeneousVectors[bridge_and_third_party.Cam]
    reveal_type(pt.transform(A2B, pt.vector_to_point(p)))  # N: geolint.typing.HomogeneousPoints[bridge_and_third_party.World]
    reveal_type(pt.transform(A2B, pt.vector_to_direction(v)))  # N: geolint.typing.HomogeneousVectors[bridge_and_third_party.World]
    reveal_type(pt.vector_to_point(np.zeros(3)))  # N: numpy.ndarray[tuple[Any, ...], numpy.dtype[Any]]
