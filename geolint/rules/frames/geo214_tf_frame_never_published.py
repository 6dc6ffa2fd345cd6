"""GEO214 tf-frame-never-published: a looked-up frame nothing publishes, spelled like one that is."""

from __future__ import annotations

import ast
import re
from ast import Constant
from typing import Final

from geolint.factbase.tf_statements import LookedUp, Published
from geolint.rules.base import Invalid, Valid
from geolint.rules.frames.tf_tree_rule import ModuleTfTree, TfTreeRule

_DIGITS: Final = re.compile(r"\d")
_MIN_LENGTH: Final = 5  # shorter names are too close to each other to call one a misspelling


class TfFrameNeverPublished(TfTreeRule):
    """A frame is looked up that nothing in the project publishes, and a frame spelled almost like it is.

    ## What it does
    Builds the tf tree the whole project states (Python nodes' `sendTransform` calls, static
    transform publishers in Python and XML launch files, URDF and xacro joints) and flags a
    `lookup_transform`, `can_transform`, `lookupTransform`, `waitForTransform`... whose target or
    source frame appears nowhere in it while a frame one edit away does (`base_link` and
    `baselink`, `camera_link` and `camera_lnik`, a different case or `-` for `_`). Frames that differ
    only in their digits (`camera1`, `camera2`) are different frames.

    ## Why is this bad?
    tf2 matches frame ids as exact strings. A misspelt frame is simply unknown: the lookup raises
    `LookupException` (or `can_transform` stays False) forever, and a node that catches the
    exception and retries, as most do, never does its work, with nothing but a log line.

    ## Example
    ```python
    # the URDF has <link name="base_link"/>
    t = buffer.lookup_transform("baselink", "laser", rclpy.time.Time())
    ```

    ## Use instead
    ```python
    t = buffer.lookup_transform("base_link", "laser", rclpy.time.Time())
    ```

    ## Fix safety
    The fix replaces the frame with the published one. It is unsafe: the frame may be published by a
    node outside the project (a driver) under the name the code uses.

    A frame may come from a ROS parameter's declared default (`declare_parameter("imu_frame",
    "imu_lnk")`, `rospy.get_param("~imu_frame", "imu_lnk")`), read through names and `self`
    attributes; the default counts only when no launch file or parameter file of the project sets
    that parameter (`<param>`, `<rosparam>`, a YAML key, a launch action's `parameters=[{...}]`).

    ## Known problems
    Only misspellings of frames the project itself publishes are found; a frame that nothing in the
    project names (published by a driver, a SLAM node, or under a parameter's name) is never
    reported. Parameters are matched by the last part of their name, so a parameter set for another
    node of the project under the same name also makes a default unknown.
    """

    code = "GEO214"
    name = "tf-frame-never-published"

    VALID = [
        Valid(
            "import tf\nbroadcaster = tf.TransformBroadcaster()\nlistener = tf.TransformListener()\n"
            "def run(p, q, now):\n    broadcaster.sendTransform(p, q, now, 'laser', 'base_link')\n"
            "    return listener.lookupTransform('base_link', 'laser', now)\n"
        ),
        Valid(  # different frames, not a misspelling
            "import tf\nbroadcaster = tf.TransformBroadcaster()\nlistener = tf.TransformListener()\n"
            "def run(p, q, now):\n    broadcaster.sendTransform(p, q, now, 'camera1', 'base_link')\n"
            "    return listener.lookupTransform('base_link', 'camera2', now)\n"
        ),
    ]
    INVALID = [
        Invalid(
            "import tf\nbroadcaster = tf.TransformBroadcaster()\nlistener = tf.TransformListener()\n"
            "def run(p, q, now):\n    broadcaster.sendTransform(p, q, now, 'laser', 'base_link')\n"
            "    return listener.lookupTransform('baselink', 'laser', now)\n",
            expected_fix="import tf\nbroadcaster = tf.TransformBroadcaster()\nlistener = tf.TransformListener()\n"
            "def run(p, q, now):\n    broadcaster.sendTransform(p, q, now, 'laser', 'base_link')\n"
            "    return listener.lookupTransform('base_link', 'laser', now)\n",
            message="`lookupTransform` asks for frame 'baselink', which nothing in the project publishes; did you mean 'base_link' (published at example.py:5)?",
            range=(6, 37, 6, 47),
        ),
        Invalid(
            "import rospy, tf\nbroadcaster = tf.TransformBroadcaster()\nlistener = tf.TransformListener()\n"
            "base = rospy.get_param('~base_frame', 'base_lnk')\n"
            "def run(p, q, now):\n    broadcaster.sendTransform(p, q, now, 'laser', 'base_link')\n"
            "    return listener.lookupTransform(base, 'laser', now)\n",
            message="`lookupTransform` asks for frame 'base_lnk' (the default of parameter '~base_frame'), which nothing in the "
            "project publishes; did you mean 'base_link' (published at example.py:6)?",
            range=(7, 12, 7, 56),
        ),
    ]

    def check_tree(self, tree: ModuleTfTree) -> None:
        frames = tree.graph.frames
        if not frames:
            return
        for found in tree.statements:
            lookup = found.statement
            if not isinstance(lookup, LookedUp):
                continue
            defaults = dict(lookup.parameters)
            for role, frame in (("target", lookup.target), ("source", lookup.source)):
                if frame is None or frame in frames:
                    continue
                close = sorted(known for known in frames if _misspelt(frame, known))
                if len(close) != 1:
                    continue
                argument = _argument_naming(found.call, frame)
                # where the frame is published as a child (its own publisher), else named as a parent
                where = min(
                    (edge.child != close[0], edge.place) for edge in tree.graph.published if close[0] in (edge.parent, edge.child)
                )[1]
                parameter = defaults.get(role)
                shown = f"{frame!r} (the default of parameter {parameter!r})" if parameter is not None else repr(frame)
                self.report(
                    argument if argument is not None else found.call,
                    f"`{lookup.how}` asks for frame {shown}, which nothing in the project publishes; did you mean "
                    f"{close[0]!r} (published at {tree.where(where)})?",
                    replacement=repr(close[0]) if argument is not None else None,
                    applicability="unsafe",
                    fix_description=f"Use {close[0]!r}",
                    frames=(frame, close[0]),
                )


