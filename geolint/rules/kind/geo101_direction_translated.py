"""GEO101 direction-translated: a direction-like value gets a translation."""

from __future__ import annotations

import libcst as cst

from geolint.rules.base import Invalid, Valid
from geolint.semantic.names import Kind, kind_of_name
from geolint.semantic.model import last_name
from geolint.semantic.prefilter import Trigger, may_translate_direction
from geolint.semantic.rule_support import SemanticRule, keyword_arg


class DirectionTranslated(SemanticRule):
    """A direction (normal, axis, velocity, force) is moved by a translation.

    ## What it does
    Flags a direction-like value that is given a translation: a homogeneous 4-vector with
    w = 1 built from it (`np.append(normal, 1)`, `np.hstack([normals, np.ones((n, 1))])`, a
    `np.ones(4)` buffer filled with it), a rotation followed by `+ t` (`R @ n + t`,
    `n @ R.T + t`, `T[:3, :3] @ n + T[:3, 3]`), or a library call that translates
    (`trimesh.transform_points(normals, T)` without `translate=False`, pytransform3d
    `vector_to_point(direction)`, Blender `obj.matrix_world @ normal`).

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
    """

    code = "GEO101"
    name = "direction-translated"
    triggers = Trigger("a direction-like value and a homogeneous construction, `<product> + t`, or a translating call", may_translate_direction)

    VALID = [
        Valid("import numpy as np\nnormal_h = np.append(normal, 0)\n"),
        Valid("import numpy as np\np_h = np.append(point, 1)\n"),
        Valid("normal_world = R_world_cam @ normal_cam\n"),
        Valid("p_world = R @ p_cam + t\n"),
        Valid("v = R @ velocity + omega_cross_r\n"),
        Valid("tip_point = R @ approach + t\n"),  # a point built from a direction on purpose
        Valid("import trimesh\nn2 = trimesh.transform_points(normals, T, translate=False)\n"),
        Valid('direction = "left"\nx = np.append(direction, 1)\n'),
        Valid("import numpy as np\nn = 3\nout = np.append(n, 1)\n"),
        Valid("from spatialmath import SE3\nT = SE3.Trans(1, 0, 0)\np_moved = T * points\n"),
        Valid("from spatialmath import SE3\nT = SE3.Trans(1, 0, 0)\nn_moved = T.R @ normals\n"),
    ]
    INVALID = [
        Invalid(
            "import numpy as np\nnormal_h = np.append(normal, 1)\n",
            expected_fix="import numpy as np\nnormal_h = np.append(normal, 0)\n",
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
        Invalid("from pytransform3d.transformations import vector_to_point\nn_h = vector_to_point(approach)\n"),
        Invalid("world_normal = obj.matrix_world @ face.normal\n"),
        Invalid(
            "import PyKDL\n"
            "def tool_frame(q):\n"
            "    return PyKDL.Frame(PyKDL.Rotation.RPY(*q), PyKDL.Vector(0, 0, 0.1))\n"
            "approach_base = tool_frame(q) * approach\n"
        ),
        Invalid("from spatialmath import SE3\nT = SE3.Trans(1, 0, 0)\nn_moved = T * normals\n"),
    ]

    # homogeneous w = 1 -----------------------------------------------------------------
    def _check_homogeneous(self, node: cst.BaseExpression) -> None:
        homogeneous = self.model.homogeneous_built_by(node)
        if homogeneous is None or homogeneous.w != 1 or not self.model.used_as_homogeneous(homogeneous):
            return
        if self.model.kind_of(homogeneous.inner) != Kind.DIRECTION:
            return
        self.report(
            node,
            f"direction `{self.code_of(homogeneous.inner)}` is given w = 1, so a transform will translate it; "
            "directions take w = 0",
            replacement=homogeneous.fixed,
            fix_description="use w = 0 for the direction",
        )

    def visit_Call(self, node: cst.Call) -> None:
        self._check_homogeneous(node)
        self._check_library_call(node)

    def visit_Subscript(self, node: cst.Subscript) -> None:
        self._check_homogeneous(node)

    # R @ n + t --------------------------------------------------------------------------
    def visit_BinaryOperation(self, node: cst.BinaryOperation) -> None:
        if isinstance(node.operator, cst.Add):
            for rotated, other in ((node.left, node.right), (node.right, node.left)):
                direction = self._rotated_direction(rotated)
                if direction is not None and self.model.is_translation_like(other) and not self._stored_as_point(node):
                    self.report(
                        node,
                        f"direction `{self.code_of(direction)}` is rotated and then translated by "
                        f"`{self.code_of(other)}`; a direction only rotates",
                        replacement=rotated,
                        fix_description="drop the translation",
                    )
                    return
        if isinstance(node.operator, cst.Multiply) and self.model.kind_of(node.right) == Kind.DIRECTION:
            library = self.model.translating_library_object(node.left)
            if library is not None:
                self.report(
                    node,
                    f"`{self.code_of(node.left)}` is a {library}, and `*` translates what it multiplies, but "
                    f"`{self.code_of(node.right)}` is a direction; apply only its rotation",
                )
                return
        if isinstance(node.operator, cst.MatrixMultiply) and isinstance(node.left, cst.Attribute):
            if node.left.attr.value == "matrix_world" and self.model.kind_of(node.right) == Kind.DIRECTION:
                self.report(
                    node,
                    f"`{self.code_of(node.left)}` translates, but `{self.code_of(node.right)}` is a direction; "
                    "rotate it with `matrix_world.to_3x3()`",
                )

    def _stored_as_point(self, node: cst.CSTNode) -> bool:
        """`tip_point = R @ offset_dir + t` builds a point from a direction on purpose."""
        parent = self.model.parent(node)
        if isinstance(parent, cst.Assign):
            return any(
                isinstance(target.target, cst.Name) and kind_of_name(target.target.value, self.context.config) == Kind.POINT
                for target in parent.targets
            )
        return False

    def _rotated_direction(self, node: cst.BaseExpression) -> cst.BaseExpression | None:
        """For `R @ n`, `n @ R.T`, `(R @ n.T).T` with n a direction, the direction n."""
        if isinstance(node, cst.Attribute) and node.attr.value == "T":
            node = node.value
        product = self.model.matmul(node)
        if product is None:
            return None
        left, right = self.model.kind_of(product.left), self.model.kind_of(product.right)
        geometric = (Kind.POINT, Kind.DIRECTION)
        if right == Kind.DIRECTION and left not in geometric:
            return product.right
        if left == Kind.DIRECTION and right not in geometric:
            return product.left
        return None

    # library calls ------------------------------------------------------------------------
    def _check_library_call(self, node: cst.Call) -> None:
        name = last_name(node.func)
        positional = [arg.value for arg in node.args if arg.keyword is None and not arg.star]
        if not positional or self.model.kind_of(positional[0]) != Kind.DIRECTION:
            return
        if name == "transform_points":
            translate = next((arg for arg in node.args if arg.keyword and arg.keyword.value == "translate"), None)
            if translate is not None or len(positional) > 2:
                return
            self.report(
                node,
                f"`transform_points` translates its input, but `{self.code_of(positional[0])}` holds directions; "
                "pass `translate=False`",
                replacement=node.with_changes(
                    args=(*node.args, keyword_arg("translate", "False"))
                ),
                applicability="unsafe",
                fix_description="pass translate=False",
            )
        elif name == "vector_to_point":
            qualified = self.model.qualified_name(node.func) or ""
            if qualified.startswith("pytransform3d") or qualified == "vector_to_point":
                self.report(
                    node,
                    f"`vector_to_point` gives w = 1, but `{self.code_of(positional[0])}` is a direction; "
                    "use `vector_to_direction`",
                    replacement=node.with_changes(func=_renamed(node.func, "vector_to_direction")),
                    applicability="unsafe",
                    fix_description="use vector_to_direction",
                )


def _renamed(func: cst.BaseExpression, new_name: str) -> cst.BaseExpression:
    if isinstance(func, cst.Attribute):
        return func.with_changes(attr=cst.Name(new_name))
    return cst.Name(new_name)
