"""GEO204 transpose-as-inverse: `.T` of a 4x4 homogeneous transform used as its inverse."""

from __future__ import annotations

import re

import libcst as cst

from geolint.rules.base import Invalid, Valid
from geolint.semantic.prefilter import Trigger, may_transpose_transform
from geolint.semantic.rule_support import SemanticRule


# Methods and functions that turn a matrix into a flat buffer: the transpose only picks the
# column-major memory layout, it is never applied as an operator.
_FLATTENING = frozenset({"flatten", "ravel", "tolist", "tobytes", "tofile", "flat"})
_OPENGL_CALL = re.compile(r"gl[A-Z]\w*$")


class TransposeAsInverse(SemanticRule):
    """The transpose of a 4x4 homogeneous transform is used where its inverse is meant.

    ## What it does
    Flags `T.T` where T is named as a full rigid transform (`T_world_cam`, `world_T_cam`,
    Drake `X_WB`, `H_a_b`) and the transpose is used as an operator or stored: `T_world_cam.T @
    p_world`, `T_cam_world = T_world_cam.T`. The row-vector form `points_h @ T_world_cam.T`
    is correct and never flagged, nor is `T.T[:3, :3]` (a rotation's transpose is its inverse),
    nor a transpose that only changes memory layout: flattened for column-major consumers
    (`T.T.flatten()`, `.ravel()`, `.tolist()`, `.tobytes()`, `np.ravel(T.T)`) or passed to an
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
    The fix `np.linalg.inv(T)` is unsafe: it needs `numpy` imported as `np`, and the code may rely
    on the (wrong) transpose elsewhere.
    """

    code = "GEO204"
    name = "transpose-as-inverse"
    triggers = Trigger("`.T` of a transform name", may_transpose_transform)

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
    ]
    INVALID = [
        Invalid(
            "T_cam_world = T_world_cam.T\n",
            expected_fix="T_cam_world = np.linalg.inv(T_world_cam)\n",
        ),
        Invalid("p_cam = (T_world_cam.T @ p_world_h)[:3]\n"),
        Invalid("X_BW = X_WB.T\n"),
        Invalid("T = world_T_base.T @ world_T_cam\n"),
        Invalid("def f(T_world_cam, p_world_h):\n    pose = T_world_cam\n    return pose.T @ p_world_h\n"),
    ]

    def visit_Attribute(self, node: cst.Attribute) -> None:
        if node.attr.value != "T":
            return
        frames = self.model.frames_of(node.value)
        if frames is None or not frames.is_operator or frames.operator != "transform":
            return
        if self._is_row_form_or_rotation_block(node):
            return
        matrix = self.code_of(node.value)
        self.report(
            node,
            f"`{matrix}.T` is not the inverse of the homogeneous transform `{matrix}` "
            f"(only a rotation's transpose is); use `np.linalg.inv({matrix})`",
            replacement=cst.parse_expression(f"np.linalg.inv({matrix})"),
            applicability="unsafe",
            fix_description="use np.linalg.inv",
        )

    def _is_row_form_or_rotation_block(self, node: cst.Attribute) -> bool:
        parent = self.model.parent(node)
        if self._is_memory_layout(node, parent):
            return True
        if isinstance(parent, cst.Subscript) and parent.value is node:
            return self.model.rotation_block_of(parent) is not None
        if isinstance(parent, cst.BinaryOperation) and isinstance(parent.operator, cst.MatrixMultiply):
            return parent.right is node
        if isinstance(parent, cst.Arg):
            call = self.model.parent(parent)
            if isinstance(call, cst.Call) and self.model.matmul(call) is not None:
                return call.args[-1] is parent
        return False

    def _is_memory_layout(self, node: cst.Attribute, parent: cst.CSTNode | None) -> bool:
        """`T.T.flatten()`, `np.ravel(T.T)`, `glLoadMatrixf(T.T)`: a column-major buffer."""
        if isinstance(parent, cst.Attribute) and parent.value is node:
            return parent.attr.value in _FLATTENING
        if isinstance(parent, cst.Arg):
            call = self.model.parent(parent)
            if isinstance(call, cst.Call):
                func = call.func
                name = func.attr.value if isinstance(func, cst.Attribute) else func.value if isinstance(func, cst.Name) else ""
                return name in _FLATTENING or _OPENGL_CALL.match(name) is not None
        return False
