"""geolint.typing with no plugin: plain mypy and pyright keep frames and kinds of annotated arrays apart."""

from typing import Literal

import numpy as np

from geolint import Frame
from geolint.typing import PointArray, RotationMatrix, VectorArray, as_points


class World(Frame):
    pass


class Cam(Frame):
    pass


def frames_and_kinds(R: RotationMatrix[World, Cam], raw: np.ndarray) -> None:
    p = as_points(raw, World)
    q: PointArray[Cam] = p  # expect-error
    back: RotationMatrix[Cam, World] = R.T
    wrong: RotationMatrix[World, Cam] = R.T  # expect-error
    named: PointArray[Literal["camera"]] = as_points(raw, World)  # expect-error
    v: VectorArray[World] = p  # expect-error
    still_an_array: np.ndarray = p
    print(q, back, wrong, named, v, still_an_array)
