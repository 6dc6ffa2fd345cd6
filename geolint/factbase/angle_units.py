"""Which unit an angle expression is in, from what the code says about it.

GEO302 (degrees passed as radians) and GEO305 (radians passed as degrees) ask `unit_of(x)`:
"deg" or "rad" with the evidence, or None. Evidence, strongest first:

- a call that returns the unit: `np.degrees(x)` / `np.rad2deg(x)` (degrees), `np.arctan2(y, x)`,
  `math.acos(c)`, `np.radians(x)` / `np.deg2rad(x)` (radians), scipy `as_euler(seq)` (radians,
  degrees with `degrees=True`);
- `np.pi` (times or over a number);
- a name or attribute whose words say it: `yaw_deg`, `fov_degrees`, `angleDeg`; `theta_rad`,
  `roll_radians`;
- a constant bound once to a literal that is no plausible angle in radians but one in degrees
  (`PHI = 73.17`, `self.tilt = 30` in `__init__`, a class attribute, a module constant of another
  project module, an attribute of an instance of a project class): degrees;
- arithmetic that keeps the unit: `-x`, `x / 2`, `x * 0.5`, `a + b` when both sides agree.

Names are followed through their bindings in the same scope (every binding must agree with the
name itself); any conflict gives None.
"""

from __future__ import annotations

import ast
import math
import re
from ast import (
    AST,
    Add,
    Attribute,
    BinOp,
    Call,
    ClassDef,
    Constant,
    Div,
    Global,
    Load,
    Mult,
    Name,
    Sub,
    Subscript,
    UAdd,
    UnaryOp,
    USub,
)
from collections import Counter
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Final

from geolint import knowledge
from geolint.factbase import library_calls
from geolint.factbase.angles import (
    DEGREES,
    EULER_METHOD_NAMES,
    RADIANS,
    RETURNED_EULER_METHODS,
)
from geolint.factbase.classes import enclosing_class, project_class, receiver_class
from geolint.factbase.control_flow import runs_unconditionally
from geolint.factbase.index import ParamBinding, Scope, UnpackBinding, module_constant
from geolint.factbase.memo import NodeMemo
from geolint.factbase.rotations import TRIG_FUNCTIONS
from geolint.factbase.summaries import (
    Function,
    Summary,
    SummaryFamily,
    agreed,
    chain,
    plain_parameters,
    settled_returns,
    shifted,
)
from geolint.factbase.syntax import (
    keyword,
    number,
    positional_args,
    string,
    walk_within,
)

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

_DEGREE_WORDS: Final = frozenset({"deg", "degs", "degree", "degrees"})
_RADIAN_WORDS: Final = frozenset({"rad", "rads", "radian", "radians"})
# words that turn a unit word into something else (`deg_per_s` is a rate, `rad2deg` a factor)
_NOT_AN_ANGLE: Final = frozenset({"per", "to", "s", "sec", "rate", "vel", "velocity", "speed", "factor", "scale", "step", "tol", "thresh", "threshold", "eps", "err", "error", "std", "sigma", "noise"})
_TO_DEGREES: Final = frozenset({"degrees", "rad2deg"})
_TO_RADIANS: Final = frozenset({"radians", "deg2rad"})
_CONVERSIONS: Final = _TO_DEGREES | _TO_RADIANS  # the names a conversion has (a cheap test before its stub is asked)
_INVERSE_TRIG: Final = frozenset({"arctan2", "arctan", "arcsin", "arccos", "atan2", "atan", "asin", "acos"})
_MAX_DEPTH: Final = 10
_TWO_PI: Final = 2 * math.pi
# The names `radian_arguments` knows without the knowledge base (whose own names it asks for).
_RADIAN_API_NAMES: Final = frozenset({"from_euler", "from_rotvec", *TRIG_FUNCTIONS, "degrees", "rad2deg"})
_KNOWLEDGE_UNITS: Final = {knowledge.RADIANS: RADIANS, knowledge.DEGREES: DEGREES}  # the stubs' unit words -> these


@dataclass(frozen=True)
class Unit:
    unit: str  # DEGREES or RADIANS
    evidence: str
    by_name: bool  # decided by a name alone (a fix must not rely on it)


