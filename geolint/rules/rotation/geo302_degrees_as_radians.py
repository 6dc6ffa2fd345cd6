"""GEO302 degrees-as-radians: literal angles in degrees passed to an API that takes radians."""

from __future__ import annotations

import math
import re

import ast

from geolint.rules.base import Invalid, Valid
from geolint.factbase.index import ParamBinding
from geolint.factbase.model import keyword, last_name, number, positional_args
from geolint.factbase.rotations import TRIG_FUNCTIONS, is_scipy_rotation_method
from geolint.factbase.rule_support import FactRule, with_keyword
from geolint.factbase.vocabulary import GATE_TRIGGER
from geolint.rules.rotation.angle_units import DEGREES, RADIANS, AngleUnits, is_trig_or_conversion, radian_arguments, report_hand_conversion_of_converted, wrong_unit_passed

_TWO_PI = 2 * math.pi
# `x * 180 / np.pi`: a hand-written conversion to degrees, which a file can hold with nothing the gate reads.
_DIVIDES_BY_PI = re.compile(r"/\s*(?:np|numpy|math|torch)\.pi\b")


class _GateOrDivisionByPi:
    """The fact rules' gate, or a division by pi (one more regex, only on files the gate turns away)."""

    def search(self, source: str, /) -> bool:
        return GATE_TRIGGER.search(source) or _DIVIDES_BY_PI.search(source) is not None

    def search_with(self, source: str, config: object, /) -> bool:
        return GATE_TRIGGER.search_with(source, config) or _DIVIDES_BY_PI.search(source) is not None
_ANGLE_NAME = re.compile(r"(?i)(fov|angle|yaw|pitch|roll|heading|theta)")
_RADIAN_NAME = re.compile(r"(?i)rad")


