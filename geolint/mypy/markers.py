"""``as_points(array, "camera")``, ``Transform.identity("camera")``: calls that name frames with strings.

The markers' overloads infer the frame from a Frame class (``type[F]``); a string argument would infer only
``str``. This function hook replaces each frame that was passed as a string literal by ``Literal["..."]``,
the same type a ``PointArray["camera"]`` annotation gets, so the two spellings meet.
"""

from __future__ import annotations

from mypy.nodes import StrExpr
from mypy.plugin import FunctionContext, MethodContext
from mypy.types import Instance, LiteralType, Type, get_proper_type


def mark(ctx: FunctionContext) -> Type:
    returned = get_proper_type(ctx.default_return_type)
    if not isinstance(returned, Instance):
        return ctx.default_return_type
    frame_args = ctx.args[1:]
    if len(frame_args) != len(returned.args):
        return ctx.default_return_type
    string_type = ctx.api.named_generic_type("builtins.str", [])
    frames: list[Type] = []
    for inferred, exprs in zip(returned.args, frame_args):
        if len(exprs) == 1 and isinstance(exprs[0], StrExpr):
            frames.append(LiteralType(exprs[0].value, string_type))
        else:
            frames.append(inferred)
    return returned.copy_modified(args=frames)


def identity(ctx: MethodContext) -> Type:
    """``Transform.identity("camera")`` is a ``Transform["camera", "camera"]`` (the overload says Any, Any)."""
    returned = get_proper_type(ctx.default_return_type)
    if not (isinstance(returned, Instance) and ctx.args and len(ctx.args[0]) == 1):
        return ctx.default_return_type
    frame = ctx.args[0][0]
    if not isinstance(frame, StrExpr):
        return ctx.default_return_type
    literal = LiteralType(frame.value, ctx.api.named_generic_type("builtins.str", []))
    return returned.copy_modified(args=[literal] * len(returned.args))
