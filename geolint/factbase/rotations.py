"""Conventions of well-known rotation APIs: quaternion component order and angle units, keyed by
qualified names resolved through the module's imports (one table per question)."""

from __future__ import annotations

from typing import Final, TYPE_CHECKING

import ast
import re
from ast import (
    AST,
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

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

SCALAR_LAST: Final = "xyzw"
SCALAR_FIRST: Final = "wxyz"
TRIG_FUNCTIONS: Final = frozenset({"sin", "cos", "tan"})

# Unresolved names (no import seen) that still mean scipy's Rotation in practice.
_SCIPY_ROTATION_ALIASES: Final = frozenset({"Rotation", "R", "Rot", "ScipyRotation", "SciRotation"})


def is_scipy_rotation_method(facts: FactBase, func: AST, *methods: str) -> bool:
    """Whether `func` is `scipy.spatial.transform.Rotation.<method>` (through imports or the usual aliases)."""
    if not isinstance(func, Attribute) or func.attr not in methods:
        return False
    qualified = facts.qualified_name(func.value) or ""
    if qualified.startswith("scipy.spatial.transform"):
        return qualified.endswith("Rotation")
    return isinstance(func.value, Name) and func.value.id in _SCIPY_ROTATION_ALIASES and func.value.id not in facts.index.imports


_CONSUMED, _PRODUCED = 0, 1  # the two tables of each simulator module


def _simulator_order(facts: FactBase, call: Call, side: int) -> str | None:
    """The order a simulator API (Isaac Gym, Isaac Sim, Isaac Lab) reads (`_CONSUMED`) or returns
    (`_PRODUCED`); `convert_quat` says both in its arguments."""
    found = simulator_function(facts, call.func)
    if found is None:
        return None
    module, name = found
    if name == "convert_quat":
        return _convert_quat_orders(call)[side]
    return _SIMULATOR_TABLES[module][side].get(name)


def quaternion_order(facts: FactBase, call: Call) -> str | None:
    """The component order the called API expects for its quaternion argument, or None if unknown."""
    func = call.func
    called = facts.called_name(func) or ""
    consumed = _simulator_order(facts, call, _CONSUMED) if called in _SIMULATOR_NAMES else None
    if consumed is not None:
        return consumed
    if called in _TRANSFORMS3D_OPERATIONS:
        operation = _operation_order(facts, func)
        if operation is not None:
            return operation
    if library_calls.called_api(facts, call) is not None:  # the knowledge base (stubs/) knows the call
        known = library_calls.expected_quaternion_order(facts, call)
        return known[0] if known is not None else None
    if "uat" not in called:
        return None  # every API below says quat / Quat in its name
    qualified = branch_qualified_name(facts, func) or ""
    name = qualified.rsplit(".", 1)[-1] if qualified else (last_name(func) or "")  # through `import ... as`
    return SCALAR_LAST if name in _PYBULLET_CONSUMERS else None  # pybullet, on the module or on a BulletClient


# transforms3d's quaternion operations (w, x, y, z; the first argument is a quaternion), also under the
# ROS names they are imported as when a module supports ROS 1 (`tf.transformations`) and ROS 2
_TRANSFORMS3D_OPERATIONS: Final = frozenset({"qmult", "qconjugate", "qinverse"})


def _operation_order(facts: FactBase, func: ast.expr) -> str | None:
    qualified = branch_qualified_name(facts, func) or ""
    module, _, name = qualified.rpartition(".")
    if module.startswith("transforms3d") and name in _TRANSFORMS3D_OPERATIONS:
        return SCALAR_FIRST
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


# pyquaternion's Quaternion class, and a module that re-exports it: the nuScenes devkit's
# eval/common/utils.py imports it, and BEVFormer-style dataset code imports it from there.
PYQUATERNION_CLASSES: Final = frozenset(
    {"pyquaternion.Quaternion", "pyquaternion.quaternion.Quaternion", "nuscenes.eval.common.utils.Quaternion"}
)
# pyquaternion Quaternion properties and methods that return another Quaternion
PYQUATERNION_RETURNS_QUATERNION: Final = frozenset({"inverse", "conjugate", "normalised", "unit"})


def is_numpy_quaternion_constructor(facts: FactBase, qualified: str) -> bool:
    """numpy-quaternion's `np.quaternion(w, x, y, z)` / `quaternion.quaternion(...)`: numpy has the
    type only once the module imports `quaternion`, and a bare `quaternion` must be that import."""
    imported = facts.index.imports.values()
    if qualified == "quaternion.quaternion":
        return "quaternion" in imported or "quaternion.quaternion" in imported
    return qualified == "numpy.quaternion" and "quaternion" in imported


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
    if isinstance(func, Attribute) and func.attr == "as_quat":
        scalar_first = keyword(call, "scalar_first")
        if scalar_first is not None:
            value = scalar_first.value
            if isinstance(value, Constant) and value.value in (True, False):
                return SCALAR_FIRST if value.value else SCALAR_LAST
            return None
        return SCALAR_LAST if is_scipy_rotation_value(facts, func.value) else None
    produced = _simulator_order(facts, call, _PRODUCED) if facts.called_name(func) in _SIMULATOR_NAMES else None
    if produced is not None:
        return produced
    qualified = branch_qualified_name(facts, func) or ""
    name = qualified.rsplit(".", 1)[-1] if qualified else (last_name(func) or "")
    if name in _PYBULLET_QUATERNIONS:  # camelCase pybullet names, on the module or a client object
        return SCALAR_LAST
    return None


def is_scipy_rotation_value(facts: FactBase, node: AST) -> bool:
    """Whether `node` is a scipy `Rotation` object: `Rotation.from_*(...)` (possibly `.inv()`-ed),
    or a name bound only to one. The method name alone (`r.as_quat()`) is no evidence."""
    for _ in range(8):
        if isinstance(node, Call) and isinstance(node.func, Attribute):
            if is_scipy_rotation_method(facts, node.func, *_SCIPY_CONSTRUCTORS):
                return True
            if node.func.attr in ("inv", "__mul__") or node.func.attr == "reduce":
                node = node.func.value
                continue
            return False
        if isinstance(node, Name):
            bound = facts.bindings(node) or []
            values = [binding for binding in bound if isinstance(binding, ast.expr)]
            if not values or len(values) != len(bound):
                return False
            return all(is_scipy_rotation_value(facts, value) for value in values if value is not node)
        return False
    return False


_SCIPY_CONSTRUCTORS: Final = (
    "from_quat", "from_matrix", "from_euler", "from_rotvec", "from_mrp", "from_davenport", "from_dcm",
    "random", "identity", "concatenate",
)  # fmt: skip
# pybullet (x, y, z, w) quaternions, called on the module or on a BulletClient.
_PYBULLET_QUATERNIONS: Final = frozenset({"getQuaternionFromEuler", "getQuaternionFromAxisAngle", "getDifferenceQuaternion"})
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
_PYBULLET_CONSUMERS: Final = frozenset({"getMatrixFromQuaternion", "getEulerFromQuaternion", "getAxisAngleFromQuaternion"})


def simulator_function(facts: FactBase, func: AST) -> tuple[str, str] | None:
    """(module, name) of an Isaac Gym / Isaac Sim / Isaac Lab quaternion function in `_SIMULATOR_TABLES`,
    through imports or through the one star import of such a module (`from isaacgym.torch_utils import *`,
    as most Isaac Gym tasks write it) when the module binds no name of its own that shadows it."""
    qualified = facts.qualified_name(func) or ""
    module, _, name = qualified.rpartition(".")
    module = _SIMULATOR_ALIASES.get(module, module)
    if module in _SIMULATOR_TABLES:
        return module, name
    if not isinstance(func, Name) or func.id in facts.index.imports:
        return None
    starred = _star_imported_tables(facts)
    if len(starred) != 1 or facts.index.lookup(func.id, facts.index.scope_of(func)):
        return None  # none, or two tables that may disagree (`quat_mul` is x, y, z, w in one, w, x, y, z in the other)
    (module,) = starred
    tables = _SIMULATOR_TABLES[module]
    return (module, func.id) if func.id in tables[0] or func.id in tables[1] or func.id == "convert_quat" else None


def _star_imported_tables(facts: FactBase) -> frozenset[str]:
    return frozenset(
        module for module in (_SIMULATOR_ALIASES.get(module, module) for module in facts.index.star_imports) if module in _SIMULATOR_TABLES
    )


def _convert_quat_orders(call: Call) -> tuple[str | None, str | None]:
    """Isaac Lab's `convert_quat(q, to="xyzw")`: (the order it reads, the order it returns). The same in
    every Isaac Lab version, whatever the library's own convention."""
    given = keyword(call, "to")
    target = given.value if given is not None else call.args[1] if len(call.args) > 1 else None
    to = SCALAR_LAST if target is None else target.value if isinstance(target, Constant) else None
    if to not in (SCALAR_LAST, SCALAR_FIRST):
        return None, None
    return (SCALAR_FIRST if to == SCALAR_LAST else SCALAR_LAST), to  # type: ignore[return-value]


def isaac_orientation_arguments(facts: FactBase, call: Call) -> list[ast.expr]:
    """The (w, x, y, z) orientation arguments of an Isaac Sim core call: `orientation=` / `orientations=`
    of a prim, object or view constructor (`XFormPrim(path, orientation=q)`, `DynamicCuboid(...)`,
    `RigidPrimView(...)`) or of `create_prim`, and the orientation of `set_world_pose(position, orientation)`,
    `set_local_pose`, `set_default_state`, `set_world_poses`, `set_local_poses` in a module that imports
    Isaac Sim's core (OmniGibson's prims, which take x, y, z, w, are left alone)."""
    if not mentions_isaac_core(facts):
        return []  # every call below is Isaac Sim's, which only an import of its core can bring in
    func = call.func
    if isinstance(func, Attribute) and func.attr in _ISAAC_POSE_SETTERS:
        if not _imports_isaac_core(facts) or any(isinstance(arg, Starred) for arg in call.args):
            return []
        found = [call.args[1]] if len(call.args) > 1 else []
        return found + [given.value for given in call.keywords if given.arg in ("orientation", "orientations")]
    qualified = facts.qualified_name(func) or ""
    name = qualified.rpartition(".")[2]
    if not qualified.startswith(_ISAAC_CORE) or not (name[:1].isupper() or qualified == _ISAAC_CREATE_PRIM):
        return []
    return [given.value for given in call.keywords if given.arg in ("orientation", "orientations")]


def mentions_isaac_core(facts: FactBase) -> bool:
    """Whether the module imports something of Isaac Sim's core: without it `isaac_orientation_arguments`
    is [] for every call (a rule asking of every call may test this once per module)."""
    return facts.module_fact("mentions isaac core", lambda: any(name.startswith(_ISAAC_CORE) for name in imported_modules(facts)))


def _imports_isaac_core(facts: FactBase) -> bool:
    """Isaac Sim's core, and not OmniGibson (whose prims take x, y, z, w)."""

    def compute() -> bool:
        return mentions_isaac_core(facts) and not any(name.startswith("omnigibson") for name in imported_modules(facts))

    return facts.module_fact("imports isaac core", compute)


def accepts_stacks(facts: FactBase, call: Call) -> bool:
    """Isaac Gym / Isaac Sim quaternion functions and prim views take (N, 4) stacks as well as one quaternion."""
    return simulator_function(facts, call.func) is not None or bool(isaac_orientation_arguments(facts, call))


def _quaternion_functions(order: str, *names: str) -> dict[str, str]:
    return {name: order for name in names}


# Isaac Gym, Isaac Sim and Isaac Lab quaternion functions: module -> (consumers, producers), each name ->
# the order of the quaternion it reads first / returns. Read in each library's source:
# - isaacgym/python/isaacgym/torch_utils.py (Isaac Gym Preview 4): `quat_mul` unpacks `x1, y1, z1, w1`,
#   `quat_from_euler_xyz` stacks `[qx, qy, qz, qw]`, `quat_rotate` takes `q_w = q[:, -1]`;
# - omni.isaac.core/omni/isaac/core/utils/rotations.py (Isaac Sim 4.1): docstrings "quaternion (w, x, y, z)";
# - omni.isaac.core/omni/isaac/core/utils/torch/rotations.py: `quat_mul` unpacks `w1, x1, y1, z1`,
#   `euler_angles_to_quats` returns "scalar first", `xyzw2wxyz` is `torch.roll(q, 1, -1)`;
# - IsaacLab source/extensions/omni.isaac.lab/omni/isaac/lab/utils/math.py: every docstring "(w, x, y, z)".
#   Its successor `isaaclab.utils.math` is left out: newer Isaac Lab releases switched it to (x, y, z, w)
#   (same function names), so only its convention-free `convert_quat` is read.
_ISAACGYM_QUATERNIONS: Final = ("quat_mul", "quat_conjugate", "quat_unit")
_OMNI_TORCH_QUATERNIONS: Final = ("quat_mul", "quat_conjugate", "quat_unit")
_OMNI_LAB_QUATERNIONS: Final = ("quat_mul", "quat_conjugate", "quat_inv", "quat_unique", "yaw_quat")
_SIMULATOR_TABLES: Final[dict[str, tuple[dict[str, str], dict[str, str]]]] = {
    "isaacgym.torch_utils": (
        _quaternion_functions(
            SCALAR_LAST, *_ISAACGYM_QUATERNIONS, "quat_apply", "quat_rotate", "quat_rotate_inverse", "get_euler_xyz",
            "get_basis_vector", "tf_inverse", "tf_apply", "tf_vector", "tf_combine",
        ),
        _quaternion_functions(SCALAR_LAST, *_ISAACGYM_QUATERNIONS, "quat_from_angle_axis", "quat_from_euler_xyz"),
    ),
    "omni.isaac.core.utils.rotations": (
        _quaternion_functions(SCALAR_FIRST, "quat_to_rot_matrix", "quat_to_euler_angles"),
        _quaternion_functions(
            SCALAR_FIRST, "euler_angles_to_quat", "rot_matrix_to_quat", "gf_quat_to_np_array", "gf_rotation_to_np_array"
        ),
    ),
    "omni.isaac.core.utils.torch.rotations": (
        {
            **_quaternion_functions(
                SCALAR_FIRST, *_OMNI_TORCH_QUATERNIONS, "quat_apply", "quat_rotate", "quat_rotate_inverse", "quat_axis",
                "quats_to_rot_matrices", "get_euler_xyz", "get_basis_vector", "quat_diff_rad", "wxyz2xyzw",
            ),
            "xyzw2wxyz": SCALAR_LAST,
        },
        {
            **_quaternion_functions(
                SCALAR_FIRST, *_OMNI_TORCH_QUATERNIONS, "quat_from_angle_axis", "quat_from_euler_xyz",
                "euler_angles_to_quats", "rot_matrices_to_quats", "gf_quat_to_tensor", "xyzw2wxyz",
            ),
            "wxyz2xyzw": SCALAR_LAST,
        },
    ),
    "omni.isaac.lab.utils.math": (
        _quaternion_functions(
            SCALAR_FIRST, *_OMNI_LAB_QUATERNIONS, "matrix_from_quat", "euler_xyz_from_quat", "quat_apply",
            "quat_apply_yaw", "quat_rotate", "quat_rotate_inverse", "axis_angle_from_quat", "quat_box_minus",
        ),
        _quaternion_functions(SCALAR_FIRST, *_OMNI_LAB_QUATERNIONS, "quat_from_euler_xyz", "quat_from_matrix", "quat_from_angle_axis"),
    ),
    "isaaclab.utils.math": ({}, {}),  # `convert_quat` only (above)
}  # fmt: skip
# `from omni.isaac.core.utils.torch import *` re-exports the rotations module
_SIMULATOR_ALIASES: Final = {"omni.isaac.core.utils.torch": "omni.isaac.core.utils.torch.rotations"}
_SIMULATOR_NAMES: Final = frozenset(
    {name for consumers, producers in _SIMULATOR_TABLES.values() for name in (*consumers, *producers)} | {"convert_quat"}
)
# Isaac Sim core (`omni.isaac.core` up to 4.2, `isaacsim.core.api` / `isaacsim.core.prims` from 4.5): prims,
# objects and views take `orientation(s)` "quaternion is scalar-first (w, x, y, z)" (docstrings of
# XFormPrim, XFormPrimView and DynamicCuboid in Isaac Sim 4.1; the isaacsim.core.api 4.8.0 API page).
_ISAAC_CORE: Final = ("omni.isaac.core.", "isaacsim.core.")
# `create_prim(path, prim_type, position=..., orientation=...)` hands `orientation` to XFormPrim (its source, 4.1)
_ISAAC_CREATE_PRIM: Final = "omni.isaac.core.utils.prims.create_prim"
_ISAAC_POSE_SETTERS: Final = frozenset({"set_world_pose", "set_local_pose", "set_default_state", "set_world_poses", "set_local_poses"})


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
