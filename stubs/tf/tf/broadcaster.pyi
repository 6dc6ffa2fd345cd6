from typing import Annotated

from geolint.knowledge.markers import TfFrame
from geolint.typing import QuaternionXYZW, Translation

class TransformBroadcaster:
    """Source: tf/src/tf/broadcaster.py (ros/geometry fe344b6c), `def sendTransform(self, translation, rotation, time, child,
    parent):` (lines 44-66): the child frame before the parent, and ":param rotation: the rotation of the transformation as a
    tuple (x, y, z, w)"."""

    def sendTransform(
        self, translation: Translation, rotation: QuaternionXYZW, time: object, child: Annotated[str, TfFrame.CHILD], parent: Annotated[str, TfFrame.PARENT]
    ) -> None: ...
