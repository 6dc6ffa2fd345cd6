"""The classes of a module a fact is about: the class around a node, the module's top-level classes
by name, the project class a called name is (of this module, or of a project module it imports), the
project class an object is an instance of (`receiver_class`) and the method a call on it runs
(`method_of`)."""

from __future__ import annotations

import ast
from ast import AST, AsyncFunctionDef, Attribute, Call, ClassDef, Constant, FunctionDef, Name
from collections import Counter
from typing import Final, TYPE_CHECKING

from geolint.factbase.index import ParamBinding

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase


def enclosing_class(facts: FactBase, node: AST) -> ClassDef | None:
    current = facts.parent(node)
    while current is not None and not isinstance(current, ClassDef):
        current = facts.parent(current)
    return current


def top_level_class(facts: FactBase, name: str) -> ClassDef | None:
    """The module's one top-level class of that name (None when there is none, or two)."""
    return top_level_classes(facts).get(name)


def top_level_classes(facts: FactBase) -> dict[str, ClassDef | None]:
    """The module's top-level classes by name; None for a name defined twice (read once per module)."""

    def find() -> dict[str, ClassDef | None]:
        classes = [node for node in facts.index.tree.body if isinstance(node, ClassDef)]
        counts = Counter(node.name for node in classes)
        return {node.name: node if counts[node.name] == 1 else None for node in classes}

    return facts.module_fact("top-level classes", find)


def called_project_class(facts: FactBase, func: ast.expr) -> tuple[FactBase, ClassDef] | None:
    """`project_class`, once per called name."""
    return facts.memoised("project class", func, lambda: project_class(facts, func))


def project_class(facts: FactBase, func: ast.expr) -> tuple[FactBase, ClassDef] | None:
    """The top-level class a called name is: of this module, or of the project module it is imported from."""
    if isinstance(func, Name):
        local = top_level_class(facts, func.id)
        if local is not None:
            return facts, local
        if func.id not in facts.index.imports:
            return None
    elif not isinstance(func, Attribute):
        return None
    if not facts.cross_module:
        return None
    found = facts.defining_module(facts.qualified_name(func) or "", facts.path)
    if found is None:
        return None
    other, name = found
    cls = top_level_class(other, name)
    return None if cls is None else (other, cls)


_MAX_BASES: Final = 4  # project base classes followed up from a class to the one that defines a method


def receiver_class(facts: FactBase, receiver: ast.expr) -> tuple[FactBase, ClassDef] | None:
    """The project class `receiver` is an instance of, when every binding says it: `self` in a method,
    `Cls(...)` itself, a name bound only to `Cls(...)`, a parameter annotated `Cls` (or `"Cls"`), `self.attr` stored only
    as `Cls(...)`. The class is a top-level class of this module or of the project module it is
    imported from; None when anything is unknown or two classes are possible."""
    if isinstance(receiver, Name) and receiver.id == "self":
        cls = enclosing_class(facts, receiver)
        return None if cls is None else (facts, cls)
    constructor: ast.expr | None = None
    if isinstance(receiver, Call):  # `Cls(...).method()`
        constructor = receiver.func
    elif isinstance(receiver, Name):
        bound = facts.bindings(receiver) or []
        if len(bound) != 1:
            return None
        binding = bound[0]
        if isinstance(binding, Call):
            constructor = binding.func
        elif isinstance(binding, ParamBinding):
            annotation = binding.arg.annotation
            if isinstance(annotation, Constant) and isinstance(annotation.value, str) and annotation.value.isidentifier():
                return _named_class(facts, annotation.value)
            constructor = annotation if isinstance(annotation, (Name, Attribute)) else None
    elif isinstance(receiver, Attribute) and isinstance(receiver.value, Name) and receiver.value.id == "self":
        stores = facts.index.self_attribute_stores.get(receiver.attr, [])
        if len(stores) == 1 and isinstance(stores[0], Call):
            constructor = stores[0].func
    if constructor is None:
        return None
    return called_project_class(facts, constructor)


def _named_class(facts: FactBase, name: str) -> tuple[FactBase, ClassDef] | None:
    """The project class a string annotation names (a forward reference of this module, or an import)."""
    local = top_level_class(facts, name)
    if local is not None:
        return facts, local
    imported = facts.index.imports.get(name)
    found = None if imported is None or not facts.cross_module else facts.defining_module(imported, facts.path)
    if found is None:
        return None
    cls = top_level_class(found[0], found[1])
    return None if cls is None else (found[0], cls)


_GETTERS: Final = frozenset({"property", "cached_property"})  # `@property`, `@functools.cached_property`


def method_of(facts: FactBase, cls: ClassDef, name: str, getter: bool = False) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
    """The plain method `name` an instance of `cls` (a class of `facts`' module) runs: defined once in
    the class, or else in the nearest project base class that defines it; with `getter`, the function
    a read of the property `name` runs instead. None for a static or class method, an overloaded
    name (a property with a setter included), or a base the project does not hold."""
    for _ in range(_MAX_BASES):
        defined = [node for node in cls.body if isinstance(node, (FunctionDef, AsyncFunctionDef)) and node.name == name]
        if defined:
            method = defined[0]
            if len(defined) != 1 or not (method.args.posonlyargs or method.args.args) or _is_getter(method) != getter:
                return None
            if method.decorator_list and not getter:
                return None
            return facts, method
        if len(cls.bases) != 1:
            return None  # no base, or several whose order of lookup would have to be followed
        found = called_project_class(facts, cls.bases[0])
        if found is None:
            return None
        facts, cls = found
    return None


def _is_getter(function: FunctionDef | AsyncFunctionDef) -> bool:
    """Decorated with `@property` / `@cached_property` alone."""
    if len(function.decorator_list) != 1:
        return False
    decorator = function.decorator_list[0]
    name = decorator.id if isinstance(decorator, Name) else decorator.attr if isinstance(decorator, Attribute) else None
    return name in _GETTERS
