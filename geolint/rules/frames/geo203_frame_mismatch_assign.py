"""GEO203 frame-mismatch-assign: the frame of a result contradicts the name it is stored in."""

from __future__ import annotations

import ast
from ast import AnnAssign, Assign, Attribute, Call, Name, Subscript

from geolint.rules.base import Invalid, Valid
from geolint.factbase.bosdyn import frame_comparison, in_tform_words
from geolint.factbase import dataflow
from geolint.factbase.model import FactBase, last_name
from geolint.rules.fact_rule import STATED, FactRule, Mismatch, SameFrame
from geolint.semantic.names import NameFrames, same_frame


class FrameMismatchAssign(FactRule):
    """A value is stored under a name that states another frame.

    ## What it does
    Flags an assignment whose target name states frames (`p_world`, `T_cam_world`) that the
    assigned expression contradicts: `p_world = T_cam_base @ p_base` (the result is in cam),
    `T_cam_world = T_world_cam` (an inverse is missing). A plain relabel between two names
    (`p_world = p_cam`, `cam2img = lidar2img`, `verts_scene = verts_cam[mask]`) is flagged only when
    it swaps a transform's two frames: otherwise both sides are names alone, the weakest evidence,
    and on real code such relabels were loosely used words (0 of 3 were bugs), not slips.

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

    ## Known problems
    Without a stated convention a value's frames must be declared, and a declared value is reported
    only when it reverses the name (`world_to_cam = buffer.lookup_transform("world", "cam", t)`):
    labels and names may use other words for one frame. Boston Dynamics' Spot SDK is the exception:
    its `a_tform_b` names and `bosdyn.client.frame_helpers` calls use the SDK's frame names, so
    `odom_tform_body = get_vision_tform_body(snapshot)` is reported; a name with a qualifier
    (`last_odom_tform_body`) or a waypoint (`body_tform_goal`) is not read. A few words in such names
    are roles, not frames of the SDK, and agree with each frame that plays the role: `robot` with
    `body` and `flat_body` (`vision_tform_robot = get_a_tform_b(snapshot, VISION_FRAME_NAME,
    GRAV_ALIGNED_BODY_FRAME_NAME)` is the robot's pose), `ko` (GraphNav's kinematic odometry) with
    `odom`, `world` with `vision`, `odom` and `seed`; so `vision_tform_robot` holding the hand's pose
    is still reported, but one holding the body's is not, whichever of the two body frames it is. So `T_cam_world = T_world_cam` is reported
    only where the convention is stated; the rule's three true findings on real code all rested on
    declared frames.
    """

    code = "GEO203"
    name = "frame-mismatch-assign"
    documents_naming = True

    VALID = [
        Valid("p_world = T_world_cam @ p_cam\n"),
        Valid("import numpy as np\nT_cam_world = np.linalg.inv(T_world_cam)\n"),
        Valid("T_cam_world = T_world_cam.T\n"),  # GEO204's business, frames agree
        Valid("p_world = T_world_cam @ p_base\n"),  # GEO201 flags the product; the result IS in world
        Valid("from pydrake.math import RigidTransform\nX_WC = X_WB @ X_BC\n"),
        Valid("p_world = compute(p_cam)\n"),
        Valid("import numpy as np\nworld2cam = np.linalg.inv(world2cam)\n"),  # a name rebound to its own inverse
        Valid("T_approach_obj = T_grasp_obj.copy()\nT_approach_obj.translation -= d\n"),  # copy, then edited
        Valid('T_table_world = RigidTransform(R, t, from_frame="patch", to_frame="world")\n'),  # label words differ
        Valid("T_word_body = T_world_tcp @ T_tcp_body\n"),  # `word`: `world` misspelt by one letter
        Valid("p_world = p_cam\n"),  # a relabel between two names: weak on both sides
        Valid("cam2img = lidar2img\n"),  # a loosely named matrix, no maths done on it
        Valid("def f(verts_cam, mask):\n    verts_scene = verts_cam[mask]\n    return verts_scene\n"),
        Valid("import numpy as np\nT_co_opt = np.linalg.inv(T_oc_opt)\n"),  # `_opt`: optimised, a qualifier, not a frame
        Valid(
            "import numpy as np\ndef init(init_c2w, last_c2w):\n"
            "    init_rel_w2c = np.linalg.inv(init_c2w @ np.linalg.inv(last_c2w))\n    return init_rel_w2c\n"
        ),  # a relative (world to world) correction named after the w2c it corrects
        Valid(
            "import numpy as np\ndef to_base(p_cam, rot, trans):\n    p_base = p_cam.T\n"
            "    p_base = np.dot(p_base, rot.T)\n    p_base = p_base + trans\n    return p_base\n"
        ),  # the start value of a name carried into base by the next statements
        Valid("T_cam_world = T_world_cam\n"),  # names on both sides, no convention stated: too weak
        # the result's frame is declared "base", the name says world: labels and names may use other words for one
        # frame, so only a reversal counts
        Valid('T_obj_world = RigidTransform(R, t, from_frame="obj", to_frame="base")\np_world = T_obj_world * p_obj\n'),
        # Boston Dynamics' `a_tform_b` maps b into a; `.inverse()` swaps the frames
        Valid("from bosdyn.client import frame_helpers\nodom_tform_body = frame_helpers.get_odom_tform_body(snapshot)\n"),
        Valid("from bosdyn.client.frame_helpers import get_vision_tform_body\nbody_tform_vision = get_vision_tform_body(snapshot).inverse()\n"),
        # a qualifier before the frame (`last_`) is not read as part of it
        Valid("from bosdyn.client import frame_helpers\nlast_odom_tform_body = frame_helpers.get_vision_tform_body(snapshot)\n"),
        # `robot` is no frame of the SDK: the robot's pose is its body's, gravity-aligned or not
        Valid(
            "from bosdyn.client.frame_helpers import VISION_FRAME_NAME, GRAV_ALIGNED_BODY_FRAME_NAME, get_a_tform_b\n"
            "vision_tform_robot = get_a_tform_b(snapshot, VISION_FRAME_NAME, GRAV_ALIGNED_BODY_FRAME_NAME)\n"
        ),
    ]
    INVALID = [
        Invalid(
            "p_world = T_cam_base @ p_base\n", options=STATED,
            message="`p_world` should be in world, but `T_cam_base @ p_base` is in cam",
            range=(1, 11, 1, 30),
        ),
        Invalid("T_cam_world = T_world_cam\n", options=STATED),
        Invalid("from pydrake.math import RigidTransform\nX_CW = X_WB @ X_BC\n", options=STATED),
        Invalid("def f(T_world_cam):\n    pose = T_world_cam\n    T_cam_world = pose\n    return T_cam_world\n", options=STATED),
        # no convention stated: tf2's lookup_transform(target, source, t) maps source into target
        Invalid('world_to_cam = tf_buffer.lookup_transform("world", "cam", rospy.Time())\n'),
        # Boston Dynamics' names and frame_helpers state their frames in one vocabulary: any other word is another frame
        Invalid("from bosdyn.client import frame_helpers\nodom_tform_body = frame_helpers.get_vision_tform_body(snapshot)\n"),
        Invalid(
            "from bosdyn.client.frame_helpers import ODOM_FRAME_NAME, BODY_FRAME_NAME, get_a_tform_b\n"
            "body_tform_odom = get_a_tform_b(snapshot, ODOM_FRAME_NAME, BODY_FRAME_NAME)\n"
        ),
        # the role word `robot` agrees with the body, but the pose is in vision, not odom
        Invalid("from bosdyn.client import frame_helpers\nodom_tform_robot = frame_helpers.get_vision_tform_body(snapshot)\n"),
    ]

    def run(self) -> None:
        for node in self.facts.index.nodes(Assign, AnnAssign):
            if isinstance(node, Assign):
                for target in node.targets:
                    self._check(target, node.value)
            elif isinstance(node, AnnAssign) and node.value is not None:
                self._check(node.target, node.value)

    def _check(self, target: ast.expr, value: ast.expr) -> None:
        if not isinstance(target, Name):
            return
        facts = self.facts
        if any(facts.name_frames(target.id, order) is None for order in facts.readings()):
            return  # the name states no frames (most names): nothing to compare, and the tests below walk the value
        if target.id in dataflow.names_read(facts.index, value):
            return  # `world2cam = inv(world2cam)`, `T_a_b = T_a_b @ D`: a name updated from itself
        if _is_copy(facts, value) or _edited_in_place(facts, target):
            return  # `T_new = T.copy(); T_new[:3, 3] -= d`: the name describes the value after the edit
        messages = []
        for order in facts.readings():
            stated, actual = facts.name_frames(target.id, order), facts.frame_fact(value, order)
            if stated is None or actual is None:
                return
            if not (facts.names_stated or actual.declared):
                return  # a name assigned from names, where the project does not state its convention: too weak
            one_vocabulary = in_tform_words(stated) and in_tform_words(actual)  # Spot SDK names and frame_helpers
            if actual.declared and not one_vocabulary and not _reversed(stated.frames, actual.frames):
                return  # labels and names use different words (`T_table_world` from "patch"): only a reversal counts
            if not actual.declared and _is_relabel(value) and not _swaps_frames(stated.frames, actual.frames):
                return  # `p_world = p_cam`, `cam2img = lidar2img`: two names, nothing computed; only a swap counts
            mismatch = self._problem(target.id, value, stated.frames, actual.frames, frame_comparison(stated, actual))
            if mismatch is None:
                return
            messages.append((mismatch, stated.evidence + actual.evidence))
        if messages:
            mismatch, evidence = messages[0]
            self.report(value, mismatch.message, evidence=evidence, frames=mismatch.frames)

    def _problem(self, name: str, value: ast.expr, stated: NameFrames, actual: NameFrames, same: SameFrame) -> Mismatch | None:
        if stated.is_operator and actual.is_operator:
            differing = [
                (wanted, got)
                for wanted, got in ((stated.dst, actual.dst), (stated.src, actual.src))
                if same(wanted, got) is False
            ]
            if differing:
                hint = " (an inverse is missing)" if same(stated.dst, actual.src) and same(stated.src, actual.dst) else ""
                wanted, got = differing[0]
                assert wanted is not None and got is not None
                return Mismatch(
                    f"`{name}` should map {stated.src} into {stated.dst}, but "
                    f"`{self.code_of(value)}` maps {actual.src} into {actual.dst}{hint}",
                    (wanted, got),
                )
        elif not stated.is_operator and not actual.is_operator:
            if same(stated.frame, actual.frame) is False:
                assert stated.frame is not None and actual.frame is not None
                return Mismatch(
                    f"`{name}` should be in {stated.frame}, but `{self.code_of(value)}` is in {actual.frame}",
                    (stated.frame, actual.frame),
                )
        return None