def name_unit(name: str) -> str | None:
    """`yaw_deg` -> deg, `theta_rad` -> rad; None for `deg2rad`, `deg_per_sec`, `rad_to_deg` or no unit word."""
    if name.isupper():
        return None  # `DEG`, `DEG2RAD`, `RAD_PER_DEG`: constants are conversion factors more often than angles
    words = [word.lower() for word in re.findall(r"[A-Z]?[a-z]+|[A-Z]+(?![a-z])|\d+", name)]
    if len(words) < 2 or any(word in _NOT_AN_ANGLE for word in words):
        return None  # a bare `deg` / `rad` is as often a unit factor (`30 * deg`) as an angle
    degree = any(word in _DEGREE_WORDS for word in words)
    radian = any(word in _RADIAN_WORDS for word in words)
    if degree == radian:
        return None
    return DEGREES if degree else RADIANS


class AngleUnits:
    """`unit_of` on one module's fact base (memoised per node)."""

    def __init__(self, facts: FactBase) -> None:
        self.facts = facts
        self._units: NodeMemo[Unit] = NodeMemo(_MAX_DEPTH)

    def converts(self, call: Call) -> str | None:
        """For `np.radians(x)` / `np.deg2rad(x)`, RADIANS (the unit it returns); DEGREES for
        `np.degrees` / `np.rad2deg`; None for anything else."""
        if self.facts.called_name(call.func) not in _CONVERSIONS or len(positional_args(call)) != 1:
            return None
        api = library_calls.called_api(self.facts, call)
        return conversion(api) if api is not None else None

    def unit_of(self, node: ast.expr) -> Unit | None:
        return self._units.get(id(node), lambda: self._unit(node))

    def _unit(self, node: ast.expr) -> Unit | None:
        facts = self.facts
        if isinstance(node, UnaryOp) and isinstance(node.op, (USub, UAdd)):
            return self.unit_of(node.operand)
        if isinstance(node, BinOp):
            return self._unit_of_arithmetic(node)
        if isinstance(node, Call):
            return self._unit_of_call(node)
        if self._is_pi(node):
            return Unit(RADIANS, f"`{facts.code_of(node)}` is an angle in radians", False)
        if isinstance(node, Name):
            return self._unit_of_name(node)
        if isinstance(node, Attribute):
            stated = name_unit(node.attr)
            by_name = Unit(stated, f"the name `{node.attr}` says {unit_word(stated)}", True) if stated else None
            literal = self.bound_literal(node)
            if literal is not None:
                return self._agree(by_name, [literal])
            returned = facts.summary_of_property(node, ANGLE_UNITS)
            if returned is not None and returned.angle_unit is not None:
                unit, evidence, named = returned.angle_unit
                return self._agree(by_name, [Unit(unit, f"the property `{facts.code_of(node)}` returns {unit_word(unit)}: {evidence}", named)])
            if isinstance(node.value, Name) and node.value.id == "self":
                stores = facts.index.self_attribute_stores.get(node.attr, [])
                return self._agree(by_name, [self.unit_of(store) for store in stores] if stores else [])
            return by_name
        if isinstance(node, Subscript) and isinstance(node.value, (Name, Attribute)):
            return self.unit_of(node.value)  # `angles_deg[0]`: an element of an array of angles has its unit
        if isinstance(node, Subscript) and isinstance(node.value, Call):
            return self._unit_of_library_call(node.value)  # `euler_from_quaternion(q)[2]`
        return None

    def converts_by_hand(self, node: BinOp) -> tuple[str, ast.expr] | None:
        """`x * np.pi / 180`, `x / 180 * math.pi`, `x * (np.pi / 180)`, `x * 0.0174533`: (RADIANS, x);
        `x * 180 / np.pi`, `x * 57.2958`: (DEGREES, x); None for any other product."""
        numerator: list[ast.expr] = []
        denominator: list[ast.expr] = []
        _factors(node, numerator, denominator)
        values = [factor for factor in numerator + denominator if number(factor) is None and not self._is_pi(factor)]
        if len(values) != 1 or values[0] not in numerator:
            return None
        # the product of the other factors: pi by name or written out (3.14159), 180, 0.0174533, a halving
        pis = sum(self._is_pi(factor) for factor in numerator) - sum(self._is_pi(factor) for factor in denominator)
        above = [abs(value) for value in map(number, numerator) if value is not None]
        below = [abs(value) for value in map(number, denominator) if value is not None]
        scale: float = math.pi**pis
        for value in above:
            scale *= value
        for value in below:
            if value == 0:
                return None
            scale /= value
        if _is_radians_per_degree(scale) or _is_radians_per_degree(2 * scale):  # `x * pi / 180`, `fov * pi / 360`
            return RADIANS, values[0]
        if _is_degrees_per_radian(scale) or _is_degrees_per_radian(scale / 2):
            return DEGREES, values[0]
        return None

    def _unit_of_arithmetic(self, node: BinOp) -> Unit | None:
        if isinstance(node.op, (Mult, Div)):
            converted = self.converts_by_hand(node)
            if converted is not None:
                return Unit(converted[0], f"`{self.facts.code_of(node)}` converts to {unit_word(converted[0])}", False)
            # halving or scaling by a plain number keeps the unit; anything else may convert it
            if number(node.right) is not None and not _is_conversion_factor(number(node.right)):
                return self.unit_of(node.left)
            if isinstance(node.op, Mult) and number(node.left) is not None and not _is_conversion_factor(number(node.left)):
                return self.unit_of(node.right)
            return None
        if isinstance(node.op, (Add, Sub)):
            left = None if number(node.left) is not None else self.unit_of(node.left)
            right = None if number(node.right) is not None else self.unit_of(node.right)
            if number(node.left) is not None:
                return right
            if number(node.right) is not None:
                return left
            if left is not None and right is not None and left.unit == right.unit:
                return left
        return None

    def _unit_of_call(self, call: Call) -> Unit | None:
        facts = self.facts
        converted = self.converts(call)
        if converted is not None:
            return Unit(converted, f"`{facts.code_of(call.func)}` returns {unit_word(converted)}", False)
        if facts.may_have_summary(call):  # a project helper whose every `return` agrees on a unit
            summary = facts.summary_of(call, ANGLE_UNITS)
            if summary is not None and summary.angle_unit is not None:
                unit, evidence, by_name = summary.angle_unit
                return Unit(unit, f"`{facts.code_of(call.func)}` returns {unit_word(unit)}: {evidence}", by_name)
        return self._unit_of_library_call(call)

    def _unit_of_library_call(self, call: Call) -> Unit | None:
        """The unit a library call returns its angles in (not asking project helpers' summaries)."""
        facts = self.facts
        converted = self.converts(call)
        if converted is not None:
            return Unit(converted, f"`{facts.code_of(call.func)}` returns {unit_word(converted)}", False)
        qualified = facts.qualified_name(call.func) or ""
        known = _KNOWLEDGE_UNITS.get(library_calls.angle_output(facts, call) or "")
        if known is not None and qualified.rpartition(".")[2] in _INVERSE_TRIG:  # `np.arctan2`, `math.atan2`
            return Unit(known, f"`{facts.code_of(call.func)}` returns {unit_word(known)}", False)
        if known is not None:  # the knowledge base (stubs/)
            api = library_calls.called_api(facts, call)
            return Unit(known, f"`{api.qualified_name if api else qualified}` returns its angles in {unit_word(known)}", False)
        method = EULER_METHOD_NAMES.get(call.func.attr) if isinstance(call.func, Attribute) and not call.args else None
        if method is not None:  # `imu.getRollPitchYaw()`: matched by its camelCase name on any receiver
            returned = RETURNED_EULER_METHODS[method][0]
            return Unit(returned, f"`{method}` returns its angles in {unit_word(returned)}", False)
        if isinstance(call.func, Attribute) and call.func.attr == "as_euler":
            degrees = keyword(call, "degrees")
            if degrees is not None and isinstance(degrees.value, Constant) and degrees.value.value is True:
                return Unit(DEGREES, "`as_euler(..., degrees=True)` returns degrees", False)
        return None

    def _unit_of_name(self, node: Name) -> Unit | None:
        facts = self.facts
        stated = name_unit(node.id)
        by_name = Unit(stated, f"the name `{node.id}` says {unit_word(stated)}", True) if stated else None
        bound = facts.bindings(node) or []
        scope = facts.index.scope_of(node)
        if node.id in scope.augmented:
            return None  # `angle *= ...`: its unit may change along the way
        literal = self.bound_literal(node)
        if literal is not None:
            return self._agree(by_name, [literal])
        found: list[Unit | None] = []
        for binding in bound:
            if isinstance(binding, ast.expr):
                found.append(self.unit_of(binding))
            elif isinstance(binding, UnpackBinding):
                found.append(self._unit_of_unpacked(binding))
            else:
                found.append(None)
        return self._agree(by_name, found)

    def _unit_of_unpacked(self, binding: UnpackBinding) -> Unit | None:
        """`roll, pitch, yaw = euler_from_quaternion(q)`: each name has the unit of every returned angle;
        `a, b = x_deg, y_deg`: the unit of its own element."""
        value = binding.value
        if isinstance(value, (ast.Tuple, ast.List)):
            return self.unit_of(value.elts[binding.position]) if binding.position < len(value.elts) else None
        return self._unit_of_library_call(value) if isinstance(value, Call) else None

    def bound_literal(self, node: Name | Attribute) -> Unit | None:
        """DEGREES when `node` is a constant bound once, in the whole module it lives in, to a literal
        angle that is no plausible radian value (above 2 pi) but a plausible degree value
        (`PHI = 73.17`, `self.tilt = 30`); None otherwise (any other store, `+=`, `global`)."""
        found = self._literal_binding(node)
        if found is None or isinstance(node, Name) and node.id in _index_names(self.facts):
            return None  # `sigma[k]` beside `np.sin(k)`: an index encoded periodically, not an angle
        value, where = found
        if not plausible_degrees(value):
            return None
        return Unit(DEGREES, f"`{self.facts.code_of(node)}` is only ever {format_angle(value)} ({where}): above 2 pi, an angle in degrees", False)

    def _literal_binding(self, node: ast.expr) -> tuple[float, str] | None:
        facts = self.facts
        if isinstance(node, Name):
            bound = facts.bindings(node) or []
            if node.id in facts.index.scope_of(node).augmented or node.id in _declared_global(facts):
                return None
            if len(bound) == 1 and isinstance(bound[0], ast.expr):
                return _literal_at(bound[0], "")
            imported = facts.index.imports.get(node.id)
            if imported is not None and facts.cross_module and len(bound) == 1:
                return _module_constant(facts, imported)  # `from config import TILT`
            return None
        if not isinstance(node, Attribute):
            return None
        owner = node.value
        if isinstance(owner, Name) and owner.id == "self":
            return _instance_or_class_literal(facts, enclosing_class(facts, node), node.attr, "")
        located = _class_of(facts, owner)
        if located is None:
            if isinstance(owner, Name) and facts.cross_module and owner.id in facts.index.imports and not attribute_stores(facts)[node.attr]:
                return _module_constant(facts, f"{facts.index.imports[owner.id]}.{node.attr}")  # `config.TILT`
            return None
        other, cls, instance = located
        if other is not facts and attribute_stores(facts)[node.attr]:
            return None  # stored here too (`cfg.tilt = ...`)
        where = "" if other is facts else f"in {_short_path(other.path)}"
        if instance:
            return _instance_or_class_literal(other, cls, node.attr, where)
        return _class_literal(other, cls, node.attr, where)

    @staticmethod
    def _agree(by_name: Unit | None, found: list[Unit | None]) -> Unit | None:
        """The name's unit unless a binding contradicts it; else the bindings' common unit."""
        known = [unit for unit in found if unit is not None]
        units = {unit.unit for unit in known}
        if by_name is not None:
            return by_name if units <= {by_name.unit} else None
        if found and len(known) == len(found) and len(units) == 1:
            return known[0]
        return None

    def _is_pi(self, node: AST) -> bool:
        qualified = self.facts.qualified_name(node)
        if qualified is None or qualified.rpartition(".")[2] != "pi":
            return False
        constant = knowledge.knowledge_base().api_as_written(qualified)  # `pi: Radians` in the stubs
        return constant is not None and constant.is_attribute and all(
            signature.returns is not None and signature.returns.angle_unit == knowledge.RADIANS for signature in constant.signatures
        )