class DegreesAsRadians(FactRule):
    """Angles written in degrees are passed to an API that reads radians.

    ## What it does
    Flags literal angles larger than 2 pi passed where radians are expected: scipy
    `Rotation.from_euler` / `from_rotvec` without `degrees=True`, transforms3d `euler2*` and
    `axangle2*`, pytransform3d `*_from_euler` / `*_from_angle`, spatialmath `SE3.Rx` and friends
    without `unit="deg"`, ROS `quaternion_from_euler`, pybullet `getQuaternionFromEuler`, and
    `np.sin`/`math.cos` of a whole multiple of 15 degrees (`np.cos(90)`). Through data it also flags a value the code itself
    puts in degrees passed to those APIs (and to `np.degrees` / `np.rad2deg`): a name that says
    so (`yaw_deg`, `fov_degrees`, `tiltDeg`), the result of `np.degrees` / `np.rad2deg` /
    `math.degrees` or of scipy `as_euler(..., degrees=True)` or of a hand-written `x * 180 / np.pi`
    (which is itself flagged when `x` is already in degrees), followed through local variables,
    `self` attributes, elements (`angles[2]`), negation, halving and sums of degrees; a
    parameter whose only value is a literal default above 2 pi (`fovy=30`); and such a value
    passed to a project helper (here or in another module, through helpers that call helpers)
    that hands the parameter unchanged to one of those APIs, or names it in radians (`theta_rad`)
    when the value's degrees are computed rather than only named; and a name or `self` attribute
    bound only to literal angle lists (`UPRIGHT = [90, 0, 0]`) passed whole to those APIs.

    ## Why is this bad?
    90 radians is about 5157 degrees, i.e. 117 degrees after wrapping: a valid, silently wrong
    rotation. No real pose needs a literal angle above 2 pi, and a value named or computed in
    degrees is degrees wherever it goes.

    ## Example
    ```python
    R_base_tool = Rotation.from_euler("xyz", [0, 0, 90]).as_matrix()
    focal = height / (2 * np.tan(fov_deg / 2))
    ```

    ## Use instead
    ```python
    R_base_tool = Rotation.from_euler("xyz", [0, 0, 90], degrees=True).as_matrix()
    focal = height / (2 * np.tan(np.deg2rad(fov_deg) / 2))
    ```

    ## Fix safety
    Adding `degrees=True` to a scipy call is safe when the angles are literals above 2 pi or
    values computed in degrees (`np.degrees(...)`), and unsafe when only a name says degrees.
    Other APIs get no automatic fix.

    ## Known problems
    All-caps names (`DEG`, `DEG2RAD`) and a bare `deg` are read as conversion factors, not angles,
    so `np.sin(30 * DEG)` stays silent; a `*_deg` name that actually holds radians (a stale
    name) is flagged. A value mixed with radians evidence in the same argument is left alone.
    Literal angles given to pybullet's `getQuaternionFromEuler`, and literal lists reaching a radian
    API through a name (`UPRIGHT = [90, 0, 0]`), are judged only when every large
    one is a whole multiple of 15 (`[90, 0, 0]`): scene constants such as `[0, 160, -80]` are
    often tuned by eye in the simulator, so the rotation they give is the one wanted.
    """

    code = "GEO302"
    name = "degrees-as-radians"
    triggers = _GateOrDivisionByPi()  # type: ignore[assignment]  # the gate, widened

    VALID = [
        Valid(
            "import numpy as np\n"
            "class Orbit:\n"
            "    def __init__(self, fovy=30):\n"
            "        self.fovy = np.radians(fovy)\n"
            "    def focal(self, height):\n"
            "        return height / (2 * np.tan(self.fovy / 2))\n"
        ),
        Valid("import numpy as np\ndef f(fov_rad=30):\n    return np.tan(fov_rad / 2)\n"),
        Valid('from scipy.spatial.transform import Rotation\nr = Rotation.from_euler("xyz", [0, 0, 90], degrees=True)\n'),
        Valid('from scipy.spatial.transform import Rotation\nr = Rotation.from_euler("xyz", [0, 0, 1.57])\n'),
        Valid("import numpy as np\nc = np.cos(np.pi / 2)\n"),
        Valid("import numpy as np\nc = np.cos(7.5)\n"),  # not a whole multiple of 15: who knows
        Valid('from spatialmath import SE3\nT = SE3.Rx(90, unit="deg")\n'),
        Valid("from spatialmath import SE3\nT = SE3.Rx(90, 'deg')\n"),
        Valid('from scipy.spatial.transform import Rotation\nr = Rotation.from_euler("z", angle)\n'),
        Valid("import numpy as np\ndef f(h, fov_deg):\n    return h / (2 * np.tan(np.deg2rad(fov_deg) / 2))\n"),
        Valid("import numpy as np\ndef f(x):\n    return np.sin(30 * DEG) + np.cos(x * DEG2RAD)\n"),
        Valid("import numpy as np\nimport pybullet as p\nplate_orientation = p.getQuaternionFromEuler([np.pi / 2, 0, 0])\n"),
        Valid("import pybullet as p\nHAND_BASE_ROT = p.getQuaternionFromEuler([0, 160, -80])\n"),  # tuned by eye (FP20)
        Valid("import numpy as np\nimport pybullet as p\nUPRIGHT = [90, 0, 0]\ndef place(body):\n    return p.getQuaternionFromEuler(np.radians(UPRIGHT))\n"),
        Valid(  # a name against a name: too weak at a helper's call
            "import numpy as np\ndef rot(theta_rad):\n    return theta_rad\ndef f(yaw_deg):\n    return rot(yaw_deg)\n"
        ),
        Valid(  # the helper converts under a condition: what it reads is not known
            "import numpy as np\ndef rot(a, degrees=False):\n    return np.cos(np.deg2rad(a) if degrees else a)\n"
            "def f(yaw_deg):\n    return rot(yaw_deg, degrees=True)\n"
        ),
        Valid("import numpy as np\ndef f(yaw_deg_per_s, dt):\n    return np.cos(yaw_deg_per_s * dt)\n"),
        Valid("import math\ndef f(dy, dx):\n    yaw = math.atan2(dy, dx)\n    return yaw * 180 / math.pi\n"),  # to degrees once
    ]
    INVALID = [
        Invalid(
            "import numpy as np\n"
            "def rot_z(theta):\n"
            "    return np.array([[np.cos(theta), -np.sin(theta)], [np.sin(theta), np.cos(theta)]])\n"
            "def yaw_matrix(angle):\n"
            "    return rot_z(angle)\n"
            "def f(yaw_deg):\n"
            "    return yaw_matrix(yaw_deg)\n"
        ),
        Invalid(
            "import numpy as np\n"
            "class Orbit:\n"
            "    def __init__(self, fovy=30):\n"
            "        self.fovy = fovy\n"
            "    def focal(self, height):\n"
            "        return height / (2 * np.tan(self.fovy / 2))\n"
        ),
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
        Invalid("import numpy as np\ndef f(h, fov_deg):\n    return h / (2 * np.tan(fov_deg / 2))\n"),
        Invalid(
            "import numpy as np\nfrom scipy.spatial.transform import Rotation\ndef f(dx, dy):\n"
            "    heading = np.degrees(np.arctan2(dy, dx))\n    return Rotation.from_euler('z', heading)\n",
            expected_fix="import numpy as np\nfrom scipy.spatial.transform import Rotation\ndef f(dx, dy):\n"
            "    heading = np.degrees(np.arctan2(dy, dx))\n    return Rotation.from_euler('z', heading, degrees=True)\n",
        ),
        Invalid("from transforms3d.euler import euler2mat\ndef f(tilt_degrees):\n    return euler2mat(0, tilt_degrees, 0)\n"),
        Invalid("import pybullet as p\nplate_orientation = p.getQuaternionFromEuler([90, 0, 0])\n"),
        Invalid("import pybullet as p\nUPRIGHT = [90, 0, 0]\ndef place(body):\n    return p.getQuaternionFromEuler(UPRIGHT)\n"),
        Invalid("import numpy as np\ndef f(r):\n    angles = r.as_euler('xyz', degrees=True)\n    return np.cos(angles[2])\n"),
        Invalid(
            "import math\ndef f(dy, dx):\n    yaw = math.atan2(dy, dx) * 180 / math.pi\n    return yaw * 180 / math.pi\n",
            expected_fix="import math\ndef f(dy, dx):\n    yaw = math.atan2(dy, dx) * 180 / math.pi\n    return yaw\n",
        ),
    ]

    def run(self) -> None:
        units = self.facts.shared(AngleUnits)
        self._arguments: dict[int, list[ast.expr] | None] = {}
        for node in self.facts.index.nodes(ast.Call):
            self._check(node, units)  # type: ignore[arg-type]
        for node in self.facts.index.nodes(ast.BinOp):
            report_hand_conversion_of_converted(self, node, DEGREES, units)  # type: ignore[arg-type]

    def _radian_arguments(self, node: ast.Call) -> list[ast.expr] | None:
        """`radian_arguments`, worked out once per call (three of the checks below ask)."""
        key = id(node)
        if key not in self._arguments:
            self._arguments[key] = radian_arguments(self.facts, node)
        return self._arguments[key]

    def _check(self, node: ast.Call, units: AngleUnits) -> None:
        angles = self._radian_angles(node)
        if angles is not None:
            too_big = [value for value in angles if abs(value) > _TWO_PI]
            if too_big and last_name(node.func) == "getQuaternionFromEuler" and not all(_round_degrees(value) for value in too_big):
                too_big = []  # pybullet scene constants tuned by eye (FP20): only round angles are a degree slip
            if too_big:
                shown = _format(too_big[0])
                fix = self._degrees_keyword_fix(node)
                self.report(
                    node,
                    f"`{self.code_of(node.func)}` takes radians, but the literal angle {shown} is above 2 pi: "
                    "it looks like degrees",
                    replacement=fix,
                    fix_description="pass degrees=True",
                )
                return
        if self._check_bound_literals(node):
            return
        self._check_units(node, units)
        self._check_helper(node, units)

    def _check_bound_literals(self, node: ast.Call) -> bool:
        """`ORN = [90, 0, 0]` then `p.getQuaternionFromEuler(ORN)`: a name (or `self` attribute) whose
        every binding is a literal list of angles, passed whole to a radian API. Judged like literals
        in the call, and only when every large angle is a whole multiple of 15 (FP20)."""
        if is_trig_or_conversion(self.facts, node):
            return False  # trig of a named scalar has its own, name-guarded path
        for argument in self._radian_arguments(node) or []:
            bound = self._literal_list_bindings(argument)
            if not bound:
                continue
            values = [value for literal in bound for value in _literals(literal)]
            too_big = [value for value in values if abs(value) > _TWO_PI]
            if not too_big or not all(_round_degrees(value) for value in too_big):
                continue
            first = bound[0]
            fix = self._degrees_keyword_fix(node)
            self.report(
                node if fix is not None else argument,  # the fix rewrites the whole call
                f"`{self.code_of(node.func)}` takes radians, but `{self.code_of(argument)}` is `{self.code_of(first)}` "
                f"(line {first.lineno}), whose angle {_format(too_big[0])} is above 2 pi: it looks like degrees",
                replacement=fix,
                applicability="unsafe",
                fix_description="pass degrees=True",
                evidence=(f"`{self.code_of(argument)}` is bound to `{self.code_of(first)}` at line {first.lineno}",),
            )
            return True
        return False

    def _literal_list_bindings(self, node: ast.expr) -> list[ast.expr]:
        """The literal angle lists a name or `self` attribute holds, when it holds nothing else and no
        element is rewritten (`ORN[0] = ...`, `ORN += ...`); else []."""
        facts = self.facts
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == "self":
            values: list[object] = list(facts.index.self_attribute_stores.get(node.attr, []))
        elif isinstance(node, ast.Name):
            scope = facts.index.scope_of(node)
            if node.id in scope.subscript_stores or node.id in scope.augmented:
                return []
            values = list(facts.bindings(node) or [])
        else:
            return []
        if not values or not all(isinstance(value, ast.expr) and _is_literal_list(value) for value in values):
            return []
        return values  # type: ignore[return-value]

    def _degrees_keyword_fix(self, node: ast.Call) -> str | None:
        """The call with `degrees=True` added: for scipy's `from_euler` / `from_rotvec` that do not say."""
        if is_scipy_rotation_method(self.facts, node.func, "from_euler", "from_rotvec") and keyword(node, "degrees") is None:
            return with_keyword(self.facts.index.segment(node), "degrees=True")
        return None

    def _check_helper(self, node: ast.Call, units: AngleUnits) -> None:
        """A value in degrees passed to a project helper that hands it to a radian API (`rot_z(yaw_deg)`
        where `rot_z(theta)` computes `np.cos(theta)`)."""
        found = wrong_unit_passed(self.facts, node, RADIANS, units)
        if found is not None:
            argument, message, evidence = found
            self.report(argument, message, evidence=evidence)

    def _check_units(self, node: ast.Call, units: AngleUnits) -> None:
        """A value the code itself puts in degrees (`yaw_deg`, `np.degrees(...)`) passed as radians."""
        arguments = self._radian_arguments(node)
        if not arguments:
            return
        elements = [element for argument in arguments for element in _elements(argument)]
        in_degrees = [(element, unit) for element in elements if (unit := units.unit_of(element)) is not None and unit.unit == DEGREES]
        if not in_degrees or any(unit.unit == RADIANS for element in elements if (unit := units.unit_of(element)) is not None):
            return  # nothing in degrees, or radians beside it: mixed evidence, say nothing
        element, unit = in_degrees[0]
        applicability = "unsafe" if any(found.by_name for _, found in in_degrees) else "safe"
        fix = self._degrees_keyword_fix(node)
        degree_nodes = {id(found) for found, _ in in_degrees}
        if fix is not None and not all(id(other) in degree_nodes or number(other) == 0 for other in elements):
            fix = None  # an angle in radians beside them would be read as degrees too
        self.report(
            node if fix is not None else element,  # the fix rewrites the whole call
            f"`{self.code_of(node.func)}` takes radians, but `{self.code_of(element)}` is in degrees ({unit.evidence})",
            replacement=fix,
            applicability=applicability,  # type: ignore[arg-type]
            fix_description="pass degrees=True",
            evidence=(unit.evidence,),
        )

    def _radian_angles(self, node: ast.Call) -> list[float] | None:
        """The literal angles of a call to a radian API, or None when the call is not one (or opted into degrees)."""
        facts = self.facts
        func = node.func
        positional = positional_args(node)
        name = last_name(func) or ""
        qualified = facts.qualified_name(func) or ""
        if name in TRIG_FUNCTIONS and len(positional) == 1 and (
            facts.is_array_call(func, *TRIG_FUNCTIONS) or qualified in {f"math.{fn}" for fn in TRIG_FUNCTIONS}
        ):
            value = number(positional[0])
            if value is None:
                value = self._angle_through_data(positional[0])
            if value is not None and _round_degrees(value) and abs(value) <= 720:
                return [float(value)]
            return None
        arguments = self._radian_arguments(node)
        if arguments is None or is_trig_or_conversion(facts, node):
            return None
        return _literals_of(arguments)

    def _angle_through_data(self, node: ast.expr) -> float | None:
        """`np.tan(self.fovy / 2)` where `fovy` only ever holds a literal (a default `fovy=30`): that
        literal, when the name reads as an angle. Halving or doubling keeps the unit."""
        if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Div, ast.Mult)) and number(node.right) is not None:
            node = node.left
        name = node.attr if isinstance(node, ast.Attribute) else node.id if isinstance(node, ast.Name) else None
        if name is None or not _ANGLE_NAME.search(name) or _RADIAN_NAME.search(name):
            return None
        values = {value for value in self._literal_sources(node, depth=0)}
        return values.pop() if len(values) == 1 and None not in values else None

    def _literal_sources(self, node: ast.expr, depth: int) -> list[float | None]:
        facts = self.facts
        if depth > 3:
            return [None]
        literal = number(node)
        if literal is not None:
            return [float(literal)]
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == "self":
            stores = facts.index.self_attribute_stores.get(node.attr, [])
            return [found for value in stores for found in self._literal_sources(value, depth + 1)] or [None]
        if isinstance(node, ast.Name):
            found: list[float | None] = []
            for binding in facts.bindings(node) or []:
                if isinstance(binding, ParamBinding):
                    found.append(float(number(binding.default)) if number(binding.default) is not None else None)  # type: ignore[arg-type]
                elif isinstance(binding, ast.expr):
                    found += self._literal_sources(binding, depth + 1)
                else:
                    found.append(None)
            return found or [None]
        return [None]


