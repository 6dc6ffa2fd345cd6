"""GEO203 frame-mismatch-assign: the frame of a result contradicts the name it is stored in."""

from __future__ import annotations

import libcst as cst

from geolint.rules.base import Invalid, Valid
from geolint.semantic.names import frames_of_name, same_frame
from geolint.semantic.prefilter import Trigger, may_mislabel_frames
from geolint.semantic.rule_support import SemanticRule


class FrameMismatchAssign(SemanticRule):
    """A value is stored under a name that states another frame.

    ## What it does
    Flags an assignment whose target name states frames (`p_world`, `T_cam_world`) that the
    assigned expression contradicts: `p_world = T_cam_base @ p_base` (the result is in cam),
    `T_cam_world = T_world_cam` (an inverse is missing), `p_world = p_cam` (a relabel).

    ## Why is this bad?
    The name is the only frame annotation untyped code has. A name that lies is worse than no
    name: every later reader and every later check trusts it.

    ## Example
    ```python
    T_cam_world = T_world_cam
    ```

    ## Use instead
    ```python
    T_cam_world = np.linalg.inv(T_world_cam)
    ```

    ## Fix safety
    No fix is offered.
    """

    code = "GEO203"
    name = "frame-mismatch-assign"
    triggers = Trigger("an assignment to a name that states frames", may_mislabel_frames)

    VALID = [
        Valid("p_world = T_world_cam @ p_cam\n"),
        Valid("import numpy as np\nT_cam_world = np.linalg.inv(T_world_cam)\n"),
        Valid("T_cam_world = T_world_cam.T\n"),  # GEO204's business, frames agree
        Valid("p_world = T_world_cam @ p_base\n"),  # GEO201 flags the product; the result IS in world
        Valid("X_WC = X_WB @ X_BC\n"),
        Valid("p_world = compute(p_cam)\n"),
    ]
    INVALID = [
        Invalid("p_world = T_cam_base @ p_base\n"),
        Invalid("T_cam_world = T_world_cam\n"),
        Invalid("p_world = p_cam\n"),
        Invalid("X_CW = X_WB @ X_BC\n"),
        Invalid("def f(T_world_cam):\n    pose = T_world_cam\n    T_base_cam = pose\n    return T_base_cam\n"),
    ]

    def visit_Assign(self, node: cst.Assign) -> None:
        for target in node.targets:
            self._check(target.target, node.value)

    def visit_AnnAssign(self, node: cst.AnnAssign) -> None:
        if node.value is not None:
            self._check(node.target, node.value)

    def _check(self, target: cst.BaseExpression, value: cst.BaseExpression) -> None:
        if not isinstance(target, cst.Name):
            return
        stated = frames_of_name(target.value, self.context.config)
        actual = self.model.frames_of(value)
        if stated is None or actual is None:
            return
        if stated.is_operator and actual.is_operator:
            if same_frame(stated.dst, actual.dst) is False or same_frame(stated.src, actual.src) is False:
                hint = (
                    " (an inverse is missing)"
                    if same_frame(stated.dst, actual.src) and same_frame(stated.src, actual.dst)
                    else ""
                )
                self.report(
                    value,
                    f"`{target.value}` should map {stated.src} into {stated.dst}, but "
                    f"`{self.code_of(value)}` maps {actual.src} into {actual.dst}{hint}",
                )
        elif not stated.is_operator and not actual.is_operator:
            if same_frame(stated.frame, actual.frame) is False:
                self.report(
                    value,
                    f"`{target.value}` should be in {stated.frame}, but `{self.code_of(value)}` is in {actual.frame}",
                )