class LibraryUnits(AngleUnits):
    """`unit_of` from this module's code and libraries only: no project helper's summary, no constant of
    another module (a cheap first look that reads no other module)."""

    def _unit_of_call(self, call: Call) -> Unit | None:
        return self._unit_of_library_call(call)

    def bound_literal(self, node: Name | Attribute) -> Unit | None:
        return None


def plausible_degrees(value: float) -> bool:
    """No plausible angle in radians (above 2 pi) but one in degrees: at most 360, or a whole
    multiple of 15 up to 720 (`90`, `73.17`, `-180`; not `0.5`, `1000`)."""
    magnitude = abs(value)
    return magnitude > _TWO_PI and (magnitude <= 360 or (magnitude <= 720 and value == int(value) and int(value) % 15 == 0))


def format_angle(value: float) -> str:
    """`90` for 90.0, `73.17` as it is."""
    return str(int(value)) if value == int(value) else str(value)


def _literal_at(value: ast.expr, where: str) -> tuple[float, str] | None:
    literal = number(value)
    if literal is None:
        return None
    place = f"line {value.lineno}" + (f" {where}" if where else "")
    return float(literal), place


def _index_names(facts: FactBase) -> frozenset[str]:
    """Names the module uses to index a sequence (`sigma[k]`, `poses[i, :3]`): counts and positions."""

    def compute() -> frozenset[str]:
        found: set[str] = set()
        for node in facts.index.nodes(Subscript):
            index = node.slice  # type: ignore[attr-defined]
            for item in index.elts if isinstance(index, ast.Tuple) else [index]:
                if isinstance(item, Name):
                    found.add(item.id)
        return frozenset(found)

    return facts.module_fact("index names", compute)


