"""GEO202 frame-mismatch-compose: two transforms are composed whose inner frames disagree."""

from __future__ import annotations

from typing import Final

from geolint.rules.base import Invalid, Valid
from geolint.factbase.model import EXTRINSICS_EVIDENCE, FrameFact, MatMul
from geolint.rules.fact_rule import STATED, Mismatch, ProductRule, SameFrame
from geolint.semantic.names import NameFrames


# Words that name a pose a body should take (a waypoint), not a body: `T_base_grasp` is the tcp's pose
# at the grasp in grasping code, so `T_base_grasp @ T_tcp_tool0` is the flange pose there.
WAYPOINT_WORDS: Final = frozenset(
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

    ## Known problems
    Without a stated convention, a composition whose frames come from names alone
    (`T_world_base @ T_cam_tool`) is not reported: none of the 24 such findings triaged on real code
    was a bug (`T_base_grasp` names a waypoint, `rel_w2c` a correction, and projects mix orders).
    A name's frame word is read as the explicit frame a declaration bound to that name gives it
    (`T_ee_rot = RigidTransform(..., from_frame="franka_tool", to_frame="franka_tool")` makes `ee`
    franka_tool in that module), but only within the module that declares it: an abbreviation used
    in one module and declared in another still meets the explicit string as another frame.
    """

    code = "GEO202"
    name = "frame-mismatch-compose"
    documents_naming = True

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
        # `T_ee_rot` is declared from and to "tool": the module's `ee` names that frame (`rot` is no frame)
        Valid('T_ee_rot = RigidTransform(R, t, from_frame="tool", to_frame="tool")\nT = T_ee_world * T_ee_rot\n'),
    ]
    INVALID = [
        Invalid(
            "T_world_tool = T_world_base @ T_cam_tool\n", options=STATED,
            message="`T_world_base` maps base into world, but `T_cam_tool` maps tool into cam: the inner frames base and cam differ",
            range=(1, 16, 1, 41),
        ),
        Invalid(  # monogram names are evidence on their own where pydrake is imported: no option needed
            "from pydrake.math import RigidTransform\nX_WG = X_WB @ X_CG\n",
            message="`X_WB` maps b into w, but `X_CG` maps g into c: the inner frames b and c differ",
            range=(2, 8, 2, 19),
        ),
        Invalid("T = T_world_base @ T_base_cam @ T_tool_grip\n", options=STATED),
        Invalid("import numpy as np\nT = np.matmul(world_from_base, cam_from_tool)\n", options=STATED),
        Invalid("T = T_world_base.dot(T_cam_tool)\n", options=STATED),
        Invalid("T = T_world_base * T_cam_tool\n", options=STATED),
        Invalid("T = cam2world @ world2base\n", options=STATED),
        Invalid("T_world_grasp = T_world_base @ T_object_grasp\n", options=STATED),  # a waypoint word elsewhere changes nothing
        # no convention stated: the declared side is evidence enough, in either reading of the name
        Invalid('base_pose = RigidTransform(R, t, from_frame="base", to_frame="world")\nT = base_pose * T_cam_tool\n'),
        # `ee` is learned to be "tool"; `cam` is still another frame
        Invalid('T_ee_rot = RigidTransform(R, t, from_frame="tool", to_frame="tool")\nT = T_cam_world * T_ee_rot\n'),
    ]

    def too_weak(self, left: FrameFact, right: FrameFact) -> bool:
        """`w2c_ref @ best_w2c`: two extrinsics of one direction, known only by their names. Such code is
        right only when one is a relative correction named after the pose it corrects (which one,
        the names cannot tell), and that is how it is written in pose refinement."""
        return left.frames == right.frames and all(
            any(item.endswith(EXTRINSICS_EVIDENCE) for item in fact.evidence) for fact in (left, right)
        )

    def problem(self, product: MatMul, left: NameFrames, right: NameFrames, same: SameFrame) -> Mismatch | None:
        if not (left.is_operator and right.is_operator):
            return None
        if left.src in WAYPOINT_WORDS:
            return None  # `T_base_pregrasp * T_tcp_tool0`: the waypoint is where a body (the tcp) should be
        if same(left.src, right.dst) is False:
            assert left.src is not None and right.dst is not None
            return Mismatch(
                f"`{self.code_of(product.left)}` maps {left.src} into {left.dst}, but "
                f"`{self.code_of(product.right)}` maps {right.src} into {right.dst}: the inner frames "
                f"{left.src} and {right.dst} differ",
                (left.src, right.dst),
            )
        return None
