"""GEO212 tf-tree-cycle: a published transform that closes a cycle in the project's tf tree."""

from __future__ import annotations

from geolint.factbase.tf_statements import Published
from geolint.rules.base import Invalid, Valid
from geolint.rules.frames.tf_tree_rule import ModuleTfTree, TfTreeRule, reverses_rep105


class TfTreeCycle(TfTreeRule):
    """A transform is published from a frame that is already its child's descendant.

    ## What it does
    Builds the tf tree the whole project states (Python nodes' `sendTransform` calls, static
    transform publishers in Python and XML launch files, URDF and xacro joints) and flags a
    publication `parent → child` of this module when `child` is already an ancestor of `parent`:
    the two frames are published in both directions, or through a longer loop.

    ## Why is this bad?
    tf2 keeps a tree: every frame has one parent. A loop makes lookups between its frames fail
    (`TF_NO_FRAME_ID`/lookup errors, or tf2 flipping between the two parents as messages arrive),
    so whatever reads poses there gets nothing or jumps. The usual cause is one of the two
    publishers having its frames swapped.

    ## Example
    ```python
    # elsewhere in the project: a static_transform_publisher from base_link to laser
    t.header.frame_id = "laser"
    t.child_frame_id = "base_link"
    broadcaster.sendTransform(t)
    ```

    ## Use instead
    ```python
    t.header.frame_id = "base_link"
    t.child_frame_id = "laser"
    broadcaster.sendTransform(t)
    ```

    ## Fix safety
    There is no automatic fix: which of the publications is wrong is for a person to decide.

    ## Known problems
    Only frames the files fix (literals, constants, launch-file `arg` defaults, xacro properties)
    are read. Publications in two launch files that are never started together, or in branches that
    never both run, still form the loop here.
    """

    code = "GEO212"
    name = "tf-tree-cycle"

    VALID = [
        Valid(
            "import tf\nbroadcaster = tf.TransformBroadcaster()\n"
            "def publish(p, q, now):\n    broadcaster.sendTransform(p, q, now, 'laser', 'base_link')\n"
            "    broadcaster.sendTransform(p, q, now, 'camera', 'base_link')\n"
        ),
        Valid(  # a chain, not a loop
            "import tf\nbroadcaster = tf.TransformBroadcaster()\n"
            "def publish(p, q, now):\n    broadcaster.sendTransform(p, q, now, 'base_link', 'odom')\n"
            "    broadcaster.sendTransform(p, q, now, 'laser', 'base_link')\n"
        ),
    ]
    INVALID = [
        Invalid(
            "import tf\nbroadcaster = tf.TransformBroadcaster()\n"
            "def publish(p, q, now):\n    broadcaster.sendTransform(p, q, now, 'laser', 'base_link')\n"
            "def publish_inverse(p, q, now):\n    broadcaster.sendTransform(p, q, now, 'base_link', 'laser')\n",
            message="`sendTransform` publishes 'laser' → 'base_link', but 'base_link' is already an ancestor of 'laser' (base_link → laser, example.py:4): the tf tree becomes a cycle, so lookups between these frames fail (one publisher has its frames swapped?)",
            range=(6, 5, 6, 63),
        ),
    ]

    def check_tree(self, tree: ModuleTfTree) -> None:
        for found in tree.statements:
            edge = found.statement
            if not isinstance(edge, Published) or edge.parent is None or edge.child is None or edge.parent == edge.child:
                continue
            loop = tree.graph.path_up(edge.parent, edge.child)
            # one finding per cycle: at the publication the project states last (by file, then line)
            if loop is None or max(step.place for step in loop) >= edge.place:
                continue
            if any(reverses_rep105(step) for step in [*loop, edge]):
                continue  # GEO211 reports the frames REP 105 orders the other way
            steps = ", ".join(f"{step.parent} → {step.child}, {tree.where(step.place)}" for step in reversed(loop))
            self.report(
                found.call,
                f"`{edge.how}` publishes {edge.parent!r} → {edge.child!r}, but {edge.child!r} is already an ancestor of "
                f"{edge.parent!r} ({steps}): the tf tree becomes a cycle, so lookups between these frames fail "
                "(one publisher has its frames swapped?)",
                frames=(edge.parent, edge.child),
            )
