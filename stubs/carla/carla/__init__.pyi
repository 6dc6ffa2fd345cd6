from geolint.typing import Degrees

class Rotation:
    """Source: CARLA Python API reference (0.9.16), carla.Rotation: "pitch (float - degrees) Y-axis rotation
    angle", "yaw (float - degrees) Z-axis rotation angle", "roll (float - degrees) X-axis rotation angle";
    the constructor is Rotation(pitch=0.0, yaw=0.0, roll=0.0)."""

    def __init__(self, pitch: Degrees = ..., yaw: Degrees = ..., roll: Degrees = ...) -> None: ...
