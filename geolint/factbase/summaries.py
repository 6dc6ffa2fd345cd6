"""Function summaries: what a helper does to its parameters and returns, so call sites anywhere in the
project know (`to_homogeneous(x)` appends w = 1 to x; `apply_pose(T, x)` rotates and translates x;
`load_normals()` returns directions; `heading(v)` returns radians; `rot_z(theta)` reads radians).

Summaries compose: a helper that calls another project helper (in its own module or in one it
imports, through aliases and relative imports, and through a package `__init__` that re-exports it)
gets the callee's effect. `ProjectSummaries` computes them lazily for one linted module, each in a
fresh scratch fact base (so a value computed under a provisional summary is never kept), and
iterates recursion and import cycles to a fixpoint: a cycle's first pass reads the summaries still
being computed as unknown, and the cycle's head is recomputed until its summary stops changing
(at most `_MAX_ROUNDS` passes; a cycle that does not settle stays unknown).

Since a summary may consult modules any number of imports away, `dependency_digest` hashes the
transitive closure of the project modules a file imports, and the findings cache keys each file by
it: editing a helper re-lints every module that may read its summary.
"""

from __future__ import annotations

import ast
from ast import AST, Add, AsyncFunctionDef, Attribute, BinOp, Call, FunctionDef, Name
import hashlib
import os
import re
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any, Final, Iterable, Iterator, Mapping, Sequence, TYPE_CHECKING

from geolint.algebra import FREE, Kind, marked_by_w
from geolint.factbase.index import ParamBinding, index_of_file  # no cycle: the index imports no fact base module
from geolint.factbase.vocabulary import THIRD_PARTY_ROOTS

if TYPE_CHECKING:
    from geolint.factbase.index import ModuleIndex
    from geolint.factbase.model import FactBase

_IMPORT: Final = re.compile(r"^[ \t]*(?:from[ \t]+([.\w]+)[ \t]+import|import[ \t]+([\w.]+))", re.MULTILINE)
# `_IMPORT` at one line start: both its alternatives hold the word "import", so only the lines that
# hold it are tried (the anchored regex alone tries every position of the text).
_IMPORT_AT_LINE_START: Final = re.compile(r"[ \t]*(?:from[ \t]+([.\w]+)[ \t]+import|import[ \t]+([\w.]+))")
_PROJECT_MARKERS: Final = ("pyproject.toml", "setup.py", "setup.cfg", ".git")


@dataclass
class FunctionSummary:
    """What one function does, as far as the project shows."""

    parameters: tuple[str, ...] = ()
    returns: Kind | None = None  # the kind every `return` agrees on
    # parameter index -> w, when the function returns that parameter made homogeneous
    homogenizes: dict[int, int] = field(default_factory=dict)
    # parameters the function moves by a rotation AND a translation (`R @ x + t`, or a helper that does)
    translates: set[int] = field(default_factory=set)
    # parameter index -> the helper chain that translates it, when that is not this function's own code
    translates_through: dict[int, str] = field(default_factory=dict)
    # the angle unit every `return` agrees on: (unit, evidence, decided by a name alone)
    angle_unit: tuple[str, str, bool] | None = None
    # the quaternion order every `return` agrees on: (order, evidence, a stack of quaternions)
    quaternion_order: tuple[str, str, bool] | None = None
    # `return pos, quat`: tuple position -> the quaternion order every `return` agrees on there
    quaternion_elements: dict[int, tuple[str, str, bool]] = field(default_factory=dict)
    # parameter index -> (unit, where, decided by its name alone): parameters passed as they are to an
    # API that reads that unit, or named in it (`angle_in_degrees`)
    reads_unit: dict[int, tuple[str, str, bool]] = field(default_factory=dict)
    # parameter index -> (quaternion order, where): parameters passed as they are, unconditionally, as
    # the quaternion of an API that reads that order (`Rotation.from_quat(q)`), directly or through helpers
    reads_quaternion: dict[int, tuple[str, str]] = field(default_factory=dict)
    # a summary still being computed, on a cycle's first pass: its `return`s constrain nothing yet
    pending: bool = False


def bound(summary: FunctionSummary) -> FunctionSummary:
    """A method's summary as its call `self.method(a, b)` sees it: `self` dropped, positions shifted."""

    def shifted(mapping: dict) -> dict:  # type: ignore[type-arg]
        return {index - 1: value for index, value in mapping.items() if index > 0}

    return FunctionSummary(
        parameters=summary.parameters[1:],
        returns=summary.returns,
        homogenizes=shifted(summary.homogenizes),
        translates={index - 1 for index in summary.translates if index > 0},
        translates_through=shifted(summary.translates_through),
        angle_unit=summary.angle_unit,
        quaternion_order=summary.quaternion_order,
        quaternion_elements=summary.quaternion_elements,
        reads_unit=shifted(summary.reads_unit),
        reads_quaternion=shifted(summary.reads_quaternion),
        pending=summary.pending,
    )


