"""GEO215 image-not-in-optical-frame: an image stamped with a camera's body frame, not its optical frame."""

from __future__ import annotations

import re
from ast import Assign, Attribute, Constant, Name
from typing import ClassVar, Final

from geolint.factbase.frame_ids import PARENT_PATH, frame_string
from geolint.factbase.library_calls import knowledge, library_type
from geolint.factbase.tf_statements import frame_name
from geolint.knowledge import knowledge_base
from geolint.knowledge.markers import CameraAxes
from geolint.rules.base import Invalid, RuleTrigger, Valid
from geolint.rules.fact_rule import FactRule
from geolint.rules.frames.tf_tree_rule import ModuleTfTree

_OPTICAL: Final = "optical"


def _camera_message(api: object) -> bool:
    """A message class whose `header` the stubs mark with the OpenCV camera axes (an optical frame)."""
    signatures = getattr(api, "signatures", ())
    return bool(getattr(api, "is_class", False)) and any(
        parameter.name == "header" and parameter.geometry is not None and parameter.geometry.camera_axes == CameraAxes.OPENCV
        for signature in signatures
        for parameter in signature.parameters
    )


class _CameraText:
    """The module stamps something and names a camera message class, or a call that returns one."""

    def __init__(self) -> None:
        self._names: re.Pattern[str] | None = None

    @property
    def pattern(self) -> str:
        return self._compiled().pattern

    def _compiled(self) -> re.Pattern[str]:
        if self._names is None:
            kb = knowledge_base()
            classes = {api.qualified_name for api in kb.apis() if _camera_message(api)}
            returning = {
                api.qualified_name for api in kb.apis() if any(signature.returns is not None and signature.returns.type_name in classes for signature in api.signatures)
            }
            self._names = re.compile("|".join(sorted(re.escape(name.rpartition(".")[2]) for name in classes | returning)))
        return self._names

    def search(self, source: str, /) -> bool:
        return "frame_id" in source and self._compiled().search(source) is not None

    def search_with(self, source: str, config: object, /) -> bool:
        return self.search(source)