def _misspelt(frame: str, known: str) -> bool:
    """Whether `frame` reads as a misspelling of `known`: the same but for case, `-`/`_` or one
    edit (for names of at least five characters), and not just other digits."""
    if frame == known:
        return False
    if _DIGITS.search(frame + known) and _DIGITS.sub("", frame) == _DIGITS.sub("", known):
        return False  # `camera1` and `camera2`: two frames
    folded = lambda text: text.lower().replace("-", "").replace("_", "")  # noqa: E731
    if folded(frame) == folded(known):
        return True
    return min(len(frame), len(known)) >= _MIN_LENGTH and _one_edit(frame, known)


def _one_edit(first: str, second: str) -> bool:
    """One insertion, deletion, substitution or swap of neighbours turns `first` into `second`."""
    if abs(len(first) - len(second)) > 1:
        return False
    if len(first) > len(second):
        first, second = second, first
    start = 0
    while start < len(first) and first[start] == second[start]:
        start += 1
    if len(first) < len(second):
        return first[start:] == second[start + 1 :]
    rest = start + 1
    if first[rest:] == second[rest:]:
        return True
    return rest < len(first) and first[start] == second[rest] and first[rest] == second[start] and first[rest + 1 :] == second[rest + 1 :]


def _argument_naming(call: ast.Call, frame: str) -> ast.expr | None:
    """The string literal argument of `call` that names `frame` (a leading slash allowed)."""
    for argument in [*call.args, *(keyword.value for keyword in call.keywords)]:
        if isinstance(argument, Constant) and isinstance(argument.value, str) and argument.value.strip().lstrip("/") == frame:
            return argument
    return None
