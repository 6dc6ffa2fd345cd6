"""Methods of the runtime values whose stubs cannot say what the plugin knows: ``batch[i]`` keeps the kind and
frame of the batch, and ``p.is_close(q)`` across kinds or frames is always False (so it is an error)."""

from __future__ import annotations

from mypy.plugin import MethodContext
from mypy.types import Type

from geolint.mypy import geometry, messages
from geolint.mypy.errorcodes import GEO_FRAME, GEO_KIND


def batch_item(ctx: MethodContext) -> Type:
    """``batch[i]`` / ``batch[i:j]`` of a ``Point[F]`` batch is a ``Point[F]`` (the runtime's __getitem__ says Any)."""
    if geometry.read(ctx.type) is None:
        return ctx.default_return_type
    return ctx.type


def is_close(ctx: MethodContext) -> Type:
    """``p.is_close(q)``: the runtime answers False whenever the kinds or the frames differ; say so statically."""
    receiver = geometry.read(ctx.type)
    other = geometry.read(ctx.arg_types[0][0]) if ctx.arg_types and len(ctx.arg_types[0]) == 1 else None
    if receiver is None or other is None or receiver.family != other.family:
        return ctx.default_return_type
    if receiver.kind != other.kind:
        ctx.api.fail(messages.compared_across(receiver, other), ctx.context, code=GEO_KIND)
    elif geometry.same_frame(receiver.frame, other.frame) is False:
        ctx.api.fail(messages.compared_across(receiver, other), ctx.context, code=GEO_FRAME)
    return ctx.default_return_type
