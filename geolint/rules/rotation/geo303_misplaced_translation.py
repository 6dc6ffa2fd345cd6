"""GEO303 misplaced-translation: a translation written into the homogeneous row or the rotation block of a pose."""

from __future__ import annotations

from typing import Final

import ast
from ast import AST, Assign, Attribute, AugAssign, Call, Constant, Module, Name, Starred, Subscript, USub, UnaryOp

from geolint.factbase import ModuleIndex, index_of
from geolint.factbase.model import is_full_slice, is_slice_upto, is_zero
from geolint.factbase.pose_parts import (
    call_name,
    int_value,
    matmul_operands,
    matrix_indices,
    pose_key,
    pose_part,
    peel_same_value,
    same_code,
    square_shape,
    stack_key,
    translation_source,
    transposed_operand,
)
from geolint.factbase.reaching import resolve, scope_of
from geolint.rules.base import AstRule, Invalid, Valid
from geolint.rules.triggers import AllOf


class MisplacedTranslation(AstRule):
    """A translation is written into the bottom (homogeneous) row or the rotation block of a pose.

    ## What it does
    Flags an assignment into row 3, columns 0-2 of a 4x4 pose or a stack of them
    (`T[3, :3] = t`, `T[3, 0] = x`, `poses[:, 3, :3] -= center`) when the array is certainly a
    pose in the column-vector convention: either it was made 4x4 (`np.eye(4)`,
    `np.zeros((4, 4))`, `torch.eye(4).repeat(n, 1, 1)`, tf `quaternion_matrix`) and the same
    function reads or writes its rotation block `[:3, :3]` or its translation column `[:3, 3]`,
    or the value written is (a mean, negation or scaling of) the same array's own translation
    column `X[..., :3, 3]`. The same own-translation value written into the rotation block
    (`poses[:, :3, :3] -= poses[:, :3, 3].mean(0)`) is flagged too. Reading the bottom row, and
    writing zeros into it, are fine. The mirror slip is flagged as well: a pose's rotation block
    given to a call that translates (`box.translate(-cam2ego[:3, :3])`, `translation_matrix(T[:3, :3])`),
    where the translation column `[:3, 3]` was meant. So is the read-side slip: the bottom row
    (`T[3, :]`, `T[3, :3]`) stored where a translation goes (`{"location": list(T[3, :])}`,
    `obj.location = T[3, :3]`, `translate(T[-1, :3])`) when the same function writes or reads the
    translation column `T[:3, 3]` of that 4x4 (so it is laid out for column vectors).

    ## Why is this bad?
    In the column-vector convention (`T @ [x, y, z, 1]`, what numpy, Open3D, trimesh, ROS and
    most robotics code use) the translation lives in column 3 and the bottom row is
    `[0, 0, 0, 1]`. A translation stored in the bottom row never moves a point; it changes the
    w of every transformed point instead, so points are scaled by `1 / w` after dehomogenising,
    or left untranslated when w is dropped.

    ## Example
    ```python
    center = poses[:, :3, 3].mean(0)
    poses[:, 3, :3] -= center
    ```

    ## Use instead
    ```python
    center = poses[:, :3, 3].mean(0)
    poses[:, :3, 3] -= center
    ```

    ## Fix safety
    The fix writes into the translation column instead (`T[3, :3]` -> `T[:3, 3]`,
    `poses[:, :3, :3]` -> `poses[:, :3, 3]`) and is unsafe: code written in the row-vector
    convention (`points_h @ T`) keeps its translation in the bottom row on purpose.

    ## Known problems
    The row-vector convention is recognised only when the same function multiplies the array from
    the right (`points_h @ T`, `np.dot(points_h, T)`) or transposes it (`M.T`) and never reads
    `M[:3, 3]` as a translation; row-vector code
    that passes the matrix elsewhere (DirectX/Unity-style engines, some OpenGL uniform builders)
    can be flagged. A projective matrix is recognised by a corner `M[3, 3]` set to anything but 1.
    """

    code = "GEO303"
    name = "misplaced-translation"
    triggers = AllOf(
        r"\[[^\]\n]*(?:\b3|:\s*3)\s*,\s*(?::\s*3|0\s*:\s*3|[012])\s*\]\s*[-+*/]?="
        r"|translate\(|translation_matrix\(|set_translation\(|from_translation\("  # each led by its own word
        r"|\[\s*(?:3|-1)\s*,\s*(?::\s*3?|0\s*:\s*3)\s*\]"  # a read of the bottom row (`T[3, :]`)
    )

    VALID = [
        Valid("import numpy as np\nT = np.eye(4)\nT[:3, :3] = R\nT[:3, 3] = t\n"),
        Valid("import numpy as np\nT = np.eye(4)\nT[:3, :3] = R\nT[3, :3] = 0\n"),
        Valid("import numpy as np\nT = np.eye(4)\nT[:3, :3] = R\nt = T[3, :3]\n"),  # a read
        Valid(
            "import numpy as np\ndef f(R, t):\n    T = np.eye(4)\n    T[:3, :3] = R\n    T[:3, 3] = t\n"
            "    assert np.allclose(T[3, :], [0, 0, 0, 1])\n    return {'location': list(T[:3, 3]), 'row': list(T[3, :])}\n"
        ),  # the bottom row read, but not stored as a translation
        Valid(
            "import numpy as np\ndef f(R, t, pts_h):\n    M = np.eye(4)\n    M[:3, :3] = R.T\n"
            "    M[3, :3] = t\n    return {'translation': M[3, :3], 'points': pts_h @ M}\n"
        ),  # the row-vector convention: no read of the translation column
        Valid("import numpy as np\nP = np.zeros((4, 4))\nP[3, 2] = -1.0\n"),  # a projection matrix
        Valid(
            "import numpy as np\ndef f(R, t, pts_h):\n    M = np.eye(4)\n    M[:3, :3] = R.T\n"
            "    M[3, :3] = t\n    return pts_h @ M\n"
        ),  # the row-vector convention, applied as such
        Valid("def f(M, t):\n    M[3, :3] = t\n"),  # nothing says M is a pose
        Valid(
            "import torch\ndef screen_camera(K3, n):\n    K = torch.zeros((n, 4, 4))\n    K[:, :3, :3] = K3\n"
            "    K[:, 2, 2] = 0\n    K[:, 2, -1] = 1\n    K[:, -1, 2] = 1\n    return K\n"
        ),  # w = z: a camera projection (PyTorch3D's screen-space K), not a pose
        Valid(
            "import numpy as np\nfrom vispy.visuals import transforms\ndef place(mesh, R, offset, p):\n"
            "    M = np.eye(4)\n    M[:3, :3] = np.dot(offset, R)\n    M[3, :3] = p\n"
            "    mesh.transform = transforms.MatrixTransform(M)\n"
        ),  # VisPy applies matrices to row vectors: the translation lives in the bottom row
        Valid("def to_camera(box, cam2ego):\n    box.translate(-cam2ego[:3, 3])\n    box.rotate(cam2ego[:3, :3].T)\n"),
        Valid(
            "import numpy as np\ndef f(R, t):\n    M = np.eye(4)\n    M[:3, :3] = R.T\n    M[3, :3] = -t\n"
            "    return M.T\n"
        ),  # built in row layout, returned transposed
        Valid(
            "import numpy as np\ndef projection(normal, point, d):\n    M = np.identity(4)\n"
            "    M[:3, 3] = point\n    M[3, :3] = -normal\n    M[3, 3] = d\n    return M\n"
        ),
        Valid(
            "import torch\ndef splat_matrix(center, rot_scale):\n    RS = rot_scale.permute(0, 2, 1)\n"
            "    M = torch.zeros((center.shape[0], 4, 4))\n    M[:, :3, :3] = RS\n    M[:, 3, :3] = center\n"
            "    M[:, 3, 3] = 1\n    return M\n"
        ),  # the whole matrix laid out transposed (row vectors): rotation block transposed, translation in row 3
    ]
    INVALID = [
        Invalid(
            "import numpy as np\ndef f(R, t):\n    T = np.eye(4)\n    T[:3, :3] = R\n    T[:3, 3] = t\n"
            "    return {'location': list(T[3, :]), 'rotation': R}\n",
            expected_fix="import numpy as np\ndef f(R, t):\n    T = np.eye(4)\n    T[:3, :3] = R\n    T[:3, 3] = t\n"
            "    return {'location': list(T[:3, 3]), 'rotation': R}\n",
            message="`T[3, :]` is the bottom (homogeneous) row of a 4x4 pose, [0, 0, 0, 1], but it is stored as a translation; the translation is column 3 (`[:3, 3]`)",
            range=(6, 30, 6, 37),
        ),
        Invalid(
            "import numpy as np\nT = np.eye(4)\nT[:3, :3] = R\nT[3, :3] = t\n",
            expected_fix="import numpy as np\nT = np.eye(4)\nT[:3, :3] = R\nT[:3, 3] = t\n",
        ),
        Invalid("import torch\ndef f(R, c, n):\n    poses = torch.eye(4).repeat(n, 1, 1)\n    poses[:, :3, :3] = R\n    poses[:, 3, :3] -= c\n    return poses\n"),
        Invalid("import numpy as np\nT = np.zeros((4, 4))\nT[:3, :3] = R\nT[3, 0] = x\nT[3, 3] = 1\n"),
        Invalid("import numpy as np\nT_inv = np.eye(4)\nT_inv[:3, :3] = R.T\nT_inv[3, :3] = -R.T @ t\n"),  # an inverse's translation
        Invalid("def center(poses):\n    c = poses[:, :3, 3].mean(0)\n    poses[:, :3, :3] -= c\n    return poses\n"),
        Invalid(
            "def to_camera(box, info):\n    cam2ego = np.array(info['cam2ego'])\n    box.translate(-cam2ego[:3, :3])\n",
            expected_fix="def to_camera(box, info):\n    cam2ego = np.array(info['cam2ego'])\n    box.translate(-cam2ego[:3, 3])\n",
        ),
        Invalid(
            "import torch\ndef orient(poses, center_poses):\n    translation = poses[..., :3, 3]\n"
            "    mean_translation = torch.mean(translation, dim=0)\n    if center_poses:\n"
            "        translation = mean_translation\n    else:\n        translation = torch.zeros_like(mean_translation)\n"
            "    oriented = transform @ poses\n    poses[:, 3, :3] -= translation\n    return oriented\n"
        ),
    ]

    def check(self, tree: Module) -> None:
        index = index_of(tree)
        for node in index.nodes(Call, Assign, AugAssign, ast.Dict):
            if isinstance(node, ast.Dict):
                for key, item in zip(node.keys, node.values):
                    if isinstance(key, Constant) and key.value in _TRANSLATION_KEYS:
                        self._check_bottom_row_read(item, index)
                continue
            if isinstance(node, Call):
                for keyword in node.keywords:
                    if keyword.arg in _TRANSLATION_KEYS:
                        self._check_bottom_row_read(keyword.value, index)
                if call_name(node) in _TRANSLATING_CALLS:
                    if node.args:
                        self._check_bottom_row_read(node.args[0], index)
                    self._check_translation_argument(node)
                continue
            if isinstance(node, Assign):
                targets, value = node.targets, node.value
            elif isinstance(node, AugAssign):
                targets, value = [node.target], node.value
            else:
                continue
            for target in targets:
                if isinstance(node, Assign) and _names_a_translation(target):
                    self._check_bottom_row_read(value, index)
                if not isinstance(target, Subscript) or not isinstance(target.value, Name):
                    continue
                indices = matrix_indices(target)
                if indices is None or is_zero(value):
                    continue
                bottom_row = _is_bottom_row_translation(indices[1], indices[2])
                rotation_block = is_slice_upto(indices[1], 3) and is_slice_upto(indices[2], 3)
                if not bottom_row and not rotation_block:
                    continue
                from_translation = self._comes_from_own_translation(target, indices[0], value, index)
                if bottom_row and (
                    from_translation or self._is_column_convention_pose(target, bool(indices[0]), index, _has_product(value))
                ):
                    self._report_bottom_row(target, indices[2])
                elif rotation_block and from_translation:
                    self.report(
                        target,
                        f"`{ast.unparse(target)}` is the rotation block, but the value written into it comes from "
                        f"the same pose's translation column; the translation is `[..., :3, 3]`",
                        replacement=f"{ast.unparse(target.value)}[{subscript_indices_text(target)}:3, 3]",
                        applicability="unsafe",
                        fix_description="write into the translation column",
                    )

    def _check_translation_argument(self, call: Call) -> None:
        """`box.translate(-T[:3, :3])`: a 3x3 rotation block where a 3-vector translation goes."""
        arguments = call.args[:1] + [k.value for k in call.keywords if k.arg in ("translation", "t", "x", "vector")]
        for argument in arguments:
            block = argument.operand if isinstance(argument, UnaryOp) and isinstance(argument.op, USub) else argument
            if not isinstance(block, Subscript):
                continue
            indices = matrix_indices(block)
            if indices is None or not (is_slice_upto(indices[1], 3) and is_slice_upto(indices[2], 3)):
                continue
            self.report(
                block,
                f"`{call_name(call)}` takes a translation, but `{ast.unparse(block)}` is the rotation block of "
                "a pose; its translation is the column `[:3, 3]`",
                replacement=f"{ast.unparse(block.value)}[{subscript_indices_text(block)}:3, 3]",
                applicability="unsafe",
                fix_description="pass the translation column",
            )

    def _check_bottom_row_read(self, value: ast.expr, index: ModuleIndex) -> None:
        """`{"location": list(T[3, :])}`: the bottom row of a column-convention 4x4 stored as a translation."""
        read = _peel_vector(value)
        if isinstance(read, Name):
            resolved = resolve(index, read)
            if isinstance(resolved, ast.expr):
                read = _peel_vector(resolved)
        if not isinstance(read, Subscript) or not isinstance(read.value, Name):
            return
        indices = matrix_indices(read)
        if indices is None or int_value(indices[1]) not in (3, -1):
            return
        if not (is_full_slice(indices[2]) or is_slice_upto(indices[2], 3)):
            return
        if not self._is_column_convention_pose(read, bool(indices[0]), index, read_side=True):
            return
        self.report(
            read,
            f"`{ast.unparse(read)}` is the bottom (homogeneous) row of a 4x4 pose, [0, 0, 0, 1], but it is "
            "stored as a translation; the translation is column 3 (`[:3, 3]`)",
            replacement=f"{ast.unparse(read.value)}[{subscript_indices_text(read)}:3, 3]",
            applicability="unsafe",
            fix_description="read the translation column",
        )

    def _comes_from_own_translation(
        self, target: Subscript, batch: list[ast.expr], value: ast.expr, index: ModuleIndex
    ) -> bool:
        """The value is (a mean, negation or scaling of) the same array's translation column `X[..., :3, 3]`."""
        key = pose_key(target.value, index)
        source = translation_source(value, index)
        if source is None:
            return False
        return source.pose in (key, f"{key}[{stack_key(batch)}]") or source.pose.startswith(f"{key}[")

    def _is_column_convention_pose(
        self,
        target: Subscript,
        stacked: bool,
        index: ModuleIndex,
        computed_translation: bool = False,
        read_side: bool = False,
    ) -> bool:
        """A 4x4 laid out for column vectors; for a read (`read_side`), only when the same function also
        reads or writes its translation column `[:3, 3]` and nothing says it is laid out for row vectors."""
        shape = square_shape(target.value, index)
        if shape is None or shape[0] != 4 or (shape[1] and not stacked):
            return False
        scope = scope_of(index, target).node
        base = target.value
        states_pose = False
        reads_translation_column = False
        row_layout = False
        divide_corners: set[tuple[int, int]] = set()
        for node in ast.walk(scope):
            if isinstance(node, Subscript) and same_code(node.value, base):
                divide_corners |= _perspective_divide_corner(node, index)
                if len(divide_corners) == 2:
                    return False  # M[2, 3] = M[3, 2] = 1: a camera projection dividing by z, not a pose
            if isinstance(node, Subscript) and node is not target and same_code(node.value, base):
                part = pose_part(node, index)
                states_pose = states_pose or part is not None
                reads_translation_column = reads_translation_column or (part is not None and part.kind == "translation")
                if _writes_projective_corner(node, index):
                    return False  # M[3, 3] = d: a projection, whose bottom row is meant to be full
            row_layout = row_layout or _says_row_layout(node, base, index, computed_translation, read_side)
        if read_side:
            return reads_translation_column and not row_layout
        return states_pose and (reads_translation_column or not row_layout)

    def _report_bottom_row(self, target: Subscript, column: ast.expr) -> None:
        replacement = None
        if is_slice_upto(column, 3):
            indices = subscript_indices_text(target)
            replacement = f"{ast.unparse(target.value)}[{indices}:3, 3]"
        self.report(
            target,
            f"`{ast.unparse(target)}` writes into the bottom (homogeneous) row of a 4x4 pose; its "
            "translation belongs in column 3 (`[:3, 3]`), and the bottom row stays [0, 0, 0, 1]",
            replacement=replacement,
            applicability="unsafe",
            fix_description="write the translation into column 3",
        )


