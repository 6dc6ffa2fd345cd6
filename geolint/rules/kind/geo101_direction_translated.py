"""GEO101 direction-translated: a direction-like value gets a translation."""

from __future__ import annotations

import ast

from geolint.rules.base import Invalid, Valid
from geolint.algebra import FREE
from geolint.factbase.model import GEOMETRIC, is_zero, keyword, last_name, last_name_target, positional_args, replace_span, transposed_value
from geolint.factbase.summaries import FunctionSummary
from geolint.factbase.rule_support import FactRule, with_keyword
from geolint.semantic.names import Kind as NameKind, kind_of_name


class DirectionTranslated(FactRule):
    """A direction (normal, axis, velocity, force) is moved by a translation.

    ## What it does
    Flags a direction-like value that is given a translation: a homogeneous 4-vector with
    w = 1 built from it (`np.append(normal, 1)`, `np.hstack([normals, np.ones((n, 1))])`,
    `F.pad(normals, (0, 1), value=1.0)`, a `np.ones(4)` buffer filled with it), a rotation
    followed by `+ t` (`R @ n + t`, `n @ R.T + t`, `T[:3, :3] @ n + T[:3, 3]`,
    `np.einsum("ij,nj->ni", R, normals) + t`), or a library call that translates
    (`trimesh.transform_points(normals, T)` without `translate=False`, pytransform3d
    `vector_to_point(direction)`, Blender `obj.matrix_world @ normal`, pybullet
    `multiplyTransforms(pos, orn, velocity, [0, 0, 0, 1])` with a position that is not zero).

    ## Why is this bad?
    A direction is a difference of two points, so it has no position: changing frames rotates it
    and never shifts it. Adding the translation gives a vector of the wrong direction and length
    (the bug looks fine for poses near the origin and breaks everywhere else).

    ## Example
    ```python
    normal_h = np.append(normal, 1)
    normal_world = (T_world_cam @ normal_h)[:3]
    ```

    ## Use instead
    ```python
    normal_h = np.append(normal, 0)
    normal_world = (T_world_cam @ normal_h)[:3]
    ```

    ## Fix safety
    Changing w from 1 to 0 on a direction and dropping `+ t` after rotating a direction are
    safe. Adding `translate=False` to a library call is marked unsafe (it changes the call).

    ## Known problems
    Directions are mostly recognised by name (`normal`, `axis`, `velocity`, `dir`). What the code
    builds wins over the name when it says points: an array written out as the origin next to
    points along the axes (`sensor_axis = np.array([[0, 0, 0], [l, 0, 0], [0, l, 0], [0, 0, l]])`,
    a drawn frame's tips) is a set of points. The three axes without the origin row stay
    directions, though a drawing may mean them as tips too.
    """

    code = "GEO101"
    name = "direction-translated"

    VALID = [
        Valid("import numpy as np\nnormal_h = np.append(normal, 0)\n"),
        Valid("import numpy as np\np_h = np.append(point, 1)\n"),
        Valid("normal_world = R_world_cam @ normal_cam\n"),
        Valid("p_world = R @ p_cam + t\n"),
        Valid("v = R @ velocity + omega_cross_r\n"),
        Valid("tip_point = R @ approach + t\n"),  # a point built from a direction on purpose
        Valid("import trimesh\nn2 = trimesh.transform_points(normals, T, translate=False)\n"),
        Valid('direction = "left"\nx = np.append(direction, 1)\n'),
        Valid("import torch.nn.functional as F\nnormals_h = F.pad(normals, (0, 1))\nworld = normals_h @ c2w.T\n"),
        Valid("import numpy as np\nn = 3\nout = np.append(n, 1)\n"),
        Valid("from spatialmath import SE3\nT = SE3.Trans(1, 0, 0)\np_moved = T * points\n"),
        Valid("from spatialmath import SE3\nT = SE3.Trans(1, 0, 0)\nn_moved = T.R @ normals\n"),
        Valid(
            "import pybullet as p\ndef to_body(orn, lin_vel):\n    inv_orn = p.invertTransform([0, 0, 0], orn)[1]\n"
            "    return p.multiplyTransforms([0, 0, 0], inv_orn, lin_vel, [0, 0, 0, 1])[0]\n"
        ),  # a zero position: a pure rotation, the idiom for vectors
        Valid("import pybullet as p\nwp, wo = p.multiplyTransforms(base_pos, base_orn, tip_offset, [0, 0, 0, 1])\n"),  # a point
        Valid(
            "import numpy as np\ndef axis_tips(pose, length):\n"
            "    sensor_axis = np.array([[0, 0, 0], [length, 0, 0], [0, length, 0], [0, 0, length]])\n"
            "    return pose.transform_points(sensor_axis)\n"
        ),  # the origin and the axis tips: points to draw
    ]
    INVALID = [
        Invalid(
            "import numpy as np\nnormal_h = np.append(normal, 1)\n",
            expected_fix="import numpy as np\nnormal_h = np.append(normal, 0)\n",
        ),
        Invalid(
            "import torch.nn.functional as F\nnormals_h = F.pad(normals, (0, 1), value=1.0)\nworld = normals_h @ c2w.T\n",
            expected_fix="import torch.nn.functional as F\nnormals_h = F.pad(normals, (0, 1), value=0.0)\nworld = normals_h @ c2w.T\n",
        ),
        Invalid(
            'import numpy as np\nworld = np.einsum("ij,nj->ni", R, normals) + t\n',
            expected_fix='import numpy as np\nworld = np.einsum("ij,nj->ni", R, normals)\n',
        ),
        Invalid(
            "normal_world = R @ normal + t\n",
            expected_fix="normal_world = R @ normal\n",
        ),
        Invalid(
            "normals_w = normals @ T[:3, :3].T + T[:3, 3]\n",
            expected_fix="normals_w = normals @ T[:3, :3].T\n",
        ),
        Invalid(
            "import numpy as np\nh = np.ones(4)\nh[:3] = ray_dir\nout = T @ h\n",
            expected_fix="import numpy as np\nh = np.zeros(4)\nh[:3] = ray_dir\nout = T @ h\n",
        ),
        Invalid(
            "import numpy as np\nn = np.cross(a, b)\nn_h = np.hstack([n, [1.0]])\n",
            expected_fix="import numpy as np\nn = np.cross(a, b)\nn_h = np.hstack([n, [0.0]])\n",
        ),
        Invalid("import trimesh\nmoved = trimesh.transform_points(mesh.vertex_normals, T)\n"),
        Invalid(
            "import numpy as np\ndef axes(pose, length):\n"
            "    sensor_axis = np.array([[length, 0, 0], [0, length, 0], [0, 0, length]])\n"
            "    return pose.transform_points(sensor_axis)\n"
        ),
        Invalid("from pytransform3d.transformations import vector_to_point\nn_h = vector_to_point(approach)\n"),
        Invalid("world_normal = obj.matrix_world @ face.normal\n"),
        Invalid(
            "import PyKDL\n"
            "def tool_frame(q):\n"
            "    return PyKDL.Frame(PyKDL.Rotation.RPY(*q), PyKDL.Vector(0, 0, 0.1))\n"
            "approach_base = tool_frame(q) * approach\n"
        ),
        Invalid("from spatialmath import SE3\nT = SE3.Trans(1, 0, 0)\nn_moved = T * normals\n"),
        Invalid(
            "import pybullet as p\ndef to_body(pos, orn, lin_acc):\n    inv_pos, inv_orn = p.invertTransform(pos, orn)\n"
            "    return p.multiplyTransforms(inv_pos, inv_orn, lin_acc, [0, 0, 0, 1])[0]\n"
        ),
    ]

    # homogeneous w = 1 -----------------------------------------------------------------
    def run(self) -> None:
        facts = self.facts
        for node in facts.index.nodes(ast.Call, ast.Subscript, ast.BinOp):
            if isinstance(node, ast.BinOp):
                self._check_binary(node)
                continue
            self._check_homogeneous(node)  # type: ignore[arg-type]
            if isinstance(node, ast.Call):
                self._check_library_call(node)
                self._check_helper_call(node)

    def _check_helper_call(self, node: ast.Call) -> None:
        """`apply_pose(T, normals)` where the helper (here or in an imported project module) does `R @ x + t`."""
        facts = self.facts
        if not facts.may_have_summary(node):
            return
        positional = positional_args(node)
        if not any(facts.is_free(arg) for arg in positional[:4]):
            return  # only a direction passed in makes the helper's body worth reading
        summary = facts.function_summary(node)
        if summary is None or not summary.translates:
            return
        for index in sorted(summary.translates):
            if index < len(positional) and facts.is_free(positional[index]):
                helper = self.code_of(node.func)
                self.report(
                    node,
                    f"`{helper}` rotates and translates its parameter `{summary.parameters[index]}`, but "
                    f"`{self.code_of(positional[index])}` is a direction; a direction only rotates",
                    evidence=(f"summary of `{helper}`: translates parameter {index}" + _through(summary, index),),
                )
                return

    def _check_homogeneous(self, node: ast.expr) -> None:
        facts = self.facts
        homogeneous = facts.homogeneous_built_by(node)
        if homogeneous is None or homogeneous.w != 1 or not facts.used_as_homogeneous(homogeneous):
            return
        if not facts.is_free(homogeneous.inner):
            return
        self.report(
            node,
            f"direction `{self.code_of(homogeneous.inner)}` is given w = 1, so a transform will translate it; "
            "directions take w = 0",
            replacement=homogeneous.fixed,
            fix_description="use w = 0 for the direction",
        )

    def _check_binary(self, node: ast.BinOp) -> None:
        facts = self.facts
        if isinstance(node.op, ast.Add):
            for rotated, other in ((node.left, node.right), (node.right, node.left)):
                direction = self._rotated_direction(rotated)
                if direction is not None and facts.is_translation_like(other) and not self._stored_as_point(node):
                    self.report(
                        node,
                        f"direction `{self.code_of(direction)}` is rotated and then translated by "
                        f"`{self.code_of(other)}`; a direction only rotates",
                        replacement=facts.index.segment(rotated),
                        fix_description="drop the translation",
                    )
                    return
        if isinstance(node.op, ast.Mult) and facts.is_free(node.right):
            library = facts.translating_library_object(node.left)
            if library is not None:
                self.report(
                    node,
                    f"`{self.code_of(node.left)}` is a {library}, and `*` translates what it multiplies, but "
                    f"`{self.code_of(node.right)}` is a direction; apply only its rotation",
                )
                return
        if isinstance(node.op, ast.MatMult) and isinstance(node.left, ast.Attribute):
            if node.left.attr == "matrix_world" and facts.is_free(node.right):
                self.report(
                    node,
                    f"`{self.code_of(node.left)}` translates, but `{self.code_of(node.right)}` is a direction; "
                    "rotate it with `matrix_world.to_3x3()`",
                )

    def _stored_as_point(self, node: ast.AST) -> bool:
        """`tip_point = R @ offset_dir + t` builds a point from a direction on purpose."""
        parent = self.facts.parent(node)
        if isinstance(parent, ast.Assign):
            return any(
                isinstance(target, ast.Name) and kind_of_name(target.id, self.context.config) == NameKind.POINT
                for target in parent.targets
            )
        return False

    def _rotated_direction(self, node: ast.expr) -> ast.expr | None:
        """For `R @ n`, `n @ R.T`, `(R @ n.T).T` with n a direction, the direction n."""
        facts = self.facts
        inner = transposed_value(node)
        if inner is not None:
            node = inner
        product = facts.matmul(node)
        if product is None:
            return None
        left, right = facts.kind_of(product.left), facts.kind_of(product.right)
        if right in FREE and left not in GEOMETRIC:
            return product.right
        if left in FREE and right not in GEOMETRIC:
            return product.left
        return None

    def _check_library_call(self, node: ast.Call) -> None:
        facts = self.facts
        name = last_name(node.func)
        if name == "multiplyTransforms":
            self._check_pybullet_multiply(node)
            return
        if name not in ("transform_points", "vector_to_point"):
            return
        positional = positional_args(node)
        if not positional or not facts.is_free(positional[0]):
            return
        if name == "transform_points":
            if keyword(node, "translate") is not None or len(positional) > 2:
                return
            self.report(
                node,
                f"`transform_points` translates its input, but `{self.code_of(positional[0])}` holds directions; "
                "pass `translate=False`",
                replacement=with_keyword(facts.index.segment(node), "translate=False"),
                applicability="unsafe",
                fix_description="pass translate=False",
            )
        elif name == "vector_to_point":
            qualified = facts.qualified_name(node.func) or ""
            if qualified.startswith("pytransform3d") or qualified == "vector_to_point":
                self.report(
                    node,
                    f"`vector_to_point` gives w = 1, but `{self.code_of(positional[0])}` is a direction; "
                    "use `vector_to_direction`",
                    replacement=replace_span(facts.index, node, [(last_name_target(node.func), "vector_to_direction")]),
                    applicability="unsafe",
                    fix_description="use vector_to_direction",
                )

    def _check_pybullet_multiply(self, node: ast.Call) -> None:
        """pybullet's `multiplyTransforms(posA, ornA, posB, ornB)` moves posB as a point: posA is added.
        A direction goes through it only with a zero position (`multiplyTransforms([0, 0, 0], orn, v, ...)`)."""
        positional = positional_args(node)
        if len(positional) != 4 or len(node.args) != 4 or is_zero(positional[0]):
            return
        if not self.facts.is_free(positional[2]):
            return
        self.report(
            node,
            f"`multiplyTransforms` adds the position `{self.code_of(positional[0])}` to its third argument, but "
            f"`{self.code_of(positional[2])}` is a direction; rotate it with a zero position "
            "(`multiplyTransforms([0, 0, 0], orn, v, [0, 0, 0, 1])`) or `rotateVector`",
        )


def _through(summary: FunctionSummary, index: int) -> str:
    """`, through `move` -> `apply_pose``: the helpers a summary's translation comes through."""
    chain = summary.translates_through.get(index)
    return f", through {chain}" if chain else ""
