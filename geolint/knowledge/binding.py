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
from typing import Any, Callable, TypeVar

from geolint.knowledge.model import Api, Parameter, Signature

_Answer = TypeVar("_Answer")
UNDECIDED = object()  # an argument whose value is known only at run time


@dataclass(frozen=True)
class Bound:
    """A call matched to one overload: parameter name -> the argument given for it (an `ast` node for
    the linter, a mypy expression for the plugin)."""

    signature: Signature
    arguments: dict[str, Any]
    spread: Any = None  # `f(*q)`: the one starred argument, spread over the positional parameters

    def argument(self, parameter: Parameter) -> Any:
        return self.arguments.get(parameter.name)


@dataclass(frozen=True)
class CallShape:
    """A call as the binder needs it, whichever tree it comes from."""

    positional: list[Any]
    keywords: dict[str, Any]
    spread: Any = None  # the one starred argument of `f(*q)`
    open_keywords: bool = False  # `f(**options)`
    unknown_positions: bool = False  # `f(a, *rest)`: which argument is which is unknown


def bind(api: Api, call: ast.Call, versions_hold: Callable[[str], bool] | None = None) -> list[Bound]:
    """The overloads `call` may be using, each with its arguments. `versions_hold(specifier)` says whether
    an overload's `@versions` holds for the project (default: only unversioned overloads count)."""
    return bind_shape(api, shape_of(call), _ast_constant, versions_hold)


def bind_shape(
    api: Api, shape: CallShape, constant: Callable[[Any], object], versions_hold: Callable[[str], bool] | None = None
) -> list[Bound]:
    """`bind` for a call of any tree: `constant(argument)` is the argument's literal value, or `UNDECIDED`."""
    if shape.unknown_positions:
        return []
    found = []
    for signature in api.signatures:
        if signature.versions is not None and (versions_hold is None or not versions_hold(signature.versions)):
            continue
        bound = _bind_one(signature, shape, constant)
        if bound is not None:
            found.append(bound)
    return found


def shape_of(call: ast.Call) -> CallShape:
    starred = [arg for arg in call.args if isinstance(arg, ast.Starred)]
    keywords = {given.arg: given.value for given in call.keywords if given.arg is not None}
    open_keywords = any(given.arg is None for given in call.keywords)
    if starred:
        if len(call.args) != 1:
            return CallShape([], keywords, unknown_positions=True)
        return CallShape([], keywords, spread=starred[0].value, open_keywords=open_keywords)
    return CallShape(list(call.args), keywords, open_keywords=open_keywords)


def agreed(bounds: list[Bound], question: Callable[[Bound], _Answer | None]) -> _Answer | None:
    """The one answer every candidate overload gives, or None (no candidate, or they differ)."""
    answers = {question(bound) for bound in bounds}  # type: ignore[misc]
    if len(answers) != 1:
        return None
    return answers.pop()


def _bind_one(signature: Signature, shape: CallShape, constant: Callable[[Any], object]) -> Bound | None:
    arguments: dict[str, Any] = {}
    parameters = signature.parameters
    spread = shape.spread
    if spread is not None:
        if sum(1 for parameter in parameters if parameter.positional and not parameter.variadic) < 2 and not any(
            parameter.variadic and parameter.positional for parameter in parameters
        ):
            return None  # `f(*q)` spreads components: an overload of one positional parameter is not it
    else:
        positional = [parameter for parameter in parameters if parameter.positional]
        for index, value in enumerate(shape.positional):
            if index >= len(positional):
                return None
            parameter = positional[index]
            if parameter.variadic:
                break
            arguments[parameter.name] = value
    any_keyword = any(parameter.variadic and parameter.keyword for parameter in parameters)
    for name, value in shape.keywords.items():
        named = signature.parameter(name)
        if named is None and any_keyword:
            continue
        if named is None or not named.keyword or name in arguments:
            return None
        arguments[name] = value
    open_keywords = shape.open_keywords
    for parameter in parameters:
        value = arguments.get(parameter.name)
        if value is None:
            if not parameter.has_default and not parameter.variadic and spread is None and not open_keywords:
                return None
            if parameter.literal is not None and not parameter.has_default and not open_keywords:
                return None
            continue
        if parameter.literal is not None:
            literal = constant(value)
            if literal is not UNDECIDED and literal not in parameter.literal:
                return None
    return Bound(signature, arguments, spread)


def _ast_constant(node: ast.expr) -> object:
    return node.value if isinstance(node, ast.Constant) else UNDECIDED
