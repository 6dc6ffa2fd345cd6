"""Conventions of well-known rotation APIs: quaternion component order and angle units, keyed by
qualified names resolved through the module's imports (one table per question)."""

from __future__ import annotations

import ast

from geolint.factbase.model import FactBase, keyword, last_name

SCALAR_LAST = "xyzw"
SCALAR_FIRST = "wxyz"
TRIG_FUNCTIONS = frozenset({"sin", "cos", "tan"})

# Unresolved names (no import seen) that still mean scipy's Rotation in practice.
_SCIPY_ROTATION_ALIASES = frozenset({"Rotation", "R", "Rot", "ScipyRotation", "SciRotation"})


def is_scipy_rotation_method(facts: FactBase, func: ast.AST, *methods: str) -> bool:
    """Whether `func` is `scipy.spatial.transform.Rotation.<method>` (through imports or the usual aliases)."""
    if not isinstance(func, ast.Attribute) or func.attr not in methods:
        return False
    qualified = facts.qualified_name(func.value) or ""
    if qualified.startswith("scipy.spatial.transform"):
        return qualified.endswith("Rotation")
    return isinstance(func.value, ast.Name) and func.value.id in _SCIPY_ROTATION_ALIASES and func.value.id not in facts.index.imports


def quaternion_order(facts: FactBase, call: ast.Call) -> str | None:
    """The component order the called API expects for its quaternion argument, or None if unknown."""
    func = call.func
    called = facts.called_name(func) or ""
    if "uat" not in called and called != "from_float_array":
        return None  # every API below says quat / Quat in its name, but numpy-quaternion's from_float_array
    if is_scipy_rotation_method(facts, func, "from_quat"):
        scalar_first = keyword(call, "scalar_first")
        if scalar_first is not None:
            value = scalar_first.value
            if isinstance(value, ast.Constant) and value.value is True:
                return SCALAR_FIRST
            if not (isinstance(value, ast.Constant) and value.value is False):
                return None  # decided at run time
        return SCALAR_LAST
    qualified = facts.qualified_name(func) or ""
    name = qualified.rsplit(".", 1)[-1] if qualified else (last_name(func) or "")  # through `import ... as`
    if qualified.startswith("transforms3d.") and name.startswith("quat2"):
        return SCALAR_FIRST
    if qualified.startswith("pytransform3d.") and (name.endswith("_from_quaternion") or name == "check_quaternion"):
        return SCALAR_FIRST
    if qualified in ("pyquaternion.Quaternion", "pyquaternion.quaternion.Quaternion"):
        return SCALAR_FIRST
    if qualified.startswith("spatialmath") and name in ("UnitQuaternion", "Quaternion"):
        return SCALAR_FIRST
    if is_numpy_quaternion_constructor(facts, qualified):
        return SCALAR_FIRST
    if qualified.startswith(("tf.transformations.", "tf_transformations.")) and "quaternion" in name:
        return SCALAR_LAST
    if qualified.startswith("geometry_msgs.") and name == "Quaternion":
        return SCALAR_LAST  # ROS 1 messages take positional fields in declaration order: x, y, z, w
    if name in _PYBULLET_CONSUMERS:  # on the module or on a BulletClient
        return SCALAR_LAST
    return _DATA_CONSUMERS.get(_library_key(qualified, name))


def quaternion_argument(facts: FactBase, call: ast.Call) -> ast.expr | None:
    """The one argument of a quaternion consumer that holds the whole quaternion (a 4-vector or a
    stack of them), or None: the call spells components out, or the API takes no quaternion first."""
    func = call.func
    positional = [arg for arg in call.args if not isinstance(arg, ast.Starred)]
    if len(positional) != len(call.args):
        return None
    if is_scipy_rotation_method(facts, func, "from_quat"):
        given = keyword(call, "quat")
        return positional[0] if positional else given.value if given is not None else None
    qualified = facts.qualified_name(func) or ""
    name = qualified.rsplit(".", 1)[-1] if qualified else (last_name(func) or "")
    if qualified in ("pyquaternion.Quaternion", "pyquaternion.quaternion.Quaternion"):
        given = keyword(call, "array")
        if given is not None and not positional:
            return given.value
        return positional[0] if len(positional) == 1 and not call.keywords else None
    if qualified.startswith("geometry_msgs.") or is_numpy_quaternion_constructor(facts, qualified):
        return None  # takes its components one by one
    if qualified.startswith(("tf.transformations.", "tf_transformations.")) and name not in _TF_QUATERNION_INPUTS:
        return None  # quaternion_from_euler & co take angles or matrices
    if qualified.startswith("spatialmath") and name in ("UnitQuaternion", "Quaternion"):
        return positional[0] if len(positional) == 1 and not call.keywords else None
    return positional[0] if positional else None