def _declared_global(facts: FactBase) -> frozenset[str]:
    """Names some function of the module declares `global` (it may rebind them)."""
    return facts.module_fact("global names", lambda: frozenset(name for node in facts.index.nodes(Global) for name in node.names))  # type: ignore[attr-defined]


def attribute_stores(facts: FactBase) -> Counter[str]:
    """How many times the module stores (or deletes) each attribute name, on any object."""

    def count() -> Counter[str]:
        found: Counter[str] = Counter()
        for node in facts.index.nodes(Attribute):
            if not isinstance(node.ctx, Load):  # type: ignore[attr-defined]
                found[node.attr] += 1  # type: ignore[attr-defined]
        for node in facts.index.nodes(Call):  # `setattr(self, "tilt", ...)`
            if isinstance(node.func, Name) and node.func.id == "setattr" and len(node.args) > 1:  # type: ignore[attr-defined]
                name = string(node.args[1])  # type: ignore[attr-defined]
                found[name if name is not None else "*"] += 1 << 20 if name is None else 1
        return found

    counted = facts.module_fact("attribute stores", count)
    return counted if not counted["*"] else Counter({name: 1 << 20 for name in counted})  # a computed `setattr`: anything


def _instance_or_class_literal(facts: FactBase, cls: ClassDef | None, attr: str, where: str) -> tuple[float, str] | None:
    """`self.<attr> = <literal>`, the module's only store of `.attr`, inside `cls`; else `cls`'s class attribute."""
    if cls is None or cls.bases and not all(isinstance(base, Name) and base.id == "object" for base in cls.bases):
        return None  # a base class (here or in a library) may set it too
    stores = facts.index.self_attribute_stores.get(attr, [])
    if stores:
        if len(stores) != 1 or attribute_stores(facts)[attr] != 1 or enclosing_class(facts, stores[0]) is not cls:
            return None
        return _literal_at(stores[0], where)
    return _class_literal(facts, cls, attr, where)


