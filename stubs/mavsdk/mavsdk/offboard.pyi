from geolint.typing import Degrees

class PositionNedYaw:
    """Source: mavsdk/offboard.py (3.15.3, 4fab80e), PositionNedYaw(north_m, east_m, down_m, yaw_deg), line 294: "Yaw in
    degrees (0 North, positive is clock-wise looking from above)" (290)."""

    def __init__(self, north_m: float, east_m: float, down_m: float, yaw_deg: Degrees) -> None: ...

class VelocityNedYaw:
    """Source: mavsdk/offboard.py (3.15.3), VelocityNedYaw(north_m_s, east_m_s, down_m_s, yaw_deg), line 578: yaw in degrees (574)."""

    def __init__(self, north_m_s: float, east_m_s: float, down_m_s: float, yaw_deg: Degrees) -> None: ...

class Attitude:
    """Source: mavsdk/offboard.py (3.15.3), Attitude(roll_deg, pitch_deg, yaw_deg, thrust_value), line 29: "Roll angle (in
    degrees, positive is right side down)" (16)."""

    def __init__(self, roll_deg: Degrees, pitch_deg: Degrees, yaw_deg: Degrees, thrust_value: float) -> None: ...
