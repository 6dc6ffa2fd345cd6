"""What the pose rules ask of an `ast` expression, answered from the code and the flow of its
function (no names needed):

- `pose_part`: whether an expression is the rotation or the translation of a pose, and of which
  one (`T[:3, :3]` / `T[:3, 3]`, `poses[:, :3, :3]`, `pose.rotation` / `pose.translation`,
  `gt["cam_R_m2c"]` / `gt["cam_t_m2c"]`, `R, t = split_pose(T)`), seen through copies, dtype
  and device moves, broadcasting reshapes and transposes (counted);
- `application`: `R @ x`, `x @ R.T`, `np.dot(R, x)`, `torch.bmm(R, x)`: which rotation is applied
  to what, and whether the rotation or its inverse is what acts on the vector;
- `difference_with`, `translation_source`: `x - t`, and what a value made of a translation is;
- `matrix_shape` / `square_shape`: whether an array is known to be a 3x3 rotation or a 4x4 pose
  (or a stack of them) from what made it;
- the expression shapes beneath them: `matrix_indices` (`[batch..., row, column]`),
  `transposed_operand` / `transpose_of`, `matmul_operands`, `peel_same_value`, `int_value`, `call_name`.

A local name holds what the one definition reaching it gave it (`geolint.factbase.reaching`:
the fact base's flow analysis, on the module's index); when several can reach it, nothing is known.
"""

from __future__ import annotations

from typing import Final

import ast
from ast import (
    AST, Attribute, BinOp, Call, Constant, Div, IfExp, MatMult, Mult, Name, Slice, Starred, Sub, Subscript, UAdd,
    USub, UnaryOp,
)
from dataclasses import dataclass

from geolint.algebra import Kind
from geolint.factbase.index import ModuleIndex
from geolint.knowledge import knowledge_base
from geolint.knowledge.markers import ArrayOperation
from geolint.factbase.syntax import dotted_name, einsum_operands, is_full_slice, is_slice_upto, last_name, subscript_parts
from geolint.factbase.reaching import Unpacked, assigned_values, binding_of, resolve

# Methods and functions that return the same values (copies, dtype/device moves, broadcasting views).
_SAME_VALUE_METHODS: Final = frozenset(
    {"copy", "clone", "detach", "float", "double", "half", "to", "cpu", "cuda", "numpy", "astype",
     "contiguous", "type", "type_as", "reshape", "view", "unsqueeze", "squeeze", "flatten", "ravel",
     "expand", "expand_as", "view_as", "reshape_as"}
)  # fmt: skip
_SAME_VALUE_FUNCTIONS: Final = frozenset(
    {"asarray", "array", "as_tensor", "tensor", "from_numpy", "copy", "deepcopy", "expand_dims", "squeeze",
     "reshape", "float32", "float64", "ascontiguousarray", "atleast_2d", "Tensor", "FloatTensor"}
)  # fmt: skip


def same_code(first: AST, second: AST) -> bool:
    return ast.unparse(first) == ast.unparse(second)


def int_value(node: AST | None) -> int | None:
    """A literal integer, negatives included."""
    if isinstance(node, Constant) and type(node.value) is int:
        return node.value
    if isinstance(node, UnaryOp) and isinstance(node.op, USub):
        inner = int_value(node.operand)
        return None if inner is None else -inner
    return None


def call_name(node: AST) -> str | None:
    """The last name of a call's function (`np.linalg.inv(x)` -> "inv")."""
    return last_name(node.func) if isinstance(node, Call) else None


def is_batch_index(node: ast.expr) -> bool:
    """`:`, `...` or a new axis (`None`) ahead of the matrix indices of a stack of matrices."""
    return is_full_slice(node) or (isinstance(node, Constant) and (node.value is Ellipsis or node.value is None))


def is_stack_index(node: ast.expr) -> bool:
    """An index that picks among stacked matrices: `:`, `...`, `None`, `head:tail`, `i`, `0`."""
    if isinstance(node, Slice):
        return node.step is None
    if isinstance(node, Constant):
        return node.value is Ellipsis or node.value is None or type(node.value) is int
    return isinstance(node, (Name, Attribute))


