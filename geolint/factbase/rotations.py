"""Conventions of well-known rotation APIs: quaternion component order and angle units, keyed by
qualified names resolved through the module's imports (one table per question)."""

from __future__ import annotations

from typing import Final, TYPE_CHECKING

import ast
import re
from ast import (
    Attribute,
    Call,
    Constant,
    ListComp,
    Name,
    Starred,
    Subscript,
)

from geolint.factbase import library_calls
from geolint.factbase.library_calls import ImportBranches, branch_qualified_name, imported_modules  # noqa: F401  (re-exported for the rules)
from geolint.factbase.control_flow import runs_unconditionally
from geolint.factbase.syntax import keyword, last_name, number
from geolint.knowledge import knowledge_base

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

SCALAR_LAST: Final = "xyzw"
SCALAR_FIRST: Final = "wxyz"
TRIG_FUNCTIONS: Final = frozenset({"sin", "cos", "tan"})

def quaternion_order(facts: FactBase, call: Call) -> str | None:
    """The component order the called API expects for its quaternion argument, or None if unknown."""
    if library_calls.called_api(facts, call) is not None:  # the knowledge base (stubs/) knows the call
        known = library_calls.expected_quaternion_order(facts, call)
        return known[0] if known is not None else None
    return None


def quaternion_argument(facts: FactBase, call: Call) -> ast.expr | None:
    """The one argument of a quaternion consumer that holds the whole quaternion (a 4-vector or a
    stack of them), or None: the call spells components out, or the API takes no quaternion first."""
    positional = [arg for arg in call.args if not isinstance(arg, Starred)]
    if len(positional) != len(call.args):
        return None
    if library_calls.called_api(facts, call) is not None:  # the knowledge base (stubs/) knows the call
        known = library_calls.expected_quaternion_order(facts, call)
        return known[1] if known is not None else None
    return positional[0] if positional else None


def spread_argument(facts: FactBase, call: Call) -> ast.expr | None:
    """`Quaternion(*q)`: the one starred argument spread into an API that takes the four
    components one by one (pyquaternion, numpy-quaternion, ROS messages), or None."""
    if len(call.args) != 1 or not isinstance(call.args[0], Starred) or call.keywords:
        return None
    if library_calls.called_api(facts, call) is not None:  # the knowledge base (stubs/) knows the call
        return library_calls.spread_quaternion(facts, call)
    return None


def pybullet_orientation_arguments(call: Call) -> list[ast.expr]:
    """The (x, y, z, w) orientation arguments of a pybullet call that takes them beside positions
    (`resetBasePositionAndOrientation(body, pos, orn)`, `loadURDF(path, pos, orn)`,
    `multiplyTransforms(p1, o1, p2, o2)`...), positional or by keyword."""
    name = last_name(call.func) or ""
    spec = _PYBULLET_ORIENTATION_ARGUMENTS.get(name)
    if spec is None or any(isinstance(arg, Starred) for arg in call.args):
        return []
    positions, keywords = spec
    found = [call.args[position] for position in positions if position < len(call.args)]
    found += [given.value for given in call.keywords if given.arg in keywords]
    return found


def pybullet_quaternion_values(call: Call) -> list[tuple[str, ast.expr]]:
    """(parameter, value) for each value a pybullet call reads as one (x, y, z, w) quaternion: its
    orientation arguments, a shape's or a body's inertial frame orientation, and each quaternion written
    out in a list of them (a list literal's items, a list comprehension's element)."""
    name = last_name(call.func) or ""
    found = [("orientation", value) for value in pybullet_orientation_arguments(call)]
    single, lists = _PYBULLET_FRAME_ORIENTATIONS.get(name, (frozenset(), frozenset()))
    for given in call.keywords:
        if given.arg in single:
            found.append((given.arg, given.value))
        elif given.arg in lists:
            value = given.value
            items = [value.elt] if isinstance(value, ListComp) else value.elts if isinstance(value, (ast.List, ast.Tuple)) else []
            found.extend((given.arg, item) for item in items)
    return found


def quaternion_producer(facts: FactBase, call: Call) -> str | None:
    """The component order of the quaternion a library call returns, or None if unknown."""
    func = call.func
    if library_calls.called_api(facts, call) is not None:  # the knowledge base (stubs/) knows the call
        return library_calls.quaternion_output(facts, call)
    if isinstance(func, Attribute) and func.attr == "as_quat":  # on an object of unknown class: the keyword says
        scalar_first = keyword(call, "scalar_first")
        value = scalar_first.value if scalar_first is not None else None
        if isinstance(value, Constant) and value.value in (True, False):
            return SCALAR_FIRST if value.value else SCALAR_LAST
    return None