def summarize(facts: FactBase, function: FunctionDef | AsyncFunctionDef) -> FunctionSummary:
    """The summary of a function of `facts`' module (helpers it calls answer through their summaries)."""
    from geolint.factbase.model import positional_args, transposed_value, walk_within

    params = tuple(arg.arg for arg in (*function.args.posonlyargs, *function.args.args))
    summary = FunctionSummary(parameters=params)
    scope = facts.index.scopes.get(function)
    if scope is None:
        return summary
    plain = {name for name in params if only_bound_as_parameter(scope, name)}
    # `return f(...)` of a summary not known yet on a cycle's first pass says nothing either way (the
    # cycle's later passes see what the other `return`s agree on)
    returns = [value for value in scope.returns if not _pending(facts, value)]
    kinds = {facts.kind_of(value) for value in returns}
    if len(kinds) == 1:
        summary.returns = kinds.pop()
    for value in returns:
        homogeneous = facts.homogeneous(value)
        if homogeneous is not None and isinstance(homogeneous.inner, Name) and homogeneous.inner.id in params:
            summary.homogenizes[params.index(homogeneous.inner.id)] = homogeneous.w
        elif isinstance(value, Call) and facts.may_have_summary(value):
            # `return to_homogeneous(x)`: the callee's w, on our parameter
            callee = facts.function_summary(value)
            arguments = positional_args(value)
            for index, w in (callee.homogenizes.items() if callee is not None else ()):
                argument = arguments[index] if index < len(arguments) else None
                if isinstance(argument, Name) and argument.id in plain:
                    summary.homogenizes.setdefault(params.index(argument.id), w)
    if returns:
        summary.angle_unit = _returned_unit(facts, returns)
        summary.quaternion_order = _returned_order(facts, returns)
        summary.quaternion_elements = _returned_element_orders(facts, returns)
    for node in walk_within(function):
        if isinstance(node, Call) and node.args:
            _record_call(facts, node, positional_args(node), params, plain, summary)
        if isinstance(node, Call) and node.keywords:
            _record_keyword_quaternions(facts, node, params, plain, summary)
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
    _add_named_units(summary)
    _record_formula_reads(facts, function, plain, summary)
    if plain and scope.attribute_stores:
        _record_component_writes(facts, scope.attribute_stores, plain, summary)
    return summary


def _record_component_writes(facts: FactBase, stores: list[tuple[Attribute, ast.expr]], plain: set[str], summary: FunctionSummary) -> None:
    """`msg.x = q[0]` ... `msg.w = q[3]` on a parameter `q`: read in that order, as if handed to an API."""
    from geolint.factbase.rotations import component_writes_of_parameter

    for name, order, where in component_writes_of_parameter(facts, stores, plain):
        _add_quaternion_read(summary, summary.parameters.index(name), order, where)


def _record_formula_reads(facts: FactBase, function: FunctionDef | AsyncFunctionDef, plain: set[str], summary: FunctionSummary) -> None:
    """A parameter whose components an unconditional textbook formula reads (`atan2(2 * (q[3] * q[2] + ...`)
    is read in that formula's order, as if handed to an API."""
    from geolint.factbase.control_flow import runs_unconditionally
    from geolint.factbase.quaternion_formulas import formula_reads_within

    for read in formula_reads_within(facts, function):
        base = read.base
        if not (isinstance(base, Name) and base.id in plain) or facts.index.scope_of(base).node is not function:
            continue
        if runs_unconditionally(facts, read.node):
            _add_quaternion_read(summary, summary.parameters.index(base.id), read.order, read.evidence(facts))


def _record_homogeneous_product(facts: FactBase, node: AST, plain: set[str], summary: FunctionSummary) -> None:
    """`T @ to_homogeneous(x).T`, `np.hstack([x, ones]) @ T.T`: a parameter given the w that marks a point
    (`algebra.marked_by_w`: 1) and multiplied by an operator is translated along with the rotation."""
    product = facts.matmul(node)
    if product is None:
        return
    from geolint.factbase.model import GEOMETRIC, transposed_value  # after the common case: an import costs a microsecond

    for operand, operator in ((product.left, product.right), (product.right, product.left)):
        homogeneous = facts.homogeneous(transposed_value(operand) or operand)
        if homogeneous is None or marked_by_w(homogeneous.w) != Kind.POINT or not isinstance(homogeneous.inner, Name):
            continue
        name = homogeneous.inner.id
        if name in plain and facts.kind_of(homogeneous.inner) not in FREE and facts.kind_of(operator) not in GEOMETRIC:
            summary.translates.add(summary.parameters.index(name))


def _pending(facts: FactBase, value: ast.expr) -> bool:
    if not isinstance(value, Call) or not facts.may_have_summary(value):
        return False
    summary = facts.function_summary(value)
    return summary is not None and summary.pending


def only_bound_as_parameter(scope, name: str) -> bool:  # type: ignore[no-untyped-def]
    """A parameter never rebound in its function (so what a callee does to it, it does to the argument)."""
    bound = scope.bindings.get(name, [])
    return len(bound) == 1 and isinstance(bound[0], ParamBinding) and name not in scope.augmented