def matrix_indices(node: Subscript) -> tuple[list[ast.expr], ast.expr, ast.expr] | None:
    """(batch indices, row index, column index) of a subscript with at least two indices."""
    indices = subscript_parts(node)
    if len(indices) < 2 or not all(is_stack_index(index) for index in indices[:-2]):
        return None
    return indices[:-2], indices[-2], indices[-1]


def stack_key(batch: list[ast.expr]) -> str:
    """Which matrices of a stack the batch indices pick, as text: new axes dropped, `...` read as `:`."""
    picked = []
    for index in batch:
        if isinstance(index, Constant) and index.value is None:
            continue
        picked.append(":" if is_batch_index(index) else ast.unparse(index))
    return ", ".join(picked)


# ---------------------------------------------------------------------------------------------
# Rotation and translation of one pose


@dataclass(frozen=True)
class PosePart:
    """`kind` ("rotation" or "translation") of the pose identified by `pose`; `transposed` counts inversions."""

    kind: str
    pose: str
    transposed: bool = False
    batched: bool = False

    def flipped(self) -> PosePart:
        return PosePart(self.kind, self.pose, not self.transposed, self.batched)


_ROTATION_WORDS: Final = frozenset({"r", "rot", "rotation", "rotmat", "rmat", "rotation_matrix"})
_TRANSLATION_WORDS: Final = frozenset({"t", "trans", "translation", "tvec", "transl"})
_ROTATION_ATTRIBUTES: Final = frozenset({"rotation", "R", "rot", "rotation_matrix", "rotmat"})
_TRANSLATION_ATTRIBUTES: Final = frozenset({"translation", "t", "trans", "tvec"})


def pose_part(node: ast.expr, index: ModuleIndex, depth: int = 12) -> PosePart | None:
    """Which pose's rotation or translation `node` is, if the code says so; None otherwise."""
    if depth <= 0:
        return None
    inner = peel_same_value(node)
    if inner is not node:
        return pose_part(inner, index, depth - 1)
    transposed = transposed_operand(node)
    if transposed is not None:
        part = pose_part(transposed, index, depth - 1)
        return part.flipped() if part is not None and part.kind == "rotation" else None
    if isinstance(node, Name):
        value = resolve(index, node)
        if isinstance(value, Unpacked):
            return _unpacked_part(value)
        return None if value is node else pose_part(value, index, depth - 1)
    if isinstance(node, Subscript):
        return _sliced_part(node, index) or _keyed_part(node, index)
    if isinstance(node, Attribute):
        if node.attr == "rotation_matrix" and _quaternion_of(node.value) is not None:
            return _quaternion_part(node.value, index, depth)
        return _named_part(node.attr, node.value, index)
    if isinstance(node, Call):
        name = call_name(node)
        if isinstance(node.func, Attribute) and not node.args and not node.keywords:
            if name == "as_matrix" or name == "as_dcm":
                return _from_rotation_object(node.func.value, index, depth)
            if name in ("rotation", "translation", "rotationMatrix", "matrix"):
                return _named_part("rotation" if name != "translation" else "translation", node.func.value, index)
        if name in ("quat2mat", "quaternion_to_matrix", "quaternion_to_rotation_matrix") and len(node.args) == 1:
            source = pose_part(node.args[0], index, depth - 1)
            return source if source is not None and source.kind == "rotation" else None
    return None


def _from_rotation_object(node: ast.expr, index: ModuleIndex, depth: int) -> PosePart | None:
    """`Rotation.from_quat(pose.rotation).as_matrix()`: the pose's rotation as a matrix."""
    if isinstance(node, Name):
        resolved = resolve(index, node)
        if isinstance(resolved, Unpacked) or resolved is node:
            return None
        node = resolved
    if isinstance(node, Call) and isinstance(node.func, Attribute):
        if node.func.attr == "inv" and not node.args:
            part = _from_rotation_object(node.func.value, index, depth - 1)
            return part.flipped() if part is not None else None
        if node.func.attr.startswith("from_") and len(node.args) == 1 and not node.keywords:
            part = pose_part(node.args[0], index, depth - 1)
            return part if part is not None and part.kind == "rotation" else None
    return None