def _class_literal(facts: FactBase, cls: ClassDef, attr: str, where: str) -> tuple[float, str] | None:
    """`class Config: TILT = 30`, bound once in the class body and stored nowhere in the module."""
    if attribute_stores(facts)[attr] or (cls.bases and not all(isinstance(base, Name) and base.id == "object" for base in cls.bases)):
        return None
    scope: Scope | None = facts.index.scopes.get(cls)
    bound = [] if scope is None else scope.bindings.get(attr, [])
    if len(bound) != 1 or not isinstance(bound[0], ast.expr):
        return None
    return _literal_at(bound[0], where)


def _module_constant(facts: FactBase, qualified: str) -> tuple[float, str] | None:
    """A module-level name of a project module bound once to a literal (`config.TILT`)."""
    found = facts.defining_module(qualified, facts.path)
    if found is None:
        return None
    other, name = found
    value = module_constant(other.index, name)
    return None if value is None else _literal_at(value, f"in {_short_path(other.path)}")


def _class_of(facts: FactBase, owner: ast.expr) -> tuple[FactBase, ClassDef, bool] | None:
    """For `Config.TILT` the class (instance False); for `cfg.tilt` where `cfg` (a name or `self`
    attribute) is an instance of a project class (`receiver_class`), the class (instance True)."""
    found = receiver_class(facts, owner)
    if found is not None:
        return (*found, True)
    if not isinstance(owner, Name):
        return None
    found = project_class(facts, owner)
    return None if found is None else (*found, False)