# (Christoph Gohlke's transformations.py, as PyPI's transformations, trimesh.transformations, ROS tf.transformations
# and tf_transformations ship it: stubs/transformations, stubs/trimesh, stubs/tf, stubs/tf_transformations.)
_PYBULLET_ORIENTATION_ARGUMENTS: Final[dict[str, tuple[tuple[int, ...], frozenset[str]]]] = {
    "resetBasePositionAndOrientation": ((2,), frozenset({"ornObj"})),
    "loadURDF": ((2,), frozenset({"baseOrientation"})),
    "createMultiBody": ((), frozenset({"baseOrientation"})),
    "multiplyTransforms": ((1, 3), frozenset({"orientationA", "orientationB"})),
    "invertTransform": ((1,), frozenset({"orientation"})),
    "calculateInverseKinematics": ((3,), frozenset({"targetOrientation"})),
}
# the names `pybullet_orientation_arguments` reads (its cheap first test, by `last_name`)
PYBULLET_ORIENTATION_CALLS: Final = frozenset(_PYBULLET_ORIENTATION_ARGUMENTS)
# pybullet keywords that take (x, y, z, w) quaternions besides the orientation arguments above: (one
# quaternion, a list of them, one per shape or link). pybullet.c reads each with
# pybullet_internalSetVector4d and ignores its result, so a sequence that is not four long leaves the
# default (0, 0, 0, 1) in place (createCollisionShape, createVisualShape, their Array forms, the base of
# createMultiBody), or an uninitialised array for createMultiBody's links.
_PYBULLET_FRAME_ORIENTATIONS: Final[dict[str, tuple[frozenset[str], frozenset[str]]]] = {
    "createVisualShape": (frozenset({"visualFrameOrientation"}), frozenset()),
    "createCollisionShape": (frozenset({"collisionFrameOrientation"}), frozenset()),
    "createVisualShapeArray": (frozenset(), frozenset({"visualFrameOrientations"})),
    "createCollisionShapeArray": (frozenset(), frozenset({"collisionFrameOrientations"})),
    "createMultiBody": (frozenset({"baseInertialFrameOrientation"}), frozenset({"linkOrientations", "linkInertialFrameOrientations"})),
}
# the names `pybullet_quaternion_values` reads
PYBULLET_QUATERNION_CALLS = PYBULLET_ORIENTATION_CALLS | frozenset(_PYBULLET_FRAME_ORIENTATIONS)


def accepts_stacks(facts: FactBase, call: Call) -> bool:
    """Whether the call takes (N, 4) stacks as well as one quaternion: its stub says so (`STACKED`)."""
    return library_calls.quaternion_stacks(facts, call)


def api_label(order: str) -> str:
    return "scalar-last (x, y, z, w)" if order == SCALAR_LAST else "scalar-first (w, x, y, z)"


_FIELD_LETTERS: Final = frozenset("wxyz")
# names that say a quaternion is the identity (`IDENTITY_QUAT`, `no_rotation`)
IDENTITY_NAME: Final = re.compile(r"(?i)(?:^|_)(?:identity|ident|no_rot(?:ation)?|zero_rot(?:ation)?|unit_quat(?:ernion)?)(?:$|_)")


def component_writes_of_parameter(facts: FactBase, stores: list[tuple[Attribute, ast.expr]], plain: set[str]) -> list[tuple[str, str, str]]:
    """A function that fills one object's `x`, `y`, `z` and `w` from the four indices of one of its
    parameters (`msg.x = q[0]` ... `msg.w = q[3]`), unconditionally: the parameter is read in that order.
    Returns (parameter, order, where) for each such object; only the two standard orders count (x, y, z
    permuted among themselves is an axis change, not a convention)."""
    groups: dict[str, dict[str, tuple[Attribute, Subscript]]] = {}
    for target, value in stores:
        if target.attr not in _FIELD_LETTERS or not isinstance(value, Subscript):
            continue
        base = value.value
        if not isinstance(base, Name) or base.id not in plain:
            continue
        groups.setdefault(ast.dump(target.value), {})[target.attr] = (target, value)
    found: list[tuple[str, str, str]] = []
    for group in groups.values():
        if len(group) != 4:
            continue
        bases = {value.value.id for _, value in group.values()}  # type: ignore[attr-defined]
        positions: dict[int, str] = {}
        for letter, (_, value) in group.items():
            index = number(value.slice)
            if type(index) is int and 0 <= index < 4:
                positions[index] = letter
        if len(bases) != 1 or len(positions) != 4:
            continue
        order = "".join(positions[index] for index in range(4))
        if order not in (SCALAR_FIRST, SCALAR_LAST):
            continue
        if not all(runs_unconditionally(facts, facts.parent(target) or target) for target, _ in group.values()):
            continue
        w_target, w_value = group["w"]
        owner = facts.code_of(w_target.value)
        where = f"the fields of `{owner}` in {', '.join(order)} order (`{owner}.w = {facts.code_of(w_value)}`)"
        found.append((bases.pop(), order, where))
    return found
