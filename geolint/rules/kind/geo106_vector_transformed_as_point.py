"""GEO106 vector-transformed-as-point: a ROS free vector sent through tf2's point transform."""

from __future__ import annotations

from typing import Final

import ast
from ast import Assign, Attribute, Call, Module, Name

from geolint.factbase import ModuleIndex, index_of
from geolint.factbase.pose_parts import call_name
from geolint.factbase.reaching import parameter_of, resolve, scope_of
from geolint.rules.base import AstRule, Invalid, Valid
from geolint.rules.triggers import AllOf

# Fields of geometry_msgs Twist / Wrench / Accel / Vector3Stamped: free vectors, never positions.
_FREE_VECTOR_FIELDS: Final = frozenset({"linear", "angular", "force", "torque", "vector"})


class VectorTransformedAsPoint(AstRule):
    """A free vector (Vector3Stamped, a velocity, a force) goes through tf2's point transform.

    ## What it does
    Flags `do_transform_point(msg, transform)` (tf2_geometry_msgs) where `msg` is certainly a
    free vector: made by `Vector3Stamped(...)` or annotated `Vector3Stamped`, or a
    `PointStamped` whose `.point` (or `.point.x/y/z`) the function filled from a twist, wrench or
    vector field (`twist.linear`, `wrench.force`, `msg.vector.x`).

    ## Why is this bad?
    `do_transform_point` rotates and translates: right for a position, wrong for a velocity, a
    force, an axis or a normal, which have no position and must only be rotated. The result is
    off by the transform's translation, which is small near the origin and large everywhere
    else. `do_transform_vector3` (or `Buffer.transform`, which picks it for a
    `Vector3Stamped`) rotates only.

    ## Example
    ```python
    velocity = Vector3Stamped()
    velocity.header = odom.header
    velocity.vector = odom.twist.twist.linear
    velocity_in_map = do_transform_point(velocity, odom_to_map)
    ```

    ## Use instead
    ```python
    velocity_in_map = do_transform_vector3(velocity, odom_to_map)
    ```

    ## Fix safety
    The fix calls `do_transform_vector3` instead and is unsafe: it needs that name imported, and
    a `PointStamped` must become a `Vector3Stamped` (field `.vector`, not `.point`).

    ## Known problems
    Only messages built in the same function (or annotated) are recognised; a vector received
    from a subscription callback without an annotation is not.
    """

    code = "GEO106"
    name = "vector-transformed-as-point"
    triggers = AllOf(r"do_transform_point", r"Vector3Stamped|\.(?:linear|angular|force|torque|vector)\b")

    VALID = [
        Valid("def f(v, t):\n    v = Vector3Stamped()\n    return do_transform_vector3(v, t)\n"),
        Valid("def f(p, t):\n    p = PointStamped()\n    p.point = pose.position\n    return do_transform_point(p, t)\n"),
        Valid("def f(msg: PointStamped, t):\n    return do_transform_point(msg, t)\n"),
    ]
    INVALID = [
        Invalid(
            "def f(t):\n    v = Vector3Stamped()\n    return do_transform_point(v, t)\n",
            message="`v` is a free vector (made by Vector3Stamped()); `do_transform_point` also translates it. Rotate it only: `do_transform_vector3`",
            range=(3, 12, 3, 36),
        ),
        Invalid("def f(normal: Vector3Stamped, t):\n    return tf2_geometry_msgs.do_transform_point(normal, t)\n"),
        Invalid(
            "def f(odom, t):\n    p = PointStamped()\n    p.header = odom.header\n    p.point.x = odom.twist.twist.linear.x\n"
            "    return do_transform_point(p, t)\n"
        ),
    ]

    def check(self, tree: Module) -> None:
        index = index_of(tree)
        for node in index.nodes(Call):
            if not (isinstance(node, Call) and call_name(node) == "do_transform_point" and node.args):
                continue
            message = node.args[0]
            if not isinstance(message, Name):
                continue
            why = _free_vector_evidence(message, index)
            if why is None:
                continue
            text = ast.get_source_segment(self.context.source, node) or ast.unparse(node)
            replacement = text.replace("do_transform_point", "do_transform_vector3", 1)
            self.report(
                node,
                f"`{message.id}` is a free vector ({why}); `do_transform_point` also translates it. "
                "Rotate it only: `do_transform_vector3`",
                replacement=replacement,
                applicability="unsafe",
                fix_description="use do_transform_vector3",
            )


def _free_vector_evidence(message: Name, index: ModuleIndex) -> str | None:
    value = resolve(index, message)
    if isinstance(value, Call) and call_name(value) == "Vector3Stamped":
        return "made by Vector3Stamped()"
    argument = parameter_of(index, message)
    annotation = argument.annotation if argument is not None else None
    if annotation is not None and ast.unparse(annotation).split(".")[-1] == "Vector3Stamped":
        return "annotated Vector3Stamped"
    if isinstance(value, Call) and call_name(value) == "PointStamped":
        for node in ast.walk(scope_of(index, message).node):
            if isinstance(node, Assign) and len(node.targets) == 1 and _fills_point_of(node.targets[0], message.id):
                field = _free_vector_field(node.value)
                if field is not None:
                    return f"its point is filled from `.{field}`"
    return None


def _fills_point_of(target: ast.expr, name: str) -> bool:
    """`name.point = ...` or `name.point.x = ...`."""
    if isinstance(target, Attribute) and target.attr in ("x", "y", "z"):
        target = target.value
    return isinstance(target, Attribute) and target.attr == "point" and isinstance(target.value, Name) and target.value.id == name


def _free_vector_field(value: ast.expr) -> str | None:
    node = value
    while isinstance(node, Attribute):
        if node.attr in _FREE_VECTOR_FIELDS:
            return node.attr
        node = node.value
    return None
