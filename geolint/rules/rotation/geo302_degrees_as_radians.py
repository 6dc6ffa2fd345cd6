"""GEO302 degrees-as-radians: literal angles in degrees passed to an API that takes radians."""

from __future__ import annotations

from typing import Final

import ast
import math
import re
from ast import (
    AST,
    Add,
    Assign,
    AsyncFunctionDef,
    Attribute,
    AugAssign,
    BinOp,
    Call,
    Constant,
    Div,
    FunctionDef,
    Lambda,
    Load,
    Mod,
    Mult,
    Name,
    Starred,
    Sub,
    Subscript,
)

from geolint.factbase.index import ParamBinding
from geolint.factbase.project_files import is_test_module
from geolint.factbase.model import last_name, number, positional_args, string
from geolint import knowledge
from geolint.knowledge import knowledge_base
from geolint.factbase import library_calls
from geolint.factbase.rotations import TRIG_FUNCTIONS
from geolint.rules.fact_rule import FactRule, with_keyword
from geolint.factbase.vocabulary import GATE_TRIGGER
from geolint.rules.base import Invalid, Valid
from geolint.factbase.angle_units import (
    ANGLE_UNITS,
    DEGREES,
    RADIANS,
    AngleUnits,
    conversion,
    degree_arguments,
    may_read_degrees,
    enclosing_class,
    format_angle,
    is_trig_or_conversion,
    may_read_radians,
    name_unit,
    radian_arguments,
)
from geolint.rules.rotation.angle_findings import report_hand_conversion_of_converted, wrong_unit_passed

_TWO_PI: Final = 2 * math.pi
# `x * 180 / np.pi`: a hand-written conversion to degrees, which a file can hold with nothing the gate
# reads; `radians` / `deg2rad`: a parse table's converter to radians (a module of parsers, no geometry).
_DIVIDES_BY_PI: Final = re.compile(r"/\s*(?:\w+\.)*pi\b|\b(?:radians|deg2rad)\b")


class _GateOrDivisionByPi:
    """The fact rules' gate, a division by pi or a conversion to radians (one more regex, only on files
    the gate turns away)."""

    def search(self, source: str, /) -> bool:
        return GATE_TRIGGER.search(source) or _DIVIDES_BY_PI.search(source) is not None

    def search_with(self, source: str, config: object, /) -> bool:
        return GATE_TRIGGER.search_with(source, config) or _DIVIDES_BY_PI.search(source) is not None
_ANGLE_NAME: Final = re.compile(r"(?i)(fov|angle|yaw|pitch|roll|heading|theta)")
_RADIAN_NAME: Final = re.compile(r"(?i)rad")


