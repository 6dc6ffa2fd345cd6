"""GEO202 frame-mismatch-compose: two transforms are composed whose inner frames disagree."""

from __future__ import annotations

from geolint.rules.base import Invalid, Valid
from geolint.factbase.model import EXTRINSICS_EVIDENCE, FrameFact, MatMul
from geolint.factbase.rule_support import STATED, Mismatch, ProductRule
from geolint.semantic.names import NameFrames, same_frame


# Words that name a pose a body should take (a waypoint), not a body: `T_base_grasp` is the tcp's pose
# at the grasp in grasping code, so `T_base_grasp @ T_tcp_tool0` is the flange pose there.
WAYPOINT_WORDS = frozenset(
    {
        "grasp", "pregrasp", "postgrasp", "retreat", "lift", "approach", "pick", "prepick", "place",
        "preplace", "goal", "target", "waypoint", "setpoint", "desired", "des", "standoff", "hover",
    }
)  # fmt: skip


class FrameMismatchCompose(ProductRule):
    """Two transforms are composed although the inner frames do not match.

    ## What it does
    Flags `A @ B` (also `.dot`, `np.dot`, `np.matmul`, and `*` on spatialmath `SE3` / PyKDL
    `Frame` values) where both are transforms with known frames and A's source frame is not B's
    destination frame: `T_world_base @ T_cam_tool`, `X_WB @ X_CG`. Chains are followed, so
    `T_a_b @ T_b_c @ T_d_e` is flagged at the last product.

    ## Why is this bad?
    `T_a_b @ T_b_c` is `T_a_c` only because the inner `b`s cancel. With different inner frames
    the product is not a transform between any two real frames, and everything computed from it
    is wrong.

    ## Example
    ```python
    T_world_tool = T_world_base @ T_cam_tool
    ```

    ## Use instead
    ```python
    T_world_tool = T_world_base @ T_base_cam @ T_cam_tool
    ```

    ## Fix safety
    No fix is offered: the missing link has to be chosen by a person.

    ## Options
    `naming = "auto" | "dst-first" | "src-first"` says how `T_a_b` / `R_a_b` read: dst-first maps b
    into a, src-first (autolab_core's `T_obj_world`) maps a into b. With `"auto"` (the default) the
    order is learned from the project: `from_frame=`/`to_frame=` declarations bound to such names,
    then the consistency of its compositions; only what is wrong in every reading left open is
    reported. A table of switches turns single conventions off; Drake's monogram names (`X_WB`,
    `p_BQ`) are read only in projects that import pydrake unless `monogram = true` (elsewhere
    `X_EQ` is a state vector). `frame-aliases` declares synonyms (cam = camera).

    Names are frame evidence on their own only where the convention is **stated**: by
    `naming = "dst-first"` or `"src-first"`, or by the project's own declarations, all in one order.
    Elsewhere a finding needs an explicit declaration on one side: `from_frame=`/`to_frame=`,
    `.as_frames(a, b)`, tf2's `lookup_transform(target, source, t)`, pycolmap's `cam_from_world`,
    BOP's `cam_R_w2c`, geolint's types (`T: TransformMatrix["world", "cam"]`, `p: Point[Camera]`).

    ## Known problems
    Without a stated convention a mismatch between two names (`T_world_base @ T_cam_tool`) is not reported. On
    real code, none of the triaged findings that rested on names alone was a bug (GEO201 0 of 4,
    GEO202 0 of 24; GEO203's three true findings all rested on declared frames): `T_base_grasp`
    names a waypoint, `rel_w2c` a correction, `T_word_body` a typo, and projects mix orders. State
    the convention to have names checked.
    """

    code = "GEO202"
    name = "frame-mismatch-compose"

    VALID = [
        Valid("T_world_tool = T_world_base @ T_base_tool\n"),
        Valid("from pydrake.math import RigidTransform\nX_WG = X_WB @ X_BG\n"),
        Valid("T = world_T_base @ base_T_cam\n"),
        Valid("import numpy as np\nT = np.linalg.inv(T_cam_world) @ T_cam_tool\n"),
        Valid("T = cam2world @ tool2cam\n"),
        Valid("R_world_tool = R_world_base @ R_base_tool\n"),
        Valid("from pydrake.math import RigidTransform\nT = T_world_base @ X_BC\n"),  # a word frame and a monogram letter are not compared
        Valid("T_base_tool0 = T_base_pregrasp @ T_tcp_tool0\n"),  # the pregrasp waypoint is a pose of the tcp
        Valid("w2c = reference_w2c @ best_w2c\n"),  # one of two same-direction extrinsics is a relative correction
        Valid("T_world_body = T_word_tcp @ T_tcp_body\n"),  # `word`: `world` misspelt
        Valid("T_world_tool = T_world_base @ T_cam_tool\n"),  # names on both sides, no convention stated: too weak
    ]
    INVALID = [
        Invalid("T_world_tool = T_world_base @ T_cam_tool\n", options=STATED),
        Invalid("from pydrake.math import RigidTransform\nX_WG = X_WB @ X_CG\n", options=STATED),
        Invalid("T = T_world_base @ T_base_cam @ T_tool_grip\n", options=STATED),
        Invalid("import numpy as np\nT = np.matmul(world_from_base, cam_from_tool)\n", options=STATED),
        Invalid("T = T_world_base.dot(T_cam_tool)\n", options=STATED),
        Invalid("T = T_world_base * T_cam_tool\n", options=STATED),
        Invalid("T = cam2world @ world2base\n", options=STATED),
        Invalid("T_world_grasp = T_world_base @ T_object_grasp\n", options=STATED),  # a waypoint word elsewhere changes nothing
        # no convention stated: the declared side is evidence enough, in either reading of the name
        Invalid('base_pose = RigidTransform(R, t, from_frame="base", to_frame="world")\nT = base_pose * T_cam_tool\n'),
    ]

    def too_weak(self, left: FrameFact, right: FrameFact) -> bool:
        """`w2c_ref @ best_w2c`: two extrinsics of one direction, known only by their names. Such code is
        right only when one is a relative correction named after the pose it corrects (which one,
        the names cannot tell), and that is how it is written in pose refinement."""
        return left.frames == right.frames and all(
            any(item.endswith(EXTRINSICS_EVIDENCE) for item in fact.evidence) for fact in (left, right)
        )

    def problem(self, product: MatMul, left: NameFrames, right: NameFrames) -> Mismatch | None:
        if not (left.is_operator and right.is_operator):
            return None
        if left.src in WAYPOINT_WORDS:
            return None  # `T_base_pregrasp * T_tcp_tool0`: the waypoint is where a body (the tcp) should be
        if same_frame(left.src, right.dst) is False:
            assert left.src is not None and right.dst is not None
            return Mismatch(
                f"`{self.code_of(product.left)}` maps {left.src} into {left.dst}, but "
                f"`{self.code_of(product.right)}` maps {right.src} into {right.dst}: the inner frames "
                f"{left.src} and {right.dst} differ",
                (left.src, right.dst),
            )
        return None
