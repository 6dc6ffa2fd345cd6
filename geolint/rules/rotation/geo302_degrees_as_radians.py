"""GEO302 degrees-as-radians: literal angles in degrees passed to an API that takes radians."""

from __future__ import annotations

import math

import libcst as cst

from geolint.rules.base import Invalid, Valid
from geolint.semantic.conventions import TRIG_FUNCTIONS, is_scipy_rotation_method
from geolint.semantic.model import int_literal, last_name
from geolint.semantic.prefilter import Trigger, may_pass_degrees
from geolint.semantic.rule_support import SemanticRule, keyword_arg

_TWO_PI = 2 * math.pi
_SPATIALMATH_ANGLE_CALLS = frozenset(
    {"Rx", "Ry", "Rz", "RPY", "Eul", "rotx", "roty", "rotz", "trotx", "troty", "trotz", "rpy2r", "eul2r", "rpy2tr", "eul2tr"}
)


class DegreesAsRadians(SemanticRule):
    """Angles written in degrees are passed to an API that reads radians.

    ## What it does
    Flags literal angles larger than 2 pi passed where radians are expected: scipy
    `Rotation.from_euler` / `from_rotvec` without `degrees=True`, transforms3d `euler2*` and
    `axangle2*`, pytransform3d `*_from_euler` / `*_from_angle`, spatialmath `SE3.Rx` and friends
    without `unit="deg"`, ROS `quaternion_from_euler`, and `np.sin`/`math.cos` of a whole
    multiple of 15 degrees (`np.cos(90)`).

    ## Why is this bad?
    90 radians is about 5157 degrees, i.e. 117 degrees after wrapping: a valid, silently wrong
    rotation. No real pose needs a literal angle above 2 pi.

    ## Example
    ```python
    R_base_tool = Rotation.from_euler("xyz", [0, 0, 90]).as_matrix()
    ```

    ## Use instead
    ```python
    R_base_tool = Rotation.from_euler("xyz", [0, 0, 90], degrees=True).as_matrix()
    ```

    ## Fix safety
    Adding `degrees=True` to a scipy call is safe: an angle above 2 pi written as a literal is a
    degree value. Other APIs get no automatic fix.
    """

    code = "GEO302"
    name = "degrees-as-radians"
    triggers = Trigger("a call to an angle API or trig of a literal", may_pass_degrees)

    VALID = [
        Valid('from scipy.spatial.transform import Rotation\nr = Rotation.from_euler("xyz", [0, 0, 90], degrees=True)\n'),
        Valid('from scipy.spatial.transform import Rotation\nr = Rotation.from_euler("xyz", [0, 0, 1.57])\n'),
        Valid("import numpy as np\nc = np.cos(np.pi / 2)\n"),
        Valid("import numpy as np\nc = np.cos(7.5)\n"),  # not a whole multiple of 15: who knows
        Valid('from spatialmath import SE3\nT = SE3.Rx(90, unit="deg")\n'),
        Valid("from spatialmath import SE3\nT = SE3.Rx(90, 'deg')\n"),
        Valid('from scipy.spatial.transform import Rotation\nr = Rotation.from_euler("z", angle)\n'),
    ]
    INVALID = [
        Invalid(
            'from scipy.spatial.transform import Rotation\nr = Rotation.from_euler("xyz", [0, 0, 90])\n',
            expected_fix='from scipy.spatial.transform import Rotation\nr = Rotation.from_euler("xyz", [0, 0, 90], degrees=True)\n',
        ),
        Invalid(
            'from scipy.spatial.transform import Rotation as R\nr = R.from_euler("z", -45.0)\n',
            expected_fix='from scipy.spatial.transform import Rotation as R\nr = R.from_euler("z", -45.0, degrees=True)\n',
        ),
        Invalid("from transforms3d.euler import euler2mat\nm = euler2mat(0, 0, 180)\n"),
        Invalid("from transforms3d.euler import euler2mat as e2m\nm = e2m(0, 0, 90)\n"),
        Invalid("from spatialmath import SE3\nT = SE3.Rz(90)\n"),
        Invalid("import numpy as np\ny = np.sin(90)\n"),
        Invalid("import pytransform3d.rotations as pr\nm = pr.active_matrix_from_angle(2, 90)\n"),
    ]

    def visit_Call(self, node: cst.Call) -> None:
        angles = self._radian_angles(node)
        if angles is None:
            return
        too_big = [value for value in angles if abs(value) > _TWO_PI]
        if not too_big:
            return
        shown = _format(too_big[0])
        fix = None
        if is_scipy_rotation_method(self.model, node.func, "from_euler", "from_rotvec") and _keyword(node, "degrees") is None:
            fix = node.with_changes(args=(*node.args, keyword_arg("degrees", "True")))
        self.report(
            node,
            f"`{self.code_of(node.func)}` takes radians, but the literal angle {shown} is above 2 pi: "
            "it looks like degrees",
            replacement=fix,
            fix_description="pass degrees=True",
        )

    def _radian_angles(self, node: cst.Call) -> list[float] | None:
        """The literal angles of a call to a radian API, or None when the call is not one (or opted into degrees)."""
        func = node.func
        positional = [arg.value for arg in node.args if arg.keyword is None and not arg.star]
        name = last_name(func) or ""
        if is_scipy_rotation_method(self.model, func, "from_euler", "from_rotvec"):
            degrees = _keyword(node, "degrees")
            if degrees is not None and not (isinstance(degrees.value, cst.Name) and degrees.value.value == "False"):
                return None
            if name == "from_euler":
                angles = positional[1] if len(positional) > 1 else getattr(_keyword(node, "angles"), "value", None)
            else:
                angles = positional[0] if positional else getattr(_keyword(node, "rotvec"), "value", None)
            return _literals(angles) if angles is not None else None
        qualified = self.model.qualified_name(func) or ""
        name = qualified.rsplit(".", 1)[-1] if qualified else name  # through `import ... as`
        if qualified.startswith("transforms3d."):
            if name.startswith("euler2"):
                return _literals_of(positional[:3])
            if name.startswith("axangle2") and len(positional) > 1:
                return _literals(positional[1])
        if qualified.startswith("pytransform3d."):
            if name.endswith("_from_euler") and positional:
                return _literals(positional[0])
            if name.endswith("_from_angle") and len(positional) > 1:
                return _literals(positional[1])
        if qualified.startswith("spatialmath") and name in _SPATIALMATH_ANGLE_CALLS:
            if _keyword(node, "unit") is not None or any(isinstance(value, cst.SimpleString) for value in positional[1:]):
                return None
            return _literals_of(positional[:1] if name not in ("RPY", "Eul", "rpy2r", "eul2r", "rpy2tr", "eul2tr") else positional[:3])
        if qualified.startswith(("tf.transformations.", "tf_transformations.")) and name == "quaternion_from_euler":
            return _literals_of(positional[:3])
        if name in TRIG_FUNCTIONS and len(positional) == 1 and (
            self.model.is_numpy(func, *TRIG_FUNCTIONS) or qualified in {f"math.{fn}" for fn in TRIG_FUNCTIONS}
        ):
            value = int_literal(positional[0])
            if value is not None and value == int(value) and int(value) % 15 == 0 and abs(value) <= 720:
                return [float(value)]
        return None


def _keyword(node: cst.Call, keyword: str) -> cst.Arg | None:
    return next((arg for arg in node.args if arg.keyword is not None and arg.keyword.value == keyword), None)


def _literals(node: cst.BaseExpression) -> list[float]:
    """The numeric literals of an angle expression: a number, or a (nested) list/tuple of them."""
    value = int_literal(node)
    if value is not None:
        return [float(value)]
    if isinstance(node, (cst.List, cst.Tuple)):
        return [found for element in node.elements for found in _literals(element.value)]
    if isinstance(node, cst.Call) and last_name(node.func) in ("array", "asarray") and node.args:
        return _literals(node.args[0].value)
    return []


def _literals_of(nodes: list[cst.BaseExpression]) -> list[float]:
    return [found for node in nodes for found in _literals(node)]


def _format(value: float) -> str:
    return str(int(value)) if value == int(value) else str(value)