def _quaternion_of(node: ast.expr) -> ast.expr | None:
    """`Quaternion(x)` (pyquaternion), possibly `.inverse`: the argument."""
    if isinstance(node, Attribute) and node.attr in ("inverse", "conjugate"):
        return _quaternion_of(node.value)
    if isinstance(node, Call) and call_name(node) == "Quaternion" and len(node.args) == 1 and not node.keywords:
        return node.args[0]
    return None


def _quaternion_part(node: ast.expr, index: ModuleIndex, depth: int) -> PosePart | None:
    inverted = False
    while isinstance(node, Attribute):
        inverted = not inverted
        node = node.value
    source = pose_part(node.args[0], index, depth - 1)  # type: ignore[attr-defined]
    if source is None or source.kind != "rotation":
        return None
    return source.flipped() if inverted else source


def _sliced_part(node: Subscript, index: ModuleIndex) -> PosePart | None:
    """`T[:3, :3]` / `T[:3, 3]` (`3:`, `-1`, `3:4`), and with batch indices `poses[:, :3, :3]`."""
    indices = matrix_indices(node)
    if indices is None:
        return None
    batch, row, column = indices
    if not is_slice_upto(row, 3):
        return None
    if is_slice_upto(column, 3):
        kind = "rotation"
    elif int_value(column) in (3, -1) or is_column_slice_from(column, 3):
        kind = "translation"
    else:
        return None
    key = pose_key(node.value, index)
    return PosePart(kind, f"{key}[{stack_key(batch)}]" if batch else key, batched=bool(batch))


def is_column_slice_from(node: ast.expr, start: int) -> bool:
    """`3:` or `3:4`: the one column `start` as a slice."""
    if not isinstance(node, Slice) or node.step is not None or int_value(node.lower) != start:
        return False
    return node.upper is None or int_value(node.upper) == start + 1


def _keyed_part(node: Subscript, index: ModuleIndex) -> PosePart | None:
    """`pose["rotation"]` / `pose["translation"]`, `gt["cam_R_m2c"]` / `gt["cam_t_m2c"]`."""
    key = node.slice
    if not (isinstance(key, Constant) and isinstance(key.value, str)):
        return None
    return _named_part(key.value, node.value, index)


def _named_part(word: str, base: ast.expr, index: ModuleIndex) -> PosePart | None:
    """Split a name such as `cam_R_w2c` into its part word (R) and the rest (cam_w2c), which names the pose."""
    if word in _ROTATION_ATTRIBUTES:
        return PosePart("rotation", pose_key(base, index))
    if word in _TRANSLATION_ATTRIBUTES:
        return PosePart("translation", pose_key(base, index))
    tokens = word.split("_")
    for position, token in enumerate(tokens):
        lowered = token if token in ("R", "t", "T") else token.lower()
        kind = (
            "rotation" if lowered in ("R", "rot", "rotation")
            else "translation" if lowered in ("t", "trans", "translation")
            else None
        )  # fmt: skip
        if kind is not None and len(tokens) > 1:
            rest = "_".join(tokens[:position] + ["*"] + tokens[position + 1 :])
            return PosePart(kind, f"{pose_key(base, index)}.{rest}")
    return None


def _unpacked_part(value: Unpacked) -> PosePart | None:
    """`R, t = split(T)`: the names say which element is which; both must be named."""
    kinds = [_kind_of_local_name(name) for name in value.names]
    if "rotation" not in kinds or "translation" not in kinds:
        return None
    kind = kinds[value.index]
    if kind is None:
        return None
    return PosePart(kind, f"<unpacked at {id(value.statement)}>")


