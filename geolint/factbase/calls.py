"""Which project function a call runs (of this module, or of a project module it imports, through
aliases, relative imports, star imports and package `__init__` re-exports), and what its summary says
(`summary_of`, one family at a time)."""

from __future__ import annotations

import ast
from ast import AsyncFunctionDef, Attribute, Call, ClassDef, FunctionDef, Name
import builtins
from typing import Final, TYPE_CHECKING, TypeVar

from geolint.factbase import summaries
from geolint.factbase import vocabulary as vocab
from geolint.factbase.classes import method_of, receiver_class
from geolint.factbase.project_files import may_be_project_import, module_file
from geolint.factbase.summaries import Summary, SummaryFamily
from geolint.factbase.syntax import dotted_name

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

_S = TypeVar("_S", bound=Summary)  # a family's summary

_MAX_REEXPORTS: Final = 3  # package `__init__` modules followed to the module that defines a helper

_BUILTIN_NAMES: Final = frozenset(dir(builtins))  # `len(x)` under a star import: the builtin, in all but odd code


def may_have_summary(facts: FactBase, call: Call) -> bool:
    """A cheap test: whether the callee can be a function of this module or of a project module."""
    func = call.func
    if type(func) is Name:
        if func.id in facts.index.functions:
            return True
    elif type(func) is Attribute and _may_be_instance(facts, func.value):  # type: ignore[attr-defined]
        if func.attr in facts.index.methods:  # type: ignore[attr-defined]
            return True
        return facts.cross_module and bound_method(facts, call) is not None
    if not facts.cross_module:
        return False
    root = func
    while type(root) is Attribute:
        root = root.value  # type: ignore[attr-defined]
    if type(root) is not Name:
        return False
    imported = facts.index.imports.get(root.id)  # type: ignore[attr-defined]
    if imported is None:
        return root is func and bool(facts.index.star_imports) and _star_imported_callee(facts, func) is not None  # type: ignore[arg-type]
    # `from numpy import array` then `array(x)`: a third-party function has no summary either,
    # nor one of a package the project's folders do not hold (`gym.make`, `time.sleep`)
    return may_be_project_import(imported, facts.path)


def summary_of(facts: FactBase, call: Call, family: SummaryFamily[_S]) -> _S | None:
    """What the called helper does, as far as `family` asks (`KINDS`, `ANGLE_UNITS`...): a function of
    this module, or of a project module it imports. Only the families asked are computed."""
    return facts.cached("summary", call, _summary_of_call, family.tag)  # type: ignore[return-value]


def summary_of_property(facts: FactBase, read: Attribute, family: SummaryFamily[_S]) -> _S | None:
    """What reading a property of a project class returns (`robot.pose` runs the class's `@property`
    getter), as far as `family` asks: a call of the getter with nothing but `self`."""
    getter = property_getter(facts, read)
    if getter is None:
        return None
    summary = facts.project.summary(getter[0], getter[1], family)
    return None if summary is None else family.bound(summary)


def property_getter(facts: FactBase, read: Attribute) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
    """The `@property` getter `obj.attr` runs, when `obj` is known to be an instance of a project class
    (`receiver_class`) that defines it (or inherits it from a project base); else None."""
    if not _may_be_instance(facts, read.value) or (read.attr not in facts.index.methods and not facts.cross_module):
        return None

    def find() -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
        found = receiver_class(facts, read.value)
        return None if found is None else method_of(found[0], found[1], read.attr, getter=True)

    return facts.memoised("property getter", read, find)


def _summary_of_call(facts: FactBase, call: Call, tag: str) -> Summary | None:
    family = summaries.family_of(tag)
    found = called_function(facts, call)
    if found is not None:
        return facts.project.summary(found[0], found[1], family)
    method = bound_method(facts, call)
    if method is None:
        return None
    summary = facts.project.summary(method[0], method[1], family)
    return None if summary is None else family.bound(summary)


def _may_be_instance(facts: FactBase, receiver: ast.expr) -> bool:
    """`self`, `self.attr`, a name that no import binds or `Name(...)`: a receiver `receiver_class` may know."""
    if type(receiver) is Name:
        return receiver.id == "self" or receiver.id not in facts.index.imports  # type: ignore[attr-defined]
    if type(receiver) is Call:
        return type(receiver.func) in (Name, Attribute)  # type: ignore[attr-defined]
    return type(receiver) is Attribute and type(receiver.value) is Name and receiver.value.id == "self"  # type: ignore[attr-defined]


