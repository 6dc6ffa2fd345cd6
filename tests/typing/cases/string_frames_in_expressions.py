"""String frames wherever a type can be written: aliases, constructors, casts, unions, callables, nested defs."""

from typing import Callable, Optional, cast

import geolint as gl
from geolint import Point as P
from geolint import Transform, Vector

CamPoint = P["camera"]
WorldFromCam = Transform["world", "camera"]


class Holder:
    p: P["camera"]

    def moved(self, T: WorldFromCam) -> Optional[P["world"]]:
        return T @ self.p


def annotations(
    a: list[P["camera"]], b: P["camera"] | None, c: Callable[[P["camera"]], P["world"]], d: gl.Point["camera"],
    e: "P['camera']", f: CamPoint,
) -> None:
    reveal_type(a)  # N: list[geolint.runtime.primitives.Point[Literal['camera']]]
    assert b is not None
    reveal_type(b)  # N: geolint.runtime.primitives.Point[Literal['camera']]
    reveal_type(c)  # N: def (geolint.runtime.primitives.Point[Literal['camera']]) -> geolint.runtime.primitives.Point[Literal['world']]
    reveal_type(d)  # N: geolint.runtime.primitives.Point[Literal['camera']]
    reveal_type(e)  # N: geolint.runtime.primitives.Point[Literal['camera']]
    reveal_type(f)  # N: geolint.runtime.primitives.Point[Literal['camera']]


def frames_named_like_builtins(p: P["map"], q: P["odom"]) -> None:
    reveal_type(p)  # N: geolint.runtime.primitives.Point[Literal['map']]
    reveal_type(cast(P["map"], q))  # N: geolint.runtime.primitives.Point[Literal['map']]


def constructors(T: WorldFromCam) -> None:
    p = P["camera"]([0.2, 0.0, 0.0])
    reveal_type(p)  # N: geolint.runtime.primitives.Point[Literal['camera']]
    reveal_type(T @ Vector["camera"]([1.0, 0.0, 0.0]))  # N: geolint.runtime.primitives.Vector[Literal['world']]
    T @ P["lidar"]([1.0, 2.0, 3.0])  # E: geo-frame: Transform["world" <- "camera"] applied to Point["lidar"]
    moved = [T @ P["camera"](xyz) for xyz in ([1.0, 2.0, 3.0],)]
    reveal_type(moved)  # N: list[geolint.runtime.primitives.Point[Literal['world']]]


def nested() -> None:
    def inner(T: Transform["map", "odom"], p: P["base_link"]) -> None:
        T @ p  # E: geo-frame


def identity() -> None:
    T = Transform.identity("camera")
    reveal_type(T)  # N: geolint.runtime.transform.Transform[Literal['camera'], Literal['camera']]
    T @ P["world"]([1.0, 2.0, 3.0])  # E: geo-frame: Transform["camera" <- "camera"] applied to Point["world"]