def _kind_of_local_name(name: str) -> str | None:
    lowered = name.lower()
    words = lowered.split("_")
    if name in ("R", "Rot") or lowered in _ROTATION_WORDS or words[0] in ("r", "rot", "rotation") or words[-1] in ("r", "rot", "rotation"):
        return "rotation"
    if name == "t" or lowered in _TRANSLATION_WORDS or words[0] in ("t", "trans", "translation") or words[-1] in ("t", "trans", "translation", "tvec"):
        return "translation"
    return None


def pose_key(base: ast.expr, index: ModuleIndex) -> str:
    """Text of the pose expression, plus which assignment its root name reads (a rebound T is another pose)."""
    root = base
    while isinstance(root, (Attribute, Subscript)):
        root = root.value
    if isinstance(root, Name):
        binding = binding_of(index, root)
        if binding is not None:
            return f"{ast.unparse(base)}@{binding}"
    return ast.unparse(base)


_AGGREGATES: Final = frozenset({"mean", "median", "average", "nanmean"})


def translation_source(node: ast.expr, index: ModuleIndex, depth: int = 8) -> PosePart | None:
    """The pose translation a value is made of: the translation itself, its mean over a stack
    (`poses[:, :3, 3].mean(0)`, `torch.mean(t, dim=0)`), its negation or a scaling of it. A local
    name counts when every value it is ever given in its function is such a value or zeros."""
    if depth <= 0:
        return None
    part = pose_part(node, index)
    if part is not None:
        return part if part.kind == "translation" else None
    inner = peel_same_value(node)
    if inner is not node:
        return translation_source(inner, index, depth - 1)
    if isinstance(node, UnaryOp) and isinstance(node.op, USub):
        return translation_source(node.operand, index, depth - 1)
    if isinstance(node, BinOp) and isinstance(node.op, (Mult, Div)):
        for side, other in ((node.left, node.right), (node.right, node.left)):
            if isinstance(other, (Constant, Name, Attribute)) and (side is node.left or isinstance(node.op, Mult)):
                found = translation_source(side, index, depth - 1)
                if found is not None and pose_part(other, index) is None:
                    return found
        return None
    if isinstance(node, Call) and call_name(node) in _AGGREGATES:
        func = node.func
        if isinstance(func, Attribute) and knowledge_base().is_array_namespace(dotted_name(func.value) or ""):
            return translation_source(node.args[0], index, depth - 1) if node.args else None
        return translation_source(func.value, index, depth - 1) if isinstance(func, Attribute) else None
    if isinstance(node, IfExp):
        return _every_source([node.body, node.orelse], index, depth)
    if isinstance(node, Name):
        return _every_source(assigned_values(index, node), index, depth)
    return None


def _every_source(candidates: list[ast.expr | Unpacked | None], index: ModuleIndex, depth: int) -> PosePart | None:
    """The translation all candidate values come from, zeros aside; None if one comes from elsewhere."""
    found = None
    for value in candidates:
        if isinstance(value, Call) and call_name(value) in ("zeros_like", "zeros"):
            continue
        source = translation_source(value, index, depth - 1) if isinstance(value, ast.expr) else None
        if source is None:
            return None
        found = found or source
    return found


def peel_same_value(node: ast.expr) -> ast.expr:
    """`t.copy()`, `t.to(device)`, `t[:, None]`, `t.reshape(3, 1)`, `np.asarray(t)`: the same values."""
    if isinstance(node, Call):
        func = node.func
        if isinstance(func, Attribute) and func.attr in _SAME_VALUE_METHODS:
            return func.value
        if call_name(node) in _SAME_VALUE_FUNCTIONS and node.args and not isinstance(node.args[0], Starred):
            return node.args[0]
    if isinstance(node, Subscript) and _is_broadcast_index(node):
        return node.value
    if isinstance(node, UnaryOp) and isinstance(node.op, UAdd):
        return node.operand
    return node


def _is_new_axis(node: AST) -> bool:
    """`np.newaxis`: an array namespace's name for None."""
    module, _, name = (dotted_name(node) or "").rpartition(".")
    return name == "newaxis" and knowledge_base().is_array_namespace(module)


