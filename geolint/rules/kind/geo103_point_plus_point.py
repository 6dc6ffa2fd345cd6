"""GEO103 point-plus-point: two positions are added."""

from __future__ import annotations

from typing import Final

import ast
from ast import AST, Add, BinOp, Call, Constant, Div, FloorDiv, Mult, Name, Slice, Sub, Subscript, USub, UnaryOp

from geolint.rules.base import Invalid, Valid
from geolint.algebra import FREE, Kind
from geolint.factbase.model import last_name, number
from geolint.rules.fact_rule import FactRule

_COLLECTION_WORDS: Final = frozenset({"points", "pts", "vertices", "verts", "positions", "centroids", "landmarks"})
# `delta_pos`, `pos_offset`, `displacement`: a displacement (a vector), never a point
_DISPLACEMENT_WORDS: Final = frozenset(
    {"delta", "d", "diff", "difference", "offset", "offsets", "displacement", "disp", "shift", "step", "increment", "inc",
     "rel", "relative"}
)  # fmt: skip
# What a rotated displacement is made from: `rot.dot(action[:3])` turns an action's translation into the world
_MOTION_WORDS = _DISPLACEMENT_WORDS | {"action", "actions", "act"}
# joint-space "positions" (`arm_motor_pos`, `joint_pos`, `qpos`) are not Euclidean points
_JOINT_SPACE_WORDS: Final = frozenset({"joint", "joints", "motor", "motors", "qpos", "arm", "actuator", "servo", "gripper_pos"})


def _name_tokens(node: AST) -> set[str]:
    while isinstance(node, Call) and last_name(node.func) in _ARRAY_WRAPPERS and len(node.args) == 1:
        node = node.args[0]  # `np.array(clipped_delta_pos)` is named by what it wraps
    name = last_name(node.value if isinstance(node, Subscript) else node)
    return set(name.lower().split("_")) if name else set()


_ARRAY_WRAPPERS: Final = frozenset({"array", "asarray", "tensor", "as_tensor"})


def _is_collection(node: AST) -> bool:
    """`points`, `mesh.vertices`, `pts_world`: many positions, not one. `grid_points[0]` is one of
    them (an anchor such as a grid's corner: `local + grid_points[0]` moves local coordinates)."""
    if isinstance(node, Subscript) and isinstance(node.slice, Constant) and isinstance(node.slice.value, int):
        return False
    return bool(_COLLECTION_WORDS & _name_tokens(node))


def _is_sequence_slice(node: AST) -> bool:
    """`points[i:]`: a sub-sequence (adding two of them concatenates lists)."""
    return isinstance(node, Subscript) and isinstance(node.slice, Slice)


# Reductions that turn a sum of points into an affine combination.
_AVERAGING_CALLS: Final = frozenset({"mean", "average", "sum", "nanmean", "median"})


