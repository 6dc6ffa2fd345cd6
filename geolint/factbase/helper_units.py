"""Which arguments of a call to a project helper or class are read in an angle unit: a helper that
passes a parameter, unchanged and unconditionally, to an API reading that unit (through its
summary, `ANGLE_UNITS`), or names it in the unit; a class whose constructor stores a parameter for
a method that hands it to such an API (`constructor_reads`). GEO302 and GEO305 ask `helper_reads`."""

from __future__ import annotations

import ast
from ast import Assign, Attribute, BinOp, Call, ClassDef, FunctionDef, Load, Name, Starred, Subscript, UnaryOp
from typing import Final, TYPE_CHECKING

from geolint.factbase.angle_units import (
    ANGLE_UNITS,
    DEGREES,
    RADIANS,
    AngleSummary,
    AngleUnits,
    LibraryUnits,
    attribute_stores,
    unit_read_by,
    unit_word,
)
from geolint.factbase.classes import called_project_class, enclosing_class, top_level_class, top_level_classes
from geolint.factbase.control_flow import runs_unconditionally
from geolint.factbase.summaries import only_bound_as_parameter
from geolint.factbase.syntax import keyword, walk_within

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase


# the expressions `AngleUnits.unit_of` can know a unit of; for any other (a constant, a list, a
# comparison...) it is None, found without following anything
_MAY_HAVE_UNIT: Final = frozenset({UnaryOp, BinOp, Call, Name, Attribute, Subscript})


def helper_reads(facts: FactBase, call: Call, unit: str, units: AngleUnits | None = None) -> list[tuple[ast.expr, str, bool]]:
    """The arguments of a call to a project helper that passes them, unchanged and unconditionally,
    to an API reading `unit` (directly or through further helpers), or names its parameter in that
    unit, each with how it gets there and whether only a name says so; and the arguments of a
    project class's constructor that stores them for a method to read in `unit` (`constructor_reads`)."""
    args = call.args
    if args and facts.may_have_summary(call):
        if any(isinstance(arg, Starred) for arg in args):
            return []
        units = facts.shared(AngleUnits) if units is None else units
        other = RADIANS if unit == DEGREES else DEGREES
        if any(type(arg) in _MAY_HAVE_UNIT and (given := units.unit_of(arg)) is not None and given.unit == other for arg in args):
            summary = facts.summary_of(call, ANGLE_UNITS)
            if summary is not None:
                return _summary_reads(facts, call, unit, summary)
        return _class_reads(facts, call, unit, None)
    if not args and not call.keywords:
        return []
    func = call.func
    if type(func) is Name and func.id in top_level_classes(facts):  # type: ignore[attr-defined]
        local = top_level_class(facts, func.id)  # type: ignore[attr-defined]
        if local is None or not constructor_reads(facts, local)[1] or any(isinstance(arg, Starred) for arg in args):
            return []  # a class of this module whose constructor reads no unit
        return _class_reads(facts, call, unit, local)
    if not args and facts.may_have_summary(call):
        return _class_reads(facts, call, unit, None)
    return []


def _class_reads(facts: FactBase, call: Call, unit: str, local: ClassDef | None) -> list[tuple[ast.expr, str, bool]]:
    """`_constructor_reads_of` for a call of a class of this module (`local`) or, named in CapWords, of
    a project module, when an argument is in the other unit by this module's own evidence or a
    library's (asked before the class is looked up: not through a project helper's summary or another
    module's constant, which would read more modules)."""
    if local is None:
        if unit == RADIANS:
            return []  # a class of another module is asked for its degrees only (GEO305's files, which its trigger narrows)
        func = call.func
        name = func.id if isinstance(func, Name) else func.attr if isinstance(func, Attribute) else ""
        if not name[:1].isupper():
            return []  # a class is named in CapWords
    other = RADIANS if unit == DEGREES else DEGREES
    cheap = facts.shared(LibraryUnits)
    given = [*call.args, *(keyword.value for keyword in call.keywords if keyword.arg)]
    if not any((found := cheap.unit_of(arg)) is not None and found.unit == other for arg in given):
        return []
    return _constructor_reads_of(facts, call, unit, cheap)


def _summary_reads(facts: FactBase, call: Call, unit: str, summary: AngleSummary) -> list[tuple[ast.expr, str, bool]]:
    helper = facts.code_of(call.func)
    found = []
    for index, (read, where, by_name) in sorted(summary.reads_unit.items()):
        if read == unit and index < len(call.args):
            parameter = summary.parameters[index]
            if by_name and not where:
                how = f"`{helper}` names its parameter `{parameter}` in {unit_word(unit)}"
            else:
                how = f"`{helper}` passes its parameter `{parameter}` to {where}, which reads {unit_word(unit)}"
            found.append((call.args[index], how, by_name))
    return found


def _constructor_reads_of(facts: FactBase, call: Call, unit: str, units: AngleUnits) -> list[tuple[ast.expr, str, bool]]:
    """The arguments of a project class's constructor call that it reads in `unit` (`constructor_reads`),
    when one of them is in the other unit: the class first (its module is one the call's kind already
    asked for), the arguments' units only for the parameters it reads."""
    located = called_project_class(facts, call.func)
    if located is None:
        return []
    other, cls = located
    parameters, reads = constructor_reads(other, cls)
    if not reads:
        return []
    wrong = RADIANS if unit == DEGREES else DEGREES
    found = []
    for index, (read, where) in sorted(reads.items()):
        if read != unit:
            continue
        parameter = parameters[index]
        if index < len(call.args):
            argument: ast.expr | None = call.args[index]
        else:
            argument = getattr(keyword(call, parameter), "value", None)
        given = None if argument is None else units.unit_of(argument)
        if argument is not None and given is not None and given.unit == wrong:
            how = f"`{facts.code_of(call.func)}` stores its parameter `{parameter}` for {where}, which reads {unit_word(unit)}"
            found.append((argument, how, False))
    return found