def _is_broadcast_index(node: Subscript) -> bool:
    """`x[:, None]`, `x[None]`, `x[..., np.newaxis]`: only new axes and full slices."""
    indices = subscript_parts(node)
    has_new_axis = False
    for index in indices:
        if (isinstance(index, Constant) and index.value is None) or _is_new_axis(index):
            has_new_axis = True
        elif not is_batch_index(index):
            return False
    return has_new_axis


def transposed_operand(node: ast.expr) -> ast.expr | None:
    """The matrix a transpose (or inverse) is taken of: `R.T`, `R.mT`, `R.t()`, `R.transpose(1, 2)`,
    `R.permute(0, 2, 1)`, `np.transpose(R)`, `torch.transpose(R, -1, -2)`, `np.linalg.inv(R)`."""
    transposed = transpose_of(node)
    if transposed is not None:
        return transposed
    if not isinstance(node, Call) or node.keywords:
        return None
    func = node.func
    if isinstance(func, Attribute) and call_name(node) == "inverse" and not node.args:
        return func.value
    if _array_operation(func) == ArrayOperation.INVERSE and len(node.args) == 1:
        return node.args[0]
    return None


def transpose_of(node: ast.expr) -> ast.expr | None:
    """The matrix whose last two axes `node` swaps: `R.T`, `R.mT`, `R.t()`, `R.transpose()`,
    `R.transpose(-1, -2)`, `R.swapaxes(-2, -1)`, `R.permute(0, 2, 1)`, and the functions the stubs
    mark as transposes (`np.transpose(R)`, `torch.transpose(R, -1, -2)`, `tf.linalg.matrix_transpose(R)`).
    Any other permutation (`image.transpose(2, 0, 1)`, `x.permute(2, 0, 1)`) is None."""
    if isinstance(node, Attribute) and node.attr in ("T", "mT"):
        return node.value
    if not isinstance(node, Call) or node.keywords:
        return None
    func = node.func
    name = call_name(node)
    if isinstance(func, Attribute) and name in ("t", "transpose", "permute", "swapaxes"):
        axes = [int_value(argument) for argument in node.args]
        if name in ("t", "transpose") and not axes:
            return func.value
        if name in ("transpose", "swapaxes") and len(axes) == 2 and _swaps_last_two(axes):
            return func.value
        if name == "permute" and len(axes) >= 2 and _permutes_last_two(axes):
            return func.value
    if _array_operation(func) == ArrayOperation.TRANSPOSE and node.args and not isinstance(node.args[0], Starred):
        # np.transpose(R) / torch.transpose(R, 1, 2) called through an array namespace
        rest = [int_value(argument) for argument in node.args[1:]]
        if not rest or _swaps_last_two(rest):
            return node.args[0]
    return None


def _array_operation(func: ast.expr) -> str | None:
    """What an array namespace's function called by its module's name (`np.linalg.inv`, `torch.bmm`) does
    to matrices, by the stubs; None for a method of a value or anything else."""
    dotted = dotted_name(func) if isinstance(func, Attribute) else None
    return knowledge_base().array_operation(dotted) if dotted is not None else None


def _swaps_last_two(axes: list[int | None]) -> bool:
    return sorted(axes) in ([-2, -1], [1, 2], [0, 1]) if None not in axes else False  # type: ignore[type-var, operator]


def _permutes_last_two(axes: list[int | None]) -> bool:
    if None in axes:
        return False
    count = len(axes)
    return axes == [*range(count - 2), count - 1, count - 2]


# ---------------------------------------------------------------------------------------------
# Applying a rotation


@dataclass(frozen=True)
class Application:
    """`rotation` acting on `operand`; `inverse` when the inverse (transpose) is what acts."""

    node: ast.expr
    product: ast.expr
    rotation: PosePart
    operand: ast.expr
    inverse: bool


_MATMUL_FUNCTIONS: Final = frozenset({"dot", "matmul", "bmm", "mm"})


