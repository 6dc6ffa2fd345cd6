"""A frame class declared with ``name=`` (or named like a string frame) is that string frame to the plugin's
checks, as it is at runtime. mypy's own assignment checks still tell the two spellings apart."""

from geolint import Frame, Point, Transform, Vector


class Optical(Frame, name="camera_optical"):
    pass


class World(Frame):
    pass


def mixed_spellings(
    T: Transform["world", "camera_optical"],
    T_class: Transform[World, Optical],
    p: Point[Optical],
    q: Point["camera_optical"],
    v: Vector["camera_optical"],
) -> None:
    reveal_type(T @ p)  # N: geolint.runtime.primitives.Point[Literal['world']]
    reveal_type(T_class @ q)  # N: geolint.runtime.primitives.Point[named_frames.World]
    reveal_type(p - q)  # N: geolint.runtime.primitives.Vector[named_frames.Optical]
    reveal_type(p + v)  # N: geolint.runtime.primitives.Point[named_frames.Optical]
    p.is_close(q)
    T @ Point["camera"]([1.0, 2.0, 3.0])  # E: geo-frame: applied to Point["camera"]: expected a Point["camera_optical"]
    T_class @ Point["Optical"]([1.0, 2.0, 3.0])  # E: geo-frame: Transform[World <- Optical ("camera_optical")] applied to Point["Optical"]: expected a Point[Optical ("camera_optical")]
    same: Point["camera_optical"] = p  # E: assignment
