from geolint.typing import Degrees

class Quaternion:
    """Source: mavsdk/telemetry.py (3.15.3, 4fab80e), Quaternion: `def __init__(self, w, x, y, z, timestamp_us):` (line 637);
    "A zero-rotation quaternion is represented by (1,0,0,0)." (613)."""

    def __init__(self, w: float, x: float, y: float, z: float, timestamp_us: int) -> None: ...

class EulerAngle:
    """Source: mavsdk/telemetry.py (3.15.3), EulerAngle(roll_deg, pitch_deg, yaw_deg, timestamp_us), line 725: "Yaw angle in
    degrees, positive is clock-wise seen from above" (718)."""

    def __init__(self, roll_deg: Degrees, pitch_deg: Degrees, yaw_deg: Degrees, timestamp_us: int) -> None: ...
