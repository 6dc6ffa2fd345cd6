"""GEO101 direction-translated: a direction-like value gets a translation."""

from __future__ import annotations

import ast
from ast import (
    AST, Add, Assign, AsyncFunctionDef, Attribute, BinOp, Call, Constant, FunctionDef, Load, MatMult, Mult, Name, Slice,
    Starred, Subscript,
)

from geolint.rules.base import Invalid, Valid
from geolint.algebra import FREE, Kind, Problem
from geolint.factbase import library_calls
from geolint.factbase import vocabulary as vocab
from geolint.factbase.index import ParamBinding, UnpackBinding
from geolint.factbase.model import (
    GEOMETRIC, FactBase, is_transpose, is_zero, keyword, last_name, last_name_target, number, positional_args, replace_span,
    subscript_parts, transposed_value,
)  # fmt: skip
from geolint.factbase.kind_summaries import TRANSLATION, TranslationSummary
from geolint.factbase.pose_parts import is_batch_index
from geolint.rules.fact_rule import FactRule, with_keyword
from geolint.semantic.names import kind_of_name


class DirectionTranslated(FactRule):
    """A direction (normal, axis, velocity, force) is moved by a translation.

    ## What it does
    Flags a direction-like value that is given a translation: a homogeneous 4-vector with
    w = 1 built from it (`np.append(normal, 1)`, `np.hstack([normals, np.ones((n, 1))])`,
    `F.pad(normals, (0, 1), value=1.0)`, a `np.ones(4)` buffer filled with it), a rotation
    followed by `+ t` (`R @ n + t`, `n @ R.T + t`, `T[:3, :3] @ n + T[:3, 3]`,
    `np.einsum("ij,nj->ni", R, normals) + t`, a batch rotated as columns: `(R @ normals[..., None])[..., 0]
    + t`, `torch.bmm(R, n.unsqueeze(-1)).squeeze(-1) + t`, with the translation column `T[..., :3, 3]` or
    `T[..., :3, 3:]`; the product in any spelling the stubs mark as one: `torch.mm`, `np.linalg.matmul`,
    `tf.linalg.matmul`, and the array methods `.dot`, `.matmul`, `.mm`, `.bmm`), or a library call that translates
    (an argument its stub in `stubs/` types as points next to a transform, on a transform, or made
    homogeneous: `trimesh.transform_points(normals, T)` without `translate=False`, pytransform3d
    `vector_to_point(direction)`, PyTorch3D `t.transform_points(normals)`), Blender
    `obj.matrix_world @ normal`, pybullet
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
    safe. The fix of a library call is the one its stub offers, marked unsafe (it changes the
    call): the keyword value that picks an overload moving the argument as a vector
    (`translate=False`), or the API beside it that does (`vector_to_direction`, `transform_normals`).

    ## Known problems
    Directions are mostly recognised by name (`normal`, `axis`, `velocity`, `dir`). What the code
    builds wins over the name when it says points: an array written out as the origin next to
    points along the axes (`sensor_axis = np.array([[0, 0, 0], [l, 0, 0], [0, l, 0], [0, 0, l]])`,
    a drawn frame's tips) is a set of points. The three axes without the origin row stay
    directions, though a drawing may mean them as tips too. A direction given w = 1 is not reported
    where every matrix it is multiplied by is known to have no translation: a literal identity or a
    block of one (`torch.eye(4)[:3, :4]`) never written into, nerfstudio's
    `auto_orient_and_center_poses(..., center_method="none")`, or a parameter of a private helper
    (`_name`) whose calls in the module all pass such; a private helper its module never calls is
    reached by no matrix and is not reported either (a subclass elsewhere calling it is missed).
    A public function's parameter may be given any matrix, so it is reported. A method called on an
    object of no library the stubs know (`pose.transform_points(normals)` on a project's own class)
    is not reported. A rotated batch is read through a trailing axis of one added to the direction
    (`n[..., None]`, `n.unsqueeze(-1)`, `np.expand_dims(n, -1)`) and dropped again (`[..., 0]`,
    `.squeeze(-1)`); another reshape to columns (`n.reshape(-1, 3, 1)`, `n.view(*shape, 3, 1)`) is not read.
    """

    code = "GEO101"
    name = "direction-translated"

    VALID = [
        Valid("import numpy as np\nnormal_h = np.append(normal, 0)\n"),
        Valid("import numpy as np\np_h = np.append(point, 1)\n"),
        Valid("normal_world = R_world_cam @ normal_cam\n"),
        Valid("p_world = R @ p_cam + t\n"),
        Valid(
            "import torch\ndef project(v_world, pose):\n"
            "    v_homo = torch.cat([v_world, torch.ones_like(v_world[:, :1])], dim=-1)\n"
            "    return (v_homo @ pose.T)[:, :3]\n"
        ),  # `v_world`: a mesh's vertices as often as a vector; `v` states the frame, not the kind
        Valid("v = R @ velocity + omega_cross_r\n"),
        Valid("tip_point = R @ approach + t\n"),  # a point built from a direction on purpose
        Valid("import trimesh\nn2 = trimesh.transform_points(normals, T, translate=False)\n"),
        Valid("import trimesh\nn2 = trimesh.transform_points(normals, T, flag)\n"),  # either overload: say nothing
        Valid("import numpy as np\nn2 = pose.transform_points(normals)\n"),  # no library the stubs know: say nothing
        Valid("from pytorch3d.transforms import Transform3d\nn = Transform3d(matrix=M).transform_normals(normals)\n"),
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
            "import numpy as np\nimport trimesh\ndef axis_tips(pose, length):\n"
            "    sensor_axis = np.array([[0, 0, 0], [length, 0, 0], [0, length, 0], [0, 0, length]])\n"
            "    return trimesh.transform_points(sensor_axis, pose)\n"
        ),  # the origin and the axis tips: points to draw
        # the only matrix the w = 1 normals meet is a literal identity: nothing is translated
        Valid("import torch\nT = torch.eye(4)[:3, :4]\nn_h = torch.cat((normals, torch.ones_like(normals[..., :1])), -1) @ T.T\n"),
        Valid("import numpy as np\nnormals_h = np.hstack([normals, np.ones((len(normals), 1))])\nout = normals_h @ np.eye(4).T\n"),
        Valid("import torch\nn_world = torch.mm(T[:3, :3], normals)\n"),
        Valid("import tensorflow as tf\np_world = tf.linalg.matmul(R, points) + t\n"),
        Valid("n_world = (T[..., :3, :3] @ normals[..., None])[..., 0]\n"),
        Valid("import torch\nn_world = torch.bmm(T[:, :3, :3], normals.unsqueeze(-1)).squeeze(-1)\n"),
        Valid("p_world = (T[..., :3, :3] @ points[..., None])[..., 0] + T[..., :3, 3]\n"),
        Valid("x_shifted = (normals @ R.T)[..., 0] + t\n"),  # the x coordinate of each rotated row, not a rotated direction
    ]
    INVALID = [
        Invalid(
            "import numpy as np\nnormal_h = np.append(normal, 1)\n",
            expected_fix="import numpy as np\nnormal_h = np.append(normal, 0)\n",
            message="direction `normal` is given w = 1, so a transform will translate it; directions take w = 0",
            range=(2, 12, 2, 32),
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
            "import numpy as np\nimport trimesh\ndef axes(pose, length):\n"
            "    sensor_axis = np.array([[length, 0, 0], [0, length, 0], [0, 0, length]])\n"
            "    return trimesh.transform_points(sensor_axis, pose)\n"
        ),
        Invalid("from pytransform3d.transformations import vector_to_point\nn_h = vector_to_point(approach)\n"),
        Invalid(
            "from pytorch3d.transforms import Transform3d\nt = Transform3d(matrix=M)\nn = t.transform_points(vertex_normals)\n",
            expected_fix="from pytorch3d.transforms import Transform3d\nt = Transform3d(matrix=M)\nn = t.transform_normals(vertex_normals)\n",
            message="`transform_points` translates its input, but `vertex_normals` holds directions; use `transform_normals`",
            range=(3, 5, 3, 39),
        ),  # the fix is the one its stub offers: pytorch3d has no `translate=False`
        Invalid(
            "import trimesh\nn = trimesh.transform_points(face_normals, T)\n",
            expected_fix="import trimesh\nn = trimesh.transform_points(face_normals, T, translate=False)\n",
            message="`transform_points` translates its input, but `face_normals` holds directions; pass `translate=False`",
            range=(2, 5, 2, 46),
        ),
        Invalid("world_normal = obj.matrix_world @ face.normal\n"),
        Invalid(
            "import torch\nfrom nerfstudio.cameras.camera_utils import auto_orient_and_center_poses\n"
            "poses, T = auto_orient_and_center_poses(poses)\n"
            "n_h = torch.cat((normals, torch.ones_like(normals[..., :1])), -1) @ T.T\n",
            expected_fix="import torch\nfrom nerfstudio.cameras.camera_utils import auto_orient_and_center_poses\n"
            "poses, T = auto_orient_and_center_poses(poses)\n"
            "n_h = torch.cat((normals, torch.zeros_like(normals[..., :1])), -1) @ T.T\n",
        ),  # centred on the poses by default: the matrix translates
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
        Invalid(
            "import torch\nn_world = torch.mm(T[:3, :3], normals) + T[:3, 3:]\n",
            expected_fix="import torch\nn_world = torch.mm(T[:3, :3], normals)\n",
            message="direction `normals` is rotated and then translated by `T[:3, 3:]`; a direction only rotates",
            range=(2, 11, 2, 51),
        ),
        Invalid("import tensorflow as tf\nn_world = tf.linalg.matmul(R, normals) + t\n"),
        Invalid(
            "n_world = (T[..., :3, :3] @ normals[..., None])[..., 0] + T[..., :3, 3]\n",
            expected_fix="n_world = (T[..., :3, :3] @ normals[..., None])[..., 0]\n",
            message="direction `normals` is rotated and then translated by `T[..., :3, 3]`; a direction only rotates",
            range=(1, 11, 1, 72),
        ),
        Invalid(
            "import torch\nn_world = torch.bmm(T[:, :3, :3], normals.unsqueeze(-1)).squeeze(-1) + T[:, :3, 3]\n",
            expected_fix="import torch\nn_world = torch.bmm(T[:, :3, :3], normals.unsqueeze(-1)).squeeze(-1)\n",
        ),
        Invalid("n_world = (R @ normals[..., :, None])[..., :, 0] + t\n"),
        Invalid("n_world = R @ normals[..., None] + T[..., :3, 3:]\n"),
    ]

    # homogeneous w = 1 -----------------------------------------------------------------
    def run(self) -> None:
        facts = self.facts
        for node in facts.index.nodes(Call, Subscript, BinOp):
            if isinstance(node, BinOp):
                self._check_binary(node)
                continue
            self._check_homogeneous(node)  # type: ignore[arg-type]
            if isinstance(node, Call):
                self._check_library_call(node)
                self._check_helper_call(node)

    def _check_helper_call(self, node: Call) -> None:
        """`apply_pose(T, normals)` where the helper (here or in an imported project module) does `R @ x + t`."""
        facts = self.facts
        if not facts.may_have_summary(node):
            return
        positional = positional_args(node)
        if not any(facts.is_free(arg) for arg in positional[:4]):
            return  # only a direction passed in makes the helper's body worth reading
        summary = facts.summary_of(node, TRANSLATION)
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
        if homogeneous is None:
            return
        outcome = facts.homogenized(homogeneous)
        if outcome is None or outcome.problem != Problem.DIRECTION_TRANSLATED or not facts.used_as_homogeneous(homogeneous):
            return
        if self._meets_only_untranslated(homogeneous.construction):
            return  # w = 1 is harmless where every matrix it meets has no translation (`torch.eye(4)[:3, :4]`)
        self.report(
            node,
            f"direction `{self.code_of(homogeneous.inner)}` is given w = 1, so a transform will translate it; "
            "directions take w = 0",
            replacement=homogeneous.fixed,
            fix_description="use w = 0 for the direction",
        )

    def _meets_only_untranslated(self, construction: ast.expr) -> bool:
        """Whether the matrices a w = 1 construction is multiplied by are known, and none translates."""
        partners = self._product_partners(construction)
        return bool(partners) and not any(self._may_translate(matrix) for matrix in partners)

    def _product_partners(self, construction: ast.expr) -> list[ast.expr]:
        """The other operands of the products a construction is an operand of: directly
        (`cat((n, ones), -1) @ T.T`), or through the one name it is stored in (`n_h = ...; T @ n_h.T`).
        Empty when some use of it is not such a product, or none is."""
        facts = self.facts
        node, parent = self._above_transposes(construction)
        partner = self._partner_in_product(node, parent)
        if partner is not None:
            return [partner]
        if not (isinstance(parent, Assign) and len(parent.targets) == 1 and isinstance(parent.targets[0], Name)):
            return []
        name, scope = parent.targets[0].id, facts.index.scope_of(parent)
        partners = []
        for use in ast.walk(scope.node):
            if not (isinstance(use, Name) and use.id == name and isinstance(use.ctx, Load)) or facts.index.scope_of(use) is not scope:
                continue
            partner = self._partner_in_product(*self._above_transposes(use))
            if partner is None:
                return []  # used otherwise too: what it meets is not known
            partners.append(partner)
        return partners

    def _above_transposes(self, node: AST) -> tuple[AST, AST | None]:
        """`node` or the outermost transpose of it (`x.T`, `x.transpose(-1, -2)`), and its parent."""
        parent = self.facts.parent(node)
        while parent is not None and is_transpose(parent):
            node, parent = parent, self.facts.parent(parent)
        return node, parent

    def _partner_in_product(self, operand: AST, parent: AST | None) -> ast.expr | None:
        """The other operand of `parent` when it is a matrix product of `operand`, else None."""
        product = self.facts.matmul(parent) if parent is not None else None
        if product is None or operand not in (product.left, product.right):
            return None
        return product.right if operand is product.left else product.left

    def _may_translate(self, matrix: ast.expr, depth: int = 0) -> bool:
        """False when `matrix` certainly has no translation: a literal identity (`np.eye(4)`,
        `torch.eye(4)[:3, :4]`) never written into, a library transform made without one
        (its stub returns a rotation alone: nerfstudio's `auto_orient_and_center_poses(...,
        center_method="none")`), a name bound only to such, or a parameter of a private helper
        whose calls in the module all pass such (a private helper nothing calls is reached by none)."""
        facts = self.facts
        while depth < 8:
            depth += 1
            inner = transposed_value(matrix)
            if inner is not None:
                matrix = inner
            elif isinstance(matrix, Subscript) and all(isinstance(part, Slice) for part in subscript_parts(matrix)):
                matrix = matrix.value  # a block of a matrix without translation has none
            elif isinstance(matrix, Call) and isinstance(matrix.func, Attribute) and matrix.func.attr in vocab.PASSTHROUGH_METHODS:
                matrix = matrix.func.value  # `.to(device)`, `.float()`
            else:
                break
        if isinstance(matrix, Call):
            if facts.is_array_call(matrix.func, "eye", "identity"):
                return False
            return _untranslated_element(facts, matrix, None) is not True
        if isinstance(matrix, Subscript):
            index = number(matrix.slice)
            return not (isinstance(matrix.value, Call) and index is not None and _untranslated_element(facts, matrix.value, int(index)))
        if not isinstance(matrix, Name) or depth >= 8:
            return True
        scope = facts.index.scope_of(matrix)
        if matrix.id in scope.subscript_stores or matrix.id in scope.augmented:
            return True  # `T = np.eye(4); T[:3, 3] = t`: written into
        bindings = facts.bindings(matrix)
        if not bindings:
            return True
        for binding in bindings:
            if isinstance(binding, ast.expr):
                if self._may_translate(binding, depth + 1):
                    return True
            elif isinstance(binding, UnpackBinding):
                if not (isinstance(binding.value, Call) and _untranslated_element(facts, binding.value, binding.position)):
                    return True
            elif not isinstance(binding, ParamBinding) or self._argument_may_translate(binding, depth + 1):
                return True
        return False

    def _argument_may_translate(self, parameter: ParamBinding, depth: int) -> bool:
        """Whether a call of the private helper that has `parameter` may pass a matrix that translates.
        Only a private helper (`_name`) has all its calls in its module; one it is also named in
        otherwise (passed as a callback, called on another object) may be given anything."""
        facts = self.facts
        function = parameter.function
        if not isinstance(function, (FunctionDef, AsyncFunctionDef)) or not function.name.startswith("_") or function.name.startswith("__"):
            return True
        params = [arg.arg for arg in (*function.args.posonlyargs, *function.args.args)]
        name = parameter.arg.arg
        calls = [call for call in facts.index.nodes(Call) if last_name(call.func) == function.name]  # type: ignore[attr-defined]
        if facts.index.source.count(function.name) != len(calls) + 1:
            return True  # named elsewhere than its definition and its calls
        for call in calls:
            assert isinstance(call, Call)
            if facts.own_method(call) is function:
                position = params.index(name) - 1 if name in params else None
            elif facts.called_function(call) == (facts, function):
                position = params.index(name) if name in params else None
            else:
                return True  # a call of another object's method of that name
            if any(isinstance(arg, Starred) for arg in call.args) or any(given.arg is None for given in call.keywords):
                return True
            given = keyword(call, name)
            if given is not None:
                argument: ast.expr | None = given.value
            elif position is not None and 0 <= position < len(call.args):
                argument = call.args[position]
            else:
                argument = parameter.default
            if argument is None or self._may_translate(argument, depth):
                return True
        return False

    def _check_binary(self, node: BinOp) -> None:
        facts = self.facts
        if isinstance(node.op, Add):
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
        if isinstance(node.op, Mult) and facts.is_free(node.right):
            library = facts.translating_library_object(node.left)
            if library is not None:
                self.report(
                    node,
                    f"`{self.code_of(node.left)}` is a {library}, and `*` translates what it multiplies, but "
                    f"`{self.code_of(node.right)}` is a direction; apply only its rotation",
                )
                return
        if isinstance(node.op, MatMult) and isinstance(node.left, Attribute):
            if node.left.attr == "matrix_world" and facts.is_free(node.right):
                self.report(
                    node,
                    f"`{self.code_of(node.left)}` translates, but `{self.code_of(node.right)}` is a direction; "
                    "rotate it with `matrix_world.to_3x3()`",
                )

    def _stored_as_point(self, node: AST) -> bool:
        """`tip_point = R @ offset_dir + t` builds a point from a direction on purpose."""
        parent = self.facts.parent(node)
        if isinstance(parent, Assign):
            return any(
                isinstance(target, Name) and kind_of_name(target.id, self.context.config) == Kind.POINT
                for target in parent.targets
            )
        return False

    def _rotated_direction(self, node: ast.expr) -> ast.expr | None:
        """For `R @ n`, `n @ R.T`, `(R @ n.T).T` with n a direction, the direction n; also for a batch
        rotated as columns: `(R @ n[..., None])[..., 0]`, `torch.bmm(R, n.unsqueeze(-1)).squeeze(-1)`."""
        facts = self.facts
        dropped = _column_dropped(node)
        if dropped is not None:
            node = dropped
        inner = transposed_value(node)
        if inner is not None:
            node = inner
        product = facts.matmul(node)
        if product is None:
            return None
        column = _column_added(product.right)
        if dropped is not None and column is None:
            return None  # `(n @ R.T)[..., 0]`: one coordinate of each rotated row, not the rotated direction
        right = product.right if column is None else column
        left, right_kind = facts.kind_of(product.left), facts.kind_of(right)
        if right_kind in FREE and left not in GEOMETRIC:
            return right
        if column is None and left in FREE and right_kind not in GEOMETRIC:
            return product.left
        return None

    def _check_library_call(self, node: Call) -> None:
        facts = self.facts
        if last_name(node.func) == "multiplyTransforms":
            self._check_pybullet_multiply(node)
            return
        for argument, moved_as in library_calls.moved_arguments(facts, node):  # the knowledge base (stubs/)
            if moved_as is Kind.POINT and facts.is_free(argument):
                self._report_translated(node, argument)

    def _report_translated(self, node: Call, argument: ast.expr) -> None:
        """A library call that moves `argument`, a direction, as a point; the fix the stubs offer, if any."""
        facts, called = self.facts, last_name(node.func)
        makes_homogeneous = "gives w = 1" if library_calls.homogenizes(facts, node) else "translates its input"
        held = "is a direction" if makes_homogeneous == "gives w = 1" else "holds directions"
        fix = library_calls.moving_as(facts, node, argument, FREE)
        if fix is None:
            self.report(node, f"`{called}` {makes_homogeneous}, but `{self.code_of(argument)}` {held}")
        elif fix[0] == "keyword":
            self.report(
                node,
                f"`{called}` {makes_homogeneous}, but `{self.code_of(argument)}` {held}; pass `{fix[1]}`",
                replacement=with_keyword(facts.index.segment(node), fix[1]),
                applicability="unsafe",
                fix_description=f"pass {fix[1]}",
            )
        else:
            self.report(
                node,
                f"`{called}` {makes_homogeneous}, but `{self.code_of(argument)}` {held}; use `{fix[1]}`",
                replacement=replace_span(facts.index, node, [(last_name_target(node.func), fix[1])]),
                applicability="unsafe",
                fix_description=f"use {fix[1]}",
            )

    def _check_pybullet_multiply(self, node: Call) -> None:
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