def constructor_reads(facts: FactBase, cls: ClassDef) -> tuple[tuple[str, ...], dict[int, tuple[str, str]]]:
    """What a class's constructor reads its parameters in: `__init__`'s parameters (without `self`) and,
    by index, the unit and where, for a parameter stored as it is (`self.yaw = yaw`, the class's only
    store of `self.yaw`, unconditionally in `__init__`) that a method of the class hands unconditionally
    to an API reading a unit (`np.radians(self.yaw)`, `carla.Rotation(self.pitch, ...)`), or that
    `__init__` itself hands to one. Read in both units: nothing."""
    return facts.memoised("constructor reads", cls, lambda: _constructor_reads(facts, cls))


def _constructor_reads(facts: FactBase, cls: ClassDef) -> tuple[tuple[str, ...], dict[int, tuple[str, str]]]:
    init = next((node for node in cls.body if isinstance(node, FunctionDef) and node.name == "__init__"), None)
    if init is None or init.decorator_list:
        return (), {}
    every = (*init.args.posonlyargs, *init.args.args)
    if not every:
        return (), {}
    parameters = tuple(arg.arg for arg in every[1:])
    scope = facts.index.scopes.get(init)
    if scope is None or not parameters:
        return parameters, {}
    plain = {name for name in parameters if only_bound_as_parameter(scope, name)}
    loads, stores = _self_attributes(facts)
    held, direct = _parameters_stored_and_read(facts, cls, init, parameters, plain, stores)
    found: dict[int, tuple[str, str]] = {}
    conflicting: set[int] = set()
    for attr, index in held.items():
        for node in loads.get(attr, ()):
            call = facts.parent(node)
            if isinstance(call, (ast.List, ast.Tuple, ast.keyword)):
                call = facts.parent(call)  # `from_euler("xyz", [self.roll, ...], degrees=True)`, `Rotation(yaw=self.yaw)`
            if not isinstance(call, Call) or enclosing_class(facts, node) is not cls:
                continue
            read = unit_read_by(facts, call, node)
            if read is not None:
                method = facts.index.scope_of(node).node
                _add_read(found, conflicting, index, read, f"`{facts.code_of(call.func)}` (as `self.{attr}`, in `{getattr(method, 'name', '?')}`)")
    for call, argument in direct:
        read = unit_read_by(facts, call, argument)
        if read is not None:
            _add_read(found, conflicting, parameters.index(argument.id), read, f"`{facts.code_of(call.func)}` (in `__init__`)")
    return parameters, {index: value for index, value in found.items() if index not in conflicting}


def _parameters_stored_and_read(
    facts: FactBase, cls: ClassDef, init: FunctionDef, parameters: tuple[str, ...], plain: set[str], stores: dict[str, list[Attribute]]
) -> tuple[dict[str, int], list[tuple[Call, Name]]]:
    """What `__init__` does with its plain parameters: `self.<attr> = <parameter>` as the class's one store
    of `self.attr`, unconditionally (attr -> the parameter's index), and the calls that read one
    directly (`np.radians(yaw)` in `__init__` itself)."""
    held: dict[str, int] = {}
    direct: list[tuple[Call, Name]] = []
    for node in walk_within(init):
        if isinstance(node, Call):
            direct.extend((node, arg) for arg in node.args if isinstance(arg, Name) and arg.id in plain)
            continue
        if not (isinstance(node, Assign) and len(node.targets) == 1 and isinstance(node.value, Name) and node.value.id in plain):
            continue
        target = node.targets[0]
        if not (isinstance(target, Attribute) and isinstance(target.value, Name) and target.value.id == "self"):
            continue
        if [store for store in stores.get(target.attr, ()) if enclosing_class(facts, store) is cls] == [target] and runs_unconditionally(facts, node.value):
            held[target.attr] = parameters.index(node.value.id)
    return held, direct


def _add_read(found: dict[int, tuple[str, str]], conflicting: set[int], index: int, unit: str, where: str) -> None:
    """Record that parameter `index` is read in `unit` (read in both units: a conflict, nothing known)."""
    known = found.get(index)
    if known is None:
        found[index] = (unit, where)
    elif known[0] != unit:
        conflicting.add(index)


def _self_attributes(facts: FactBase) -> tuple[dict[str, list[Attribute]], dict[str, list[Attribute]]]:
    """The module's reads and its stores (or deletions) of `self.<attr>`, by attribute name; with a
    `setattr` of a computed name anywhere, every attribute counts as stored once more."""

    def collect() -> tuple[dict[str, list[Attribute]], dict[str, list[Attribute]]]:
        loads: dict[str, list[Attribute]] = {}
        stores: dict[str, list[Attribute]] = {}
        for node in facts.index.nodes(Attribute):
            if isinstance(node.value, Name) and node.value.id == "self":  # type: ignore[attr-defined]
                (loads if isinstance(node.ctx, Load) else stores).setdefault(node.attr, []).append(node)  # type: ignore[attr-defined,arg-type]
        if "setattr" in facts.index.source and (attribute_stores(facts)["*"] or any(count >= 1 << 20 for count in attribute_stores(facts).values())):
            stores = {attr: [*found, *found] for attr, found in stores.items()}  # `setattr(self, key, value)`: anything
        return loads, stores

    return facts.module_fact("self attributes", collect)