def _record_call(
    facts: FactBase, call: Call, arguments: list[ast.expr], params: tuple[str, ...], plain: set[str], summary: FunctionSummary
) -> None:
    """What a call inside the function does to the function's own parameters (its `positional_args`):
    a project helper that translates one (`apply_pose(T, x)`), an API that reads an angle unit (`np.cos(theta)`)."""
    passed = {index: params.index(arg.id) for index, arg in enumerate(arguments) if isinstance(arg, Name) and arg.id in plain}
    if not passed:
        if arguments and isinstance(arguments[0], BinOp):
            _record_rotation_vector(facts, call, plain, summary)
        return
    if facts.may_have_summary(call):
        callee = facts.function_summary(call)
        if callee is not None:

            def helper() -> str:  # the callee's text, read only when something is recorded
                return facts.code_of(call.func)

            for index in callee.translates:
                if index in passed and facts.kind_of(arguments[index]) not in FREE:
                    own = passed[index]
                    if own not in summary.translates:
                        summary.translates.add(own)
                        through = callee.translates_through.get(index)
                        summary.translates_through[own] = _chain(f"`{helper()}`", through)
            for index, (unit, where, by_name) in callee.reads_unit.items():
                if index in passed and unit:
                    if where:
                        through = _chain(f"`{helper()}`", where)
                    else:
                        through = f"`{helper()}` (whose parameter `{callee.parameters[index]}` is named in {'degrees' if unit == 'deg' else 'radians'})"
                    _add_unit_read(summary, passed[index], unit, through, by_name)
            for index, (order, where) in callee.reads_quaternion.items():
                if index in passed and order:
                    _add_quaternion_read(summary, passed[index], order, _chain(f"`{helper()}`", where))
            return
    from geolint.factbase.angle_units import unit_read_by

    for index, own in passed.items():
        read = unit_read_by(facts, call, arguments[index])
        if read is not None:
            _add_unit_read(summary, own, read, f"`{facts.code_of(call.func)}`")
        read_order = quaternion_read_by(facts, call, arguments[index])
        if read_order is not None:
            _add_quaternion_read(summary, own, read_order, f"`{facts.code_of(call.func)}`")


def _record_rotation_vector(facts: FactBase, call: Call, plain: set[str], summary: FunctionSummary) -> None:
    """`from_rotation_vector(theta * axis)`: a parameter that scales a rotation vector is its angle, read in radians."""
    from geolint.factbase.angle_units import rotation_vector_factors, unit_read_by

    for factor in rotation_vector_factors(facts, call):
        if isinstance(factor, Name) and factor.id in plain:
            read = unit_read_by(facts, call, factor)
            if read is not None:
                where = f"`{facts.code_of(call.func)}` (as the angle of the rotation vector `{facts.code_of(facts.parent(factor) or factor)}`)"
                _add_unit_read(summary, summary.parameters.index(factor.id), read, where)


def _record_keyword_quaternions(facts: FactBase, call: Call, params: tuple[str, ...], plain: set[str], summary: FunctionSummary) -> None:
    """`XFormPrim(path, orientation=q)`, `loadURDF(path, baseOrientation=q)`: a parameter passed by keyword
    as an API's quaternion."""
    for given in call.keywords:
        value = given.value
        if isinstance(value, Name) and value.id in plain:
            order = quaternion_read_by(facts, call, value)
            if order is not None:
                _add_quaternion_read(summary, params.index(value.id), order, f"`{facts.code_of(call.func)}`")


def quaternion_read_by(facts: FactBase, call: Call, argument: ast.expr) -> str | None:
    """The component order `call` reads `argument` in, when it is the call's whole quaternion (scipy
    `from_quat(q)`, pybullet's orientation arguments...) and the call runs whenever its function does."""
    from geolint.factbase.rotations import SCALAR_FIRST, SCALAR_LAST, isaac_orientation_arguments, pybullet_orientation_arguments, quaternion_argument, quaternion_order
    from geolint.factbase.control_flow import runs_unconditionally

    if any(found is argument for found in pybullet_orientation_arguments(call)):
        order: str | None = SCALAR_LAST
    elif any(found is argument for found in isaac_orientation_arguments(facts, call)):
        order = SCALAR_FIRST
    else:
        order = quaternion_order(facts, call)
        if order is None or quaternion_argument(facts, call) is not argument:
            return None
    return order if runs_unconditionally(facts, call) else None


def _add_quaternion_read(summary: FunctionSummary, index: int, order: str, where: str) -> None:
    known = summary.reads_quaternion.get(index)
    if known is None:
        summary.reads_quaternion[index] = (order, where)
    elif known[0] != order:
        summary.reads_quaternion[index] = ("", "")  # read in both orders: no evidence


_CONFLICT: Final = ("", "", False)
_ARROW: Final = " -> "
_SHOWN_HOPS: Final = 5  # a longer chain of helpers is shown as its first hops, "...", and its end


