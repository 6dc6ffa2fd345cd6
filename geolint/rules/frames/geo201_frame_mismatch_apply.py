"""GEO201 frame-mismatch-apply: a transform is applied to a value from another frame."""

from __future__ import annotations

from geolint.rules.base import Invalid, Valid
from geolint.factbase.model import MatMul
from geolint.rules.fact_rule import STATED, Mismatch, ProductRule, SameFrame
from geolint.semantic.names import NameFrames


class FrameMismatchApply(ProductRule):
    """A transform is applied to a value expressed in a frame it does not map from.

    ## What it does
    Reads frames from names in every common convention (`T_world_cam`, `world_T_cam`, Drake
    `X_WB` / `p_BQ`, `world_from_cam`, `cam_to_world`, `cam2world`, suffixes `p_world`,
    `points_in_cam`) and flags `T @ x` (also `.dot`, `np.dot`, `np.matmul`, `SE3 * x`, and the
    row form `x @ T.T`) when x's frame is not the transform's source frame.

    ## Why is this bad?
    `T_world_cam` maps camera coordinates into the world. Fed base-frame coordinates, it returns
    numbers that are in no frame at all, with no error and plausible magnitudes.

    ## Example
    ```python
    p_world = T_world_cam @ p_base
    ```

    ## Use instead
    ```python
    p_world = T_world_base @ p_base
    ```

    ## Fix safety
    No fix is offered: the right transform has to be chosen by a person.

    ## Known problems
    Without a stated convention, a product whose two frames come from names alone
    (`T_world_cam @ p_base`) is not reported: none of the 4 such findings triaged on real code was a
    bug. State the convention to have names checked.
    """

    code = "GEO201"
    name = "frame-mismatch-apply"
    documents_naming = True

    VALID = [
        Valid("p_world = T_world_cam @ p_cam\n"),
        Valid("from pydrake.math import RigidTransform\np_W = X_WB @ p_BQ\n"),
        Valid("p_world = world_T_cam @ p_cam\n"),
        Valid("pts_world = pts_cam @ R_world_cam.T\n"),
        Valid("p_world = cam2world @ point_in_cam\n"),
        Valid("p_world = T_world_cam @ p\n"),
        Valid("p_cam = np.linalg.inv(T_world_cam) @ p_world\n"),
        Valid("p_world = T_world_camera @ p_cam\n"),  # an abbreviation may name the same frame
        Valid("p_world = T_world_cam @ p_base\n"),  # names on both sides, no convention stated: too weak
        # a `Transform` that is not geolint's states nothing
        Valid('class Transform:\n    pass\ndef to_world(T: Transform["world", "cam"], p_base):\n    return T @ p_base\n'),
        Valid("import numpy as np\nT_world_base = T_world_cam @ T_cam_base\np = np.linalg.inv(T_world_cam) @ p_cam\n"),
    ]
    INVALID = [
        Invalid(
            "p_world = T_world_cam @ p_base\n", options=STATED,
            message="`T_world_cam` maps cam into world, but `p_base` is in base",
            range=(1, 11, 1, 31),
        ),
        Invalid(  # monogram names are evidence on their own where pydrake is imported: no option needed
            "from pydrake.math import RigidTransform\np_W = X_WB @ p_CQ\n",
            message="`X_WB` maps b into w, but `p_CQ` is in c",
            range=(2, 7, 2, 18),
        ),
        Invalid("p = cam_to_world @ p_world\n", options=STATED),
        Invalid("import numpy as np\np = np.dot(world_from_cam, point_in_base)\n", options=STATED),
        Invalid("pts = pts_base @ R_world_cam.T\n", options=STATED),
        Invalid("p = T_world_cam.dot(p_base)\n", options=STATED),
        # no convention stated: the declared side is evidence enough
        Invalid('cam_pose = RigidTransform(R, t, from_frame="cam", to_frame="world")\np_world = cam_pose * p_base\n'),
        # a geolint type is a declaration too (geolint.typing's arrays, the runtime's classes)
        Invalid(
            "from geolint.typing import TransformMatrix\n"
            'def to_world(T: TransformMatrix["world", "cam"], p_base):\n    return T @ p_base\n'
        ),
        # a declaration bound to a `T_a_b` name states the project's order, so names count
        Invalid(
            'import numpy as np\nT_world_cam = RigidTransform(R, t, from_frame="cam", to_frame="world")\n'
            "p = np.linalg.inv(T_world_base) @ p_cam\n"
        ),
    ]

    def problem(self, product: MatMul, left: NameFrames, right: NameFrames, same: SameFrame) -> Mismatch | None:
        if left.is_operator and right.frame is not None:
            if same(left.src, right.frame) is False:
                assert left.src is not None
                return Mismatch(
                    f"`{self.code_of(product.left)}` maps {left.src} into {left.dst}, but "
                    f"`{self.code_of(product.right)}` is in {right.frame}",
                    (left.src, right.frame),
                )
        elif right.is_operator and left.frame is not None:
            # Row vectors: `x @ M` applies M.T, which maps M.dst into M.src.
            if same(right.dst, left.frame) is False:
                assert right.dst is not None
                return Mismatch(
                    f"`{self.code_of(product.left)} @ {self.code_of(product.right)}` maps {right.dst} into "
                    f"{right.src}, but `{self.code_of(product.left)}` is in {left.frame}",
                    (right.dst, left.frame),
                )
        return None