class DegreesAsRadians(FactRule):
    """Angles written in degrees are passed to an API that reads radians.

    ## What it does
    Flags literal angles larger than 2 pi passed where radians are expected: scipy
    `Rotation.from_euler` / `from_rotvec` without `degrees=True`, transforms3d `euler2*` and
    `axangle2*`, pytransform3d `*_from_euler` / `*_from_angle`, spatialmath `SE3.Rx` and friends
    without `unit="deg"`, ROS `quaternion_from_euler`, pybullet `getQuaternionFromEuler`,
    numpy-quaternion's `from_rotation_vector`, and
    `np.sin`/`math.cos` of a whole multiple of 15 degrees (`np.cos(90)`). Through data it also flags a value the code itself
    puts in degrees passed to those APIs (and to `np.degrees` / `np.rad2deg`): a name that says
    so (`yaw_deg`, `fov_degrees`, `tiltDeg`), the result of `np.degrees` / `np.rad2deg` /
    `math.degrees` or of scipy `as_euler(..., degrees=True)` or of a hand-written `x * 180 / np.pi`
    (which is itself flagged when `x` is already in degrees), followed through local variables,
    `self` attributes, elements (`angles[2]`), negation, halving and sums of degrees; a
    parameter whose only value is a literal default above 2 pi (`fovy=30`); and such a value
    passed to a project helper or method (here or in another module, through helpers that call
    helpers, and methods of the object's class or its project base classes) that hands the parameter
    unchanged to one of those APIs (or scales a rotation vector by it,
    `quaternion.from_rotation_vector(theta * axis)`, or converts it by hand, `heading * 180 / np.pi`), or names it in radians (`theta_rad`)
    when the value's degrees are computed rather than only named; such a value passed to a class of
    the same module whose constructor stores the parameter as it is (`self.angle = angle`) for a method that
    hands it to one of those APIs (`np.tan(self.angle)`); and a name or `self` attribute
    bound only to literal angle lists (`UPRIGHT = [90, 0, 0]`) passed whole to those APIs.

    Constants count too: a module constant, class attribute or `self.x = <literal>` that is the
    module's only store of it (`self.phi = 73.17`), or such a constant of another project module
    (`from config import TILT`, `config.TILT`, `cfg.phi` for `cfg = Configuration()` or a parameter
    annotated `Configuration`), whose literal is no plausible
    angle in radians (above 2 pi) but one in degrees (at most 360, or a multiple of 15 up to 720),
    given to those APIs directly or scaled by a number (`np.cos(TILT / 2)`; not `np.sin(self.omega *
    t)`). One value given both to a library that reads degrees (OpenGL `glRotatef` / `glRotated`,
    OpenCV `getRotationMatrix2D`, `scipy.ndimage.rotate`, torchvision's `rotate`) and to a radian
    API or a project helper that hands it to one (also one reached through `from .module import *`),
    with no conversion between, is flagged at the radian use: one of the two is wrong. The same
    value may reach the degrees reader through a dict of the same module (`{"y_rot": rotate}`
    stored, `glRotatef(obj["y_rot"], 0, 1, 0)` read back). And a parse table (`{"RMC": [("course", to_radians, 8)],
    "VTG": [("course", safe_float, 1)]}`) that converts a field to radians in one row and parses the
    same field as a plain number in another is flagged at the plain row.

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
    name) is flagged, unless the function's own arithmetic contradicts its degree names (adds pi
    to one or wraps it with pi, `degree = (degree + np.pi) % (2 * np.pi) - np.pi`) and only the
    name says degrees (it is bound to a parameter or a value of no known unit): then it says
    nothing, and a real degree slip in such a function is missed. A value mixed with radians evidence in the same argument is left alone.
    A constant is followed only when nothing else in its module stores that attribute or name
    (`global`, `+=`, `setattr` with a computed name, a class with base classes all make it silent),
    and only one step (`cfg = Configuration()` or `cfg: Configuration` then `cfg.phi`; not a `cfg`
    received as an unannotated parameter). Literal angles in a test module (`test_*.py`, `*_test.py`,
    a `tests/` folder) are test data and are not judged. A constant tuned in radians that happens to exceed 2 pi (`self.k = 40` given to
    `np.cos`) would be read as degrees. A library method that reads degrees is known only on a value whose class the code shows
    (`cv2.getRotationMatrix2D`, `Image.open(path).rotate`, `img: Image.Image`): a PIL image passed in
    untyped, or matplotlib's `Affine2D.rotate_deg`, is not recognised. The parse table's converters must be
    `math.radians` / `np.deg2rad` or functions of the same module: one whose every `return` is in
    radians, one that is `float` / `int` or only returns `float(...)`/`int(...)` of its text. A dict key is matched by its text within one module, so two
    unrelated dicts sharing a key (`"angle"`) could be taken for one.
    Literal angles given to pybullet's `getQuaternionFromEuler`, and literal lists reaching a radian
    API through a name (`UPRIGHT = [90, 0, 0]`), are judged only when every large
    one is a whole multiple of 15 (`[90, 0, 0]`): scene constants such as `[0, 160, -80]` are
    often tuned by eye in the simulator, so the rotation they give is the one wanted.
    A class's constructor is read only through attributes stored once, unconditionally in `__init__`,
    and read by the class's own methods; a class whose methods read the attribute in both units says
    nothing; a class of another module is not asked (GEO305 asks it for degrees), and the value's
    degrees must show in the module's own code or a library call, not in a project helper's return. A helper's parameter that scales a rotation vector is taken for its angle: a helper
    scaling an angle by a time step (`from_rotvec(omega * dt)`) would be said to read `dt` in radians.
    """

    code = "GEO302"
    name = "degrees-as-radians"
    triggers = _GateOrDivisionByPi()  # type: ignore[assignment]  # the gate, widened

    VALID = [
        Valid(  # the inherited method converts its parameter from radians: given radians
            "import numpy as np\nclass Body:\n    def set_heading(self, heading):\n        self.heading_deg = heading * 180 / np.pi\n"
            "class Car(Body):\n    def reset(self, v):\n        self.set_heading(np.arctan2(v[1], v[0]))\n"
        ),
        Valid(  # a degree name rebound to an arc cosine (radians) before it is converted
            "import numpy as np\nimport tensorflow as tf\ndef colour(cosine):\n"
            "    degree_diff = tf.acos(cosine)\n    return degree_diff * 180 / np.pi\n"
        ),
        Valid(
            "import numpy as np\n"
            "class Orbit:\n"
            "    def __init__(self, fovy=30):\n"
            "        self.fovy = np.radians(fovy)\n"
            "    def focal(self, height):\n"
            "        return height / (2 * np.tan(self.fovy / 2))\n"
        ),
        Valid("import numpy as np\ndef f(fov_rad=30):\n    return np.tan(fov_rad / 2)\n"),
        Valid(  # pi written out, and halved with it: the half field of view in radians
            "import math\ndef focal(fov_degrees):\n    return 1 / math.tan(fov_degrees * 3.14159 / 360)\n"
        ),
        Valid("import numpy as np\ndef focal(fov_deg):\n    return 0.5 / np.tan(fov_deg * np.pi / 360)\n"),
        Valid(  # an index (it picks `sigma[k_plot]`) encoded as a periodic feature, not an angle
            "import numpy as np\nk_plot = 50\nassert k_plot >= 0 and k_plot < K\n"
            "X = np.vstack((xs.flatten(), 0 * xs.flatten() + np.sin(k_plot)))\nplt.plot(X[0, :] - sigma[k_plot] * Y[0, :])\n"
        ),
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
        Valid("import numpy as np\nclass Gait:\n    def __init__(self):\n        self.omega = 12.0\n    def phase(self, t):\n        return np.sin(self.omega * t)\n"),
        Valid(
            "import numpy as np\nclass Leg:\n    def __init__(self):\n        self.phi = 73.17\n"
            "    def set_phi(self, phi_deg):\n        self.phi = np.radians(phi_deg)\n    def offset(self):\n        return np.sin(self.phi)\n"
        ),
        Valid("import numpy as np\nTILT = 0.35\ndef f(h):\n    return h * np.cos(TILT)\n"),
        Valid(
            "import math\nfrom OpenGL.GL import glRotatef\ndef draw(obj):\n    y_rot = obj['rotate']\n"
            "    glRotatef(y_rot, 0, 1, 0)\n    return math.cos(math.radians(y_rot))\n"
        ),
        Valid(  # a stale name: the function's own arithmetic on its degree names is in radians
            "import numpy as np\ndef arc(r, start_phase, sweep):\n    start_degree = start_phase\n"
            "    degree = (start_degree - sweep + np.pi) % (2 * np.pi) - np.pi\n"
            "    return r * np.cos(start_degree), r * np.sin(degree)\n"
        ),
    ]
    INVALID = [
        Invalid(  # ... given degrees: converted twice
            "import numpy as np\nclass Body:\n    def set_heading(self, heading):\n        self.heading_deg = heading * 180 / np.pi\n"
            "class Car(Body):\n    def reset(self, v):\n        self.set_heading(np.rad2deg(np.arctan2(v[1], v[0])))\n",
            message="`self.set_heading` passes its parameter `heading` to a conversion written out (`heading * 180 / np.pi`), which reads radians, but `np.rad2deg(np.arctan2(v[1], v[0]))` is in degrees (`np.rad2deg` returns degrees)",
            range=(7, 26, 7, 60),
        ),
        Invalid(
            # computed degrees are degrees, whatever other names the function wraps in pi
            "import numpy as np\ndef f(h):\n    yaw_deg = np.degrees(h)\n"
            "    heading_deg = (h + np.pi) % (2 * np.pi) - np.pi\n    return np.cos(yaw_deg)\n",
            message="`np.cos` takes radians, but `yaw_deg` is in degrees (the name `yaw_deg` says degrees)",
            range=(5, 19, 5, 26),
        ),
        Invalid(
            "import numpy as np\nimport quaternion\n"
            "def quat_from_angle_axis(theta, axis):\n    return quaternion.from_rotation_vector(theta * axis)\n"
            "def look(c):\n    theta = -180 * np.arccos(c) / np.pi\n    return quat_from_angle_axis(theta, np.array([0, 1, 0]))\n"
        ),
        Invalid(
            "import numpy as np\nclass Steering:\n    def __init__(self, angle):\n        self.angle = angle\n"
            "    def curvature(self, wheelbase):\n        return np.tan(self.angle) / wheelbase\n"
            "def f(command):\n    return Steering(np.degrees(command))\n"
        ),
        Invalid("import math as m\nclass Config:\n    def __init__(self):\n        self.phi = 73.17\n        self.offset = 0.05 * m.sin(self.phi)\n"),
        Invalid("import numpy as np\nHIP_TILT = 30.0\ndef height(h):\n    return h * np.cos(HIP_TILT / 2)\n"),
        Invalid(
            "import math\nfrom OpenGL.GL import glRotatef\ndef draw(obj):\n    y_rot = obj['rotate']\n"
            "    glRotatef(y_rot, 0, 1, 0)\n    return math.cos(y_rot)\n"
        ),
        Invalid(
            "import math\ndef to_rad(text):\n    return math.radians(float(text))\n"
            "FIELDS = {'RMC': [('course', to_rad, 8)], 'VTG': [('course', float, 1)]}\n"
        ),
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
        facts = self.facts
        units = facts.shared(AngleUnits)
        # the call being checked and its `radian_arguments` (asked by several checks of one call)
        self._arguments: tuple[Call | None, list[ast.expr] | None] = (None, None)
        consumers = bool(self._degree_consumers())
        for node in facts.index.nodes(Call):
            self._check(node, units, consumers)  # type: ignore[arg-type]
        for node in self.facts.index.nodes(BinOp):
            report_hand_conversion_of_converted(self, node, DEGREES, units)  # type: ignore[arg-type]
        for node in self.facts.index.nodes(ast.Dict):
            self._check_field_table(node)  # type: ignore[arg-type]

    def _check_field_table(self, table: ast.Dict) -> None:
        """A parse table (`{"RMC": [("true_course", convert_deg_to_rads, 8)], "VTG": [("true_course",
        safe_float, 1)]}`: groups of `(field, converter, ...)` rows) that converts a field to radians in
        one row and parses the same field as a plain number in another: readers of that field get
        radians from one row and degrees from the other."""
        rows: dict[str, list[tuple[ast.Tuple, Name, str]]] = {}
        for key, group in zip(table.keys, table.values):
            if not isinstance(group, (ast.List, ast.Tuple)):
                continue
            group_label = (string(key) or self.code_of(key)) if key is not None else ""
            for row in group.elts:
                if isinstance(row, ast.Tuple) and len(row.elts) >= 2 and isinstance(row.elts[1], Name):
                    field = string(row.elts[0])
                    if field is not None:
                        rows.setdefault(field, []).append((row, row.elts[1], group_label))
        for field, found in rows.items():
            if len(found) < 2:
                continue
            converted = [(row, converter, label) for row, converter, label in found if self._converts_to_radians(converter)]
            if not converted:
                continue
            other, converter_used, other_label = converted[0]
            for row, converter, label in found:
                if self._passes_number_through(converter.id, depth=0):
                    self.report(
                        row,
                        f"field `{field!r}` is parsed as a plain number by `{converter.id}` here ({label!r}), but converted "
                        f"to radians by `{converter_used.id}` for {other_label!r} (line {other.lineno}): readers of "
                        f"`{field!r}` get degrees from this row",
                        evidence=(f"`{converter_used.id}` returns radians", f"`{converter.id}` returns its text as a number"),
                    )

    def _converts_to_radians(self, converter: Name) -> bool:
        """`math.radians` / `np.deg2rad` themselves, or a project function of this module whose every
        `return` is in radians (not by a name alone)."""
        api = knowledge_base().api_as_written(self.facts.qualified_name(converter) or "")
        if api is not None and conversion(api) == RADIANS:  # `math.radians`, `np.deg2rad` by their stubs
            return True
        function = self.facts.index.functions.get(converter.id)
        if function is None:
            return False
        summary = self.facts.project.summary(self.facts, function, ANGLE_UNITS)
        return summary is not None and summary.angle_unit is not None and summary.angle_unit[0] == RADIANS and not summary.angle_unit[2]

    def _passes_number_through(self, name: str, depth: int) -> bool:
        """`float`, `int`, or a function of this module that only returns `float(...)` / `int(...)`,
        a number, None, or another such function's result (`safe_float`): no unit conversion."""
        if name in ("float", "int"):
            return name not in self.facts.index.functions
        function = self.facts.index.functions.get(name)
        if function is None or depth > 2:
            return False
        scope = self.facts.index.scopes.get(function)
        returns = [] if scope is None else scope.returns
        if not returns:
            return False
        for value in returns:
            if number(value) is not None or (isinstance(value, Constant) and value.value is None):
                continue
            if isinstance(value, Call) and isinstance(value.func, Name) and self._passes_number_through(value.func.id, depth + 1):
                continue
            return False
        return True

    def _radian_arguments(self, node: Call) -> list[ast.expr] | None:
        """`radian_arguments`, worked out once per call (three of the checks below ask)."""
        checked, arguments = self._arguments
        if checked is not node:
            arguments = radian_arguments(self.facts, node)
            self._arguments = (node, arguments)
        return arguments

    def _check(self, node: Call, units: AngleUnits, consumers: bool) -> None:
        # one cheap name test first: a call named like no radian API (most calls) has no radian
        # arguments, so only the helper and shared-value checks can say anything about it
        if may_read_radians(self.facts, self.facts.called_name(node.func) or "") and self._check_radian_api(node, units):
            return
        if self._check_helper(node, units):
            return
        if consumers:
            self._check_shared_value(node)

    def _check_radian_api(self, node: Call, units: AngleUnits) -> bool:
        """The checks of a call that may be a radian API; True once one reports."""
        trig = is_trig_or_conversion(self.facts, node)
        angles = self._radian_angles(node, trig)
        if angles is not None:
            too_big = [value for value in angles if abs(value) > _TWO_PI]
            if too_big and last_name(node.func) == "getQuaternionFromEuler" and not all(_round_degrees(value) for value in too_big):
                too_big = []  # pybullet scene constants tuned by eye (FP20): only round angles are a degree slip
            if too_big and is_test_module(self.facts.path):
                too_big = []  # a test's literal angles are data: any number is a rotation
            if too_big:
                shown = format_angle(too_big[0])
                fix = self._degrees_keyword_fix(node)
                self.report(
                    node,
                    f"`{self.code_of(node.func)}` takes radians, but the literal angle {shown} is above 2 pi: "
                    "it looks like degrees",
                    replacement=fix,
                    fix_description="pass degrees=True",
                )
                return True
        return self._check_bound_literals(node, trig) or self._check_units(node, units)

    def _check_bound_literals(self, node: Call, trig: bool) -> bool:
        """`ORN = [90, 0, 0]` then `p.getQuaternionFromEuler(ORN)`: a name (or `self` attribute) whose
        every binding is a literal list of angles, passed whole to a radian API. Judged like literals
        in the call, and only when every large angle is a whole multiple of 15 (FP20)."""
        if trig:
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
                f"(line {first.lineno}), whose angle {format_angle(too_big[0])} is above 2 pi: it looks like degrees",
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
        if isinstance(node, Attribute) and isinstance(node.value, Name) and node.value.id == "self":
            values: list[object] = list(facts.index.self_attribute_stores.get(node.attr, []))
        elif isinstance(node, Name):
            scope = facts.index.scope_of(node)
            if node.id in scope.subscript_stores or node.id in scope.augmented:
                return []
            values = list(facts.bindings(node) or [])
        else:
            return []
        if not values or not all(isinstance(value, ast.expr) and _is_literal_list(value) for value in values):
            return []
        return values  # type: ignore[return-value]

    def _degrees_keyword_fix(self, node: Call) -> str | None:
        """The call with the keyword its stub says reads degrees added (scipy's `from_euler(..., degrees=True)`)."""
        chosen = library_calls.unit_keyword(self.facts, node, knowledge.DEGREES)
        if chosen is not None:
            return with_keyword(self.facts.index.segment(node), chosen)
        return None

    def _check_helper(self, node: Call, units: AngleUnits) -> bool:
        """A value in degrees passed to a project helper that hands it to a radian API (`rot_z(yaw_deg)`
        where `rot_z(theta)` computes `np.cos(theta)`)."""
        found = wrong_unit_passed(self.facts, node, RADIANS, units)
        if found is not None:
            argument, message, evidence = found
            self.report(argument, message, evidence=evidence)
        return found is not None

    def _check_shared_value(self, node: Call) -> None:
        """`glRotatef(y_rot, 0, 1, 0)` and `np.cos(y_rot)` (or a project helper that hands it to one)
        of the same value, with no conversion between: one library reads it in degrees, the other in
        radians, so one of the two uses is wrong."""
        consumers = self._degree_consumers()
        if not consumers:
            return
        for element, how in self._radian_reads(node):
            key = self._value_key(element)
            if key is None:
                continue
            fields = self._fields_holding(key)
            for other, consumer in consumers:
                if other is element:
                    continue
                field = self._field_read(other)
                if self._value_key(other) == key or (field is not None and field in fields):
                    where = f"`{self.code_of(consumer.func)}` (line {consumer.lineno})"
                    through = f" (stored as `{field!r}` and read back as `{self.code_of(other)}`)" if self._value_key(other) != key else ""
                    self.report(
                        element,
                        f"{how} reads `{self.code_of(element)}` in radians, but the same value is given to {where}{through}, "
                        "which reads degrees: one of the two uses is wrong",
                        evidence=(f"{where} reads its angle in degrees", f"{how} reads radians"),
                    )
                    return

    def _field_read(self, node: ast.expr) -> str | None:
        """For `obj["y_rot"]`, or a name bound only to it (`y_rot = obj["y_rot"]`): the key."""
        if isinstance(node, Name):
            bound = self.facts.bindings(node) or []
            if len(bound) != 1 or not isinstance(bound[0], Subscript) or node.id in self.facts.index.scope_of(node).augmented:
                return None
            node = bound[0]
        if isinstance(node, Subscript) and isinstance(node.ctx, Load):
            return string(node.slice)
        return None

    def _fields_holding(self, key: tuple[object, ...]) -> set[str]:
        """The string keys of the module's dict literals whose value there is the value `key` names
        (`{"y_rot": rotate}` for `rotate`): where that value is stored to be read back by key."""
        found = set()
        for table in self._dict_literals():
            for label, value in zip(table.keys, table.values):
                if isinstance(value, (Name, Attribute)) and string(label) is not None and self._value_key(value) == key:
                    found.add(string(label))  # type: ignore[arg-type]
        return found  # type: ignore[return-value]

    def _dict_literals(self) -> list[ast.Dict]:
        return self.facts.module_fact("dict literals", lambda: self.facts.index.nodes(ast.Dict))  # type: ignore[arg-type,return-value]

    def _degree_consumers(self) -> list[tuple[ast.expr, Call]]:
        """The module's calls to a library that reads degrees however it is called (`glRotatef`, not
        `from_euler(..., degrees=True)`, whose keyword may be a test's round trip), with their angle argument."""

        def collect() -> list[tuple[ast.expr, Call]]:
            found: list[tuple[ast.expr, Call]] = []
            facts = self.facts
            for call in facts.index.nodes(Call):
                assert isinstance(call, Call)
                if may_read_degrees(facts, facts.called_name(call.func) or ""):  # `degree_arguments`' own first test
                    found.extend((argument, call) for argument in degree_arguments(facts, call, whatever_the_keywords=True))
            return found

        return self.facts.module_fact("degree consumers", collect)

    def _radian_reads(self, node: Call) -> list[tuple[ast.expr, str]]:
        """The arguments `node` reads in radians, each with how: a radian API's angles, or a project
        helper's parameter it hands unchanged to one (not a parameter only named in radians)."""
        facts = self.facts
        found = [(element, f"`{self.code_of(node.func)}`") for argument in self._radian_arguments(node) or [] for element in _elements(argument)]
        summary = facts.summary_of(node, ANGLE_UNITS) if node.args and facts.may_have_summary(node) else None
        if summary is not None:
            for index, (unit, where, by_name) in sorted(summary.reads_unit.items()):
                if unit == RADIANS and where and not by_name and index < len(node.args) and not isinstance(node.args[index], Starred):
                    found.append((node.args[index], f"`{self.code_of(node.func)}` (through {where})"))
        return found

    def _value_key(self, node: ast.expr) -> tuple[object, ...] | None:
        """What makes two reads the same value: a name with the same reaching bindings in the same
        scope, or `self.<attr>` in the same class never stored from itself (`self.a = np.radians(self.a)`)."""
        facts = self.facts
        if isinstance(node, Name):
            scope = facts.index.scope_of(node)
            if node.id in scope.augmented:
                return None
            bound = facts.bindings(node)
            if not bound:
                return None
            return ("name", id(scope), node.id, tuple(id(binding) for binding in bound))
        if isinstance(node, Attribute) and isinstance(node.value, Name) and node.value.id == "self":
            stores = facts.index.self_attribute_stores.get(node.attr, [])
            if any(isinstance(inner, Attribute) and inner.attr == node.attr for store in stores for inner in ast.walk(store)):
                return None  # converted in place
            if any(isinstance(target, Attribute) and target.attr == node.attr for target in self._augmented_targets()):
                return None
            return ("self", id(enclosing_class(facts, node)), node.attr)
        return None

    def _augmented_targets(self) -> list[ast.expr]:
        return self.facts.module_fact(
            "augmented targets", lambda: [node.target for node in self.facts.index.nodes(AugAssign)]  # type: ignore[attr-defined]
        )

    def _check_units(self, node: Call, units: AngleUnits) -> bool:
        """A value the code itself puts in degrees (`yaw_deg`, `np.degrees(...)`) passed as radians."""
        arguments = self._radian_arguments(node)
        if not arguments:
            return False
        elements = [element for argument in arguments for element in _elements(argument)]
        in_degrees = [(element, unit) for element in elements if (unit := units.unit_of(element)) is not None and unit.unit == DEGREES]
        if not in_degrees or any(unit.unit == RADIANS for element in elements if (unit := units.unit_of(element)) is not None):
            return False  # nothing in degrees, or radians beside it: mixed evidence, say nothing
        if all(self._named_only(found, units) for found, _ in in_degrees) and self._wraps_degree_names_in_pi(node, units):
            return False  # `start_degree = start_phase` where `(degree + np.pi) % ...`: the names are stale
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
        return True

    def _named_only(self, node: ast.expr, units: AngleUnits, depth: int = 4) -> bool:
        """Whether only a name says `node` is in degrees: a name bound to parameters (no literal default),
        to names bound so, or to values of no known unit (`start_degree = start_phase`)."""
        if not isinstance(node, Name) or depth <= 0 or units.bound_literal(node) is not None:
            return False
        for binding in self.facts.bindings(node) or []:
            if isinstance(binding, ParamBinding):
                continue
            if not isinstance(binding, ast.expr):
                return False
            if isinstance(binding, Name):
                if not self._named_only(binding, units, depth - 1) and units.unit_of(binding) is not None:
                    return False
            elif units.unit_of(binding) is not None:
                return False
        return True

    def _wraps_degree_names_in_pi(self, node: Call, units: AngleUnits) -> bool:
        """Whether the function holding `node` adds pi to, or wraps with pi, a value whose name says
        degrees (`degree = (degree + np.pi) % (2 * np.pi) - np.pi`, `arc_degree = (x + np.pi) % ...`):
        radian arithmetic, so its degree names say nothing."""
        scope = self.facts.index.scope_of(node).node
        if not isinstance(scope, (FunctionDef, AsyncFunctionDef, Lambda)):
            return False
        for statement in ast.walk(scope):
            if isinstance(statement, (Assign, AugAssign)):
                targets = statement.targets if isinstance(statement, Assign) else [statement.target]
                named = any(isinstance(name, Name) and name_unit(name.id) == DEGREES for target in targets for name in ast.walk(target))
                if named and self._pi_arithmetic(statement.value, units):
                    return True
            elif isinstance(statement, BinOp) and self._pi_arithmetic(statement, units, degree_operand=True):
                return True
        return False

    def _pi_arithmetic(self, node: ast.expr, units: AngleUnits, degree_operand: bool = False) -> bool:
        """`x + np.pi`, `x - np.pi`, `x % (2 * np.pi)` somewhere in `node` (with `degree_operand`: `node`
        itself, with a name that says degrees in `x`)."""
        candidates = [node] if degree_operand else [found for found in ast.walk(node) if isinstance(found, BinOp)]
        for binop in candidates:
            if not isinstance(binop, BinOp) or not isinstance(binop.op, (Add, Sub, Mod)):
                continue
            for side, other in ((binop.left, binop.right), (binop.right, binop.left)):
                if self._is_pi_multiple(side, units) and (
                    not degree_operand or any(isinstance(name, Name) and name_unit(name.id) == DEGREES for name in ast.walk(other))
                ):
                    return True
        return False

    @staticmethod
    def _is_pi_multiple(node: ast.expr, units: AngleUnits) -> bool:
        """`np.pi`, `2 * np.pi`, `np.pi * 2`."""
        if isinstance(node, BinOp) and isinstance(node.op, Mult):
            return (number(node.left) is not None and units._is_pi(node.right)) or (number(node.right) is not None and units._is_pi(node.left))
        return units._is_pi(node)

    def _radian_angles(self, node: Call, trig: bool) -> list[float] | None:
        """The literal angles of a call to a radian API, or None when the call is not one (or opted into
        degrees). `trig`: `is_trig_or_conversion` of the call."""
        facts = self.facts
        func = node.func
        if trig and last_name(func) in TRIG_FUNCTIONS and len(positional := positional_args(node)) == 1:
            value = number(positional[0])
            if value is None:
                value = self._angle_through_data(positional[0])
            if value is not None and _round_degrees(value) and abs(value) <= 720:
                return [float(value)]
            return None
        arguments = self._radian_arguments(node)
        if arguments is None or trig:
            return None
        return _literals_of(arguments)

    def _angle_through_data(self, node: ast.expr) -> float | None:
        """`np.tan(self.fovy / 2)` where `fovy` only ever holds a literal (a default `fovy=30`): that
        literal, when the name reads as an angle. Halving or doubling keeps the unit."""
        if isinstance(node, BinOp) and isinstance(node.op, (Div, Mult)) and number(node.right) is not None:
            node = node.left
        name = node.attr if isinstance(node, Attribute) else node.id if isinstance(node, Name) else None
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
        if isinstance(node, Attribute) and isinstance(node.value, Name) and node.value.id == "self":
            stores = facts.index.self_attribute_stores.get(node.attr, [])
            return [found for value in stores for found in self._literal_sources(value, depth + 1)] or [None]
        if isinstance(node, Name):
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


def _literals(node: AST) -> list[float]:
    """The numeric literals of an angle expression: a number, or a (nested) list/tuple of them."""
    value = number(node)
    if value is not None:
        return [float(value)]
    if isinstance(node, (ast.List, ast.Tuple)):
        return [found for element in node.elts for found in _literals(element)]
    if isinstance(node, Call) and last_name(node.func) in ("array", "asarray", "tensor") and node.args:
        return _literals(node.args[0])
    return []


def _is_literal_list(node: ast.expr) -> bool:
    """`[90, 0, 0]`, `(0, 0, -90.0)`, `np.array([90, 0, 0])`: a flat list of numeric literals."""
    if isinstance(node, Call) and last_name(node.func) in ("array", "asarray", "tensor") and len(node.args) == 1 and not node.keywords:
        node = node.args[0]
    return isinstance(node, (ast.List, ast.Tuple)) and bool(node.elts) and all(number(element) is not None for element in node.elts)


def _round_degrees(value: float) -> bool:
    """90, 180, -45, 360...: a whole multiple of 15, the angles people write in degrees."""
    return value == int(value) and int(value) % 15 == 0


def _literals_of(nodes: list[ast.expr]) -> list[float]:
    return [found for node in nodes for found in _literals(node)]


def _elements(node: ast.expr) -> list[ast.expr]:
    """The angles of an angle argument: the elements of a literal list, else the argument itself."""
    if isinstance(node, Call) and last_name(node.func) in ("array", "asarray", "tensor") and len(node.args) == 1:
        node = node.args[0]
    if isinstance(node, (ast.List, ast.Tuple)):
        return [found for element in node.elts for found in _elements(element)]
    return [node]