def matmul_operands(node: AST) -> tuple[ast.expr, ast.expr] | None:
    """(left, right) of `a @ b`, `np.dot(a, b)`, `a.dot(b)`, `torch.matmul(a, b)`, `torch.bmm(a, b)`."""
    if isinstance(node, BinOp) and isinstance(node.op, MatMult):
        return node.left, node.right
    if not isinstance(node, Call) or node.keywords:
        return None
    name = call_name(node)
    if name not in _MATMUL_FUNCTIONS and name != "einsum":
        return None
    func = node.func
    if not isinstance(func, Attribute):
        return None
    operation = _array_operation(func)
    if operation == ArrayOperation.EINSUM:
        return einsum_operands(*node.args) if len(node.args) == 3 else None
    if operation == ArrayOperation.MATMUL:
        return (node.args[0], node.args[1]) if len(node.args) == 2 and not _has_starred(node.args) else None
    if name == "einsum":
        return None
    if len(node.args) == 1 and not _has_starred(node.args):
        return func.value, node.args[0]
    return None


def _has_starred(arguments: list[ast.expr]) -> bool:
    return any(isinstance(argument, Starred) for argument in arguments)


def application(node: ast.expr, index: ModuleIndex) -> Application | None:
    """A pose's rotation applied to something: column form `R @ x` or row form `x @ R.T`.

    A transpose of the whole product (`(R @ x.T).T`) applies the same rotation.
    """
    outer = node
    for _ in range(8):
        if isinstance(node, Name):
            value = resolve(index, node)
            if isinstance(value, Unpacked) or value is node:
                return None
            node = value
            continue
        inner = peel_same_value(node)
        transposed = transposed_operand(inner) if inner is node else None
        if inner is not node:
            node = inner
        elif transposed is not None and matmul_operands(transposed):
            node = transposed
        else:
            break
    operands = matmul_operands(node)
    if operands is None:
        return None
    left, right = operands
    rotation = pose_part(left, index)
    if rotation is not None and rotation.kind == "rotation":
        return Application(outer, node, rotation, right, rotation.transposed)
    rotation = pose_part(right, index)
    if rotation is not None and rotation.kind == "rotation":
        # x @ R applies R's transpose to each row x.
        return Application(outer, node, rotation, left, not rotation.transposed)
    return None


def difference_with(node: ast.expr, index: ModuleIndex, depth: int = 6) -> tuple[ast.expr, PosePart] | None:
    """`x - t` (seen through names, copies, reshapes, transposes): x and the translation part t."""
    for _ in range(depth):
        peeled = peel_same_value(node)
        transposed = transposed_operand(peeled)
        if peeled is not node:
            node = peeled
        elif transposed is not None:
            node = transposed
        elif isinstance(node, Name):
            value = resolve(index, node)
            if isinstance(value, Unpacked) or value is node:
                return None
            node = value
        else:
            break
    if isinstance(node, BinOp) and isinstance(node.op, Sub):
        part = pose_part(node.right, index)
        if part is not None and part.kind == "translation":
            return node.left, part
    return None


# ---------------------------------------------------------------------------------------------
# Matrix shapes


ROTATION_MAKERS: Final = frozenset(
    {"quat2mat", "euler2mat", "axangle2mat", "quaternion_to_matrix", "euler_angles_to_matrix",
     "axis_angle_to_matrix", "matrix_from_quaternion", "matrix_from_euler", "active_matrix_from_angle",
     "matrix_from_axis_angle"}
)  # fmt: skip
_POSE_MAKERS: Final = frozenset(
    {"quaternion_matrix", "euler_matrix", "translation_matrix", "rotation_matrix", "compose_matrix",
     "transform_from", "transform_from_pq", "homogeneous_matrix", "make_transform", "pose_to_matrix"}
)  # fmt: skip
_SIZE_MAKERS: Final = frozenset({"eye", "identity"})
_FILLED_MAKERS: Final = frozenset({"zeros", "ones", "empty", "full"})