def _short_path(path: str) -> str:
    return path.replace("\\", "/").rsplit("/", 1)[-1]


def _factors(node: ast.expr, numerator: list[ast.expr], denominator: list[ast.expr], inverted: bool = False) -> None:
    """The factors of a chain of `*` and `/` (`a * b / c` -> [a, b] over [c])."""
    if isinstance(node, BinOp) and isinstance(node.op, (Mult, Div)):
        _factors(node.left, numerator, denominator, inverted)
        _factors(node.right, numerator, denominator, inverted != isinstance(node.op, Div))
        return
    (denominator if inverted else numerator).append(node)


def _is_conversion_factor(value: float | None) -> bool:
    """pi / 180 and 180 / pi written as numbers (and 180 itself, as in `x / 180 * pi`)."""
    return value is not None and (_is_radians_per_degree(value) or _is_degrees_per_radian(value) or abs(value) == 180)


def _is_radians_per_degree(value: float) -> bool:
    """pi / 180 written as a number (0.0174533), or the product of factors that make it (3.14159 / 180)."""
    return abs(abs(value) - 0.0174533) < 1e-4


def _is_degrees_per_radian(value: float) -> bool:
    """180 / pi written as a number (57.2958)."""
    return abs(abs(value) - 57.29578) < 1e-2


def unit_word(unit: str | None) -> str:
    return "degrees" if unit == DEGREES else "radians"


def may_read_radians(facts: FactBase, called: str) -> bool:
    """Whether a call named `called` (`FactBase.called_name`) can be one `radian_arguments` knows
    (trig and `degrees` / `rad2deg` included): the cheap first test, asked of every call of a module.
    For any other name `radian_arguments` is None and `is_trig_or_conversion` is False."""
    return called in _RADIAN_API_NAMES or library_calls.may_read_angles(facts, called, knowledge.RADIANS)


def radian_arguments(facts: FactBase, node: Call) -> list[ast.expr] | None:
    """The angle arguments of a call to a radian API, or None when the call is not one (or opted into degrees)."""
    func = node.func
    if not may_read_radians(facts, facts.called_name(func) or ""):
        return None  # named like none of the APIs below (asked of every call of a module)
    if library_calls.called_api(facts, node) is not None:  # the knowledge base (stubs/) knows the call
        return library_calls.angle_arguments(facts, node, knowledge.RADIANS) or None
    positional = positional_args(node)
    if is_trig_or_conversion(facts, node):
        return positional[:1]
    return None


def is_trig_or_conversion(facts: FactBase, node: Call) -> bool:
    """`np.sin(x)`, `math.cos(x)`, and `np.degrees(x)` / `np.rad2deg(x)` (which read radians too)."""
    func = node.func
    called = facts.called_name(func)
    if called not in TRIG_FUNCTIONS and called not in ("degrees", "rad2deg"):
        return False
    if len(positional_args(node)) != 1:
        return False
    api = library_calls.called_api(facts, node)  # the stubs say which modules' `sin` reads radians
    return api is not None and bool(api.signatures) and all(
        bool(signature.parameters) and signature.parameters[0].geometry is not None and signature.parameters[0].geometry.angle_unit == knowledge.RADIANS
        for signature in api.signatures
    )


def conversion(api: knowledge.Api) -> str | None:
    """The unit a unit conversion returns (`np.deg2rad`: RADIANS, `math.degrees`: DEGREES), by its stub: one
    angle in one unit in, the other out; None for any other API."""
    units = set()
    for signature in api.signatures:
        given = signature.parameters[0].geometry if signature.parameters else None
        returned = signature.returns
        if given is None or returned is None or given.angle_unit is None or returned.angle_unit in (None, given.angle_unit):
            return None
        units.add(returned.angle_unit)
    return _KNOWLEDGE_UNITS.get(units.pop()) if len(units) == 1 else None


def may_read_degrees(facts: FactBase, called: str) -> bool:
    """Whether a call named `called` (`FactBase.called_name`) may be a library API that reads degrees
    (`degree_arguments`): the cheap first test, asked of every call of a module."""
    return library_calls.may_read_angles(facts, called, knowledge.DEGREES)