class PointPlusPoint(FactRule):
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

    ## Known problems
    The rule is opt-in (select `GEO103` by its code). Whether an operand is a position is read
    from its name (`*_pos`, `position`, `centroid`, `p_*`), and in application code such names
    hold offsets, joint angles, layout grids and random perturbations as often as points: of the
    12 findings triaged on real code, none was a bug. Names that say relative (`rel_`, `relative`,
    `delta`, `offset`) and values made by rotating an action or a delta (`rot.dot(action[:3])`)
    are read as displacements whatever the rest of the name says.
    """

    code = "GEO103"
    name = "point-plus-point"
    opt_in = True

    VALID = [
        Valid("target_arm_pos = processed_delta_pos + cur_arm_pos\n"),  # a displacement, joint space
        Valid("agent.arm_motor_pos = delta_pos + agent.arm_motor_pos\n"),
        Valid(
            "import numpy as np\ndef step(old_local_pos, delta_pos):\n    clipped_delta_pos = np.clip(delta_pos, -0.1, 0.1)\n"
            "    return np.array(old_local_pos) + np.array(clipped_delta_pos)\n"
        ),  # a displacement, wrapped in an array
        Valid("pos, quat = get_ee_pose(q)\ntarget = (pos + pos_diff_goal, quat)\n"),  # a difference, named so
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
        Valid("verts = marching_verts + grid_points[0]\n"),  # local coordinates moved to the grid's corner
        Valid(
            "import torch.nn.functional as F\n"
            "def fuse(plane_a, plane_b, loc):\n"
            "    a_pts = F.grid_sample(plane_a, loc)\n"
            "    b_pts = F.grid_sample(plane_b, loc)\n"
            "    return a_pts + b_pts\n"
        ),  # features sampled at points, summed: not coordinates
        Valid("self._pos = max(0, self._pos + pos)\n"),  # a file offset
        Valid("point = expr.point + point\n"),  # sympy: tuples of coordinates, concatenated
        Valid(
            "import torch\ndef goal(root_pos, n, radius):\n"
            "    rand_pos = radius * (2.0 * torch.rand([n, 2]) - 1.0)\n    return root_pos + rand_pos\n"
        ),  # a scaled random vector: an offset around the root
        Valid(
            "def target(pos, rot, action):\n    position = rot.dot(action[:3])\n"
            "    return (pos[0] + position[0], pos[1] + position[1], pos[2] + position[2])\n"
        ),  # an action's translation rotated into the world: a displacement
        Valid(
            "import numpy as np\ndef place(drawer_pos, drawer_rot, sampled_pos):\n"
            "    rel_pod_pos = drawer_rot @ sampled_pos\n    return np.array(drawer_pos) + rel_pod_pos\n"
        ),  # a relative position is an offset
        Valid(
            "import torch\ndef ring(root_pos, dist, theta):\n"
            "    pos_x = dist * torch.cos(theta)\n    return root_pos[..., 0] + pos_x\n"
        ),  # polar coordinates around the root: an offset
    ]
    INVALID = [
        Invalid(
            "grasp_position = object_centroid + gripper_position\n",
            message="`object_centroid` and `gripper_position` are both points; adding two positions depends on the origin (did you mean an offset, a difference or a midpoint?)",
            range=(1, 18, 1, 52),
        ),
        Invalid("def f(p_world, tip_position):\n    return p_world + tip_position\n"),
        Invalid("both = mesh_a.centroid + mesh_b.centroid\n"),
        Invalid("x = tip_position_world + base_position_world + offset\n"),
        Invalid(
            "def target(pos, rot, goal_position):\n    position = rot.dot(goal_position)\n"
            "    return pos + position\n"
        ),  # a rotated position is still a position
    ]

    def run(self) -> None:
        facts = self.facts
        for node in facts.index.nodes(BinOp):
            if isinstance(node.op, Add):  # type: ignore[attr-defined]
                self._check(node)  # type: ignore[arg-type]

    def _check(self, node: BinOp) -> None:
        facts = self.facts
        if facts.kind_of(node.left) != Kind.POINT or facts.kind_of(node.right) != Kind.POINT:
            return
        if _is_sequence_slice(node.left) or _is_sequence_slice(node.right):
            return
        if any(_DISPLACEMENT_WORDS & _name_tokens(side) or _JOINT_SPACE_WORDS & _name_tokens(side) for side in (node.left, node.right)):
            return  # `delta_pos + pos`, `arm_motor_pos + ...`: a displacement, or joint space
        if any(self._is_scaled_quantity(side) for side in (node.left, node.right)):
            return  # `rand_pos = r * (2 * rand - 1)`, `pos_x = d * cos(theta)`: an offset, whatever its name
        if any(self._is_rotated_displacement(side) for side in (node.left, node.right)):
            return  # `position = rot.dot(action[:3])`: a displacement turned into the world, whatever its name
        if not (facts.has_geometric_evidence(node.left) or facts.has_geometric_evidence(node.right)):
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

    def _is_scaled_quantity(self, side: ast.expr) -> bool:
        """A name bound only to a product none of whose factors is a point (`dist * cos(theta)`,
        `radius * (2 * rand - 1)`): scaling gives a vector relative to some centre, not a location."""
        if not isinstance(side, Name):
            return False
        bindings = self.facts.bindings(side) or []
        return bool(bindings) and all(
            isinstance(value, BinOp) and isinstance(value.op, Mult)
            and all(self.facts.kind_of(factor) != Kind.POINT for factor in (value.left, value.right))
            for value in bindings
        )

    def _is_rotated_displacement(self, side: ast.expr) -> bool:
        """A name (or one of its components, `position[0]`) bound only to a product that rotates an
        action or a delta (`rot.dot(action[:3])`, `R @ delta_pos`): a displacement, not a location."""
        while isinstance(side, Subscript):
            side = side.value
        if not isinstance(side, Name):
            return False
        bindings = self.facts.bindings(side) or []
        products = [self.facts.matmul(value) if isinstance(value, ast.expr) else None for value in bindings]
        return bool(products) and all(
            product is not None and any(_MOTION_WORDS & _name_tokens(operand) for operand in (product.left, product.right))
            for product in products
        )

    def _is_affine(self, node: AST) -> bool:
        """Whether this sum is divided, scaled, averaged, or part of a combination whose point
        weights sum to 0 or 1 (`a + b - c` reflects a point): `algebra.affine_combination`."""
        facts = self.facts
        current = node
        parent = facts.parent(current)
        while isinstance(parent, BinOp) and isinstance(parent.op, (Add, Sub)):
            current, parent = parent, facts.parent(parent)
        weight = self._point_weight(current)
        if weight is None or weight in (0, 1):
            return True
        if isinstance(parent, BinOp):
            if isinstance(parent.op, (Div, FloorDiv)) and parent.left is current:
                return True
            if isinstance(parent.op, Mult):
                other = parent.right if parent.left is current else parent.left
                scale = number(other)
                return scale is None or abs(scale) < 1
        # Inside a list/argument of a reduction: `np.mean([a + b, ...])`, `sum(...)`.
        while parent is not None and not isinstance(parent, ast.stmt):
            if isinstance(parent, Call) and last_name(parent.func) in _AVERAGING_CALLS:
                return True
            parent = facts.parent(parent)
        return False

    def _point_weight(self, root: AST) -> int | None:
        """The sum of the weights of the point terms of an additive expression, or None when a
        term of unknown kind is subtracted or scaled (it may be a point that balances the sum).
        Iterative, so a chain of thousands of terms costs linear time."""
        facts = self.facts
        total = 0
        stack: list[tuple[AST, int]] = [(root, 1)]
        while stack:
            node, sign = stack.pop()
            if isinstance(node, BinOp) and isinstance(node.op, (Add, Sub)):
                stack.append((node.left, sign))
                stack.append((node.right, -sign if isinstance(node.op, Sub) else sign))
                continue
            if isinstance(node, UnaryOp) and isinstance(node.op, USub):
                stack.append((node.operand, -sign))
                continue
            kind = facts.kind_of(node)
            if kind == Kind.POINT:
                total += sign
            elif kind in FREE:
                continue
            elif sign < 0 or isinstance(node, BinOp):
                return None  # `- last_control`, `s * b`: could be a point
        return total
