"""GEO305 radians-as-degrees: an angle already in radians converted again, or passed where degrees are expected."""

from __future__ import annotations

import ast
import re
from ast import BinOp, Call
from typing import Final

from geolint.factbase import library_calls
from geolint.factbase.angle_units import (
    DEGREES,
    RADIANS,
    AngleUnits,
    angle_elements,
    degree_arguments,
)
from geolint.factbase.model import positional_args, string
from geolint.rules.base import Invalid, Valid
from geolint.rules.fact_rule import FactRule
from geolint.rules.rotation.angle_findings import (
    report_conversion_of_converted,
    report_hand_conversion_of_converted,
    wrong_unit_passed,
)
from geolint.rules.triggers import AllOf

# `angle_units="degrees"`, `unit="deg"`: a keyword that states the unit of the call's angles
_UNIT_KEYWORD: Final = re.compile(r"(?:^|_)units?$")
_DEGREE_STRINGS: Final = frozenset({"deg", "degree", "degrees"})


class RadiansAsDegrees(FactRule):
    """An angle the code already has in radians is converted from degrees again, or passed as degrees.

    ## What it does
    Flags `np.deg2rad` / `np.radians` / `math.radians` / `torch.deg2rad`, or the same conversion
    written by hand (`x * np.pi / 180`, `x * (math.pi / 180)`, `x * 0.0174533`), applied to a
    value that is already in radians, scipy `Rotation.from_euler(..., degrees=True)` given one, and a
    library call that reads degrees given one (OpenGL `glRotatef` / `glRotated`, OpenCV
    `getRotationMatrix2D`, `scipy.ndimage.rotate`, torchvision's `rotate`, CARLA's
    `carla.Rotation(pitch, yaw, roll)`; not when only a name says radians). Radians
    are known from the code itself: an inverse trigonometric function (`np.arctan2`,
    `math.acos`), a previous `np.radians`, scipy's `as_euler` without `degrees=True`, a library's
    Euler conversion (tf's `euler_from_quaternion` / `euler_from_matrix`, transforms3d's
    `quat2euler` / `mat2euler`, pytransform3d's `euler_from_*`, pybullet's
    `getEulerFromQuaternion`, Webots' `InertialUnit.getRollPitchYaw()`; each element, unpacked or
    indexed), `np.pi`,
    or a name that says so (`theta_rad`, `yaw_radians`), followed through local variables and
    halving or negation, and through project helpers whose every `return` is in radians. A value
    in radians passed to a project helper that hands the parameter unchanged to one of those
    conversions, or names it in degrees (`angle_in_degrees`), is flagged too (not when only names
    say so on both sides); so is one passed to a project class whose constructor stores the
    parameter as it is (`self.yaw = yaw`) for a method that converts it from degrees
    (`np.radians(self.yaw)`) or hands it to a library reading degrees (`carla.Rotation(self.pitch,
    ...)`), here or in another module, and a value in radians in a call that states by a keyword
    that its angles are in degrees (`Pose(roll=np.pi / 2, angle_units="degrees")`, `unit="deg"`).

    ## Why is this bad?
    Converting radians "to radians" divides the angle by about 57.3: a 90 degree heading becomes
    1.6 degrees. The result is a valid, silently wrong angle; nothing raises.

    ## Example
    ```python
    heading = np.deg2rad(np.arctan2(dy, dx))
    ```

    ## Use instead
    ```python
    heading = np.arctan2(dy, dx)
    ```

    ## Fix safety
    Dropping the conversion (`np.deg2rad(x)` -> `x`) is offered as an unsafe fix: when the
    evidence is a name, the name may be the mistake.

    ## Known problems
    A variable named `*_rad` that actually holds degrees (a stale name) is flagged where it is
    converted; rename it. Names alone never decide when the same name is also bound to a value
    in degrees in the same scope. A library method that reads degrees is known only on a value whose class the code shows
    (`Image.open(path).rotate(...)`, `img: Image.Image`): a PIL image passed in untyped, or
    matplotlib's `Affine2D.rotate_deg`, is not recognised. A class's constructor is read only through attributes stored once, unconditionally in
    `__init__`, and read by the class's own methods (not by other classes, `rotation.yaw`); a class
    whose methods read the attribute in both units says nothing, and the value's radians must show in
    the module's own code or a library call (not only in a project helper's return). A keyword named `unit` / `*_units`
    with the value `"deg"` / `"degrees"` is taken to state the unit of the call's angles; a helper
    whose keyword picks the unit of its output would be misread.
    """

    code = "GEO305"
    name = "radians-as-degrees"
    # a conversion from degrees, or (for a project helper that reads degrees) radians in plain sight
    triggers = AllOf(r"\bpi\b|deg2rad|radians|degrees\s*=\s*True|arctan|atan|acos|asin|arccos|arcsin|_rad|as_euler|euler_from|2euler|EulerFrom|units?\s*=\s*[\"\']deg")  # type: ignore[assignment]

    VALID = [
        Valid(
            "import math\nclass Heading:\n    def __init__(self, yaw):\n        self.yaw = yaw\n"
            "    def forward(self):\n        return math.cos(math.radians(self.yaw))\n"
            "def f(dy, dx):\n    return Heading(math.degrees(math.atan2(dy, dx)))\n"
        ),
        Valid(  # read in both units by its own methods: what it takes is not known
            "import math\nclass Bearing:\n    def __init__(self, angle):\n        self.angle = angle\n"
            "    def a(self):\n        return math.radians(self.angle)\n    def b(self):\n        return math.cos(self.angle)\n"
            "def f(dy, dx):\n    return Bearing(math.atan2(dy, dx))\n"
        ),
        Valid("import numpy as np\ndef f(make_pose):\n    return make_pose(roll=90.0, yaw=np.degrees(np.pi / 2), angle_units='degrees')\n"),
        Valid("import numpy as np\nimport cv2\ndef f(img, dy, dx):\n    return cv2.getRotationMatrix2D((0, 0), np.degrees(np.arctan2(dy, dx)), 1.0)\n"),
        Valid("import numpy as np\ndef f(heading_deg):\n    return np.deg2rad(heading_deg)\n"),
        Valid("import numpy as np\ndef f(dy, dx):\n    return np.degrees(np.arctan2(dy, dx))\n"),
        Valid("import math\ndef f(angle):\n    return math.radians(angle)\n"),
        Valid("import numpy as np\ndef f(yaw_deg):\n    return yaw_deg * np.pi / 180\n"),
        Valid("import numpy as np\ndef f(dy, dx):\n    return np.arctan2(dy, dx) * 180 / np.pi\n"),  # to degrees: right
        Valid(
            "from scipy.spatial.transform import Rotation\ndef f(yaw_deg):\n"
            "    return Rotation.from_euler('z', yaw_deg, degrees=True)\n"
        ),
        Valid("import numpy as np\ndef f(x):\n    theta_rad = np.degrees(x)\n    return np.radians(theta_rad)\n"),  # conflicting
    ]
    INVALID = [
        Invalid(
            "import cv2\nfrom tf.transformations import euler_from_quaternion\ndef f(q):\n"
            "    roll, pitch, yaw = euler_from_quaternion(q)\n    return cv2.getRotationMatrix2D((0, 0), yaw, 1.0)\n",
            message="`cv2.getRotationMatrix2D` reads its angle in degrees, but `yaw` is in radians (`tf.transformations.euler_from_quaternion` returns its angles in radians)",
            range=(5, 44, 5, 47),
        ),
        Invalid(
            "import math\nclass Heading:\n    def __init__(self, yaw):\n        self.yaw = yaw\n"
            "    def forward(self):\n        return math.cos(math.radians(self.yaw))\n"
            "def f(dy, dx):\n    return Heading(math.atan2(dy, dx))\n"
        ),
        Invalid(
            "class Rotation:\n    def __init__(self, pitch=0.0, yaw=0.0, roll=0.0):\n"
            "        self.pitch = pitch\n        self.yaw = yaw\n        self.roll = roll\n"
            "    def as_carla(self):\n        import carla\n        return carla.Rotation(pitch=self.pitch)\n"
            "def f(quat):\n    from tf.transformations import euler_from_quaternion\n"
            "    return Rotation(pitch=euler_from_quaternion(quat)[1])\n"
        ),
        Invalid("import numpy as np\ndef f(make_pose):\n    return make_pose(roll=np.pi / 2, yaw=-90.0, angle_units='degrees')\n"),
        Invalid("import numpy as np\nimport cv2\ndef f(img, dy, dx):\n    return cv2.getRotationMatrix2D((0, 0), np.arctan2(dy, dx), 1.0)\n"),
        Invalid(  # nothing but `pi` says radians
            "import numpy as np\nfrom PIL import Image\ndef f(path):\n    return Image.open(path).rotate(np.pi / 4)\n",
            message="`Image.open(path).rotate` reads its angle in degrees, but `np.pi / 4` is in radians (`np.pi` is an angle in radians)",
            range=(4, 36, 4, 45),
        ),
        Invalid(
            "import numpy as np\n"
            "def wrap_degrees(angle_deg):\n"
            "    return (angle_deg + 180.0) % 360.0 - 180.0\n"
            "def f(dy, dx):\n"
            "    return wrap_degrees(np.arctan2(dy, dx))\n"
        ),
        Invalid(
            "import numpy as np\ndef f(dy, dx):\n    return np.deg2rad(np.arctan2(dy, dx))\n",
            expected_fix="import numpy as np\ndef f(dy, dx):\n    return np.arctan2(dy, dx)\n",
        ),
        Invalid("import math\ndef f(theta_rad):\n    return math.radians(theta_rad)\n"),
        Invalid(
            "import numpy as np\ndef f(dy, dx):\n    yaw = np.arctan2(dy, dx)\n    return yaw * np.pi / 180\n",
            expected_fix="import numpy as np\ndef f(dy, dx):\n    yaw = np.arctan2(dy, dx)\n    return yaw\n",
        ),
        Invalid("import numpy as np\ndef f(c):\n    half = np.arccos(c) / 2\n    return np.radians(half)\n"),
        Invalid(
            "import numpy as np\nfrom scipy.spatial.transform import Rotation\ndef f(dy, dx):\n"
            "    yaw = np.arctan2(dy, dx)\n    return Rotation.from_euler('z', yaw, degrees=True)\n"
        ),
    ]

    def run(self) -> None:
        units = self.facts.shared(AngleUnits)
        for node in self.facts.index.nodes(Call):
            self._check(node, units)  # type: ignore[arg-type]
        for node in self.facts.index.nodes(BinOp):
            report_hand_conversion_of_converted(self, node, RADIANS, units)  # type: ignore[arg-type]

    def _check_unit_keyword(self, node: Call, units: AngleUnits) -> bool:
        """`Pose(roll=np.pi / 2, ..., angle_units="degrees")`, `SE3.Rx(np.pi / 2, unit="deg")`: the call
        says by a keyword that its angles are in degrees, and one of them is in radians by the code
        (not by a name)."""
        stated = next(
            (given for given in node.keywords if given.arg and _UNIT_KEYWORD.search(given.arg) and string(given.value) in _DEGREE_STRINGS), None
        )
        if stated is None:
            return False
        for argument in [*node.args, *(given.value for given in node.keywords if given is not stated)]:
            for element in argument.elts if isinstance(argument, (ast.List, ast.Tuple)) else [argument]:
                unit = units.unit_of(element)
                if unit is not None and unit.unit == RADIANS and not unit.by_name:
                    said = f"{stated.arg}={self.code_of(stated.value)}"
                    self.report(
                        element,
                        f"`{self.code_of(node.func)}(..., {said})` is told its angles are in degrees, but `{self.code_of(element)}` "
                        f"is in radians ({unit.evidence})",
                        evidence=(f"`{said}` states degrees", unit.evidence),
                    )
                    return True
        return False

    def _check(self, node: Call, units: AngleUnits) -> None:
        facts = self.facts
        found = wrong_unit_passed(facts, node, DEGREES, units)
        if found is not None:
            argument, message, evidence = found
            self.report(argument, message, evidence=evidence)
            return
        if units.converts(node) == RADIANS:
            report_conversion_of_converted(self, node, self.code_of(node.func), positional_args(node)[0], RADIANS, units)
            return
        if node.keywords and self._check_unit_keyword(node, units):
            return
        angles = degree_arguments(facts, node)
        if not angles:
            return
        told = library_calls.choosing_keywords(facts, node)  # `degrees=True`: the call itself says degrees
        reads = f"`{self.code_of(node.func)}(..., {', '.join(told)})` reads degrees" if told else f"`{self.code_of(node.func)}` reads its angle in degrees"
        for angle in angles:
            judged = [(element, units.unit_of(element)) for element in angle_elements(angle)]
            if any(unit is not None and unit.unit == DEGREES for _, unit in judged):
                continue  # radians beside degrees in one list: which one is wrong is not clear
            # a name that says radians contradicts a call that says degrees itself; an API that always reads
            # degrees needs the code's evidence
            in_radians = [(element, unit) for element, unit in judged if unit is not None and unit.unit == RADIANS and (told or not unit.by_name)]
            if in_radians:
                element, unit = in_radians[0]
                self.report(element, f"{reads}, but `{self.code_of(element)}` is in radians ({unit.evidence})", evidence=(unit.evidence,))
                return

