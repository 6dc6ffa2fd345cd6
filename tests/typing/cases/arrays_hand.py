"""The textbook formulas written by hand on annotated arrays: inverse, composition, affine combinations, and the
bugs that look like them."""

import numpy as np

from geolint import Frame
from geolint.typing import PointArray, RotationMatrix, TransformMatrix, Translation, VectorArray


class World(Frame):
    pass


class Cam(Frame):
    pass


class Body(Frame):
    pass


def inverse_point(R: RotationMatrix[World, Cam], t: Translation[World, Cam], p_w: PointArray[World]) -> PointArray[Cam]:
    return R.T @ (p_w - t)


def inverse_translation(R: RotationMatrix[World, Cam], t: Translation[World, Cam]) -> Translation[Cam, World]:
    return -R.T @ t


def inverse_translation_spelled_out(R: RotationMatrix[World, Cam], t: Translation[World, Cam]) -> Translation[Cam, World]:
    reveal_type(-t)  # N: geolint.typing.OriginOffset[arrays_hand.World, arrays_hand.Cam, arrays_hand.World]
    return R.T @ -t


def inverse_matrix(T: TransformMatrix[World, Cam]) -> tuple[RotationMatrix[Cam, World], Translation[Cam, World]]:
    R, t = T[:3, :3], T[:3, 3]
    return R.T, -(R.T @ t)


def compose(R_wc: RotationMatrix[World, Cam], t_wc: Translation[World, Cam], t_cb: Translation[Cam, Body]) -> Translation[World, Body]:
    reveal_type(R_wc @ t_cb)  # N: geolint.typing.OriginOffset[arrays_hand.World, arrays_hand.Cam, arrays_hand.Body]
    return R_wc @ t_cb + t_wc


def compose_other_order(R_wc: RotationMatrix[World, Cam], t_wc: Translation[World, Cam], t_cb: Translation[Cam, Body]) -> Translation[World, Body]:
    return t_wc + R_wc @ t_cb


def composition_bugs(
    R_wc: RotationMatrix[World, Cam], t_wc: Translation[World, Cam], t_cb: Translation[Cam, Body], t_wb: Translation[World, Body]
) -> None:
    t_wc + t_cb  # E: geo-frame: Translation[World <- Cam] + Translation[Cam <- Body]: the operands live in different frames
    R_wc.T @ t_cb  # E: geo-frame: RotationMatrix[Cam <- World] applied to Translation[Cam <- Body]: expected a Translation[World <- Body]
    R_wc @ t_cb + t_wb  # E: geo-frame: does not start where


def midpoints(a: PointArray[World], b: PointArray[World], c: PointArray[World], p_c: PointArray[Cam]) -> PointArray[World]:
    reveal_type((a + b) / 2)  # N: geolint.typing.PointArray[arrays_hand.World]
    reveal_type(0.5 * (a + b))  # N: geolint.typing.PointArray[arrays_hand.World]
    reveal_type((a + b + c) / 3.0)  # N: geolint.typing.PointArray[arrays_hand.World]
    reveal_type(0.25 * a + 0.75 * b)  # N: geolint.typing.PointArray[arrays_hand.World]
    reveal_type((a + b) / 2 - c)  # N: geolint.typing.VectorArray[arrays_hand.World]
    (a + b) / 3  # E: geo-kind: the point weights sum to 0.666667, not 1
    a + b  # E: geo-kind: adding two points
    (a + p_c) / 2  # E: geo-frame: the operands live in different frames
    return (a + b) / 2


def translated_vectors(R: RotationMatrix[World, Cam], t: Translation[World, Cam], v: VectorArray[Cam], p: PointArray[Cam]) -> None:
    R @ v - t  # E: geo-translation: VectorArray[World] - Translation[World <- Cam]: a translation added to a vector
    reveal_type(R @ p - t)  # N: geolint.typing.PointArray[arrays_hand.World]
    p - t  # E: geo-frame: PointArray[Cam] - Translation[World <- Cam]: the operands live in different frames
