"""GEO103 point-plus-point: two positions are added."""

from __future__ import annotations

import libcst as cst

from geolint.rules.base import Invalid, Valid
from geolint.semantic.model import int_literal, last_name
from geolint.semantic.names import Kind
from geolint.semantic.prefilter import Trigger, may_add_points
from geolint.semantic.rule_support import SemanticRule

# Reductions that turn a sum of points into an affine combination.
_AVERAGING_CALLS = frozenset({"mean", "average", "sum", "nanmean", "median"})


class PointPlusPoint(SemanticRule):
    """Two points are added, which has no geometric meaning.

    ## What it does
    Flags `a + b` where both operands are point-like (positions, vertices, centroids,
    `p_*` names), unless the sum is part of an affine combination: `(a + b) / 2`,
    `0.5 * (a + b)`, `(1 - s) * a + s * b` or a mean.

    ## Why is this bad?
    A point plus a point depends on where the origin is: move the origin and the answer moves
    twice. The intended operation is almost always `point + (other - origin)` (an offset), the
    midpoint, or a difference.

    ## Example
    ```python
    grasp_position = object_position + gripper_position
    ```

    ## Use instead
    ```python
    grasp_position = object_position + (gripper_position - hand_origin)
    ```

    ## Fix safety
    No fix is offered: the intended operation cannot be inferred.
    """

    code = "GEO103"
    name = "point-plus-point"
    triggers = Trigger("a `+` whose operands both mention point-like names", may_add_points)

    VALID = [
        Valid("midpoint = (p_start + p_end) / 2\n"),
        Valid("mid = 0.5 * (point_a + point_b)\n"),
        Valid("x = (1 - s) * p_start + s * p_end\n"),
        Valid("target = position + velocity * dt\n"),
        Valid("center = (vertex_a + vertex_b + vertex_c) / 3\n"),
        Valid("import numpy as np\nc = np.mean([point_a + point_b], axis=0)\n"),
        Valid("n_points = 3\ntotal = n_points + n_points\n"),
        Valid("centroid = 0\nfor p in points:\n    centroid += p\n"),
    ]
    INVALID = [
        Invalid("grasp_position = object_position + gripper_position\n"),
        Invalid("def f(p_world, points_world):\n    return points_world + p_world\n"),
        Invalid("moved = mesh.vertices + mesh.centroid\n"),
    ]

    def visit_BinaryOperation(self, node: cst.BinaryOperation) -> None:
        if not isinstance(node.operator, cst.Add):
            return
        if self.model.kind_of(node.left) != Kind.POINT or self.model.kind_of(node.right) != Kind.POINT:
            return
        if self._is_affine(node):
            return
        self.report(
            node,
            f"`{self.code_of(node.left)}` and `{self.code_of(node.right)}` are both points; adding two "
            "positions depends on the origin (did you mean an offset, a difference or a midpoint?)",
        )

    def _is_affine(self, node: cst.CSTNode) -> bool:
        """Whether this sum is divided, scaled, averaged, or one term of a weighted sum."""
        current = node
        parent = self.model.parent(current)
        while isinstance(parent, cst.BinaryOperation) and isinstance(parent.operator, cst.Add):
            current, parent = parent, self.model.parent(parent)
        if isinstance(parent, cst.BinaryOperation):
            if isinstance(parent.operator, (cst.Divide, cst.FloorDivide)) and parent.left is current:
                return True
            if isinstance(parent.operator, cst.Multiply):
                other = parent.right if parent.left is current else parent.left
                scale = int_literal(other)
                return scale is None or abs(scale) < 1
        # Inside a list/argument of a reduction: `np.mean([a + b, ...])`, `sum(...)`.
        while parent is not None and not isinstance(parent, (cst.BaseSmallStatement, cst.BaseCompoundStatement)):
            if isinstance(parent, cst.Call) and last_name(parent.func) in _AVERAGING_CALLS:
                return True
            parent = self.model.parent(parent)
        return False
