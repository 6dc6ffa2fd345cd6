"""The two steps every checking hook ends with: report the problem, return the inferred type."""

from __future__ import annotations

from mypy.plugin import FunctionContext, MethodContext
from mypy.types import Type

from geolint.mypy import geometry
from geolint.mypy.algebra import Outcome


def report_and_build(ctx: FunctionContext | MethodContext, outcome: Outcome | None) -> Type:
    """Report `outcome`'s problem at the call under its geolint code; return its result type (or mypy's)."""
    if outcome is None:
        return ctx.default_return_type
    if outcome.problem is not None:
        ctx.api.fail(outcome.problem.message, ctx.context, code=outcome.problem.code)
    if outcome.result is None:
        return ctx.default_return_type
    return geometry.build(ctx.api, outcome.result) or ctx.default_return_type
