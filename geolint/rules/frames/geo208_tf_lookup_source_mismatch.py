"""GEO208 tf-lookup-source-mismatch: a looked-up transform applied to a message from another frame."""

from __future__ import annotations

import ast
from ast import Attribute, Call, Constant, Name
from typing import ClassVar

from geolint.factbase import ModuleIndex
from geolint.factbase.frame_ids import CHILD_PATH, PARENT_PATH, StampedFrames
from geolint.factbase.tf_statements import lookup_frames
from geolint.factbase.index import module_constant
from geolint.factbase.pose_parts import call_name
from geolint.factbase.reaching import resolve
from geolint.rules.base import Invalid, RuleTrigger, Valid
from geolint.rules.fact_rule import FactRule
from geolint.rules.triggers import AllOf


class TfLookupSourceMismatch(FactRule):
    """A transform from `lookup_transform(target, source)` is applied to a message stamped in another frame.

    ## What it does
    Flags `do_transform_point/vector3/pose/pose_stamped/cloud(msg, transform)` where `transform`
    comes from `buffer.lookup_transform(target, source, ...)` (tf2_ros `Buffer`), or is a
    `TransformStamped` whose `child_frame_id` the function set to `source`, and the function set
    `msg.header.frame_id` to a literal frame that is not `source`. The lookup is followed through
    local names, through `self.t` when the class sets it only to lookups of the same frames (a
    timer that refreshes it), and through a function of the module that returns one. Frames are
    compared as literals (or module constants holding literals), leading slashes ignored.

    ## Why is this bad?
    `lookup_transform(target, source)` returns the transform that maps data expressed in `source`
    into `target`. `do_transform_*` does not check the message's `header.frame_id`: it applies the
    transform whatever frame the data is in and stamps the result with `target`, so data in any
    other frame comes out silently wrong. Swapped target and source arguments are the usual cause.

    ## Example
    ```python
    goal.header.frame_id = "base_link"
    transform = buffer.lookup_transform("base_link", "map", rclpy.time.Time())
    goal_in_map = do_transform_pose_stamped(goal, transform)
    ```

    ## Use instead
    ```python
    goal.header.frame_id = "base_link"
    transform = buffer.lookup_transform("map", "base_link", rclpy.time.Time())
    goal_in_map = do_transform_pose_stamped(goal, transform)
    ```

    ## Fix safety
    There is no automatic fix: either the lookup's arguments or the message's frame is wrong.

    ## Known problems
    The message's frame must be stated in the same function; a message received from a topic, or
    frames read from parameters, are not checked. Prefer `buffer.transform(msg,
    target)`, which looks up the message's own frame.
    """

    code = "GEO208"
    name = "tf-lookup-source-mismatch"
    triggers: ClassVar[RuleTrigger | None] = AllOf(r"do_transform_", r"lookup_transform|lookupTransform|child_frame_id")

    VALID = [
        Valid(
            "def f(buffer, p):\n    p.header.frame_id = 'camera'\n"
            "    t = buffer.lookup_transform('map', 'camera', 0)\n    return do_transform_point(p, t)\n"
        ),
        Valid("def f(buffer, p):\n    t = buffer.lookup_transform('map', 'camera', 0)\n    return do_transform_point(p, t)\n"),
        Valid(
            "def f(buffer, p, frame):\n    p.header.frame_id = frame\n"
            "    t = buffer.lookup_transform('map', 'camera', 0)\n    return do_transform_point(p, t)\n"
        ),
        Valid(  # a new message and a new transform: the first ones' stamps say nothing about them
            "def f():\n    t = TransformStamped()\n    t.child_frame_id = 'b'\n    v = Vector3Stamped()\n"
            "    v.header.frame_id = 'a'\n    t = TransformStamped()\n    v = Vector3Stamped()\n"
            "    return do_transform_vector3(v, t)\n"
        ),
        Valid(
            "def f(p):\n    t = TransformStamped()\n    t.header.frame_id = 'map'\n    t.child_frame_id = 'base_link'\n"
            "    p.header.frame_id = 'base_link'\n    return do_transform_point(p, t)\n"
        ),
        Valid(  # the attribute holds lookups of two different pairs of frames: unknown
            "import tf2_ros\nclass Relay:\n    def a(self):\n        self.t = self.buffer.lookup_transform('map', 'base_link', 0)\n"
            "    def b(self):\n        self.t = self.buffer.lookup_transform('map', 'camera', 0)\n"
            "    def relay(self, p):\n        p.header.frame_id = 'camera'\n        return do_transform_point(p, self.t)\n"
        ),
        Valid(
            "def f(buffer, p):\n    p.header.frame_id = '/camera'\n"
            "    t = buffer.lookup_transform('map', 'camera', 0)\n    return do_transform_point(p, t)\n"
        ),
    ]
    INVALID = [
        Invalid(
            "def f(p, q):\n    t = TransformStamped()\n    t.header.frame_id = 'map'\n    t.child_frame_id = 'odom'\n"
            "    p.header.frame_id = 'base_link'\n    return do_transform_point(p, t)\n",
            message="`p` is stamped in 'base_link', but `t` is stamped with child_frame_id 'odom': it maps data from 'odom', so `do_transform_point` moves `p` from the wrong frame (the message or the transform names the wrong frame)",
            range=(6, 12, 6, 36),
        ),
        Invalid(
            "from tf2_geometry_msgs import do_transform_pose_stamped\n"
            "def f(buffer, goal):\n    goal.header.frame_id = 'base_link'\n"
            "    t = buffer.lookup_transform('base_link', 'map', 0)\n    return do_transform_pose_stamped(goal, t)\n"
        ),
        Invalid(  # the lookup kept on the node by another method
            "import tf2_ros\nclass Relay:\n    def on_timer(self):\n        self.to_map = self.buffer.lookup_transform('base_link', 'map', 0)\n"
            "    def relay(self, goal):\n        goal.header.frame_id = 'base_link'\n        return do_transform_pose_stamped(goal, self.to_map)\n",
            message="`goal` is stamped in 'base_link', but `self.to_map` is lookup_transform('base_link', 'map'): it maps data from 'map', so `do_transform_pose_stamped` moves `goal` from the wrong frame (swapped lookup arguments?)",
            range=(7, 16, 7, 60),
        ),
        Invalid(  # the lookup made by a helper of the module
            "import tf2_ros\ndef base_to_map(buffer):\n    return buffer.lookup_transform('map', 'base_link', 0)\n"
            "def f(buffer, p):\n    p.header.frame_id = 'camera_link'\n    t = base_to_map(buffer)\n    return do_transform_point(p, t)\n"
        ),
        Invalid(
            "import tf2_geometry_msgs\nCAMERA = 'camera_optical'\nMAP = 'map'\ndef f(buffer, p):\n    p.header.frame_id = CAMERA\n"
            "    t = buffer.lookup_transform(MAP, 'camera_link', 0)\n    return tf2_geometry_msgs.do_transform_point(p, t)\n"
        ),
    ]

    def run(self) -> None:
        facts = self.facts
        index = facts.index
        stamps = StampedFrames(index)
        for node in index.nodes(Call):
            if not (isinstance(node, Call) and (call_name(node) or "").startswith("do_transform_") and len(node.args) >= 2):
                continue
            message, transform = node.args[0], node.args[1]
            if not isinstance(message, Name) or not isinstance(transform, (Name, Attribute)):
                continue
            shown = ast.unparse(transform)
            lookup = lookup_frames(facts, transform)
            if lookup is not None:
                source, target = lookup.source, lookup.target
                stated = f"{lookup.how}({target!r}, {source!r})"
                hint = "swapped lookup arguments?"
            elif isinstance(transform, Name):  # a TransformStamped built here: `t.child_frame_id = "camera"` is the frame it maps from
                source = _literal(stamps.frame_before(transform, node, CHILD_PATH), index)
                stated = f"stamped with child_frame_id {source!r}"
                hint = "the message or the transform names the wrong frame"
            else:
                continue
            stamped = _literal(stamps.frame_before(message, node, PARENT_PATH), index)
            if source is None or stamped is None or stamped.lstrip("/") == source.lstrip("/"):
                continue
            self.report(
                node,
                f"`{message.id}` is stamped in {stamped!r}, but `{shown}` is {stated}: it maps "
                f"data from {source!r}, so `{call_name(node)}` moves `{message.id}` from the wrong frame ({hint})",
                frames=(source.lstrip("/"), stamped.lstrip("/")),
            )


def _literal(node: ast.expr | None, index: ModuleIndex) -> str | None:
    """A string literal, or a name that certainly holds one (a module constant)."""
    if node is None:
        return None
    if isinstance(node, Name):
        resolved = resolve(index, node)
        constant = module_constant(index, node.id) if isinstance(resolved, Name) else resolved
        node = constant if isinstance(constant, ast.expr) else node
    if isinstance(node, Constant) and isinstance(node.value, str):
        return node.value
    return None

