"""Match a call in linted code to the overloads of an `Api`: which argument is which parameter, and
which overloads the call may be using.

A parameter annotated `Literal[...]` tells overloads apart: a constant argument picks the overloads
that accept it, an absent one the overloads that give it a default, and any other expression keeps
every overload it could be (decided at run time). Questions are then answered with `agreed`: an
answer counts only when every overload the call may be using gives the same one.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass
from typing import Callable, TypeVar

from geolint.knowledge.model import Api, Parameter, Signature

_Answer = TypeVar("_Answer")
_UNDECIDED = object()


@dataclass(frozen=True)
class Bound:
    """A call matched to one overload: parameter name -> the argument expression given for it."""

    signature: Signature
    arguments: dict[str, ast.expr]
    spread: ast.expr | None = None  # `f(*q)`: the one starred argument, spread over the positional parameters

    def argument(self, parameter: Parameter) -> ast.expr | None:
        return self.arguments.get(parameter.name)


def bind(api: Api, call: ast.Call, versions_hold: Callable[[str], bool] | None = None) -> list[Bound]:
    """The overloads `call` may be using, each with its arguments. `versions_hold(specifier)` says whether
    an overload's `@versions` holds for the project (default: only unversioned overloads count)."""
    found = []
    for signature in api.signatures:
        if signature.versions is not None and (versions_hold is None or not versions_hold(signature.versions)):
            continue
        bound = _bind_one(signature, call)
        if bound is not None:
            found.append(bound)
    return found


def agreed(bounds: list[Bound], question: Callable[[Bound], _Answer | None]) -> _Answer | None:
    """The one answer every candidate overload gives, or None (no candidate, or they differ)."""
    answers = {question(bound) for bound in bounds}  # type: ignore[misc]
    if len(answers) != 1:
        return None
    return answers.pop()


def _bind_one(signature: Signature, call: ast.Call) -> Bound | None:
    arguments: dict[str, ast.expr] = {}
    parameters = signature.parameters
    starred = [arg for arg in call.args if isinstance(arg, ast.Starred)]
    spread = None
    if starred:
        if len(call.args) != 1:
            return None  # `f(a, *rest)`: positions unknown
        if sum(1 for parameter in parameters if parameter.positional and not parameter.variadic) < 2 and not any(
            parameter.variadic for parameter in parameters
        ):
            return None  # `f(*q)` spreads components: an overload of one positional parameter is not it
        spread = starred[0].value
    else:
        positional = [parameter for parameter in parameters if parameter.positional]
        for index, value in enumerate(call.args):
            if index >= len(positional):
                return None
            parameter = positional[index]
            if parameter.variadic:
                break
            arguments[parameter.name] = value
    open_keywords = False
    for given in call.keywords:
        if given.arg is None:
            open_keywords = True  # `**options`
            continue
        parameter = signature.parameter(given.arg)
        if parameter is None or not parameter.keyword or given.arg in arguments:
            return None
        arguments[given.arg] = given.value
    for parameter in parameters:
        value = arguments.get(parameter.name)
        if value is None:
            if not parameter.has_default and not parameter.variadic and spread is None and not open_keywords:
                return None
            if parameter.literal is not None and not parameter.has_default and not open_keywords:
                return None
            continue
        if parameter.literal is not None:
            constant = _constant(value)
            if constant is not _UNDECIDED and constant not in parameter.literal:
                return None
    return Bound(signature, arguments, spread)


def _constant(node: ast.expr) -> object:
    if isinstance(node, ast.Constant):
        return node.value
    return _UNDECIDED