def matrix_shape(node: ast.expr, index: ModuleIndex) -> int | None:
    """3 for an array certainly made as a single 3x3 matrix, 4 for a single 4x4; else None.

    Only makers that fix the shape count: `np.eye(3)`, a literal 3x3, `T[:3, :3]`,
    transforms3d `quat2mat`, `cv2.Rodrigues(r)[0]`, pyquaternion `.rotation_matrix`,
    `.reshape(3, 3)` (3); `np.eye(4)`, `np.zeros((4, 4))`, tf `quaternion_matrix`, pyquaternion
    `.transformation_matrix` (4). A copy or transpose keeps the shape.
    """
    shape = square_shape(node, index)
    return shape[0] if shape is not None and not shape[1] else None


def square_shape(node: ast.expr, index: ModuleIndex, depth: int = 8) -> tuple[int, bool] | None:
    """(3 or 4, stacked): the size of the last two axes of an array of square matrices, and whether
    there are batch axes ahead of them (`np.zeros((n, 4, 4))`, `torch.eye(4).repeat(n, 1, 1)`)."""
    if depth <= 0:
        return None
    reshaped = _square_of_reshape(node, index, depth)
    if reshaped != _UNDECIDED:
        return reshaped
    same = _square_of_same_value(node, index, depth)
    if same != _UNDECIDED:
        return same
    if isinstance(node, (ast.List, ast.Tuple)):
        size = _literal_square(node)
        return (size, False) if size is not None else None
    if isinstance(node, Subscript):
        return _square_of_block(node)
    if isinstance(node, Attribute):
        if _quaternion_of(node.value) is not None and node.attr in ("rotation_matrix", "transformation_matrix"):
            return (3 if node.attr == "rotation_matrix" else 4, False)
        return None
    if isinstance(node, Call):
        return _square_of_maker(node)
    return None


# What the steps of `square_shape` answer when they do not decide, and the next step asks (no shape has size 0;
# compared by value: the compiled build may box a tuple anew).
_UNDECIDED: Final = (0, False)


def _square_of_reshape(node: ast.expr, index: ModuleIndex, depth: int) -> tuple[int, bool] | None:
    """`.reshape(n, 4, 4)`, `.view(3, 3)`; `np.tile(R, ...)`, `.repeat(...)`, `.expand(...)`, `.unsqueeze(0)`,
    `R[None]`: the shape they give (batched when they add axes); `_UNDECIDED` for anything else."""
    if isinstance(node, Call) and isinstance(node.func, Attribute):
        method = node.func.attr
        if method in ("reshape", "view") and node.args:
            sizes = [int_value(argument) for argument in node.args]
            if len(sizes) == 1 and isinstance(node.args[0], (ast.Tuple, ast.List)):
                sizes = [int_value(element) for element in node.args[0].elts]
            return _square_of_sizes(sizes)
        if method in ("tile", "repeat", "broadcast_to") and node.args and knowledge_base().is_array_namespace(dotted_name(node.func.value) or ""):
            return _batched(square_shape(node.args[0], index, depth - 1))
        if method in ("repeat", "expand") or (method == "unsqueeze" and int_value(node.args[0] if node.args else None) == 0):
            return _batched(square_shape(node.func.value, index, depth - 1))
    if isinstance(node, Subscript) and _is_broadcast_index(node) and int_value(subscript_parts(node)[0]) is None:
        return _batched(square_shape(node.value, index, depth - 1))
    return _UNDECIDED


def _batched(inner: tuple[int, bool] | None) -> tuple[int, bool] | None:
    return (inner[0], True) if inner is not None else None


def _square_of_same_value(node: ast.expr, index: ModuleIndex, depth: int) -> tuple[int, bool] | None:
    """The shape of what `node` is the same array as: a copy, a transpose, the value a name is bound
    to; `_UNDECIDED` when it is none of these."""
    peeled = peel_same_value(node)
    if peeled is not node and not _reshapes(node):
        return square_shape(peeled, index, depth - 1)
    transposed = transposed_operand(node)
    if transposed is not None:
        return square_shape(transposed, index, depth - 1)
    if isinstance(node, Name):
        value = resolve(index, node)
        if isinstance(value, Unpacked) or value is node:
            return None
        return square_shape(value, index, depth - 1)
    return _UNDECIDED