def _chain(helper: str, rest: str | None) -> str:
    """`helper -> rest`, with at most `_SHOWN_HOPS` hops spelled out (chains nest one helper at a
    time, so an unbounded text would grow with the square of the chain's length)."""
    hops = [helper, *rest.split(_ARROW)] if rest else [helper]
    if len(hops) > _SHOWN_HOPS:
        hops = [*hops[: _SHOWN_HOPS - 2], "...", hops[-1]]
    return _ARROW.join(hops)


def _add_unit_read(summary: FunctionSummary, index: int, unit: str, where: str, by_name: bool = False) -> None:
    known = summary.reads_unit.get(index)
    if known is None:
        summary.reads_unit[index] = (unit, where, by_name)
    elif known[0] != unit:
        summary.reads_unit[index] = _CONFLICT  # read as both units: no evidence


def _add_named_units(summary: FunctionSummary) -> None:
    """`def normalize(angle_in_degrees)`: a parameter named in a unit is read in it, unless its body
    reads it in the other unit (then nothing is known)."""
    from geolint.factbase.angle_units import name_unit

    for index, name in enumerate(summary.parameters):
        unit = name_unit(name)
        if unit is not None:
            _add_unit_read(summary, index, unit, "", by_name=True)  # no call: the name itself


def _returned_unit(facts: FactBase, returns: list[ast.expr]) -> tuple[str, str, bool] | None:
    from geolint.factbase.angle_units import AngleUnits

    found = _agreed([facts.shared(AngleUnits).unit_of(value) for value in returns], "unit")
    return None if found is None else (found[0].unit, found[0].evidence, any(unit.by_name for unit in found))


def _returned_order(facts: FactBase, returns: list[ast.expr]) -> tuple[str, str, bool] | None:
    from geolint.factbase.quaternion_orders import QuaternionFlow

    found = _agreed([facts.shared(QuaternionFlow).order_of(value) for value in returns], "order")
    return None if found is None else (found[0].order, found[0].evidence, all(order.batch for order in found))


def _returned_element_orders(facts: FactBase, returns: list[ast.expr]) -> dict[int, tuple[str, str, bool]]:
    """`return pos, quat_wxyz`: the order of each position of the returned tuple, when every `return`
    is a tuple of one length and all of them agree on that position."""
    if not all(isinstance(value, ast.Tuple) for value in returns) or len({len(value.elts) for value in returns}) != 1:  # type: ignore[attr-defined]
        return {}
    from geolint.factbase.quaternion_orders import QuaternionFlow

    flow = facts.shared(QuaternionFlow)
    found: dict[int, tuple[str, str, bool]] = {}
    for position in range(len(returns[0].elts)):  # type: ignore[attr-defined]
        orders = _agreed([flow.order_of(value.elts[position]) for value in returns], "order")  # type: ignore[attr-defined]
        if orders is not None:
            found[position] = (orders[0].order, orders[0].evidence, all(order.batch for order in orders))
    return found


def _agreed(found: list, field: str) -> list | None:  # type: ignore[type-arg]
    """`found` when every `return` has a fact and all agree on `field`, else None."""
    if not found or any(fact is None for fact in found) or len({getattr(fact, field) for fact in found}) != 1:
        return None
    return found


# --- composition: summaries of one linted module's helpers, to a fixpoint ------------------------

_MAX_SUMMARY_DEPTH: Final = 12  # helpers calling helpers this deep; deeper calls are unknown
_MAX_ROUNDS: Final = 4  # passes over a recursion or import cycle before it is given up as unknown
_BUDGET: Final = 3000  # summaries computed for one linted module (each costs about its function's size)
_NO_CUT: Final = 1 << 30