def degree_arguments(facts: FactBase, call: Call, *, whatever_the_keywords: bool = False) -> list[ast.expr]:
    """The arguments a library call reads in degrees, as its stub says (`glRotatef(angle, ...)`,
    `carla.Rotation(pitch=...)`, `from_euler(seq, angles, degrees=True)`), else []. With
    `whatever_the_keywords`, only those the API reads in degrees however it is called (not
    `from_euler`'s, which `degrees=True` chose)."""
    if not may_read_degrees(facts, facts.called_name(call.func) or ""):
        return []  # the cheap test first: asked of every call
    api = library_calls.called_api(facts, call)
    if api is not None and conversion(api) is not None:
        return []  # `np.radians(x)` converts what it is given (`AngleUnits.converts`): no API that needs degrees
    return library_calls.angle_arguments(facts, call, knowledge.DEGREES, whatever_the_keywords=whatever_the_keywords)


def unit_read_by(facts: FactBase, call: Call, argument: ast.expr) -> str | None:
    """The unit `call` reads its argument `argument` in, when the call always runs with it (not under
    a condition of its function): RADIANS for a radian API (`np.cos(theta)`, `from_euler` without
    `degrees=True`), DEGREES for a conversion from degrees (`np.radians(a)`) or `from_euler(...,
    degrees=True)` or a library call that reads degrees (`glRotatef(a, 0, 1, 0)`); None otherwise."""
    if not runs_unconditionally(facts, call):
        return None
    if any(element is argument for found in radian_arguments(facts, call) or () for element in angle_elements(found)):
        return RADIANS
    if any(factor is argument for factor in rotation_vector_factors(facts, call)):
        return RADIANS
    if any(element is argument for found in degree_arguments(facts, call) for element in angle_elements(found)):
        return DEGREES
    positional = positional_args(call)
    if facts.shared(AngleUnits).converts(call) == RADIANS and positional and positional[0] is argument:
        return DEGREES
    return None


def rotation_vector_factors(facts: FactBase, call: Call) -> list[ast.expr]:
    """For a call reading a rotation vector in radians written as a product (`from_rotvec(theta * axis)`,
    numpy-quaternion's `from_rotation_vector(angle * axis)`): the product's factors that are no number
    literal (the angle among them); [] for any other call."""
    if not library_calls.may_read_angles(facts, facts.called_name(call.func) or "", knowledge.RADIANS):
        return []  # the cheap test first: asked of every call
    arguments = library_calls.rotation_vector_arguments(facts, call)
    if not arguments or not isinstance(arguments[0], BinOp) or not isinstance(arguments[0].op, Mult):
        return []
    product = arguments[0]
    return [factor for factor in (product.left, product.right) if number(factor) is None]


def angle_elements(node: ast.expr) -> list[ast.expr]:
    """The angles an angle argument holds: a list or tuple literal's items, or the argument itself."""
    if isinstance(node, (ast.List, ast.Tuple)):
        return list(node.elts)
    return [node]


# --- the summaries of angle units: what a helper returns and what it reads its parameters in ------


@dataclass
class AngleSummary(Summary):
    # the angle unit every `return` agrees on: (unit, evidence, decided by a name alone)
    angle_unit: tuple[str, str, bool] | None = None
    # parameter index -> (unit, where, decided by its name alone): parameters passed as they are to an
    # API that reads that unit, or named in it (`angle_in_degrees`)
    reads_unit: dict[int, tuple[str, str, bool]] = field(default_factory=dict)


_CONFLICT: Final = ("", "", False)


def _summarize_angle_units(facts: FactBase, function: Function, params: tuple[str, ...]) -> AngleSummary:
    """The unit a function returns its angles in, and the unit it reads each parameter in (`heading(v)`
    returns radians; `rot_z(theta)` reads radians)."""
    summary = AngleSummary(parameters=params)
    scope = facts.index.scopes.get(function)
    if scope is None:
        return summary
    plain = plain_parameters(scope, params)
    returns = settled_returns(facts, scope, ANGLE_UNITS)
    if returns:
        summary.angle_unit = _returned_unit(facts, returns)
    units = facts.shared(AngleUnits)
    for node in walk_within(function):
        if isinstance(node, Call) and node.args:
            _record_unit_reads(facts, node, positional_args(node), params, plain, summary)
        elif isinstance(node, BinOp) and isinstance(node.op, (Mult, Div)):
            _record_hand_conversion(facts, node, units, plain, summary)
    _add_named_units(summary)
    return summary


