"""The summaries of what a helper does to kinds: the kind it returns (`KINDS`: `load_normals()` returns
directions), the w it appends to a parameter it returns (`HOMOGENEOUS`: `to_homogeneous(x)`), and the
parameters it rotates and translates (`TRANSLATION`: `apply_pose(T, x)`, GEO101's helper evidence).
Each is a family of `geolint.factbase.summaries`, computed only when asked."""

from __future__ import annotations

import ast
from ast import AST, Add, BinOp, Call, Name
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Final

from geolint.algebra import FREE, Kind, marked_by_w
from geolint.factbase.fact_types import GEOMETRIC
from geolint.factbase.summaries import Function, Summary, SummaryFamily, chain, plain_parameters, settled_returns, shifted
from geolint.factbase.syntax import positional_args, transposed_value, walk_within

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase


@dataclass
class KindSummary(Summary):
    returns: Kind | None = None  # the kind every `return` agrees on


@dataclass
class HomogeneousSummary(Summary):
    # parameter index -> w, when the function returns that parameter made homogeneous
    homogenizes: dict[int, int] = field(default_factory=dict)


@dataclass
class TranslationSummary(Summary):
    # parameters the function moves by a rotation AND a translation (`R @ x + t`, or a helper that does)
    translates: set[int] = field(default_factory=set)
    # parameter index -> the helper chain that translates it, when that is not this function's own code
    translates_through: dict[int, str] = field(default_factory=dict)


def _returned_kind(facts: FactBase, function: Function, params: tuple[str, ...]) -> KindSummary:
    summary = KindSummary(parameters=params)
    scope = facts.index.scopes.get(function)
    if scope is None:
        return summary
    kinds = {facts.kind_of(value) for value in settled_returns(facts, scope, KINDS)}
    if len(kinds) == 1:
        summary.returns = kinds.pop()
    return summary


def _returned_homogeneous(facts: FactBase, function: Function, params: tuple[str, ...]) -> HomogeneousSummary:
    summary = HomogeneousSummary(parameters=params)
    scope = facts.index.scopes.get(function)
    if scope is None:
        return summary
    plain = plain_parameters(scope, params)
    for value in settled_returns(facts, scope, HOMOGENEOUS):
        homogeneous = facts.homogeneous(value)
        if homogeneous is not None and isinstance(homogeneous.inner, Name) and homogeneous.inner.id in params:
            summary.homogenizes[params.index(homogeneous.inner.id)] = homogeneous.w
        elif isinstance(value, Call) and facts.may_have_summary(value):
            # `return to_homogeneous(x)`: the callee's w, on our parameter
            callee = facts.summary_of(value, HOMOGENEOUS)
            arguments = positional_args(value)
            for index, w in (callee.homogenizes.items() if callee is not None else ()):
                argument = arguments[index] if index < len(arguments) else None
                if isinstance(argument, Name) and argument.id in plain:
                    summary.homogenizes.setdefault(params.index(argument.id), w)
    return summary


def _translated_parameters(facts: FactBase, function: Function, params: tuple[str, ...]) -> TranslationSummary:
    summary = TranslationSummary(parameters=params)
    scope = facts.index.scopes.get(function)
    if scope is None:
        return summary
    plain = plain_parameters(scope, params)
    for node in walk_within(function):
        if isinstance(node, Call) and node.args:
            _record_translating_call(facts, node, positional_args(node), params, plain, summary)
        if isinstance(node, (BinOp, Call)):
            _record_homogeneous_product(facts, node, plain, summary)
        if isinstance(node, Call):
            continue
        # `R @ x + t` (or row form `x @ R.T + t`) on a parameter x
        if not isinstance(node, BinOp) or not isinstance(node.op, Add):
            continue
        for rotated, other in ((node.left, node.right), (node.right, node.left)):
            inner = transposed_value(rotated) or rotated
            product = facts.matmul(inner)
            if product is None or not facts.is_translation_like(other):
                continue
            for operand in (product.left, product.right):
                operand = transposed_value(operand) or operand
                if isinstance(operand, Name) and operand.id in params and facts.kind_of(operand) not in FREE:
                    operator = product.right if operand is product.left else product.left
                    if facts.kind_of(operator) not in (Kind.POINT, Kind.VECTOR, Kind.DIRECTION):
                        summary.translates.add(params.index(operand.id))
    return summary


def _record_translating_call(
    facts: FactBase, call: Call, arguments: list[ast.expr], params: tuple[str, ...], plain: set[str], summary: TranslationSummary
) -> None:
    """A project helper that translates one of the function's own parameters (`apply_pose(T, x)`)."""
    passed = {index: params.index(arg.id) for index, arg in enumerate(arguments) if isinstance(arg, Name) and arg.id in plain}
    if not passed or not facts.may_have_summary(call):
        return
    callee = facts.summary_of(call, TRANSLATION)
    if callee is None:
        return
    for index in callee.translates:
        if index in passed and facts.kind_of(arguments[index]) not in FREE:
            own = passed[index]
            if own not in summary.translates:
                summary.translates.add(own)
                through = callee.translates_through.get(index)
                summary.translates_through[own] = chain(f"`{facts.code_of(call.func)}`", through)


def _record_homogeneous_product(facts: FactBase, node: AST, plain: set[str], summary: TranslationSummary) -> None:
    """`T @ to_homogeneous(x).T`, `np.hstack([x, ones]) @ T.T`: a parameter given the w that marks a point
    (`algebra.marked_by_w`: 1) and multiplied by an operator is translated along with the rotation."""
    product = facts.matmul(node)
    if product is None:
        return
    for operand, operator in ((product.left, product.right), (product.right, product.left)):
        homogeneous = facts.homogeneous(transposed_value(operand) or operand)
        if homogeneous is None or marked_by_w(homogeneous.w) != Kind.POINT or not isinstance(homogeneous.inner, Name):
            continue
        name = homogeneous.inner.id
        if name in plain and facts.kind_of(homogeneous.inner) not in FREE and facts.kind_of(operator) not in GEOMETRIC:
            summary.translates.add(summary.parameters.index(name))


def _bound_kind(summary: KindSummary) -> KindSummary:
    return KindSummary(parameters=summary.parameters[1:], returns=summary.returns, pending=summary.pending)


def _bound_homogeneous(summary: HomogeneousSummary) -> HomogeneousSummary:
    return HomogeneousSummary(parameters=summary.parameters[1:], homogenizes=shifted(summary.homogenizes), pending=summary.pending)


def _bound_translation(summary: TranslationSummary) -> TranslationSummary:
    return TranslationSummary(
        parameters=summary.parameters[1:],
        translates={index - 1 for index in summary.translates if index > 0},
        translates_through=shifted(summary.translates_through),
        pending=summary.pending,
    )


KINDS: Final = SummaryFamily("kind", KindSummary, _returned_kind, _bound_kind)
HOMOGENEOUS: Final = SummaryFamily("homogeneous", HomogeneousSummary, _returned_homogeneous, _bound_homogeneous)
TRANSLATION: Final = SummaryFamily("translation", TranslationSummary, _translated_parameters, _bound_translation)