# Dict keys and keyword arguments whose value is a translation (`{"location": ...}`, `translation=...`).
_TRANSLATION_KEYS: Final = frozenset({"location", "position", "translation", "trans", "tvec", "t"})
# Words of a name that holds a translation (`cam_location`, `obj.position`, `t_w2c`).
_TRANSLATION_WORDS: Final = frozenset({"location", "position", "translation", "trans", "tvec", "t"})


def _says_row_layout(node: AST, base: ast.expr, index: ModuleIndex, computed_translation: bool, read_side: bool) -> bool:
    """Whether `node` shows the 4x4 `base` laid out for row vectors (its transpose is the pose)."""
    if not computed_translation and _writes_transposed_rotation(node, base, index):
        return True  # [R^T 0; t 1]: the transpose of a pose, laid out for row vectors
    transposed = transposed_operand(node) if isinstance(node, ast.expr) else None
    if transposed is not None and same_code(transposed, base) and not (read_side and _inverts(node)):
        return True  # built transposed (row-vector layout), then transposed into place
    operands = matmul_operands(node)
    if operands is not None and same_code(operands[1], base) and not _is_pose_like(operands[0], index):
        return True  # points_h @ T: the row-vector convention
    return _row_vector_consumer(node, base, index)  # vispy's MatrixTransform(T) applies T to row vectors


