"""A frame-generic function called with arguments that disagree on a frame names both frames."""

from typing import TypeVar

from geolint import Frame, Point, Transform, Vector


class World(Frame):
    pass


class Cam(Frame):
    pass


class Body(Frame):
    pass


F = TypeVar("F")
G = TypeVar("G")


def to_world(T: Transform[World, F], p: Point[F]) -> Point[World]:
    return T @ p


def chain(T_ab: Transform[F, G], T_bc: Transform[G, F]) -> Transform[F, F]:
    return T_ab @ T_bc


def run(T_wc: Transform[World, Cam], T_cb: Transform[Cam, Body], p_c: Point[Cam], p_b: Point[Body], v: Vector["base"]) -> None:
    reveal_type(to_world(T_wc, p_c))  # N: geolint.runtime.primitives.Point[generic_calls.World]
    to_world(T_wc, p_b)  # E: geo-frame: to_world(): frame F is Cam from "T" (Transform[World <- Cam]) but Body from "p" (Point[Body])
    moved = to_world(T_wc, p=p_b)  # E: geo-frame: frame F is Cam from "T"
    reveal_type(moved)  # N: geolint.runtime.primitives.Point[generic_calls.World]
    chain(T_wc, T_cb)  # E: geo-frame: chain(): frame F is World from "T_ab" (Transform[World <- Cam]) but Body from "T_bc"
    to_world(T_wc, v)  # E: arg-type
