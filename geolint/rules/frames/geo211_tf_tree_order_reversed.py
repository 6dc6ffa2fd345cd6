"""GEO211 tf-tree-order-reversed: a transform published with REP 105's parent and child swapped."""

from __future__ import annotations

from geolint.factbase.tf_statements import Published
from geolint.rules.base import Invalid, Valid
from geolint.rules.frames.tf_tree_rule import ModuleTfTree, TfTreeRule, reverses_rep105


class TfTreeOrderReversed(TfTreeRule):
    """A transform is published from a frame that REP 105 places below the other.

    ## What it does
    Flags a published transform (tf2's `sendTransform` of a `TransformStamped`, ROS 1 tf's
    `sendTransform(translation, rotation, time, child, parent)`, a `static_transform_publisher`
    started from a launch file) whose parent and child are both frames of REP 105's chain
    `earth → map → odom → base_link`, with the parent below the child (`base_link` → `odom`,
    `odom` → `map`). A static publisher of the identity transform (all zeros) is not reported: it is
    the same either way round, the stand-in tree of a benchmark or a simulator with no localization.
    Nor is a test module (`test_*.py`, a `tests` folder), which sets up the tree it needs.

    ## Why is this bad?
    REP 105 fixes the tree every localization and navigation node expects: `map` is the parent of
    `odom`, and `odom` of `base_link`. A transform published the other way round gives `odom` (or
    `map`) two parents or makes the tree a cycle, and tf2 then fails or flips between the two, so
    navigation sees the robot jump. The usual cause is ROS 1 tf's `sendTransform`, which takes the
    child frame before the parent, or the frames swapped on a `TransformStamped`.

    ## Example
    ```python
    broadcaster.sendTransform(position, orientation, rospy.Time.now(), "odom", "base_link")
    ```

    ## Use instead
    ```python
    broadcaster.sendTransform(position, orientation, rospy.Time.now(), "base_link", "odom")
    ```

    ## Fix safety
    There is no automatic fix: swapping the frames also needs the transform inverted, unless the
    frames alone were swapped by mistake.

    ## Known problems
    Only frames the code fixes (literals, constants, strings built from them) are compared, and only
    the four names of REP 105 (`base_footprint`, prefixed frames such as `robot1/odom` and frames
    renamed by parameters are not). A node that deliberately publishes the inverse tree (a
    localization that does not own `odom`) is reported; suppress it there with a comment.

    ## References
    - [REP 105: Coordinate Frames for Mobile Platforms](https://www.ros.org/reps/rep-0105.html)
    """

    code = "GEO211"
    name = "tf-tree-order-reversed"

    VALID = [
        Valid(
            "import tf2_ros\nfrom geometry_msgs.msg import TransformStamped\n"
            "def publish(self):\n    t = TransformStamped()\n    t.header.frame_id = 'odom'\n    t.child_frame_id = 'base_link'\n"
            "    self.broadcaster.sendTransform(t)\n"
        ),
        Valid(  # ROS 1 tf: the child comes first
            "import tf\nbroadcaster = tf.TransformBroadcaster()\n"
            "def publish(position, orientation, now):\n    broadcaster.sendTransform(position, orientation, now, 'base_link', 'odom')\n"
        ),
        Valid(  # frames outside REP 105's chain
            "import tf2_ros\nfrom geometry_msgs.msg import TransformStamped\n"
            "def publish(self):\n    t = TransformStamped()\n    t.header.frame_id = 'camera_link'\n    t.child_frame_id = 'base_link'\n"
            "    self.broadcaster.sendTransform(t)\n"
        ),
        Valid(  # the identity transform: the same either way round
            "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
            "def generate_launch_description():\n    return LaunchDescription([Node(package='tf2_ros', executable='static_transform_publisher',\n"
            "        arguments=['--x', '0', '--yaw', '0', '--frame-id', 'base_link', '--child-frame-id', 'map'])])\n"
        ),
        Valid(  # a frame read from a parameter
            "import tf2_ros\nfrom geometry_msgs.msg import TransformStamped\n"
            "def publish(self):\n    t = TransformStamped()\n    t.header.frame_id = self.base_frame\n    t.child_frame_id = 'odom'\n"
            "    self.broadcaster.sendTransform(t)\n"
        ),
    ]
    INVALID = [
        Invalid(
            "import tf\nbroadcaster = tf.TransformBroadcaster()\n"
            "def publish(position, orientation, now):\n    broadcaster.sendTransform(position, orientation, now, 'odom', 'base_link')\n",
            message="`sendTransform` publishes 'base_link' as the parent of 'odom', but REP 105 orders the tree earth → map → odom → base_link, so 'odom' is the parent of 'base_link' (ROS 1 tf's `sendTransform` takes the child frame before the parent)",
            range=(4, 5, 4, 79),
        ),
        Invalid(
            "import tf2_ros\nfrom geometry_msgs.msg import TransformStamped\n"
            "def publish(self):\n    t = TransformStamped()\n    t.header.frame_id = '/odom'\n    t.child_frame_id = 'map'\n"
            "    self.broadcaster.sendTransform(t)\n"
        ),
        Invalid(
            "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
            "def generate_launch_description():\n    return LaunchDescription([Node(package='tf2_ros', executable='static_transform_publisher',\n"
            "        arguments=['0.2', '0', '0', '0', '0', '0', 'base_link', 'odom'])])\n"
        ),
    ]

    def check_tree(self, tree: ModuleTfTree) -> None:
        for found in tree.statements:
            edge = found.statement
            if not isinstance(edge, Published) or edge.parent is None or edge.child is None or not reverses_rep105(edge):
                continue
            if edge.identity:  # the same transform either way round: a stand-in tree, not a swapped one
                continue
            hint = " (ROS 1 tf's `sendTransform` takes the child frame before the parent)" if len(found.call.args) >= 5 else " (parent and child swapped?)"
            self.report(
                found.call,
                f"`{edge.how}` publishes {edge.parent!r} as the parent of {edge.child!r}, but REP 105 orders the tree "
                f"earth → map → odom → base_link, so {edge.child!r} is the parent of {edge.parent!r}{hint}",
                frames=(edge.parent, edge.child),
            )