def _record_hand_conversion(facts: FactBase, node: BinOp, units: AngleUnits, plain: set[str], summary: AngleSummary) -> None:
    """`heading * 180 / np.pi` of a parameter: the function reads it in radians (and `* np.pi / 180` in
    degrees), as `np.degrees(heading)` would."""
    converted = units.converts_by_hand(node)
    if converted is not None and isinstance(converted[1], Name) and converted[1].id in plain:
        read = RADIANS if converted[0] == DEGREES else DEGREES
        _add_unit_read(summary, summary.parameters.index(converted[1].id), read, f"a conversion written out (`{facts.code_of(node)}`)")


def _record_unit_reads(
    facts: FactBase, call: Call, arguments: list[ast.expr], params: tuple[str, ...], plain: set[str], summary: AngleSummary
) -> None:
    """What a call inside the function reads the function's own parameters in (its `positional_args`):
    a project helper that reads a unit, an API that does (`np.cos(theta)`)."""
    passed = {index: params.index(arg.id) for index, arg in enumerate(arguments) if isinstance(arg, Name) and arg.id in plain}
    if not passed:
        if arguments and isinstance(arguments[0], BinOp):
            _record_rotation_vector(facts, call, plain, summary)
        return
    if facts.may_have_summary(call):
        callee = facts.summary_of(call, ANGLE_UNITS)
        if callee is not None:
            for index, (unit, where, by_name) in callee.reads_unit.items():
                if index in passed and unit:
                    if where:
                        through = chain(f"`{facts.code_of(call.func)}`", where)
                    else:
                        through = f"`{facts.code_of(call.func)}` (whose parameter `{callee.parameters[index]}` is named in {'degrees' if unit == 'deg' else 'radians'})"
                    _add_unit_read(summary, passed[index], unit, through, by_name)
            return
    for index, own in passed.items():
        read = unit_read_by(facts, call, arguments[index])
        if read is not None:
            _add_unit_read(summary, own, read, f"`{facts.code_of(call.func)}`")


def _record_rotation_vector(facts: FactBase, call: Call, plain: set[str], summary: AngleSummary) -> None:
    """`from_rotation_vector(theta * axis)`: a parameter that scales a rotation vector is its angle, read in radians."""
    for factor in rotation_vector_factors(facts, call):
        if isinstance(factor, Name) and factor.id in plain:
            read = unit_read_by(facts, call, factor)
            if read is not None:
                where = f"`{facts.code_of(call.func)}` (as the angle of the rotation vector `{facts.code_of(facts.parent(factor) or factor)}`)"
                _add_unit_read(summary, summary.parameters.index(factor.id), read, where)


def _add_unit_read(summary: AngleSummary, index: int, unit: str, where: str, by_name: bool = False) -> None:
    known = summary.reads_unit.get(index)
    if known is None:
        summary.reads_unit[index] = (unit, where, by_name)
    elif known[0] != unit:
        summary.reads_unit[index] = _CONFLICT  # read as both units: no evidence


def _add_named_units(summary: AngleSummary) -> None:
    """`def normalize(angle_in_degrees)`: a parameter named in a unit is read in it, unless its body
    reads it in the other unit (then nothing is known)."""
    for index, name in enumerate(summary.parameters):
        unit = name_unit(name)
        if unit is not None:
            _add_unit_read(summary, index, unit, "", by_name=True)  # no call: the name itself


def _returned_unit(facts: FactBase, returns: list[ast.expr]) -> tuple[str, str, bool] | None:
    found = agreed([facts.shared(AngleUnits).unit_of(value) for value in returns], "unit")
    return None if found is None else (found[0].unit, found[0].evidence, any(unit.by_name for unit in found))


def _bound_angle_summary(summary: AngleSummary) -> AngleSummary:
    return AngleSummary(parameters=summary.parameters[1:], angle_unit=summary.angle_unit, reads_unit=shifted(summary.reads_unit), pending=summary.pending)


ANGLE_UNITS: Final = SummaryFamily("angle units", AngleSummary, _summarize_angle_units, _bound_angle_summary)