class ImageNotInOpticalFrame(FactRule):
    """An image or camera-info message is stamped with a camera's body frame, whose optical frame the project publishes.

    ## What it does
    Flags `msg.header.frame_id = "camera_link"` on a `sensor_msgs` `Image`, `CompressedImage` or
    `CameraInfo` (built here, or returned by cv_bridge's `cv2_to_imgmsg`) when the project's tf tree
    (its URDF, launch files and nodes) publishes a child of that frame named as an optical frame
    (`camera_link` → `camera_optical_frame`), and offers that frame instead.

    ## Why is this bad?
    REP 103 and the messages' own definitions put camera data in the optical frame: x right, y down,
    z forward into the image. A body frame such as `camera_link` follows the robot convention (x
    forward, z up). Stamped with it, every consumer that projects the image into 3D (depth to points,
    detections to poses, rviz) rotates it by the 90° turns between the two, so points appear on the
    ceiling or behind the robot.

    ## Example
    ```python
    image = bridge.cv2_to_imgmsg(frame, "bgr8")
    image.header.frame_id = "camera_link"
    ```

    ## Use instead
    ```python
    image = bridge.cv2_to_imgmsg(frame, "bgr8")
    image.header.frame_id = "camera_optical_frame"
    ```

    ## Fix safety
    The fix names the optical frame the project publishes under the stamped one. It is unsafe: a
    driver that rotates its images into the body frame itself is rare, but possible.

    ## Known problems
    Only frames the code fixes and messages whose type the analysis knows are checked, and only where
    the project itself publishes exactly one optical child of the stamped frame.

    ## References
    - [REP 103: Standard Units of Measure and Coordinate Conventions](https://www.ros.org/reps/rep-0103.html), "Suffix Frames"
    """

    code = "GEO215"
    name = "image-not-in-optical-frame"
    triggers: ClassVar[RuleTrigger | None] = _CameraText()

    VALID = [
        Valid(
            "import tf\nfrom sensor_msgs.msg import Image\nbroadcaster = tf.TransformBroadcaster()\n"
            "def publish(frame, now):\n    broadcaster.sendTransform((0, 0, 0), (0.5, -0.5, 0.5, -0.5), now, 'camera_optical_frame', 'camera_link')\n"
            "    image = Image()\n    image.header.frame_id = 'camera_optical_frame'\n    return image\n"
        ),
        Valid(  # the project publishes no optical frame under the stamped one
            "from sensor_msgs.msg import Image\n"
            "def publish(frame):\n    image = Image()\n    image.header.frame_id = 'camera_link'\n    return image\n"
        ),
    ]
    INVALID = [
        Invalid(
            "import tf\nfrom cv_bridge import CvBridge\nbridge = CvBridge()\nbroadcaster = tf.TransformBroadcaster()\n"
            "def publish(frame, now):\n    broadcaster.sendTransform((0, 0, 0), (0.5, -0.5, 0.5, -0.5), now, 'camera_optical_frame', 'camera_link')\n"
            "    image = bridge.cv2_to_imgmsg(frame, 'bgr8')\n    image.header.frame_id = 'camera_link'\n    return image\n",
            expected_fix="import tf\nfrom cv_bridge import CvBridge\nbridge = CvBridge()\nbroadcaster = tf.TransformBroadcaster()\n"
            "def publish(frame, now):\n    broadcaster.sendTransform((0, 0, 0), (0.5, -0.5, 0.5, -0.5), now, 'camera_optical_frame', 'camera_link')\n"
            "    image = bridge.cv2_to_imgmsg(frame, 'bgr8')\n    image.header.frame_id = 'camera_optical_frame'\n    return image\n",
            message="`image` is camera data (sensor_msgs Image), whose frame is the camera's optical frame (x right, y down, z forward), but it is stamped with 'camera_link'; the project publishes 'camera_optical_frame' under 'camera_link' (example.py:6)",
            range=(8, 29, 8, 42),
        ),
    ]

    def run(self) -> None:
        facts = self.facts
        kb = knowledge(facts)
        tree: ModuleTfTree | None = None
        for node in facts.index.nodes(Assign):
            assert isinstance(node, Assign)
            target = node.targets[0] if len(node.targets) == 1 else None
            owner = _stamped_owner(target)
            if owner is None:
                continue
            frame = frame_name(frame_string(node.value, facts.index))
            if frame is None or _OPTICAL in frame.lower():
                continue
            type_name = library_type(facts, owner)  # the one type every definition reaching it gives
            api = kb.api(type_name) if type_name is not None else None
            if api is None or type_name is None or not _camera_message(api):
                continue
            if tree is None:
                tree = facts.shared(ModuleTfTree)
            if tree.is_test:
                return
            graph = tree.whole_graph()
            optical = sorted({child for child, parents in graph.parents.items() if frame in parents and _OPTICAL in child.lower()})
            if len(optical) != 1:
                continue
            where = min(graph.parents[optical[0]][frame], key=lambda edge: edge.place).place
            literal = isinstance(node.value, Constant)
            self.report(
                node.value,
                f"`{owner.id}` is camera data (sensor_msgs {type_name.rpartition('.')[2]}), whose frame is the camera's optical "
                f"frame (x right, y down, z forward), but it is stamped with {frame!r}; the project publishes {optical[0]!r} "
                f"under {frame!r} ({tree.where(where)})",
                replacement=repr(optical[0]) if literal else None,
                applicability="unsafe",
                fix_description=f"Stamp with {optical[0]!r}",
                frames=(frame, optical[0]),
            )


def _stamped_owner(target: object) -> Name | None:
    """`image` of `image.header.frame_id = ...`."""
    if not (isinstance(target, Attribute) and target.attr == PARENT_PATH[1] and isinstance(target.value, Attribute)):
        return None
    header = target.value
    return header.value if header.attr == PARENT_PATH[0] and isinstance(header.value, Name) else None
