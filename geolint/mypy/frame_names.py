"""Frame classes and string frames that name the same frame: ``class Optical(Frame, name="camera_optical")``
and ``"camera_optical"``; ``class World(Frame)`` and ``"World"``.

At runtime a frame *is* its name, so those pairs are one frame. Statically they are different types, and mypy's
own checks (an assignment, a return) keep them apart; the plugin's checks (``@``, ``+``, ``-``, ``is_close``,
generic calls) compare frames by name. The typing trick: a *base class hook* on ``Frame`` records the ``name=``
keyword in the class's plugin metadata, which mypy stores in its cache with the class, so a cached module
answers exactly like a freshly analyzed one.
"""

from __future__ import annotations

from mypy.nodes import StrExpr
from mypy.plugin import ClassDefContext
from mypy.types import Instance, LiteralType, ProperType

from geolint.mypy import fullnames as names

METADATA_KEY = "geolint"


def record_declared_name(ctx: ClassDefContext) -> None:
    """``class X(Frame, name="...")``: remember the declared name on the class."""
    declared = ctx.cls.keywords.get("name")
    if isinstance(declared, StrExpr):
        ctx.cls.info.metadata.setdefault(METADATA_KEY, {})["frame_name"] = declared.value


def frame_name(frame: ProperType) -> str | None:
    """The runtime name of a frame type: a string frame's text, a Frame class's declared name or class name."""
    if isinstance(frame, LiteralType) and isinstance(frame.value, str):
        return frame.value
    if isinstance(frame, Instance) and frame.type.has_base(names.FRAME) and frame.type.fullname != names.FRAME:
        declared = frame.type.metadata.get(METADATA_KEY, {}).get("frame_name")
        return declared if isinstance(declared, str) else frame.type.name
    return None