class ProjectSummaries:
    """The summaries one linted module reads, computed on demand and kept for its lint only (so a
    long-running process never serves a summary computed against an older version of a module).

    Each summary is computed in a scratch fact base of its module. A call that reaches a summary
    still being computed (recursion, an import cycle) reads its provisional value (unknown on the
    first pass) and marks every summary computed since as provisional; the first summary of the
    cycle is recomputed until it stops changing, and only then kept.
    """

    def __init__(self, config) -> None:  # type: ignore[no-untyped-def]
        self.config = config
        self._final: dict[tuple[int, int], FunctionSummary | None] = {}
        self._provisional: dict[tuple[int, int], FunctionSummary] = {}
        self._positions: dict[tuple[int, int], int] = {}
        self._lowest_cut: list[int] = []  # per frame of the stack: the lowest frame a cycle reached
        self._modules: dict[str, FactBase | None] = {}
        self.computed = 0

    def adopt(self, facts: FactBase) -> None:
        """The linted module itself: other modules that import it read its in-memory text."""
        if facts.path and os.path.isfile(facts.path):
            self._modules.setdefault(os.path.abspath(facts.path), facts)

    def close(self) -> None:
        """Forget the fact bases and summaries read for this lint. They refer back to this object, and
        the cycle would keep every module's syntax tree alive until the cycle collector ran."""
        for facts in self._modules.values():
            if facts is not None:
                facts.close()
        self._modules.clear()
        self._final.clear()
        self._provisional.clear()

    def facts_of(self, file: Path) -> FactBase | None:
        """The fact base of another project module (its parse and index are shared by the process)."""
        key = os.path.abspath(file)
        if key not in self._modules:
            from geolint.factbase.model import FactBase

            index = _module_index_of_file(file)
            self._modules[key] = None if index is None else FactBase(index, self.config, key, project=self)
        return self._modules[key]

    def summary(self, facts: FactBase, function: FunctionDef | AsyncFunctionDef) -> FunctionSummary | None:
        key = (id(facts.index), id(function))
        if key in self._final:
            return self._final[key]
        position = self._positions.get(key)
        if position is not None:  # recursion or an import cycle: read what is known so far
            self._lowest_cut[-1] = min(self._lowest_cut[-1], position)
            return self._provisional.get(key) or FunctionSummary(pending=True)
        if len(self._lowest_cut) >= _MAX_SUMMARY_DEPTH or self.computed >= _BUDGET:
            if self._lowest_cut:
                self._lowest_cut[-1] = -1  # cut short: nothing computed from here on is kept
            return None
        position = len(self._lowest_cut)
        self._positions[key] = position
        self._lowest_cut.append(_NO_CUT)
        rounds = 0
        try:
            while True:
                self.computed += 1
                scratch = facts.scratch()
                try:
                    result: FunctionSummary | None = summarize(scratch, function)
                finally:
                    scratch.close()
                lowest = self._lowest_cut[position]
                if lowest == _NO_CUT:
                    self._final[key] = result
                    return result
                if lowest < position:  # part of a cycle through a summary below: provisional
                    if position:
                        self._lowest_cut[position - 1] = min(self._lowest_cut[position - 1], lowest)
                    return result
                # the head of a cycle: again, with this pass's summary, until it settles
                if rounds and result == self._provisional.get(key):
                    break
                rounds += 1
                if rounds >= _MAX_ROUNDS:
                    result = None
                    break
                self._provisional[key] = result  # type: ignore[assignment]
                self._lowest_cut[position] = _NO_CUT
            self._provisional.pop(key, None)
            self._final[key] = result
            return result
        finally:
            del self._positions[key]
            self._lowest_cut.pop()


# --- the project: modules imported by qualified name ------------------------------------------


def project_root(path: str) -> Path | None:
    """The nearest folder above `path`, symlinks resolved, that holds a project marker (pyproject.toml,
    setup.py, setup.cfg, .git): the project whose naming votes the file reads, and whose files one
    worker takes in a row."""
    folder = os.path.dirname(os.path.realpath(path)) if os.path.islink(path) else _real_folder(_folder_of(path))
    root = _root_of_folder(folder)
    return None if root is None else Path(root)


@lru_cache(maxsize=65536)
def _real_folder(folder: str) -> str:
    return os.path.realpath(folder)  # asked once per folder, not once per file


# Module resolution works on `str` paths: it runs for every import line of every file of a run, and
# `Path` objects cost more to build, hash and compare than the lookups themselves.
@lru_cache(maxsize=65536)
def _root_of_folder(folder: str) -> str | None:
    candidate = folder
    while True:
        if any(os.path.exists(os.path.join(candidate, marker)) for marker in _PROJECT_MARKERS):
            return candidate
        parent = os.path.dirname(candidate)
        if parent == candidate:
            return None
        candidate = parent


def module_file(module: str, importer: str, level: int = 0) -> Path | None:
    """The project file a module name resolves to from `importer` (absolute or relative), or None."""
    found = module_path(module, importer, level)
    return None if found is None else _one_path(found)


def module_path(module: str, importer: str, level: int = 0) -> str | None:
    """`module_file` as an absolute `str` path."""
    return _module_file_from(module, _folder_of(importer), level)


def may_be_project_import(imported: str, importer: str) -> bool:
    """Whether a name imported as `imported` (`slam.geometry.apply_pose`) may be a project module's:
    not a known third-party package (`numpy`, `torch`), and one a project folder can hold."""
    top = imported.split(".")[0]
    return top not in THIRD_PARTY_ROOTS and (not top or not importer or may_be_project_module(top, importer))


def may_be_project_module(top: str, importer: str) -> bool:
    """Whether an absolute import whose first name is `top` can resolve to a project file from
    `importer`: the first test `_module_in` makes in each folder `module_file` searches (`gym`,
    `carla` and `time` are in none of them). Always True outside `folder_listings`."""
    if _listings is None:
        return True
    here = _folder_of(importer)
    return _top_held_from(top, here) or _top_held_in_workspace(top, here)


def _top_held_in_workspace(top: str, here: str) -> bool:
    """`top` (or `top.py`) in a folder of the ROS workspace around `here` (`_workspace_folders`)."""
    folders = _workspace_folders(here)
    if not folders:
        return False
    key = (top, here)
    found = _workspace_tops.get(key)
    if found is None:
        found = _workspace_tops[key] = any(_may_hold(base, top) or _may_hold(base, top + ".py") for base in folders)
    return found