def is_numpy_quaternion_constructor(facts: FactBase, qualified: str) -> bool:
    """numpy-quaternion's `np.quaternion(w, x, y, z)` / `quaternion.quaternion(...)`: numpy has the
    type only once the module imports `quaternion`, and a bare `quaternion` must be that import."""
    imported = facts.index.imports.values()
    if qualified == "quaternion.quaternion":
        return "quaternion" in imported or "quaternion.quaternion" in imported
    return qualified == "numpy.quaternion" and "quaternion" in imported


def spread_argument(facts: FactBase, call: ast.Call) -> ast.expr | None:
    """`Quaternion(*q)`: the one starred argument spread into an API that takes the four
    components one by one (pyquaternion, numpy-quaternion, ROS messages), or None."""
    if len(call.args) != 1 or not isinstance(call.args[0], ast.Starred) or call.keywords:
        return None
    qualified = facts.qualified_name(call.func) or ""
    if (
        qualified in ("pyquaternion.Quaternion", "pyquaternion.quaternion.Quaternion")
        or (qualified.startswith("geometry_msgs.") and qualified.endswith(".Quaternion"))
        or is_numpy_quaternion_constructor(facts, qualified)
    ):
        return call.args[0].value
    return None


def pybullet_orientation_arguments(call: ast.Call) -> list[ast.expr]:
    """The (x, y, z, w) orientation arguments of a pybullet call that takes them beside positions
    (`resetBasePositionAndOrientation(body, pos, orn)`, `loadURDF(path, pos, orn)`,
    `multiplyTransforms(p1, o1, p2, o2)`...), positional or by keyword."""
    name = last_name(call.func) or ""
    spec = _PYBULLET_ORIENTATION_ARGUMENTS.get(name)
    if spec is None or any(isinstance(arg, ast.Starred) for arg in call.args):
        return []
    positions, keywords = spec
    found = [call.args[position] for position in positions if position < len(call.args)]
    found += [given.value for given in call.keywords if given.arg in keywords]
    return found


def quaternion_producer(facts: FactBase, call: ast.Call) -> str | None:
    """The component order of the quaternion a library call returns, or None if unknown."""
    func = call.func
    if isinstance(func, ast.Attribute) and func.attr == "as_quat":
        scalar_first = keyword(call, "scalar_first")
        if scalar_first is not None:
            value = scalar_first.value
            if isinstance(value, ast.Constant) and value.value in (True, False):
                return SCALAR_FIRST if value.value else SCALAR_LAST
            return None
        return SCALAR_LAST if is_scipy_rotation_value(facts, func.value) else None
    qualified = facts.qualified_name(func) or ""
    name = qualified.rsplit(".", 1)[-1] if qualified else (last_name(func) or "")
    if name in _PYBULLET_QUATERNIONS:  # camelCase pybullet names, on the module or a client object
        return SCALAR_LAST
    if qualified.startswith("transforms3d.") and (name.endswith("2quat") or name in ("qmult", "qconjugate", "qinverse", "qeye")):
        return SCALAR_FIRST
    if qualified.startswith("pytransform3d.") and name.startswith("quaternion_from_"):
        return SCALAR_FIRST
    if qualified.startswith("pytorch3d.") and (name.endswith("_to_quaternion") or name in _PYTORCH3D_QUATERNIONS):
        return SCALAR_FIRST
    if qualified.startswith(("tf.transformations.", "tf_transformations.")) and name in _GOHLKE_PRODUCERS:
        return SCALAR_LAST
    if qualified.startswith("trimesh.transformations.") and name in _GOHLKE_PRODUCERS:
        return SCALAR_FIRST
    if qualified.startswith("spatialmath") and name == "r2q" and keyword(call, "order") is None:
        return SCALAR_FIRST
    return _DATA_PRODUCERS.get(_library_key(qualified, name))


def is_scipy_rotation_value(facts: FactBase, node: ast.AST) -> bool:
    """Whether `node` is a scipy `Rotation` object: `Rotation.from_*(...)` (possibly `.inv()`-ed),
    or a name bound only to one. The method name alone (`r.as_quat()`) is no evidence."""
    for _ in range(8):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
            if is_scipy_rotation_method(facts, node.func, *_SCIPY_CONSTRUCTORS):
                return True
            if node.func.attr in ("inv", "__mul__") or node.func.attr == "reduce":
                node = node.func.value
                continue
            return False
        if isinstance(node, ast.Name):
            bound = facts.bindings(node) or []
            values = [binding for binding in bound if isinstance(binding, ast.expr)]
            if not values or len(values) != len(bound):
                return False
            return all(is_scipy_rotation_value(facts, value) for value in values if value is not node)
        return False
    return False


