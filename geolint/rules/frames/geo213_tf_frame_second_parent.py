"""GEO213 tf-frame-second-parent: a frame published as the child of two different frames."""

from __future__ import annotations

from ast import AST, Attribute, Call, If, Name, walk
from typing import Final

from geolint.factbase.model import FactBase
from geolint.factbase.tf_statements import URDF_SUFFIXES, Place, Published
from geolint.rules.base import Invalid, Valid
from geolint.rules.frames.tf_tree_rule import ModuleTfTree, TfTreeRule


class TfFrameSecondParent(TfTreeRule):
    """A frame is published as the child of a second parent.

    ## What it does
    Flags a published transform `parent → child` when the same `child` also gets another parent:
    from a joint of the project's URDF or xacro (what robot_state_publisher publishes), or from
    another publication in the same module that can run with this one (not the other arm of an
    `if`).

    ## Why is this bad?
    A tf frame has exactly one parent. With two publishers tf2 takes whichever message came last,
    so the frame jumps between two poses and every lookup through it is wrong half the time
    (tf2 logs `TF_REPEATED_DATA` or nothing at all). A sensor frame that the URDF already
    attaches to the robot and a launch file publishes again from another frame is the usual case.

    ## Example
    ```python
    # the URDF has <joint><parent link="base_link"/><child link="laser"/></joint>
    broadcaster.sendTransform(p, q, now, "laser", "base_footprint")
    ```

    ## Use instead
    ```python
    # publish the sensor once: from the URDF, or from this node (and drop the joint)
    ```

    ## Fix safety
    There is no automatic fix: which publisher to keep is for a person to decide.

    ## Known problems
    A publication that runs only on an option whose name says so (`if self.publish_tf:`) is not
    reported: such a node is written to leave the frame to another publisher. Nor is one that a
    robot description agrees with while another does not (the URDFs are variants), and test
    folders' URDF and launch files are not read. Only frames the files
    fix are compared. Publications in different Python modules or launch files
    are not compared with each other (they are often alternatives, a simulator's and a robot's), only
    with the URDF.
    """

    code = "GEO213"
    name = "tf-frame-second-parent"

    VALID = [
        Valid(
            "import tf\nbroadcaster = tf.TransformBroadcaster()\n"
            "def publish(p, q, now):\n    broadcaster.sendTransform(p, q, now, 'laser', 'base_link')\n"
            "    broadcaster.sendTransform(p, q, now, 'laser', 'base_link')\n"
        ),
        Valid(  # alternatives: only one of them runs
            "import tf\nbroadcaster = tf.TransformBroadcaster()\n"
            "def publish(p, q, now, simulated):\n    if simulated:\n        broadcaster.sendTransform(p, q, now, 'base_link', 'world')\n"
            "    else:\n        broadcaster.sendTransform(p, q, now, 'base_link', 'odom')\n"
        ),
        Valid(  # published only when the node is told to, leaving the frame to another publisher otherwise
            "import tf\nbroadcaster = tf.TransformBroadcaster()\n"
            "def publish(self, p, q, now):\n    broadcaster.sendTransform(p, q, now, 'base_link', 'base_footprint')\n"
            "    if self.publish_odom_tf:\n        broadcaster.sendTransform(p, q, now, 'base_link', 'odom')\n"
        ),
    ]
    INVALID = [
        Invalid(
            "import tf\nbroadcaster = tf.TransformBroadcaster()\n"
            "def publish(p, q, now):\n    broadcaster.sendTransform(p, q, now, 'laser', 'base_link')\n"
            "    broadcaster.sendTransform(p, q, now, 'laser', 'base_footprint')\n",
            message="`sendTransform` publishes 'laser' as a child of 'base_footprint', but it is also published as a child of 'base_link' (example.py:4): a tf frame has one parent, so tf2 flips between the two and lookups through 'laser' are wrong",
            range=(5, 5, 5, 68),
        ),
    ]

    def check_tree(self, tree: ModuleTfTree) -> None:
        calls = {found.statement.place: found.call for found in tree.statements}
        for found in tree.statements:
            edge = found.statement
            if not isinstance(edge, Published) or edge.parent is None or edge.child is None:
                continue
            if tree.graph.path_up(edge.parent, edge.child) is not None:
                continue  # a cycle: GEO212 reports it
            if _published_on_option(self.facts, found.call):
                continue
            parents = tree.graph.parents.get(edge.child, {})
            if any(other.place.path.endswith(URDF_SUFFIXES) for other in parents.get(edge.parent, ())):
                continue  # a robot description agrees: the others are variants (another arm, the simulator's)
            others = [other for parent, edges in parents.items() if parent != edge.parent for other in edges if self._conflicts(edge, other, calls)]
            if not others:
                continue
            other = min(others, key=lambda published: published.place)
            self.report(
                found.call,
                f"`{edge.how}` publishes {edge.child!r} as a child of {edge.parent!r}, but it is also published as a child of "
                f"{other.parent!r} ({tree.where(other.place)}): a tf frame has one parent, so tf2 flips between the two and lookups "
                f"through {edge.child!r} are wrong",
                frames=(edge.parent, edge.child),
            )

    def _conflicts(self, edge: Published, other: Published, calls: dict[Place, Call]) -> bool:
        if other.place.path.endswith(URDF_SUFFIXES):
            return True
        if other.place not in calls or other.place >= edge.place:  # another module; or reported at the later one
            return False
        return not _exclusive(self.facts, calls[edge.place], calls[other.place])


_OPTION_WORDS: Final = ("transform", "publish", "broadcast")  # `publish_tf`, `should_publish_transform`


def _published_on_option(facts: FactBase, call: AST) -> bool:
    """Whether the publication runs only when the node is told to (`if self.publish_tf:`), the way a
    node offers to publish a frame that something else (a simulator, an EKF) may publish instead."""
    current = facts.parent(call)
    while current is not None:
        if isinstance(current, If):
            words = [node.id if isinstance(node, Name) else node.attr for node in walk(current.test) if isinstance(node, (Name, Attribute))]
            if any(word in name.lower() for name in words for word in _OPTION_WORDS):
                return True
        current = facts.parent(current)
    return False


def _exclusive(facts: FactBase, first: AST, second: AST) -> bool:
    """Whether the two nodes sit in the two arms of one `if` (at most one of them runs)."""
    arms: dict[int, bool] = {}
    child, current = first, facts.parent(first)
    while current is not None:
        if isinstance(current, If):
            arms[id(current)] = any(statement is child for statement in current.body)
        child, current = current, facts.parent(current)
    child, current = second, facts.parent(second)
    while current is not None:
        if isinstance(current, If) and id(current) in arms:
            return arms[id(current)] != any(statement is child for statement in current.body)
        child, current = current, facts.parent(current)
    return False