def _top_held_from(top: str, here: str) -> bool:
    """`top` (or `top.py`) in `here` or a folder searched after it: the folders searched from a folder
    below the project root are that folder and those searched from its parent, so each answer is
    one listing lookup plus its parent's answer."""
    key = (top, here)
    found = _listed_tops.get(key)
    if found is None:
        folders = _search_folders(here, 0)
        found = bool(folders) and (
            _may_hold(folders[0], top) or _may_hold(folders[0], top + ".py") or (len(folders) > 1 and _top_held_from(top, folders[1]))
        )
        _listed_tops[key] = found
    return found


@lru_cache(maxsize=65536)
def _folder_of(path: str) -> str:
    return os.path.dirname(os.path.abspath(path))


@lru_cache(maxsize=65536)
def _module_file_from(module: str, here: str, level: int) -> str | None:
    parts = tuple(part for part in module.split(".") if part)
    if not parts:
        return None
    for base in _search_folders(here, level):
        found = _module_in(base, parts)
        if found is not None:
            return found
    if not level:
        for base in _workspace_folders(here):
            found = _module_in(base, parts)
            if found is not None:
                return found
    return None


PACKAGE_MANIFEST: Final = "package.xml"  # a ROS package (REP 140/149)


@lru_cache(maxsize=65536)
def _workspace_folders(here: str) -> tuple[str, ...]:
    """Where the other packages of a ROS workspace keep their modules, for a file in one of them: the
    packages beside its own (each with a `package.xml`), their `src/` (catkin) and themselves
    (ament_python). A workspace's packages import each other (`carla_common.transforms` from
    `carla_ros_bridge`), and none of them holds the others."""
    package = package_of_folder(here)
    if package is None:
        return ()
    workspace = os.path.dirname(package)
    try:
        names = sorted(os.listdir(workspace))
    except OSError:
        return ()
    found: list[str] = []
    for name in names:
        sibling = os.path.join(workspace, name)
        if sibling != package and os.path.isfile(os.path.join(sibling, PACKAGE_MANIFEST)):
            found += [os.path.join(sibling, "src"), sibling]
    return tuple(found)


@lru_cache(maxsize=65536)
def package_of_folder(folder: str) -> str | None:
    """The ROS package a folder belongs to: the nearest folder at or above it holding a `package.xml`."""
    candidate = folder
    while True:
        if os.path.isfile(os.path.join(candidate, PACKAGE_MANIFEST)):
            return candidate
        parent = os.path.dirname(candidate)
        if parent == candidate:
            return None
        candidate = parent


@lru_cache(maxsize=65536)
def _search_folders(here: str, level: int) -> tuple[str, ...]:
    """Where a module name imported from folder `here` may live (relative: `level` folders up)."""
    if level:
        base = here
        for _ in range(level - 1):
            base = os.path.dirname(base)
        return (base,)
    root = _root_of_folder(here)
    if root is None:
        return ()
    candidates = []
    folder = here
    while True:  # src layouts and scripts next to their package: any folder up to the root
        candidates.append(folder)
        parent = os.path.dirname(folder)
        if folder == root or parent == folder:
            break
        folder = parent
    return tuple(candidates)


@lru_cache(maxsize=65536)
def _one_path(file: str) -> Path:
    """One `Path` object per module file: the summaries' dicts then find it by identity."""
    return Path(file)


@lru_cache(maxsize=65536)
def _module_in(base: str, parts: tuple[str, ...]) -> str | None:
    """`base/a/b.py` or `base/a/b/__init__.py` for module `a.b`, when it is a file: asked once per folder
    (the modules of sibling folders share the folders above them)."""
    if not _may_hold(base, parts[0]) and not (len(parts) == 1 and _may_hold(base, parts[0] + ".py")):
        return None
    folder = os.path.join(base, *parts[:-1])
    target = os.path.join(folder, parts[-1])
    # the listing of the module's own folder first: most names tried are not there (`from utils
    # import helper_function` tries `utils/helper_function.py`), and a listing is read once per folder
    if _may_hold(folder, parts[-1] + ".py") and os.path.isfile(target + ".py"):
        return target + ".py"
    if _may_hold(folder, parts[-1]) and os.path.isfile(os.path.join(target, "__init__.py")):
        return os.path.join(target, "__init__.py")
    return None


# folder -> its entries' names, casefolded, while `folder_listings` is active (one listing per folder
# instead of a stat per module name per folder: `import numpy` is looked for in every folder up to the root)
_listings: dict[str, frozenset[str]] | None = None
_listed_tops: dict[tuple[str, str], bool] = {}  # `may_be_project_module`'s answers, for one listing
_workspace_tops: dict[tuple[str, str], bool] = {}  # the same, for the packages of a ROS workspace


@contextmanager
def folder_listings() -> Iterator[None]:
    """Within this block, a folder's listing says which module names it cannot hold (for a run that
    resolves the imports of many files at one moment; the files found are still checked one by one)."""
    global _listings
    _listings = {}
    _listed_tops.clear()
    _workspace_tops.clear()
    try:
        yield
    finally:
        _listings = None
        _listed_tops.clear()
        _workspace_tops.clear()