def _inverts(node: AST) -> bool:
    """`np.linalg.inv(T)`, `T.inverse()`: an inverse, which keeps the layout (unlike a transpose)."""
    return isinstance(node, Call) and call_name(node) in ("inv", "pinv", "inverse", "inverted")


def _names_a_translation(target: ast.expr) -> bool:
    name = target.id if isinstance(target, Name) else target.attr if isinstance(target, Attribute) else ""
    return not _TRANSLATION_WORDS.isdisjoint(name.lower().split("_"))


def _peel_vector(node: ast.expr) -> ast.expr:
    """`list(x)`, `tuple(x)`, `Vector(x)`, `x.tolist()`, `np.array(x)`, `x.copy()`: the same values."""
    for _ in range(4):
        inner = peel_same_value(node)
        if inner is node and isinstance(node, Call):
            if call_name(node) in ("list", "tuple", "Vector") and len(node.args) == 1 and not node.keywords:
                inner = node.args[0]
            elif isinstance(node.func, Attribute) and node.func.attr == "tolist" and not node.args:
                inner = node.func.value
        if inner is node or isinstance(inner, Starred):
            return node
        node = inner
    return node


# Calls whose argument is a translation (nuScenes/pyquaternion boxes, trimesh, Open3D, spatialmath).
_TRANSLATING_CALLS: Final = frozenset({"translate", "translation_matrix", "set_translation", "from_translation"})


