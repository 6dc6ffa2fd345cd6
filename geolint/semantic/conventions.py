"""Conventions of well-known rotation APIs: quaternion component order and angle units.

One table per question, keyed by fully qualified names, so the lint rules, the mypy plugin and
the editor server agree on what `Rotation.from_quat` or `transforms3d.euler.euler2mat` expect.
"""

from __future__ import annotations

import libcst as cst

from geolint.semantic.model import SemanticModel, last_name

SCALAR_LAST = "xyzw"
SCALAR_FIRST = "wxyz"

# Unresolved names (no import seen) that still mean scipy's Rotation in practice.
_SCIPY_ROTATION_ALIASES = frozenset({"Rotation", "R", "Rot", "ScipyRotation", "SciRotation"})


def is_scipy_rotation_method(model: SemanticModel, func: cst.BaseExpression, *methods: str) -> bool:
    """Whether `func` is `scipy.spatial.transform.Rotation.<method>` (through imports or the usual aliases)."""
    if not isinstance(func, cst.Attribute) or func.attr.value not in methods:
        return False
    qualified = model.qualified_name(func.value) or ""
    if qualified.startswith("scipy.spatial.transform"):
        return qualified.endswith("Rotation")
    return isinstance(func.value, cst.Name) and func.value.value in _SCIPY_ROTATION_ALIASES and (
        func.value.value not in model.facts.imports
    )


def quaternion_order(model: SemanticModel, call: cst.Call) -> str | None:
    """The component order the called API expects for its quaternion argument, or None if unknown."""
    func = call.func
    if is_scipy_rotation_method(model, func, "from_quat"):
        scalar_first = next((arg for arg in call.args if arg.keyword and arg.keyword.value == "scalar_first"), None)
        if scalar_first is not None:
            if isinstance(scalar_first.value, cst.Name) and scalar_first.value.value == "True":
                return SCALAR_FIRST
            if not (isinstance(scalar_first.value, cst.Name) and scalar_first.value.value == "False"):
                return None  # decided at run time
        return SCALAR_LAST
    qualified = model.qualified_name(func) or ""
    name = qualified.rsplit(".", 1)[-1] if qualified else (last_name(func) or "")  # through `import ... as`
    if qualified.startswith("transforms3d.") and name.startswith("quat2"):
        return SCALAR_FIRST
    if qualified.startswith("pytransform3d.") and (name.endswith("_from_quaternion") or name == "check_quaternion"):
        return SCALAR_FIRST
    if qualified in ("pyquaternion.Quaternion", "pyquaternion.quaternion.Quaternion"):
        return SCALAR_FIRST
    if qualified.startswith(("spatialmath.", "spatialmath")) and name in ("UnitQuaternion", "Quaternion"):
        return SCALAR_FIRST
    if qualified.startswith(("tf.transformations.", "tf_transformations.")) and "quaternion" in name:
        return SCALAR_LAST
    return None


def api_label(order: str) -> str:
    return "scalar-last (x, y, z, w)" if order == SCALAR_LAST else "scalar-first (w, x, y, z)"


# Radian APIs: qualified-name test -> how to tell that the call opted into degrees.
TRIG_FUNCTIONS = frozenset({"sin", "cos", "tan"})