def _library_key(qualified: str, name: str) -> str:
    """`pytorch3d.transforms.rotation_conversions.quaternion_to_matrix` -> `pytorch3d.quaternion_to_matrix`."""
    return f"{qualified.split('.', 1)[0]}.{name}" if qualified else ""


_SCIPY_CONSTRUCTORS = (
    "from_quat", "from_matrix", "from_euler", "from_rotvec", "from_mrp", "from_davenport", "from_dcm",
    "random", "identity", "concatenate",
)  # fmt: skip
# pybullet (x, y, z, w) quaternions, called on the module or on a BulletClient.
_PYBULLET_QUATERNIONS = frozenset({"getQuaternionFromEuler", "getQuaternionFromAxisAngle", "getDifferenceQuaternion"})
# Christoph Gohlke's transformations.py: (w, x, y, z) as trimesh ships it, (x, y, z, w) in ROS tf.
_GOHLKE_PRODUCERS = frozenset(
    {"quaternion_from_matrix", "quaternion_from_euler", "quaternion_about_axis", "random_quaternion",
     "quaternion_multiply", "quaternion_conjugate", "quaternion_inverse", "quaternion_slerp"}
)  # fmt: skip
_TF_QUATERNION_INPUTS = frozenset(
    {"quaternion_matrix", "euler_from_quaternion", "quaternion_multiply", "quaternion_conjugate",
     "quaternion_inverse", "quaternion_slerp", "quaternion_real", "quaternion_imag"}
)  # fmt: skip
_PYTORCH3D_QUATERNIONS = frozenset(
    {"quaternion_multiply", "quaternion_raw_multiply", "quaternion_invert", "standardize_quaternion", "random_quaternions"}
)
# Consumers and producers keyed by `<top package>.<function>` (any submodule).
_DATA_CONSUMERS = {
    **{f"trimesh.{name}": SCALAR_FIRST for name in _TF_QUATERNION_INPUTS},
    **{f"pytorch3d.{name}": SCALAR_FIRST for name in (
        "quaternion_to_matrix", "quaternion_to_axis_angle", "quaternion_apply", "quaternion_multiply",
        "quaternion_raw_multiply", "quaternion_invert", "standardize_quaternion")},
    "quaternion.from_float_array": SCALAR_FIRST,  # numpy-quaternion
    "quaternion.as_quat_array": SCALAR_FIRST,
    "pytransform3d.quaternion_xyzw_from_wxyz": SCALAR_FIRST,
    "pytransform3d.quaternion_wxyz_from_xyzw": SCALAR_LAST,
    "open3d.get_rotation_matrix_from_quaternion": SCALAR_FIRST,
    **{f"roma.{name}": SCALAR_LAST for name in (
        "unitquat_to_rotmat", "unitquat_to_rotvec", "unitquat_to_euler", "quat_product", "quat_action",
        "quat_conjugation", "quat_inverse", "unitquat_slerp")},
}  # fmt: skip
_PYBULLET_ORIENTATION_ARGUMENTS: dict[str, tuple[tuple[int, ...], frozenset[str]]] = {
    "resetBasePositionAndOrientation": ((2,), frozenset({"ornObj"})),
    "loadURDF": ((2,), frozenset({"baseOrientation"})),
    "createMultiBody": ((), frozenset({"baseOrientation"})),
    "multiplyTransforms": ((1, 3), frozenset({"orientationA", "orientationB"})),
    "invertTransform": ((1,), frozenset({"orientation"})),
    "calculateInverseKinematics": ((3,), frozenset({"targetOrientation"})),
}
_PYBULLET_CONSUMERS = frozenset({"getMatrixFromQuaternion", "getEulerFromQuaternion", "getAxisAngleFromQuaternion"})
_DATA_PRODUCERS = {
    **{f"roma.{name}": SCALAR_LAST for name in (
        "rotmat_to_unitquat", "rotvec_to_unitquat", "euler_to_unitquat", "quat_product", "quat_conjugation",
        "quat_inverse", "random_unitquat", "unitquat_slerp")},
    "quaternion.as_float_array": SCALAR_FIRST,  # numpy-quaternion
    "pytransform3d.quaternion_wxyz_from_xyzw": SCALAR_FIRST,
    "pytransform3d.quaternion_xyzw_from_wxyz": SCALAR_LAST,
}


def api_label(order: str) -> str:
    return "scalar-last (x, y, z, w)" if order == SCALAR_LAST else "scalar-first (w, x, y, z)"
