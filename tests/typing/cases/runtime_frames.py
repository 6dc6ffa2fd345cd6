"""The runtime classes with class frames: the plugin's precise messages and inference."""

from typing import TypeVar

import numpy as np

from geolint import Direction, Frame, Point, Transform, Vector


class World(Frame):
    pass


class Camera(Frame):
    pass


class Base(Frame):
    pass


A = TypeVar("A")
B = TypeVar("B")
C = TypeVar("C")


def apply(T: Transform[A, B], p: Point[B]) -> Point[A]:
    return T @ p


def compose(T_ab: Transform[A, B], T_bc: Transform[B, C]) -> Transform[A, C]:
    return T_ab @ T_bc


def apply_wrong(T: Transform[A, B], p: Point[A]) -> Point[A]:
    return T @ p  # E: geo-frame: Transform[A <- B] applied to Point[A]: expected a Point[B]


def run(
    T_wc: Transform[World, Camera],
    T_cb: Transform[Camera, Base],
    T_bb: Transform[Base, Base],
    p_c: Point[Camera],
    p_b: Point[Base],
    v_c: Vector[Camera],
    d_c: Direction[Camera],
) -> None:
    reveal_type(T_wc @ p_c)  # N: geolint.runtime.primitives.Point[runtime_frames.World]
    reveal_type(T_wc @ v_c)  # N: geolint.runtime.primitives.Vector[runtime_frames.World]
    reveal_type(T_wc @ d_c)  # N: geolint.runtime.primitives.Direction[runtime_frames.World]
    reveal_type(T_wc @ T_cb)  # N: geolint.runtime.transform.Transform[runtime_frames.World, runtime_frames.Base]
    T_wc @ p_b  # E: geo-frame: Transform[World <- Camera] applied to Point[Base]: expected a Point[Camera]
    T_wc @ T_bb  # E: geo-frame: Transform[World <- Camera] composed with Transform[Base <- Base]: expected a Transform[Camera <- Base]
    p_c + p_c  # E: geo-kind: Point[Camera] + Point[Camera]: adding two points
    reveal_type(p_c - p_c)  # N: geolint.runtime.primitives.Vector[runtime_frames.Camera]
    reveal_type(p_c + v_c)  # N: geolint.runtime.primitives.Point[runtime_frames.Camera]
    v_c - p_c  # E: geo-kind: a vector minus a point
    reveal_type(apply(T_wc, p_c))  # N: geolint.runtime.primitives.Point[runtime_frames.World]
    reveal_type(compose(T_wc, T_cb))  # N: geolint.runtime.transform.Transform[runtime_frames.World, runtime_frames.Base]
    reveal_type(T_wc.inverse())  # N: geolint.runtime.transform.Transform[runtime_frames.Camera, runtime_frames.World]
    silenced = T_wc @ p_b  # type: ignore[geo-frame]
    wrong: Point[World] = p_c  # E: assignment


def raw_arrays(T_wc: Transform[World, Camera], p_c: Point[Camera], raw: np.ndarray) -> None:
    T_wc @ raw  # E: geo-kind: Transform[World <- Camera] @ a raw ndarray: its kind and frame are unknown
    p_c + raw  # E: geo-kind: wrap it first, e.g. Vector[Camera](array)
    T_wc @ Point[Camera](raw)
    reveal_type(raw @ raw)  # N: Any
