"""Plain ndarrays annotated with geolint.typing: frame checks and inference on @, np.dot, np.matmul, +, -."""

import numpy as np
from numpy.typing import NDArray

from geolint import Frame
from geolint.typing import (
    DirectionArray,
    PointArray,
    RotationMatrix,
    TransformMatrix,
    Translation,
    VectorArray,
    as_points,
    as_transform,
    as_vectors,
)


class World(Frame):
    pass


class Cam(Frame):
    pass


class Base(Frame):
    pass


def columns(
    R: RotationMatrix[World, Cam], t: Translation[World, Cam], p: PointArray[Cam], n: DirectionArray[Cam],
    v: VectorArray[Cam], p_b: PointArray[Base],
) -> None:
    reveal_type(R @ p + t)  # N: geolint.typing.PointArray[arrays.World]
    reveal_type(R @ n)  # N: geolint.typing.DirectionArray[arrays.World]
    reveal_type(R @ v)  # N: geolint.typing.VectorArray[arrays.World]
    R @ v + t  # E: geo-translation: VectorArray[World] + Translation[World <- Cam]: a translation added to a vector
    R @ n + t  # E: geo-translation: a translation added to a direction
    R @ p_b  # E: geo-frame: RotationMatrix[World <- Cam] applied to PointArray[Base]: expected a PointArray[Cam]
    p_b + t  # E: geo-frame: PointArray[Base] + Translation[World <- Cam]: the operands live in different frames
    reveal_type(np.dot(R, p))  # N: geolint.typing.PointArray[arrays.World]
    np.dot(R, p_b)  # E: geo-frame: applied to PointArray[Base]
    reveal_type(np.matmul(R, v))  # N: geolint.typing.VectorArray[arrays.World]
    np.matmul(R, p_b)  # E: geo-frame: applied to PointArray[Base]
    reveal_type(p - p)  # N: geolint.typing.VectorArray[arrays.Cam]
    p + p  # E: geo-kind: adding two points
    reveal_type(p + v)  # N: geolint.typing.PointArray[arrays.Cam]
    reveal_type(2.0 * n)  # N: geolint.typing.VectorArray[arrays.Cam]
    reveal_type(-n)  # N: geolint.typing.DirectionArray[arrays.Cam]


def rows(R: RotationMatrix[World, Cam], t: Translation[World, Cam], pts: PointArray[Cam], normals: DirectionArray[Cam]) -> None:
    reveal_type(pts @ R.T + t)  # N: geolint.typing.PointArray[arrays.World]
    normals @ R.T + t  # E: geo-translation
    pts @ R  # E: geo-frame: PointArray[Cam] @ RotationMatrix[World <- Cam] (row vectors): expected rows in World


def homogeneous(T: TransformMatrix[World, Cam], T_cb: TransformMatrix[Cam, Base], p: PointArray[Cam], v: VectorArray[Cam]) -> None:
    reveal_type(T[:3, :3])  # N: geolint.typing.RotationMatrix[arrays.World, arrays.Cam]
    reveal_type(T[:3, 3])  # N: geolint.typing.Translation[arrays.World, arrays.Cam]
    reveal_type(T[0:3, -1])  # N: geolint.typing.Translation[arrays.World, arrays.Cam]
    R, t = T[:3, :3], T[:3, 3]
    R @ v + t  # E: geo-translation
    reveal_type(T @ np.append(p, 1))  # N: geolint.typing.HomogeneousPoints[arrays.World]
    reveal_type(T @ np.append(v, 0))  # N: geolint.typing.HomogeneousVectors[arrays.World]
    T @ np.append(v, 1)  # E: geo-translation: the vector was homogenized with w=1
    reveal_type(T @ T_cb)  # N: geolint.typing.TransformMatrix[arrays.World, arrays.Base]
    T_cb @ T  # E: geo-frame: TransformMatrix[Cam <- Base] composed with TransformMatrix[World <- Cam]: expected a TransformMatrix[Base <- Cam]
    reveal_type(np.linalg.inv(T))  # N: geolint.typing.TransformMatrix[arrays.Cam, arrays.World]


def markers(raw: NDArray[np.float64]) -> None:
    reveal_type(as_points(raw, World))  # N: geolint.typing.PointArray[arrays.World]
    reveal_type(as_vectors(raw, "camera"))  # N: geolint.typing.VectorArray[Literal['camera']]
    reveal_type(as_transform(raw, "world", "camera"))  # N: geolint.typing.TransformMatrix[Literal['world'], Literal['camera']]
    reveal_type(raw + raw)  # N: numpy.ndarray[tuple[Any, ...], numpy.dtype[numpy.float64]]
    p = as_points(raw, World)
    q: PointArray[Cam] = p  # E: assignment
    reveal_type(p * p)  # N: numpy.ndarray[tuple[Any, ...], numpy.dtype[numpy.float64]]
