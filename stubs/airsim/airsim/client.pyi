from geolint.typing import Degrees, Radians

class MultirotorClient:
    """Source: PythonClient/airsim/client.py (1.8.1, 13448700). rotateToYawAsync(yaw, timeout_sec, margin, vehicle_name)
    (line 1257): degrees, yaw and margin (AirLib MultirotorApiBase.cpp:545 normalises the target with
    `VectorMath::normalizeAngle(yaw)`, whose range is 360); moveByRollPitchYawZAsync (1286): "Roll angle, pitch angle,
    and yaw angle set points are given in **radians**" (1289); simSetCameraFov (781): "fov_degrees (float): Value of
    field of view in degrees"."""

    def rotateToYawAsync(self, yaw: Degrees, timeout_sec: float = ..., margin: Degrees = ..., vehicle_name: str = ...) -> object: ...
    def moveByRollPitchYawZAsync(self, roll: Radians, pitch: Radians, yaw: Radians, z: float, duration: float, vehicle_name: str = ...) -> object: ...
    def simSetCameraFov(self, camera_name: str, fov_degrees: Degrees, vehicle_name: str = ..., external: bool = ...) -> None: ...