def consulted_folders(files: Iterable[str]) -> set[str]:
    """The folders whose entries decided where the imports of `files` (absolute paths) resolved within
    this `folder_listings` block: every folder listed, and each file's folders up to its project root
    (where project markers were looked for; up to the file system's root when there is none)."""
    folders = set(_listings or ())
    climbed: set[str] = set()
    for folder in {_folder_of(file) for file in files}:
        root = _root_of_folder(folder)
        while folder not in climbed:
            climbed.add(folder)
            parent = os.path.dirname(folder)
            if folder == root or parent == folder:
                break
            folder = parent
    return folders | climbed


def _may_hold(folder: str, name: str) -> bool:
    listings = _listings
    if listings is None:
        return True
    names = listings.get(folder)
    if names is None:
        try:
            names = frozenset(entry.casefold() for entry in os.listdir(folder))
        except OSError:
            names = frozenset()
        listings[folder] = names
    return name.casefold() in names  # casefolded: a case-insensitive file system finds `Geometry.py` too


def imported_files(path: str, source: str, read: bool = False) -> list[str]:
    """The project files `source` imports directly (by a cheap scan of its import lines): the modules
    named, and for `from pkg import geom` the submodule `pkg.geom` too. `read`: the caller read
    `source` from the file at `path` (no need to check that it is one)."""
    if not read and not os.path.isfile(path):
        return []
    found = []
    tops: dict[str, bool] = {}  # `from numpy import a, b, c` asks about `numpy` once
    for name in imported_names(source, members=True):
        level = len(name) - len(name.lstrip("."))
        if not level:
            top = name.partition(".")[0]
            held = tops.get(top)
            if held is None:
                held = tops[top] = may_be_project_module(top, path)
            if not held:
                continue  # `numpy`, `torch.nn`: no project folder holds the package
        file = module_path(name.lstrip("."), path, level)
        if file is not None and file not in found:
            found.append(file)
    return found


def imported_names(source: str, members: bool = False) -> list[str]:
    """The module names of the import statements in `source`, exactly as `_IMPORT.finditer` finds them
    (a match never spans lines, so each line start gives at most one). With `members`, each name a
    `from X import a, b` brings in is added as `X.a`, `X.b` too (it may be a submodule)."""
    names = []
    tried = -1
    at = source.find("import")
    while at >= 0:
        line = source.rfind("\n", 0, at) + 1
        if line != tried:
            tried = line
            match = _IMPORT_AT_LINE_START.match(source, line)
            if match is not None:
                names.append(match.group(1) or match.group(2))
                if members and match.group(1):
                    names.extend(_joined(match.group(1), member) for member in _imported_members(source, match.end()))
        at = source.find("import", at + 6)
    return names


_MEMBER: Final = re.compile(r"[A-Za-z_]\w*")


def _imported_members(source: str, start: int) -> list[str]:
    """The names after `from X import` (up to the line's end, or the closing parenthesis)."""
    rest = source[start : start + 2000]
    stripped = rest.lstrip(" \t")
    if stripped.startswith("("):
        text = stripped[1 : stripped.find(")") if ")" in stripped else len(stripped)]
    else:
        text = rest.split("\n", 1)[0]
        while text.rstrip().endswith("\\"):  # a continued line
            consumed = len(text) + 1
            text = text.rstrip()[:-1] + " " + rest[consumed:].split("\n", 1)[0]
    members = []
    for part in text.split("#", 1)[0].split(","):
        words = part.split()
        if words and _MEMBER.fullmatch(words[0]):
            members.append(words[0])
    return members


def _joined(module: str, member: str) -> str:
    return f"{module}{member}" if module.endswith(".") else f"{module}.{member}"


_UNREADABLE: Final = "-"  # the hash of a module that could not be read