def subscript_indices_text(target: Subscript) -> str:
    """The batch indices of a stacked pose subscript, as text with a trailing comma (`:, `)."""
    indices = target.slice.elts if isinstance(target.slice, ast.Tuple) else [target.slice]
    return "".join(f"{ast.unparse(index)}, " for index in indices[:-2])


def _is_bottom_row_translation(row: ast.expr, column: ast.expr) -> bool:
    if int_value(row) not in (3, -1):
        return False
    return is_slice_upto(column, 3) or int_value(column) in (0, 1, 2)


def _writes_projective_corner(node: Subscript, index: ModuleIndex) -> bool:
    """`M[3, 3] = value` with anything but 1: the matrix is projective, not a rigid pose."""
    indices = matrix_indices(node)
    if indices is None or int_value(indices[1]) not in (3, -1) or int_value(indices[2]) not in (3, -1):
        return False
    statement = index.parents.get(node)
    if isinstance(statement, Assign) and node in statement.targets:
        return not (isinstance(statement.value, Constant) and statement.value.value == 1)
    return isinstance(statement, AugAssign) and statement.target is node


def _perspective_divide_corner(node: Subscript, index: ModuleIndex) -> set[tuple[int, int]]:
    """{(2, 3)} or {(3, 2)} when `node` is `M[2, 3] = 1` or `M[3, 2] = 1` (`-1` for 3 too): together they
    are the signature of a screen-space camera matrix (PyTorch3D's `K` with `in_ndc=False`: w = z)."""
    indices = matrix_indices(node)
    statement = index.parents.get(node)
    if indices is None or not (isinstance(statement, Assign) and node in statement.targets):
        return set()
    if not (isinstance(statement.value, Constant) and statement.value.value == 1):
        return set()
    corner = tuple(3 if value == -1 else value for value in (int_value(indices[1]), int_value(indices[2])))
    return {corner} if corner in ((2, 3), (3, 2)) else set()  # type: ignore[return-value]


