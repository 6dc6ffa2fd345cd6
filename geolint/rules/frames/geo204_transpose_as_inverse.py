"""GEO204 transpose-as-inverse: the transpose of a 4x4 homogeneous transform used as its inverse."""

from __future__ import annotations

from typing import Final

import re

import ast
from ast import AST, Attribute, BinOp, Call, MatMult, Subscript

from geolint.rules.base import Invalid, Valid
from geolint.factbase.model import FactBase, last_name, number
from geolint.factbase.syntax import dotted_name
from geolint.rules.fact_rule import FactRule


# Methods and functions that turn a matrix into a flat buffer: the transpose only picks the
# column-major memory layout, it is never applied as an operator.
_FLATTENING: Final = frozenset({"flatten", "ravel", "tolist", "tobytes", "tofile", "flat"})
# A contiguous copy of the transpose (`T.T.copy()`, `np.ascontiguousarray(T.T)`) is the column-major
# buffer an OpenGL uniform takes: nobody copies a transpose to use it as an inverse.
_LAYOUT_COPIES: Final = frozenset({"copy", "ascontiguousarray"})
_OPENGL_CALL: Final = re.compile(r"gl[A-Z]\w*$")


class TransposeAsInverse(FactRule):
    """The transpose of a 4x4 homogeneous transform is used where its inverse is meant.

    ## What it does
    Flags the transpose of T where T is named as a full rigid transform (`T_world_cam`, `world_T_cam`,
    Drake `X_WB`, `H_a_b`) and the transpose is used as an operator or stored: `T_world_cam.T @
    p_world`, `T_cam_world = T_world_cam.T`. A transpose is any swap of the last two axes: `T.T`,
    `T.mT`, `T.transpose()`, `T.transpose(-2, -1)`, `T.swapaxes(-1, -2)`, torch's `T.t()` and
    `T.permute(1, 0)`, and the functions the stubs mark as transposes (`np.transpose(T)`,
    `torch.transpose(T, -1, -2)`, `tf.linalg.matrix_transpose(T)`); any other permutation
    (`T.permute(2, 0, 1)`, `np.transpose(T, (2, 0, 1))`) is not one. The row-vector form `points_h @ T_world_cam.T`
    is correct and never flagged, nor is `T.T[:3, :3]` (a rotation's transpose is its inverse),
    nor a transpose that only changes memory layout: flattened for column-major consumers
    (`T.T.flatten()`, `.ravel()`, `.tolist()`, `.tobytes()`, `np.ravel(T.T)`), copied into a contiguous
    buffer (`T.T.copy()`, `np.ascontiguousarray(T.T)`) or passed to an
    OpenGL call (`glUniformMatrix4fv(loc, 1, GL_FALSE, T.T)`, `glLoadMatrixf(T.T)`).

    ## Why is this bad?
    Only a rotation's transpose is its inverse. Transposing a homogeneous transform moves the
    translation into the bottom row: the result is not a rigid transform at all, and applying it
    to `[x, y, z, 1]` produces a w != 1 and a point that never saw the inverse translation.

    ## Example
    ```python
    p_cam = (T_world_cam.T @ p_world_h)[:3]
    ```

    ## Use instead
    ```python
    p_cam = (np.linalg.inv(T_world_cam) @ p_world_h)[:3]
    ```

    ## Fix safety
    The fix `np.linalg.inv(T)` (`torch.linalg.inv(T)` for `torch.transpose(T, -1, -2)`: the inverse of
    the namespace the transpose function was called through) is unsafe: it needs that module imported
    under that name, and the code may rely on the (wrong) transpose elsewhere.

    ## Known problems
    That the matrix is a 4x4 homogeneous transform is read from its name (`T_world_cam`, Drake's
    `X_WB`). Drake's monogram names count only in projects that import pydrake: in control code
    `X_EQ`, `X_GOAL` are state vectors and `.T` is a plain transpose. A `T_`-named 3x4 or a matrix
    only named like a pose can still be misread. A method transpose is read by its spelling, not its
    receiver's type: `T.transpose(0, 1)` of a stack of poses named like one pose would be misread.
    `np.transpose(T, (1, 0))` with the axes as a tuple, and a transpose through keywords
    (`tf.transpose(T, perm=[1, 0])`), are not read.
    """

    code = "GEO204"
    name = "transpose-as-inverse"

    VALID = [
        Valid("R_cam_world = R_world_cam.T\n"),
        Valid("pts_world = pts_cam_h @ T_world_cam.T\n"),
        Valid("R_cam_world = T_world_cam.T[:3, :3]\n"),
        Valid("import numpy as np\nT_cam_world = np.linalg.inv(T_world_cam)\n"),
        Valid("p = cam2world.T @ p_world\n"),  # 3x3 or 4x4? the name does not say
        Valid("import numpy as np\nout = np.dot(points_h, T_world_cam.T)\n"),
        Valid("gl_model = T_world_obj.T.flatten().astype(np.float32)\n"),  # column-major export
        Valid("import numpy as np\nbuf = np.ravel(T_world_cam.T)\n"),
        Valid("glUniformMatrix4fv(loc, 1, GL_FALSE, T_world_obj.T)\n"),
        Valid("import numpy as np\nubo = np.hstack((T_view_world.T.reshape(-1), T_proj_view.T.reshape(16)))\n"),
        Valid("def gl_matrix(self):\n    return self.T_CW.T.copy()\n"),  # a contiguous column-major copy for a shader
        Valid("import numpy as np\nmodel = np.ascontiguousarray(np.linalg.inv(T_CW).T)\n"),
        Valid("x_var = x_var - X_EQ.T\n"),
        Valid("import numpy as np\npts_world = pts_cam_h @ np.transpose(T_world_cam)\n"),
        Valid("import numpy as np\nR_cam_world = np.transpose(T_world_cam)[:3, :3]\n"),
        Valid("chw = T_world_cam.permute(2, 0, 1)\n"),  # not a swap of the last two axes
        Valid("import torch\npts_world = torch.matmul(pts_cam_h, T_world_cam.transpose(-2, -1))\n"),  # outside Drake code `X_EQ` is a state vector (control's X), not a pose
    ]
    INVALID = [
        Invalid(
            "T_cam_world = T_world_cam.T\n",
            expected_fix="T_cam_world = np.linalg.inv(T_world_cam)\n",
            message="`T_world_cam.T` is not the inverse of the homogeneous transform `T_world_cam` (only a rotation's transpose is); use `np.linalg.inv(T_world_cam)`",
            range=(1, 15, 1, 28),
        ),
        Invalid("p_cam = (T_world_cam.T @ p_world_h)[:3]\n"),
        Invalid("from pydrake.math import RigidTransform\nX_BW = X_WB.T\n"),
        Invalid("T = world_T_base.T @ world_T_cam\n"),
        Invalid("def f(T_world_cam, p_world_h):\n    pose = T_world_cam\n    return pose.T @ p_world_h\n"),
        Invalid(
            "import numpy as np\nT_cam_world = np.transpose(T_world_cam)\n",
            expected_fix="import numpy as np\nT_cam_world = np.linalg.inv(T_world_cam)\n",
            message="`np.transpose(T_world_cam)` is not the inverse of the homogeneous transform `T_world_cam` (only a rotation's transpose is); use `np.linalg.inv(T_world_cam)`",
            range=(2, 15, 2, 40),
        ),
        Invalid(
            "import torch\np_cam = torch.transpose(T_world_cam, -1, -2) @ p_world_h\n",
            expected_fix="import torch\np_cam = torch.linalg.inv(T_world_cam) @ p_world_h\n",
            message="`torch.transpose(T_world_cam, -1, -2)` is not the inverse of the homogeneous transform `T_world_cam` (only a rotation's transpose is); use `torch.linalg.inv(T_world_cam)`",
            range=(2, 9, 2, 45),
        ),
        Invalid(
            "p_cam = T_world_cam.transpose(-2, -1) @ p_world_h\n",
            message="`T_world_cam.transpose(-2, -1)` is not the inverse of the homogeneous transform `T_world_cam` (only a rotation's transpose is); use `np.linalg.inv(T_world_cam)`",
            range=(1, 9, 1, 38),
        ),
        Invalid("T_cam_world = T_world_cam.mT\n"),
        Invalid("p_cam = T_world_cam.t() @ p_world_h\n"),
        Invalid("import numpy as np\nT_cam_world = np.swapaxes(T_world_cam, -1, -2)\n"),
    ]

    def run(self) -> None:
        facts = self.facts
        for node in (*facts.index.nodes(Attribute), *facts.index.nodes(Call)):
            matrix_node = facts.transposed(node)
            if matrix_node is None:
                continue
            fact = facts.frame_fact(matrix_node, facts.readings()[0])
            if fact is None or not fact.frames.is_operator or fact.frames.operator != "transform":
                continue
            if self._is_row_form_or_rotation_block(node):  # type: ignore[arg-type]
                continue
            matrix, inverse = self.code_of(matrix_node), _inverse_function(facts, node)
            self.report(
                node,
                f"`{self.code_of(node)}` is not the inverse of the homogeneous transform `{matrix}` "
                f"(only a rotation's transpose is); use `{inverse}({matrix})`",
                replacement=f"{inverse}({facts.index.segment(matrix_node)})",
                applicability="unsafe",
                fix_description=f"use {inverse}",
                evidence=fact.evidence,
            )

    def _is_row_form_or_rotation_block(self, node: ast.expr) -> bool:
        facts = self.facts
        parent = facts.parent(node)
        if self._is_memory_layout(node, parent):
            return True
        if isinstance(parent, Subscript) and parent.value is node:
            return facts.rotation_block_of(parent) is not None
        if isinstance(parent, BinOp) and isinstance(parent.op, MatMult):
            return parent.right is node
        if isinstance(parent, Call) and any(arg is node for arg in parent.args):
            if facts.matmul(parent) is not None:
                return parent.args[-1] is node
        return False

    def _is_memory_layout(self, node: ast.expr, parent: AST | None) -> bool:
        """`T.T.flatten()`, `T.T.reshape(-1)`, `np.ravel(T.T)`, `glLoadMatrixf(T.T)`: a column-major buffer."""
        if isinstance(parent, Attribute) and parent.value is node:
            if parent.attr == "reshape":
                call = self.facts.parent(parent)
                return isinstance(call, Call) and _is_flat_shape(call.args)
            return parent.attr in _FLATTENING or parent.attr in _LAYOUT_COPIES
        if isinstance(parent, Call) and any(arg is node for arg in parent.args):
            name = last_name(parent.func) or ""
            if name == "reshape":
                return _is_flat_shape(parent.args[1:])
            return name in _FLATTENING or name in _LAYOUT_COPIES or _OPENGL_CALL.match(name) is not None
        return False


def _inverse_function(facts: FactBase, node: AST) -> str:
    """The inverse in the namespace a transpose function was called through (`torch.transpose(T, -1, -2)`:
    `torch.linalg.inv`); numpy's for a method or an attribute."""
    if isinstance(node, Call) and isinstance(node.func, Attribute) and facts.is_module_like(node.func.value):
        head = (dotted_name(node.func.value) or "np").partition(".")[0]
        return f"{head}.linalg.inv"
    return "np.linalg.inv"


def _is_flat_shape(args: list[ast.expr]) -> bool:
    """`(-1)`, `(16,)`, `-1`: a reshape to one dimension."""
    if len(args) == 1 and isinstance(args[0], (ast.Tuple, ast.List)):
        args = list(args[0].elts)
    return len(args) == 1 and number(args[0]) in (-1, 16)
