from geolint.typing import QuaternionXYZW, Translation

class TransformListener:
    """Source: tf/src/tf/listener.py (ros/geometry fe344b6c), Transformer.lookupTransform(target_frame, source_frame, time),
    inherited by TransformListener: `return [t.x, t.y, t.z], [r.x, r.y, r.z, r.w]` (lines 103-107), a translation and an
    (x, y, z, w) quaternion; lookupTransformFull(target_frame, target_time, source_frame, source_time, fixed_frame) likewise
    (109-113)."""

    def lookupTransform(self, target_frame: str, source_frame: str, time: object) -> tuple[Translation, QuaternionXYZW]: ...
    def lookupTransformFull(self, target_frame: str, target_time: object, source_frame: str, source_time: object, fixed_frame: str) -> tuple[Translation, QuaternionXYZW]: ...