def _square_of_block(node: Subscript) -> tuple[int, bool] | None:
    """`T[:3, :3]` (3, batched when indexed past a batch axis), `cv2.Rodrigues(r)[0]` (3)."""
    indices = matrix_indices(node)
    if indices is not None and is_slice_upto(indices[1], 3) and is_slice_upto(indices[2], 3):
        return (3, bool(indices[0]))
    if call_name(node.value) == "Rodrigues" and int_value(node.slice) == 0:
        return (3, False)
    return None


def _square_of_maker(node: Call) -> tuple[int, bool] | None:
    """`np.eye(4)`, `np.zeros((n, 3, 3))`, `torch.zeros(4, 4)`, `quat2mat(q)`, tf's `quaternion_matrix(q)`."""
    name = call_name(node)
    if name in (_SIZE_MAKERS | _FILLED_MAKERS) and not _array_module_call(node):
        return None  # sympy's `eye(3)` / `zeros(3, 3)` make matrices with flat indexing (`s[3]`)
    if name in _SIZE_MAKERS and len(node.args) == 1:
        size = int_value(node.args[0])
        return (size, False) if size in (3, 4) else None
    if name in _FILLED_MAKERS and node.args:
        shape = node.args[0]
        if isinstance(shape, (ast.Tuple, ast.List)):
            return _square_of_sizes([int_value(element) for element in shape.elts])
        if not _takes_separate_sizes(node):
            return None  # numpy's one shape argument: a bare size is a vector's
        return _square_of_sizes([int_value(argument) for argument in node.args])
    if name in ROTATION_MAKERS:
        return (3, False) if not _stacks(node) else None
    if name in _POSE_MAKERS and _is_tf_style_maker(node):
        return (4, False)
    return None


def _array_module_call(node: Call) -> bool:
    """`np.eye(3)`, `torch.zeros(4, 4)`, `numpy.identity(4)`: a maker called through an array namespace's
    module (as written, or as conventionally imported), by the stubs."""
    return isinstance(node.func, Attribute) and knowledge_base().is_array_namespace(dotted_name(node.func) or "")


def _takes_separate_sizes(node: Call) -> bool:
    """`torch.zeros(4, 4)`: a maker whose stub takes the shape as separate sizes (`*size: int`)."""
    api = knowledge_base().api_as_written(dotted_name(node.func) or "")
    return api is not None and any(signature.parameters and signature.parameters[0].variadic for signature in api.signatures)


def _square_of_sizes(sizes: list[int | None]) -> tuple[int, bool] | None:
    """(4, True) for sizes (n, 4, 4); (3, False) for (3, 3)."""
    if len(sizes) < 2 or sizes[-1] != sizes[-2] or sizes[-1] not in (3, 4):
        return None
    return (sizes[-1], len(sizes) > 2)  # type: ignore[return-value]


def _reshapes(node: ast.expr) -> bool:
    return isinstance(node, Call) and call_name(node) in ("reshape", "view", "unsqueeze", "squeeze", "flatten", "ravel", "expand", "expand_dims")


def _stacks(node: Call) -> bool:
    """A torch maker (pytorch3d `quaternion_to_matrix`) keeps the batch shape of its input: not known 2-D."""
    return call_name(node) in ("quaternion_to_matrix", "euler_angles_to_matrix", "axis_angle_to_matrix")


def _is_tf_style_maker(node: Call) -> bool:
    """tf.transformations / transforms3d style 4x4 makers, not a method of some object: `rotation_matrix`
    only as a module function whose stub returns a 4x4 transform."""
    if call_name(node) != "rotation_matrix":
        return True
    api = knowledge_base().api_as_written(dotted_name(node.func) or "")
    returned = {signature.returns.kind for signature in api.signatures if signature.returns is not None} if api is not None else set()
    return returned == {Kind.TRANSFORM}


def _literal_square(node: ast.expr) -> int | None:
    if not isinstance(node, (ast.List, ast.Tuple)) or len(node.elts) not in (3, 4):
        return None
    size = len(node.elts)
    if all(isinstance(row, (ast.List, ast.Tuple)) and len(row.elts) == size for row in node.elts):
        return size
    return None