class ImportGraph:
    """The project modules each file imports, transitively, and one digest of them per file.

    Files are registered with their text and hash as a run reads them (`register`); a module outside
    the run is read when first reached. Digests are computed once per strongly connected component
    of the import graph (an import cycle is one component): the digest of a component combines its
    members' hashes with the digests of the components it imports, so each module is read, scanned
    and hashed once and each edge followed once, however many files reach it.
    """

    def __init__(self, content_hash, resolved_before: Mapping[str, Sequence[Any]] | None = None) -> None:  # type: ignore[no-untyped-def]
        self.content_hash = content_hash
        # file -> [its hash, its imports] from an earlier run whose folders are unchanged (`resolved`):
        # a file with the same hash imports the same files, without being decoded or scanned
        self._resolved_before = resolved_before or {}
        self.reused = 0  # files whose imports came from `resolved_before`
        self._imports: dict[str, list[str]] = {}
        self._hashes: dict[str, str] = {}
        self._component: dict[str, int] = {}  # file -> its component's number
        self._component_digest: list[str | None] = []  # None: the component imports nothing else

    def register(self, path: str, source: str, own_hash: str, read: bool = False) -> str:
        """A file of the run, given by the caller (`read`: read from `path` just now): its hash and
        direct imports (its absolute path is returned)."""
        key = os.path.abspath(path)
        if key not in self._imports:
            self._hashes[key] = own_hash
            self._imports[key] = imported_files(path, source, read) if "import" in source else []
        return key

    def register_file(self, path: str, data: bytes, read: bool = False) -> tuple[str, str]:
        """`register` from the file's bytes: (its hash, its key)."""
        own = self.content_hash(data)
        key = os.path.abspath(path)
        if key not in self._imports and not self._reuse(key, own):
            self.register(path, data.decode("utf-8", errors="replace"), own, read)
        return own, key

    def _reuse(self, key: str, own_hash: str) -> bool:
        """Take the file's imports from the earlier run when its bytes are the same."""
        before = self._resolved_before.get(key)
        if before is None or before[0] != own_hash:
            return False
        self._hashes[key], self._imports[key] = own_hash, list(before[1])
        self.reused += 1
        return True

    @property
    def all_reused(self) -> bool:
        """Whether every file read so far took its imports from `resolved_before`."""
        return self.reused == len(self._hashes)

    def resolved(self) -> dict[str, list[Any]]:
        """file -> [its hash, the project files it imports] for every file read so far (what
        `resolved_before` takes in a later run)."""
        return {file: [own, self._imports[file]] for file, own in self._hashes.items() if own != _UNREADABLE}

    def file_digest(self, key: str, own_hash: str) -> str:
        """The digest a registered file is cached under: its own hash, combined with `digest(key)`."""
        imported = self.digest(key)
        if imported is None:
            return own_hash
        return hashlib.blake2b(f"{own_hash}:{imported}".encode(), digest_size=16).hexdigest()

    def _read(self, file: str) -> None:
        try:
            with open(file, "rb") as stream:
                data = stream.read()
        except OSError:
            self._hashes[file], self._imports[file] = _UNREADABLE, []
            return
        own = self._hashes[file] = self.content_hash(data)
        if not self._reuse(file, own):
            source = data.decode("utf-8", errors="replace")
            self._imports[file] = imported_files(file, source, read=True) if "import" in source else []

    def _successors(self, file: str) -> list[str]:
        if file not in self._imports:
            self._read(file)
        return self._imports[file]

    def digest(self, key: str) -> str | None:
        """The digest of everything `key` (registered) imports, directly or not, itself included when
        it is in a cycle; None when it imports no project module."""
        if key not in self._component:
            self._number_components(key)
        return self._component_digest[self._component[key]]

    def _number_components(self, start: str) -> None:
        """Tarjan's algorithm, iterative, from `start`: number every new component and compute its
        digest (a component is finished only after every component it imports)."""
        index: dict[str, int] = {}
        lowlink: dict[str, int] = {}
        stack: list[str] = []
        on_stack: set[str] = set()
        work = [(start, iter(self._successors(start)))]
        index[start] = lowlink[start] = 0
        stack.append(start)
        on_stack.add(start)
        while work:
            file, successors = work[-1]
            pushed = False
            for successor in successors:
                if successor in self._component:
                    continue  # finished in an earlier call
                if successor not in index:
                    index[successor] = lowlink[successor] = len(index)
                    stack.append(successor)
                    on_stack.add(successor)
                    work.append((successor, iter(self._successors(successor))))
                    pushed = True
                    break
                if successor in on_stack:
                    lowlink[file] = min(lowlink[file], index[successor])
            if pushed:
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                lowlink[parent] = min(lowlink[parent], lowlink[file])
            if lowlink[file] == index[file]:
                members = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    members.append(member)
                    if member == file:
                        break
                self._finish_component(members)

    def _finish_component(self, members: list[str]) -> None:
        number = len(self._component_digest)
        for member in members:
            self._component[member] = number
        inside = set(members)
        # a module that imports nothing stands for itself by its hash
        imported = sorted(
            {self._component_digest[self._component[file]] or self._hashes[file]
             for member in members for file in self._imports[member] if file not in inside}
        )  # fmt: skip
        in_cycle = len(members) > 1 or members[0] in self._imports[members[0]]
        if not imported and not in_cycle:
            self._component_digest.append(None)
            return
        digest = hashlib.blake2b(digest_size=16)
        for member in sorted(members):
            digest.update(self._hashes[member].encode())
        for part in imported:
            digest.update(part.encode())
        self._component_digest.append(digest.hexdigest())


def dependency_digest(path: str, data: bytes, content_hash, graph: ImportGraph | None = None) -> str:  # type: ignore[no-untyped-def]
    """The file's own hash, combined with the digest of every project module it imports, directly or
    through other project modules (a summary may read a helper any number of imports away).

    A run passes one `graph` for all its files, so each module is read and scanned once; a run that
    registers all its files first (`register_file`) never reads one of them a second time.
    """
    graph = graph or ImportGraph(content_hash)
    own, key = graph.register_file(path, data)
    return graph.file_digest(key, own)


def _module_index_of_file(file: Path) -> ModuleIndex | None:
    """The parse and index of a project module, shared by every lint of the process (and with the
    engine, when the module is linted too): they depend on the file's text alone, unlike its summaries."""
    return index_of_file(file)
