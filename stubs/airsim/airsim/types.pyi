from geolint.typing import Degrees, QuaternionXYZW

class Quaternionr:
    """Source: PythonClient/airsim/types.py (1.8.1, 13448700), Quaternionr: `def __init__(self, x_val = 0.0, y_val = 0.0,
    z_val = 0.0, w_val = 1.0)` (line 158); to_numpy_array() is `np.array([self.x_val, self.y_val, self.z_val, self.w_val])`
    (238)."""

    def to_numpy_array(self) -> QuaternionXYZW: ...

class YawMode:
    """Source: AirSim docs/apis.md (1.8.1), line 274: "If `is_rate` is False then `yaw_or_rate` is interpreted as angle in
    degrees", and as degrees/sec when it is True; types.py:282 `YawMode(is_rate=True, yaw_or_rate=0.0)`."""

    def __init__(self, is_rate: bool = ..., yaw_or_rate: Degrees = ...) -> None: ...
