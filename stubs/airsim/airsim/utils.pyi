from airsim.types import Quaternionr
from geolint.typing import Radians

def to_quaternion(pitch: Radians, roll: Radians, yaw: Radians) -> Quaternionr:
    """Source: PythonClient/airsim/utils.py (1.8.1, 13448700), to_quaternion(pitch, roll, yaw), lines 83-95: pitch first,
    radians (`math.cos(yaw * 0.5)`, no conversion); returns a Quaternionr."""

def to_eularian_angles(q: Quaternionr) -> tuple[Radians, Radians, Radians]:
    """Source: PythonClient/airsim/utils.py (1.8.1), to_eularian_angles(q), lines 55-80: `return (pitch, roll, yaw)`, from
    math.atan2/asin (radians)."""
