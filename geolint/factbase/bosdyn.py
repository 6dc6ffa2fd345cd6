"""Boston Dynamics' Spot SDK states frames in its names: `odom_tform_body` is the pose of body in
odom (it maps body coordinates into odom), `a_tform_b * b_tform_c` is `a_tform_c`, `.inverse()`
swaps the two. `bosdyn.client.frame_helpers` returns such transforms from a frame-tree snapshot:
`get_a_tform_b(snapshot, a, b)`, `get_odom_tform_body(snapshot)`, `get_vision_tform_body(snapshot)`.

Names (`geolint.semantic.names.tform_frames`) and these calls are explicit statements in one
vocabulary (the SDK's frame names), so two of them are compared word for word, where a name and a
label of another library may use two words for one frame. The exceptions are the few words Spot
code writes for a role rather than one of the SDK's frames (`vision_tform_robot`, `ko_tform_body`):
such a word agrees with the frames that can play its role (`same_tform_frame`).
"""

from __future__ import annotations

import ast
from ast import Call
from typing import Callable, Final, TYPE_CHECKING

from geolint.factbase.fact_types import FrameFact
from geolint.factbase.syntax import keyword, positional_args, string
from geolint.semantic.names import NameFrames, same_frame

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

# The evidence every statement in the SDK's words ends with (names and frame_helpers calls).
TFORM_EVIDENCE: Final = "(Boston Dynamics' a_tform_b)"

_HELPERS: Final = "bosdyn.client.frame_helpers."
# frame_helpers' functions with their frames in the name
_NAMED_HELPERS: Final = {
    _HELPERS + "get_odom_tform_body": NameFrames(dst="odom", src="body", operator="transform"),
    _HELPERS + "get_vision_tform_body": NameFrames(dst="vision", src="body", operator="transform"),
}
# frame_helpers' functions taking (snapshot, frame_a, frame_b, ...) and returning a_tform_b (SE3, or SE2)
_GENERIC_HELPERS: Final = frozenset({_HELPERS + "get_a_tform_b", _HELPERS + "get_se2_a_tform_b"})
# frame_helpers' frame-name constants (those a transform is commonly asked between)
_FRAME_CONSTANTS: Final = {
    _HELPERS + "VISION_FRAME_NAME": "vision",
    _HELPERS + "BODY_FRAME_NAME": "body",
    _HELPERS + "GRAV_ALIGNED_BODY_FRAME_NAME": "flat_body",
    _HELPERS + "ODOM_FRAME_NAME": "odom",
    _HELPERS + "SEED_FRAME_NAME": "seed",
    _HELPERS + "GROUND_PLANE_FRAME_NAME": "gpe",
    _HELPERS + "HAND_FRAME_NAME": "hand",
    _HELPERS + "TOOL_FRAME_NAME": "tool",
    _HELPERS + "TASK_FRAME_NAME": "task",
}


# Words Spot code writes in `a_tform_b` names for a role, not a frame of the SDK's frame tree, with the
# frames that play it. `robot`: the robot's pose is its body's, or the gravity-aligned body's (the SDK's
# fetch tutorial: vision_tform_robot = get_a_tform_b(snapshot, VISION_FRAME_NAME, GRAV_ALIGNED_BODY_FRAME_NAME)).
# `ko`: GraphNav's kinematic odometry, the odom frame (`set_localization(..., ko_tform_body=odom_tform_body)`).
# `world`: a frame fixed in the world (fiducial_follow: body_tform_world = get_a_tform_b(snapshot,
# BODY_FRAME_NAME, VISION_FRAME_NAME)).
_ROLE_FRAMES: Final = {
    "robot": frozenset({"body", "flat_body"}),
    "ko": frozenset({"odom"}),
    "world": frozenset({"vision", "odom", "seed"}),
}


def same_tform_frame(first: str | None, second: str | None) -> bool | None:
    """`same_frame` for two frames in the SDK's words, where a role word (`robot`) is each frame that plays it
    (`body`, `flat_body`) and still another frame than the rest (`vision`, `hand`)."""
    if first is not None and second is not None and (second in _ROLE_FRAMES.get(first, ()) or first in _ROLE_FRAMES.get(second, ())):
        return True
    return same_frame(first, second)


def frame_comparison(*facts: FrameFact) -> Callable[[str | None, str | None], bool | None]:
    """How to compare the frames of `facts`: with the SDK's role words when one of them is in its words."""
    return same_tform_frame if any(in_tform_words(fact) for fact in facts) else same_frame


def helper_frames(facts: FactBase, call: Call) -> FrameFact | None:
    """The transform a frame_helpers call returns (`get_vision_tform_body(snapshot)`: body into vision)."""
    called = facts.called_name(call.func)
    if called is None or "_tform_" not in called:
        return None  # most calls: decided before resolving any import
    qualified = facts.qualified_name(call.func) or ""
    frames = _NAMED_HELPERS.get(qualified)
    if frames is None and qualified in _GENERIC_HELPERS:
        positional = positional_args(call)
        given_a, given_b = keyword(call, "frame_a"), keyword(call, "frame_b")
        node_a = given_a.value if given_a else positional[1] if len(positional) > 1 else None
        node_b = given_b.value if given_b else positional[2] if len(positional) > 2 else None
        dst, src = _frame_name(facts, node_a), _frame_name(facts, node_b)
        if dst and src:
            frames = NameFrames(dst=dst, src=src, operator="transform")
    if frames is None:
        return None
    return FrameFact(frames, (f"`{facts.code_of(call.func)}(...)` at line {call.lineno} {TFORM_EVIDENCE}",), True)


def _frame_name(facts: FactBase, node: ast.expr | None) -> str | None:
    """A frame given as a literal or as one of frame_helpers' constants."""
    if node is None:
        return None
    literal = string(node)
    if literal is not None:
        return literal if literal.isidentifier() else None
    return _FRAME_CONSTANTS.get(facts.qualified_name(node) or "")


def name_fact(name: str, frames: NameFrames) -> FrameFact:
    """What an `a_tform_b` name states: as strong as a declaration (the name says its direction)."""
    return FrameFact(frames, (f"name `{name}` {TFORM_EVIDENCE}",), True)


def in_tform_words(fact: FrameFact) -> bool:
    """Whether every statement the frames rest on is in the SDK's words (names, frame_helpers)."""
    return bool(fact.evidence) and all(item.endswith(TFORM_EVIDENCE) for item in fact.evidence)
