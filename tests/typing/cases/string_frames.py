"""String frames in annotations behave like class frames, with no "name not defined" errors."""

from typing import Literal

from geolint import Frame, Point, Transform, Vector
from geolint.typing import PointArray, as_points


def to_world(T: Transform["world", "camera"], p: Point["camera"]) -> Point["world"]:
    return T @ p


def wrong_frame(T: Transform["world", "camera"], p: Point["base_link"]) -> Point["world"]:
    return T @ p  # E: geo-frame: Transform["world" <- "camera"] applied to Point["base_link"]: expected a Point["camera"]


def literal_is_the_same_type(p: Point[Literal["camera"]]) -> Point["camera"]:
    return p


def strings_are_distinct(p: Point["camera"]) -> Point["world"]:
    return p  # E: return-value


def forward_reference(p: Point["Odom"]) -> Point[Odom]:
    return p


def unusual_names(T: Transform["map", "base_link/lidar"], p: Point["base_link/lidar"]) -> Point["map"]:
    return T @ p


def mixed(T: Transform["world", Cam], v: Vector[Cam]) -> Vector["world"]:
    reveal_type(T @ v)  # N: geolint.runtime.primitives.Vector[Literal['world']]
    return T @ v


def marked(raw: list[float]) -> PointArray["camera"]:
    return as_points(raw, "camera")


class Odom(Frame):
    pass


class Cam(Frame):
    pass


world_point: Point["world"]
camera_point: Point["camera"] = world_point  # E: assignment