def _reversed(stated: NameFrames, declared: NameFrames) -> bool:
    return bool(same_frame(stated.dst, declared.src)) and bool(same_frame(stated.src, declared.dst))


def _swaps_frames(stated: NameFrames, actual: NameFrames) -> bool:
    """`T_cam_world = T_world_cam`: a transform stored under its inverse's name."""
    return stated.is_operator and actual.is_operator and _reversed(stated, actual)


def _is_relabel(value: ast.expr) -> bool:
    """A name, or a part of one (`verts_cam[mask]`, `meta["lidar2img"]`, `self.T_world_cam`): nothing computed."""
    while isinstance(value, (Subscript, Attribute)):
        value = value.value
    return isinstance(value, Name)


def _is_copy(facts: FactBase, value: ast.expr) -> bool:
    """`T.copy()`, `np.copy(T)`, `copy.deepcopy(T)`, `T.clone()`."""
    if not isinstance(value, Call):
        return False
    name = last_name(value.func)
    return name in ("copy", "deepcopy", "clone") or facts.is_array_call(value.func, "array", "copy") and bool(value.args)


def _edited_in_place(facts: FactBase, target: Name) -> bool:
    """Whether the scope writes into the target after binding it (`T[:3, 3] = t`, `T.translation -= d`,
    `T += D`, or a later `T = f(T)`)."""
    index = facts.index
    scope = index.scope_of(target)
    # `p_base = p_cam.T` then `p_base = np.dot(p_base, R.T)`: a later binding updates the name from itself
    return dataflow.writes_into(index, scope, target.id) or dataflow.last_update_from_itself(index, scope, target.id) > target.lineno
