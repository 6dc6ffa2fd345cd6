from geolint.typing import Radians

from pyquaternion import Quaternion as Quaternion

def quaternion_yaw(q: object) -> Radians:
    """Source: nuscenes/eval/common/utils.py (1.2.0), quaternion_yaw: ":return: Yaw angle in radians"."""

def yaw_diff(gt_box: object, eval_box: object, period: float = ...) -> Radians:
    """Source: nuscenes/eval/common/utils.py (1.2.0), yaw_diff: ":return: Yaw angle difference in radians in
    [0, pi]"; `from pyquaternion import Quaternion` at the module's top (re-exported above)."""