def bound_method(facts: FactBase, call: Call) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
    """For `obj.method(...)`: the plain method it runs, when `obj` is known to be an instance of a
    project class (`receiver_class`: `self`, `Cls(...)`, a parameter annotated `Cls`), defined in
    that class or inherited from a project base; else None."""

    def find() -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
        func = call.func
        if not isinstance(func, Attribute):
            return None
        found = receiver_class(facts, func.value)
        return None if found is None else method_of(found[0], found[1], func.attr)

    return facts.memoised("bound method", call, find)


def own_method(facts: FactBase, call: Call) -> FunctionDef | AsyncFunctionDef | None:
    """For `self.helper(...)` inside a method: the one `helper` of the same class, when it takes
    `self` (not a static or class method); else None."""
    func = call.func
    if not (isinstance(func, Attribute) and isinstance(func.value, Name) and func.value.id == "self"):
        return None
    candidates = facts.index.methods.get(func.attr, [])
    if not candidates:
        return None
    enclosing = facts.parent(call)
    while enclosing is not None and not isinstance(enclosing, ClassDef):
        enclosing = facts.parent(enclosing)
    if enclosing is None:
        return None
    own = [method for method in candidates if facts.parent(method) is enclosing]
    if len(own) != 1 or own[0].decorator_list or not (own[0].args.posonlyargs or own[0].args.args):
        return None  # overloads, properties, static/class methods: no plain bound method
    return own[0]


def called_function(facts: FactBase, call: Call) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
    """The project function a call runs (of this module, or of a project module it imports,
    through aliases, relative imports and package `__init__` re-exports) and the fact base of
    the module that defines it."""
    if not may_have_summary(facts, call):
        return None
    func = call.func
    if isinstance(func, Name) and func.id in facts.index.functions:
        return facts, facts.index.functions[func.id]
    if not facts.cross_module:
        return None
    head = func.id if isinstance(func, Name) else dotted_name(func)
    if head is None:
        return None
    if head.split(".")[0] not in facts.index.imports:
        return _star_imported_callee(facts, func) if isinstance(func, Name) else None
    return _imported_function(facts, facts.qualified_name(func) or "", facts.path)


def _star_imported_callee(facts: FactBase, func: Name) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
    """`star_imported_function` for a called name that no scope around the call binds."""
    return None if facts.index.lookup(func.id, facts.index.scope_of(func)) else star_imported_function(facts, func.id)


def star_imported_function(facts: FactBase, name: str) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
    """The project function a module-level `name` is when the module neither binds nor imports it
    there and exactly one of its star imports of project modules (`from ..collision import *`)
    defines it."""
    if not facts.cross_module or name in _BUILTIN_NAMES or name in facts.index.imports or name in facts.index.scopes[facts.index.tree].bindings:
        return None

    def find() -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
        found = [defined for module in facts.index.star_imports if (defined := _imported_function(facts, f"{module}.{name}", facts.path)) is not None]
        return found[0] if len(found) == 1 else None

    return facts.module_fact(f"star-imported function {name}", find)


def _imported_function(facts: FactBase, qualified: str, importer: str) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
    for _ in range(_MAX_REEXPORTS):
        found = defining_module(facts, qualified, importer)
        if found is None:
            return None
        other, name = found
        if name in other.index.functions:
            return other, other.index.functions[name]
        qualified = other.index.imports.get(name, "")  # `from .points import to_h` in a package's __init__
        importer = other.path
    return None


def defining_module(facts: FactBase, qualified: str, importer: str) -> tuple[FactBase, str] | None:
    """For `pkg.mod.name` (or `.mod.name`) imported by `importer`: the fact base of the project module
    `pkg.mod` and `name`; None for a third-party or unresolved module."""
    module, _, name = qualified.rpartition(".")
    if not module.strip(".") or not name or vocab.is_third_party_root(module.lstrip(".").split(".")[0]):
        return None
    level = len(module) - len(module.lstrip("."))
    file = module_file(module.lstrip("."), importer, level)
    other = None if file is None else facts.project.facts_of(file)
    return None if other is None else (other, name)