def _literals(node: ast.AST) -> list[float]:
    """The numeric literals of an angle expression: a number, or a (nested) list/tuple of them."""
    value = number(node)
    if value is not None:
        return [float(value)]
    if isinstance(node, (ast.List, ast.Tuple)):
        return [found for element in node.elts for found in _literals(element)]
    if isinstance(node, ast.Call) and last_name(node.func) in ("array", "asarray", "tensor") and node.args:
        return _literals(node.args[0])
    return []


def _is_literal_list(node: ast.expr) -> bool:
    """`[90, 0, 0]`, `(0, 0, -90.0)`, `np.array([90, 0, 0])`: a flat list of numeric literals."""
    if isinstance(node, ast.Call) and last_name(node.func) in ("array", "asarray", "tensor") and len(node.args) == 1 and not node.keywords:
        node = node.args[0]
    return isinstance(node, (ast.List, ast.Tuple)) and bool(node.elts) and all(number(element) is not None for element in node.elts)


def _round_degrees(value: float) -> bool:
    """90, 180, -45, 360...: a whole multiple of 15, the angles people write in degrees."""
    return value == int(value) and int(value) % 15 == 0


def _literals_of(nodes: list[ast.expr]) -> list[float]:
    return [found for node in nodes for found in _literals(node)]


def _elements(node: ast.expr) -> list[ast.expr]:
    """The angles of an angle argument: the elements of a literal list, else the argument itself."""
    if isinstance(node, ast.Call) and last_name(node.func) in ("array", "asarray", "tensor") and len(node.args) == 1:
        node = node.args[0]
    if isinstance(node, (ast.List, ast.Tuple)):
        return [found for element in node.elts for found in _elements(element)]
    return [node]


def _format(value: float) -> str:
    return str(int(value)) if value == int(value) else str(value)