def _has_product(value: ast.expr) -> bool:
    """`-R.T @ t`, `R.dot(t)`: a computed translation (an inverse's), not a value laid out as it is."""
    return any(matmul_operands(node) is not None for node in ast.walk(value))


def _writes_transposed_rotation(node: AST, base: ast.expr, index: ModuleIndex) -> bool:
    """`M[..., :3, :3] = R.T` (or a name bound to `R.permute(0, 2, 1)`): the rotation block of `base`
    is written transposed, so a translation in its bottom row is the same layout, not a slip."""
    if not isinstance(node, Assign) or len(node.targets) != 1:
        return False
    target = node.targets[0]
    if not isinstance(target, Subscript) or not same_code(target.value, base):
        return False
    indices = matrix_indices(target)
    if indices is None or not (is_slice_upto(indices[1], 3) and is_slice_upto(indices[2], 3)):
        return False
    value = resolve(index, node.value)
    if not isinstance(value, ast.expr) or transposed_operand(value) is None:
        return False
    return not (isinstance(value, Call) and call_name(value) in ("inverse", "inv", "pinv"))


# Library classes that apply a 4x4 to row vectors (`coords @ M`): VisPy's transforms.
_ROW_VECTOR_CONSUMERS: Final = frozenset({"vispy.visuals.transforms.MatrixTransform", "vispy.visuals.transforms.linear.MatrixTransform"})


def _row_vector_consumer(node: AST, base: ast.expr, index: ModuleIndex) -> bool:
    """`transforms.MatrixTransform(T)` with `transforms` imported from vispy: the matrix is laid out
    for row vectors, so its translation belongs in the bottom row."""
    if not isinstance(node, Call) or not node.args or not same_code(node.args[0], base):
        return False
    func = node.func
    if isinstance(func, Name):
        qualified = index.imports.get(func.id, "")
    elif isinstance(func, Attribute) and isinstance(func.value, Name) and func.value.id in index.imports:
        qualified = f"{index.imports[func.value.id]}.{func.attr}"
    else:
        return False
    return qualified in _ROW_VECTOR_CONSUMERS


def _is_pose_like(node: ast.expr, index: ModuleIndex) -> bool:
    shape = square_shape(node, index)
    return shape is not None and shape[0] == 4
