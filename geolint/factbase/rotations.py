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
    if qualified.startswith(("tf.transformations.", "tf_transformations.")) and "quaternion" in name:
        return SCALAR_LAST
    return None


def api_label(order: str) -> str:
    return "scalar-last (x, y, z, w)" if order == SCALAR_LAST else "scalar-first (w, x, y, z)"
