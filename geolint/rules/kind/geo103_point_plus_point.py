"""GEO103 point-plus-point: two positions are added."""

from __future__ import annotations

import libcst as cst

from geolint.rules.base import Invalid, Valid
from geolint.semantic.model import int_literal, last_name
from geolint.semantic.names import Kind
from geolint.semantic.prefilter import Trigger, may_add_points
from geolint.semantic.rule_support import SemanticRule

_COLLECTION_WORDS = frozenset({"points", "pts", "vertices", "verts", "positions", "centroids", "landmarks"})


def _is_collection(node: cst.BaseExpression) -> bool:
    """`points`, `mesh.vertices`, `pts_world`: many positions, not one."""
    name = last_name(node.value if isinstance(node, cst.Subscript) else node)
    return name is not None and bool(_COLLECTION_WORDS & set(name.lower().split("_")))


def _is_sequence_slice(node: cst.BaseExpression) -> bool:
    """`points[i:]`: a sub-sequence (adding two of them concatenates lists)."""
    return isinstance(node, cst.Subscript) and len(node.slice) == 1 and isinstance(node.slice[0].slice, cst.Slice)


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
        Valid("mirrored = current_pos + current_pos - last_control\n"),  # 2a - b: an affine reflection
        Valid("rotated = points[start:] + points[:start]\n"),  # sequence concatenation
        Valid("curve = current_pt + points\n"),  # a collection and a position: concatenation or offset
        Valid("self._pos = max(0, self._pos + pos)\n"),  # a file offset
        Valid("point = expr.point + point\n"),  # sympy: tuples of coordinates, concatenated
    ]
    INVALID = [
        Invalid("grasp_position = object_centroid + gripper_position\n"),
        Invalid("def f(p_world, tip_position):\n    return p_world + tip_position\n"),
        Invalid("both = mesh_a.centroid + mesh_b.centroid\n"),
        Invalid("x = tip_position_world + base_position_world + offset\n"),
    ]

    def visit_BinaryOperation(self, node: cst.BinaryOperation) -> None:
        if not isinstance(node.operator, cst.Add):
            return
        if self.model.kind_of(node.left) != Kind.POINT or self.model.kind_of(node.right) != Kind.POINT:
            return
        if _is_sequence_slice(node.left) or _is_sequence_slice(node.right):
            return
        if not (self.model.has_geometric_evidence(node.left) or self.model.has_geometric_evidence(node.right)):
            return  # `self._pos + pos`: file offsets, cursor positions and tuples are "positions" too
        if _is_collection(node.left) != _is_collection(node.right):
            return
        if self._is_affine(node):
            return
        self.report(
            node,
            f"`{self.code_of(node.left)}` and `{self.code_of(node.right)}` are both points; adding two "
            "positions depends on the origin (did you mean an offset, a difference or a midpoint?)",
        )

    def _is_affine(self, node: cst.CSTNode) -> bool:
        """Whether this sum is divided, scaled, averaged, or part of a combination whose point
        weights sum to 0 or 1 (`a + b - c` reflects a point)."""
        current = node
        parent = self.model.parent(current)
        while isinstance(parent, cst.BinaryOperation) and isinstance(parent.operator, (cst.Add, cst.Subtract)):
            current, parent = parent, self.model.parent(parent)
        weight = self._point_weight(current, 1)
        if weight is None or weight in (0, 1):
            return True
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

    def _point_weight(self, node: cst.BaseExpression, sign: int) -> int | None:
        """The sum of the weights of the point terms of an additive expression, or None when a
        term of unknown kind is subtracted or scaled (it may be a point that balances the sum)."""
        if isinstance(node, cst.BinaryOperation) and isinstance(node.operator, (cst.Add, cst.Subtract)):
            left = self._point_weight(node.left, sign)
            right = self._point_weight(node.right, -sign if isinstance(node.operator, cst.Subtract) else sign)
            return None if left is None or right is None else left + right
        if isinstance(node, cst.UnaryOperation) and isinstance(node.operator, cst.Minus):
            return self._point_weight(node.expression, -sign)
        kind = self.model.kind_of(node)
        if kind == Kind.POINT:
            return sign
        if kind == Kind.DIRECTION:
            return 0
        if sign < 0 or isinstance(node, cst.BinaryOperation):
            return None  # `- last_control`, `s * b`: could be a point
        return 0
