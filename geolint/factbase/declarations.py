"""The frames a call states in so many words: `from_frame=` / `to_frame=` keywords (autolab_core's
`RigidTransform`), `.as_frames(from, to)`, tf2's `lookup_transform(target, source, t)`."""

from __future__ import annotations

from ast import Attribute, Call

from geolint.factbase.syntax import keyword, string
from geolint.semantic.names import NameFrames


def declared_call_frames(call: Call) -> tuple[NameFrames, str] | None:
    """The frames a call states in so many words, and how it states them."""
    from_kw, to_kw = keyword(call, "from_frame"), keyword(call, "to_frame")
    source, target = string(from_kw.value) if from_kw else None, string(to_kw.value) if to_kw else None
    if source and target:
        return NameFrames(dst=target.lower(), src=source.lower(), operator="transform"), f"from_frame={source!r}, to_frame={target!r}"
    func = call.func
    if isinstance(func, Attribute) and func.attr == "as_frames" and len(call.args) >= 2:
        source, target = string(call.args[0]), string(call.args[1])
        if source and target:
            return NameFrames(dst=target.lower(), src=source.lower(), operator="transform"), f".as_frames({source!r}, {target!r})"
    if isinstance(func, Attribute) and func.attr in ("lookup_transform", "lookupTransform") and len(call.args) >= 2:
        target, source = string(call.args[0]), string(call.args[1])
        if source and target:
            return NameFrames(dst=target.strip("/").lower(), src=source.strip("/").lower(), operator="transform"), f"{func.attr}({target!r}, {source!r})"
    return None
