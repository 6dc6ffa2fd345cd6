from typing import Annotated

from geolint.knowledge.markers import TfFrame
from geolint.typing import QuaternionXYZW, Translation

_Target = Annotated[str, TfFrame.TARGET]
_Source = Annotated[str, TfFrame.SOURCE]

class TransformListener:
    """Source: tf/src/tf/listener.py (ros/geometry fe344b6c), Transformer.lookupTransform(target_frame, source_frame, time),
    inherited by TransformListener: `return [t.x, t.y, t.z], [r.x, r.y, r.z, r.w]` (lines 103-107), a translation and an
    (x, y, z, w) quaternion; lookupTransformFull(target_frame, target_time, source_frame, source_time, fixed_frame) likewise
    (109-113). `canTransform(target_frame, source_frame, time)` and `waitForTransform(target_frame, source_frame, time,
    timeout, polling_sleep_duration)` take the frames in the same order (tf/src/tf/listener.py, Transformer)."""

    def lookupTransform(self, target_frame: _Target, source_frame: _Source, time: object) -> tuple[Translation, QuaternionXYZW]: ...
    def lookupTransformFull(
        self, target_frame: _Target, target_time: object, source_frame: _Source, source_time: object, fixed_frame: str
    ) -> tuple[Translation, QuaternionXYZW]: ...
    def canTransform(self, target_frame: _Target, source_frame: _Source, time: object) -> bool: ...
    def waitForTransform(
        self, target_frame: _Target, source_frame: _Source, time: object, timeout: object, polling_sleep_duration: object = ...
    ) -> None: ...
