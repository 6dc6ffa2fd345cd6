"""GEO205 half-inverse-transform: a pose's rotation used one way and its translation the other."""

from __future__ import annotations

from typing import Final

import ast
from ast import (
    AST,
    Add,
    Assign,
    Attribute,
    AugAssign,
    BinOp,
    Call,
    Constant,
    Module,
    Name,
    Sub,
    Subscript,
    UnaryOp,
    USub,
)

from geolint.factbase import ModuleIndex, index_of
from geolint.factbase.pose_parts import (
    Application,
    application,
    difference_with,
    matmul_operands,
    peel_same_value,
    pose_part,
    same_code,
    transposed_operand,
)
from geolint.factbase.reaching import Unpacked, resolve, scope_of
from geolint.factbase.project_files import may_be_project_import
from geolint.rules.base import AstRule, Invalid, Valid
from geolint.rules.triggers import MATMUL_TEXT, POSE_PART_TEXT, AllOf, AnyOf

# A product, or a transpose/inverse written into a pose's rotation block.
_PRODUCT_OR_TRANSPOSE_TEXT: Final = AnyOf(MATMUL_TEXT, r"\.m?T\b|\.transpose\(|\binv\(")


class HalfInverseTransform(AstRule):
    """A pose's rotation is inverted and its translation is not (or the reverse): neither T nor T⁻¹.

    ## What it does
    Flags a point mapped by the rotation R and the translation t of one pose (the same `T[:3, :3]`
    and `T[:3, 3]`, `poses[:, :3, :3]` and `poses[:, :3, 3]`, `pose.rotation` and
    `pose.translation`, `gt["cam_R_m2c"]` and `gt["cam_t_m2c"]`, or `R, t` unpacked from one
    call) where one of them is inverted and the other is not:

    - `R.T @ p + t` (or `- t`), row form `p @ R + t`: the inverse rotation with the forward
      translation;
    - `R @ (p - t)`, row form `(p - t) @ R.T`, and the batched torch form
      `(x - poses[:, None, :3, 3]) @ poses[:, :3, :3].transpose(1, 2)`: the inverse translation
      with the forward rotation.

    The parts are followed through local names, copies, reshapes (`t[:, None]`) and transposes
    (`.T`, `.mT`, `.transpose(1, 2)`, `.permute(0, 2, 1)`, `np.linalg.inv(R)`). The true forward
    map `R @ p + t` / `p @ R.T + t` and the true inverse `R.T @ (p - t)` / `(p - t) @ R` are
    silent, and so is a rotation about the pose's origin (`R @ (p - t) + t`).

    Two more ways to write the same slip are flagged:

    - an inverse assembled block by block with the rotation inverted and the translation only
      negated: `M[:3, :3] = R.T` then `M[:3, 3] = -t` (the inverse's translation is `-R.T @ t`);
    - the row form in place, over two statements: `x[:, :3] = x[:, :3] @ R` then
      `x[:, :3] -= t` (that is `Rᵀ p - t`; the inverse is `(p - t) @ R`).

    ## Why is this bad?
    For a pose T = (R, t) that maps frame b into frame a, `R p + t` moves a point from b to a and
    `Rᵀ (p - t)` moves it back. Mixing the halves (`Rᵀ p + t`, `R (p - t)`) is neither: the
    result is off by a rotation of the translation, so it looks right for poses near identity or
    near the origin, and drifts everywhere else. It is the usual slip when an inverse is written
    out by hand.

    ## Example
    ```python
    def world_to_camera(points_world, T_world_cam):
        R = T_world_cam[:3, :3]
        t = T_world_cam[:3, 3]
        return points_world @ R + t
    ```

    ## Use instead
    ```python
    def world_to_camera(points_world, T_world_cam):
        R = T_world_cam[:3, :3]
        t = T_world_cam[:3, 3]
        return (points_world - t) @ R
    ```

    ## Fix safety
    There is no automatic fix: only the author knows whether the forward map or the inverse
    was meant.

    ## Known problems
    A rotation read from a key is taken to be stored as a rotation (column form); when the same
    module writes that key from a computed matrix (`info["rot"] = R` laid out for `points @ R`),
    the in-place row form is not judged. Nor is the row form `x @ R` (R not transposed) when R is an
    entry or element of what a project function returned (`tform["rotation"]` of
    `d, Z, tform = procrustes(X, Y)`, `rot` of `rot, trans = fit(X, Y)`): a port of MATLAB's
    `procrustes` builds R for right multiplication (`Z = b * Y @ T + c` is the fitted map), and
    the rule does not read the function to tell; a project function that returns a column-form
    rotation in a dict is then missed. The rule needs evidence that R and t belong to one pose; rotations and translations passed in
    separately (`def f(R, t, p)`) are not checked. A codebase that stores a camera *centre* under a
    translation's name (`pose.t` = centre, so `R @ (p - pose.t)` is right) is flagged; such a
    value is better named `center`.
    """

    code = "GEO205"
    name = "half-inverse-transform"
    triggers = AllOf(_PRODUCT_OR_TRANSPOSE_TEXT, POSE_PART_TEXT)

    VALID = [
        Valid("p_world = T[:3, :3] @ p_cam + T[:3, 3]\n"),
        Valid("p_cam = T[:3, :3].T @ (p_world - T[:3, 3])\n"),
        Valid("def f(pts, T):\n    R, t = T[:3, :3], T[:3, 3]\n    return (pts - t) @ R\n"),
        Valid("def f(pts, T):\n    return pts @ T[:3, :3].T + T[:3, 3]\n"),
        Valid("def f(R, t, p):\n    return R.T @ p + t\n"),  # no evidence R and t are one pose
        Valid("def f(pose, p):\n    return pose.rotation @ (p - pose.translation) + pose.translation\n"),
        Valid("center = -T[:3, :3].T @ T[:3, 3]\n"),
        Valid("def f(T, S, p):\n    return T[:3, :3].T @ p + S[:3, 3]\n"),
        Valid(
            "def f(T, p):\n    R = T[:3, :3]\n    T = other_pose()\n    return R.T @ p + T[:3, 3]\n"
        ),
        Valid(
            "def invert(info):\n"
            "    M = np.eye(4)\n"
            "    M[:3, :3] = info['sensor2lidar_rotation'].T\n"
            "    M[:3, 3] = -info['sensor2lidar_rotation'].T @ info['sensor2lidar_translation']\n"
            "    return M\n"
        ),
        Valid("def g(T, S):\n    M = np.eye(4)\n    M[:3, :3] = T[:3, :3].T\n    M[:3, 3] = -S[:3, 3]\n    return M\n"),
        Valid(
            "def to_sensor(points, T):\n"
            "    points[:, :3] = points[:, :3] @ T[:3, :3].T\n"
            "    points[:, :3] += T[:3, 3]\n"
            "    return points\n"
        ),
        Valid(
            "def build(sweep, R_a, R_b):\n"
            "    sweep['sweep2lidar_rotation'] = R_a.T @ R_b.T  # laid out for points @ R\n"
            "def load(points, sweep):\n"
            "    points[:, :3] = points[:, :3] @ sweep['sweep2lidar_rotation']\n"
            "    points[:, :3] += sweep['sweep2lidar_translation']\n"
            "    return points\n"
        ),
        Valid(
            "def to_sensor(points, T):\n"
            "    points[:, :3] -= T[:3, 3]\n"
            "    points[:, :3] = points[:, :3] @ T[:3, :3]\n"
            "    return points\n"
        ),
        Valid(  # built by a project function, maybe for rows (MATLAB procrustes: Z = b * Y @ T + c)
            "def fit(X, Y):\n    return 0.0, Y, {'rotation': rows_rotation(X, Y), 'translation': offset(X, Y)}\n"
            "def align(pred, true):\n    d, Z, tform = fit(true, pred)\n"
            "    return pred @ tform['rotation'] + tform['translation']\n"
        ),
        Valid(
            "def fit(X, Y):\n    return rows_rotation(X, Y), offset(X, Y)\n"
            "def align(pred, true):\n    rot, trans = fit(true, pred)\n    return pred @ rot + trans\n"
        ),
    ]
    INVALID = [
        Invalid(
            "p_cam = T[:3, :3].T @ p_world + T[:3, 3]\n",
            message="`T[:3, :3].T @ p_world + T[:3, 3]` applies the inverse rotation of a pose with its forward translation (+ t): neither the pose nor its inverse. The inverse is Rᵀ (p - t) (rows: (p - t) @ R); the pose itself is R p + t (rows: p @ R.T + t)",
            range=(1, 9, 1, 41),
        ),
        Invalid("def f(pts, T):\n    R = T[:3, :3]\n    t = T[:3, 3]\n    return pts @ R + t\n"),
        Invalid("def f(pose, p):\n    return pose.rotation @ (p - pose.translation)\n"),
        Invalid("def f(pts, T):\n    R, t = T[:3, :3], T[:3, 3]\n    return (pts - t) @ R.T\n"),
        Invalid(
            "def to_cam(x, poses):\n"
            "    x = x - poses[:, None, :3, 3]\n"
            "    return x @ poses[:, :3, :3].transpose(1, 2)\n"
        ),
        Invalid("def f(gt, p):\n    return gt['cam_R_m2c'].T.dot(p) + gt['cam_t_m2c'].reshape(3, 1)\n"),
        Invalid("def f(T, pts):\n    R, t = split_pose(T)\n    return (R.T @ pts.T).T + t\n"),
        Invalid(  # transposed by hand: the author reads it as a rotation for column vectors
            "def fit(X, Y):\n    return rows_rotation(X, Y), offset(X, Y)\n"
            "def align(pred, true):\n    rot, trans = fit(true, pred)\n    return (rot.T @ pred.T).T + trans\n"
        ),
        Invalid(  # sliced from a 4x4 with the translation in the last column: column layout
            "def fit(X, Y):\n    return make_pose(X, Y)\n"
            "def align(pred, true):\n    T = fit(true, pred)\n    return pred @ T[:3, :3] + T[:3, 3]\n"
        ),
        Invalid(
            "def invert(info):\n"
            "    M = np.eye(4)\n"
            "    M[:3, :3] = info['sensor2lidar_rotation'].T\n"
            "    M[:3, 3] = -info['sensor2lidar_translation']\n"
            "    return M\n"
        ),
        Invalid(
            "def to_lidar(points, sweep):\n"
            "    T = np.array(sweep['lidar2sensor'])\n"
            "    points[:, :3] = points[:, :3] @ T[:3, :3]\n"
            "    points[:, :3] -= T[:3, 3]\n"
            "    return points\n"
        ),
    ]

    def check(self, tree: Module) -> None:
        index = index_of(tree)
        settled: set[AST] = set()  # products already judged as part of a sum
        for node in index.nodes(BinOp):
            if isinstance(node.op, (Add, Sub)):  # type: ignore[attr-defined]
                self._check_sum(node, index, settled)  # type: ignore[arg-type]
        for node in index.nodes(BinOp, Call):
            if node not in settled and matmul_operands(node) is not None:
                applied = application(node, index)  # type: ignore[arg-type]
                if applied is not None and applied.product is node:
                    self._check_forward_of_difference(applied, index)
        for node in index.nodes(Assign, AugAssign):
            if isinstance(node, Assign):
                self._check_block_write(node, index)
            elif isinstance(node, AugAssign) and isinstance(node.op, (Add, Sub)):
                self._check_in_place_row_form(node, index)

    def _check_block_write(self, node: Assign, index: ModuleIndex) -> None:
        """`M[:3, 3] = -t` (or `t`) after `M[:3, :3] = R.T`, with R and t one pose's parts."""
        if len(node.targets) != 1:
            return
        target = node.targets[0]
        if not isinstance(target, Subscript):
            return
        written = pose_part(target, index)
        if written is None or written.kind != "translation":
            return
        value = node.value.operand if isinstance(node.value, UnaryOp) and isinstance(node.value.op, USub) else node.value
        translation = pose_part(value, index)
        if translation is None or translation.kind != "translation" or translation.pose == written.pose:
            return
        rotation_write = self._earlier_rotation_write(node, target, index)
        if rotation_write is None:
            return
        rotation = pose_part(rotation_write.value, index)
        if rotation is None or rotation.kind != "rotation" or rotation.pose != translation.pose or not rotation.transposed:
            return
        self.report(
            node,
            f"`{ast.unparse(target.value)}` gets the inverse rotation of a pose (line {rotation_write.lineno}) "  # type: ignore[attr-defined]
            f"but `{ast.unparse(node.value)}` as its translation: neither the pose nor its inverse. "
            "The inverse's translation is -Rᵀ t",
        )

    def _earlier_rotation_write(self, node: Assign, target: Subscript, index: ModuleIndex) -> Assign | None:
        """The last `M[:3, :3] = ...` before this statement in the same block, for the same M."""
        block = self._block_of(node, index)
        found = None
        for statement in block:
            if statement is node:
                return found
            if isinstance(statement, Assign) and len(statement.targets) == 1:
                other = statement.targets[0]
                if isinstance(other, Subscript) and same_code(other.value, target.value):
                    part = pose_part(other, index)
                    if part is not None and part.kind == "rotation":
                        found = statement
        return None

    def _check_in_place_row_form(self, node: AugAssign, index: ModuleIndex) -> None:
        """`x[:, :3] = x[:, :3] @ R` then `x[:, :3] -= t`: Rᵀ p - t, over two statements."""
        translation = pose_part(node.value, index)
        if translation is None or translation.kind != "translation" or translation.transposed:
            return
        block = self._block_of(node, index)
        position = next((i for i, statement in enumerate(block) if statement is node), 0)
        if position == 0:
            return
        previous = block[position - 1]
        if not (isinstance(previous, Assign) and len(previous.targets) == 1 and same_code(previous.targets[0], node.target)):
            return
        applied = application(previous.value, index)
        if applied is None or not applied.inverse or applied.rotation.pose != translation.pose:
            return
        if not same_code(applied.operand, node.target):
            return  # `x = y @ R; x -= t`: not a point moved in place
        if self._module_stores_key_computed(previous.value, index):
            return  # `info["rot"] = R` with R composed for `points @ R`: the module chose the layout
        if self._layout_unknown(applied, index):
            return
        sign = "+" if isinstance(node.op, Add) else "-"
        self.report(
            node,
            f"`{ast.unparse(node.target)}` was given the inverse rotation of a pose on line {previous.lineno} "
            f"and now its forward translation ({sign}= t): neither the pose nor its inverse. The inverse "
            "is Rᵀ (p - t) (rows: (p - t) @ R)",
        )

    def _layout_unknown(self, applied: Application, index: ModuleIndex) -> bool:
        """A row-form product `x @ R` (R not transposed) whose R is an entry of what a project function
        returned (`tform["rotation"]` of `d, Z, tform = procrustes(X, Y)`, or `T` of `T, c = fit(X, Y)`):
        that function may have built R for right multiplication (MATLAB's `Z = b * Y * T + c`), so
        `x @ R` is not known to apply R's inverse. A 4x4 sliced (`T[:3, :3]`) says its layout."""
        operands = matmul_operands(applied.product)
        if operands is None or transposed_operand(operands[1]) is not None:
            return False
        node = operands[1]
        for _ in range(8):
            inner = peel_same_value(node)
            if inner is not node:
                node = inner
                continue
            if isinstance(node, Name):
                value = resolve(index, node)
                if isinstance(value, Unpacked):
                    return isinstance(value.value, Call) and self._project_callee(value.value, index)
                if value is node:
                    return False
                node = value
                continue
            break
        if not (isinstance(node, Subscript) and isinstance(node.slice, Constant) and isinstance(node.slice.value, str)):
            return False
        container = resolve(index, node.value) if isinstance(node.value, Name) else node.value
        if isinstance(container, Unpacked):
            container = container.value
        return isinstance(container, Call) and self._project_callee(container, index)

    def _project_callee(self, call: Call, index: ModuleIndex) -> bool:
        """Whether the called function may be one of the project's (this module's, or an imported
        module the project's folders hold), not a library's."""
        root = call.func
        while isinstance(root, Attribute):
            root = root.value
        if not isinstance(root, Name):
            return False
        if root is call.func and root.id in index.functions:
            return True
        imported = index.imports.get(root.id)
        return imported is not None and may_be_project_import(imported, self.context.path)

    @staticmethod
    def _module_stores_key_computed(product: ast.expr, index: ModuleIndex) -> bool:
        """Whether the rotation in `product` is read from a string key (`sweep["sweep2lidar_rotation"]`)
        that this module also writes from something other than a plain rotation: the stored layout
        (row-form, for `points @ R`) is then the module's own choice, and the read may be right."""
        keys = set()
        for operand in matmul_operands(product) or ():
            read = transposed_operand(operand) or operand
            if isinstance(read, Subscript) and isinstance(read.slice, Constant) and isinstance(read.slice.value, str):
                keys.add(read.slice.value)
        if not keys:
            return False
        for node in index.nodes(Assign):
            if isinstance(node, Assign) and len(node.targets) == 1:
                target = node.targets[0]
                if isinstance(target, Subscript) and isinstance(target.slice, Constant) and target.slice.value in keys:
                    stored = pose_part(node.value, index)
                    if stored is None or stored.transposed:
                        return True
        return False

    @staticmethod
    def _block_of(node: ast.stmt, index: ModuleIndex) -> list[ast.stmt]:
        """The statement list holding `node` (a function body, a loop or branch body, the module)."""
        parent = index.parents.get(node)
        for field in ("body", "orelse", "finalbody", "handlers"):
            block = getattr(parent, field, None)
            if isinstance(block, list) and any(statement is node for statement in block):
                return block
        return [node]

    def _check_sum(self, node: BinOp, index: ModuleIndex, settled: set[AST]) -> None:
        sides = [(node.left, node.right)]
        if isinstance(node.op, Add):
            sides.append((node.right, node.left))
        for applied_side, other in sides:
            applied = application(applied_side, index)
            if applied is None:
                continue
            translation = pose_part(other, index)
            if translation is None or translation.kind != "translation" or translation.pose != applied.rotation.pose:
                continue
            settled.add(applied.product)
            if not applied.inverse:
                return  # R @ p + t, or R @ (p - t) + t (a rotation about the pose's origin)
            if self._layout_unknown(applied, index):
                return  # `b * Y @ T + c` with T from a project function: maybe built for rows
            removed = difference_with(applied.operand, index)
            if removed is not None and removed[1].pose == translation.pose:
                return  # R.T @ (p - t) + t: an un-rotation about the pose's origin
            operand_part = pose_part(applied.operand, index)
            if operand_part is not None and operand_part.kind == "translation":
                return  # R.T @ t: a camera centre being computed, not a point mapped
            sign = "+" if isinstance(node.op, Add) else "-"
            self.report(
                node,
                f"`{ast.unparse(node)}` applies the inverse rotation of a pose with its forward "
                f"translation ({sign} t): neither the pose nor its inverse. The inverse is Rᵀ (p - t) "
                "(rows: (p - t) @ R); the pose itself is R p + t (rows: p @ R.T + t)",
            )
            return

    def _check_forward_of_difference(self, applied: Application, index: ModuleIndex) -> None:
        if applied.inverse:
            return  # Rᵀ (p - t): the true inverse
        removed = difference_with(applied.operand, index)
        if removed is None or removed[1].pose != applied.rotation.pose:
            return
        if self._adds_translation_back(applied, index):
            return
        self.report(
            applied.product,
            f"`{ast.unparse(applied.product)}` subtracts a pose's translation and then applies its "
            "forward rotation: neither the pose nor its inverse. The inverse is Rᵀ (p - t) "
            "(rows: (p - t) @ R)",
        )

    def _adds_translation_back(self, applied: Application, index: ModuleIndex) -> bool:
        """`x = x - t; x = x @ R.T; x = x + t` (a rotation about the pose's origin, in steps)."""
        scope = scope_of(index, applied.product).node
        start = (applied.product.lineno, applied.product.col_offset)  # type: ignore[attr-defined]
        for node in ast.walk(scope):
            if isinstance(node, BinOp) and isinstance(node.op, Add) and (node.lineno, node.col_offset) >= start:
                for side in (node.left, node.right):
                    part = pose_part(side, index)
                    if part is not None and part.kind == "translation" and part.pose == applied.rotation.pose:
                        return True
            if isinstance(node, AugAssign) and isinstance(node.op, Add) and (node.lineno, node.col_offset) >= start:
                part = pose_part(node.value, index)
                if part is not None and part.kind == "translation" and part.pose == applied.rotation.pose:
                    return True
        return False