def _column_added(node: ast.expr) -> ast.expr | None:
    """For `x[..., None]`, `x[:, :, None]`, `x.unsqueeze(-1)`, `np.expand_dims(x, -1)` (a trailing axis
    of one, so that a stack of matrices acts on x's rows as columns), x; else None."""
    if isinstance(node, Subscript):
        parts = subscript_parts(node)
        last = parts[-1]
        if len(parts) >= 2 and isinstance(last, Constant) and last.value is None and all(is_batch_index(part) for part in parts[:-1]):
            return node.value
        return None
    if isinstance(node, Call) and number(node.args[-1] if node.args else None) == -1 and not node.keywords:
        if isinstance(node.func, Attribute) and node.func.attr == "unsqueeze" and len(node.args) == 1:
            return node.func.value
        if last_name(node.func) == "expand_dims" and len(node.args) == 2:
            return node.args[0]
    return None


def _column_dropped(node: ast.expr) -> ast.expr | None:
    """For `y[..., 0]`, `y[..., :, 0]`, `y[:, :, 0]`, `y.squeeze(-1)`, `np.squeeze(y, -1)` (the trailing axis
    of one dropped again), y; else None."""
    if isinstance(node, Subscript):
        parts = subscript_parts(node)
        if len(parts) >= 2 and number(parts[-1]) == 0 and all(is_batch_index(part) for part in parts[:-1]):
            return node.value
        return None
    if isinstance(node, Call) and number(node.args[-1] if node.args else None) == -1 and not node.keywords:
        if isinstance(node.func, Attribute) and node.func.attr == "squeeze" and len(node.args) == 1:
            return node.func.value
        if last_name(node.func) == "squeeze" and len(node.args) == 2:
            return node.args[0]
    return None


def _untranslated_element(facts: FactBase, call: Call, position: int | None) -> bool:
    """Whether element `position` of what `call` returns (None: the value itself) is, by its stub, a
    rotation alone: a transform made without translation (nerfstudio's `auto_orient_and_center_poses(...,
    center_method="none")`)."""
    returned = library_calls.returned_part(facts, call, position)
    return returned is not None and returned.kind is Kind.ROTATION


def _through(summary: TranslationSummary, index: int) -> str:
    """`, through `move` -> `apply_pose``: the helpers a summary's translation comes through."""
    chain = summary.translates_through.get(index)
    return f", through {chain}" if chain else ""
