"""GEO307 euler-angles-in-quaternion: Euler angles (roll, pitch, yaw) written into a quaternion's components,
or given whole where pybullet takes a quaternion."""

from __future__ import annotations

from typing import Final

import ast
from ast import AST, Add, Assign, Attribute, BinOp, Call, Load, Name, Sub, Subscript, UAdd, USub, UnaryOp
import re
from collections.abc import Sequence
from dataclasses import dataclass

from geolint.factbase import library_calls
from geolint.factbase.angles import (
    EULER_METHOD_NAMES,
    RETURNED_EULER_METHODS,
)
from geolint.factbase.index import Scope, UnpackBinding
from geolint.factbase.messages import MessageTypes, holds_quaternion_components
from geolint.factbase.model import dotted_name, last_name, number, positional_args, walk_within
from geolint.factbase.rotations import PYBULLET_QUATERNION_CALLS, TRIG_FUNCTIONS, pybullet_quaternion_values
from geolint.rules.fact_rule import FactRule
from geolint.rules.base import Invalid, Valid
from geolint.rules.triggers import AllOf

_COMPONENTS: Final = ("x", "y", "z", "w")
# Fields that hold a message's orientation: a Quaternion message placed there is read as a rotation.
_ORIENTATION_FIELDS: Final = frozenset({"orientation", "rotation"})
_ANGLE_WORDS: Final = ("roll", "pitch", "yaw")
_SEQUENCE_WORDS: Final = frozenset({"rpy", "euler", "eulers"})
# Words that make `yaw_rate`, `roll_vel`, `pitch_std`, `yaw_quat` something other than an angle.
_NOT_AN_ANGLE: Final = frozenset(
    {"rate", "rates", "vel", "velocity", "speed", "dot", "acc", "accel", "std", "sigma", "cov", "covariance", "noise", "gain", "sin", "cos", "half"}
    | {"q", "quat", "quaternion", "qx", "qy", "qz", "qw", "orientation", "rot", "rotation"}
)
_UNIT_CALLS: Final = frozenset({"degrees", "radians", "deg2rad", "rad2deg"})
_MAX_DEPTH: Final = 6


@dataclass(frozen=True)
class _Angle:
    label: str  # which angle: "roll", "element 2 of `rpy`"
    evidence: str  # why it is an Euler angle
    strong: bool  # a library call says it (not a name)
    instead: str | None = None  # the same object's call that returns a quaternion


@dataclass(frozen=True)
class _Source:
    names: tuple[str, ...]  # the angles in order, when the source says
    evidence: str
    strong: bool
    instead: str | None = None


class EulerAnglesInQuaternion(FactRule):
    """Euler angles (roll, pitch, yaw) are written into a quaternion message's components, or given
    where pybullet takes a quaternion.

    ## What it does
    Flags a ROS `geometry_msgs/Quaternion` (a message's `orientation` or `rotation` field, a
    `Quaternion()` built and placed there, or `Quaternion(x=..., y=..., z=..., w=...)`) whose `x`, `y`,
    `z` or `w` is given an Euler angle. An angle is known from the library call that returned it:
    an element of tf's `euler_from_quaternion` / `euler_from_matrix`, transforms3d's `quat2euler`,
    pybullet's `getEulerFromQuaternion`, scipy's `as_euler`, Webots' `InertialUnit.getRollPitchYaw()`
    (the tables of `geolint.factbase.angles`), followed through names, `-a`, `float(a)` and
    `np.degrees(a)`. Names alone (`roll`, `pitch`, `yaw`, `rpy[0]`, `rpy.x`) count only when they fill two
    components or more with different angles.

    It also flags three Euler angles given whole where pybullet reads an (x, y, z, w) quaternion: the
    orientation arguments GEO301 reads (`resetBasePositionAndOrientation`, `loadURDF`,
    `multiplyTransforms`...), a shape's frame or a body's inertial frame (`visualFrameOrientation`,
    `collisionFrameOrientation`, `baseInertialFrameOrientation`), and each item of the per-shape and
    per-link lists (`visualFrameOrientations`, `collisionFrameOrientations`, `linkOrientations`,
    `linkInertialFrameOrientations`: a list literal's items, a list comprehension's element). Here a
    value is Euler angles when a library call says so (`getEulerFromQuaternion`, as above) or when
    its name or attribute says so (`rpy`, `euler`, `visual.origin_rpy`) and it is not bound to a call
    that makes a quaternion (`start_euler = p.getQuaternionFromEuler(...)`).

    ## Why is this bad?
    A quaternion's components are not angles: (x, y, z) is the rotation axis times sin(angle / 2) and
    w is cos(angle / 2). Roll, pitch and yaw copied into x, y and z give a quaternion that is not unit
    length and not the rotation (with w left at its default, 0.0 in ROS 1 and 1.0 in ROS 2, a small
    roll of 0.1 rad reads as a rotation of about 11 degrees in ROS 2 and 180 degrees in ROS 1).
    Consumers (tf, RViz, robot_localization) normalise it or reject it without a word. pybullet reads
    a quaternion with `pybullet_internalSetVector4d`, and the shape functions and `createMultiBody`
    ignore its result (`examples/pybullet/pybullet.c`): a sequence that is not four long leaves the
    default (0, 0, 0, 1), so a shape frame given roll, pitch and yaw is silently left unrotated (a
    link's frame is left uninitialised).

    ## Example
    ```python
    from sensor_msgs.msg import Imu

    def imu_message(inertial_unit):
        rpy = inertial_unit.getRollPitchYaw()
        msg = Imu()
        msg.orientation.x = rpy[0]
        msg.orientation.y = rpy[1]
        msg.orientation.z = rpy[2]
        return msg
    ```

    ## Use instead
    ```python
    from sensor_msgs.msg import Imu
    from tf_transformations import quaternion_from_euler

    def imu_message(inertial_unit):
        roll, pitch, yaw = inertial_unit.getRollPitchYaw()
        msg = Imu()
        msg.orientation.x, msg.orientation.y, msg.orientation.z, msg.orientation.w = quaternion_from_euler(roll, pitch, yaw)
        return msg
    ```
    (or, in Webots, `inertial_unit.getQuaternion()`, which returns x, y, z, w).

    ## Fix safety
    No fix is offered: which Euler convention the angles follow (the axes and their order) is the
    author's to state in the conversion.

    ## Known problems
    Of messages, only `geometry_msgs` Quaternion messages are checked (a Quaternion message that is neither a
    field of a known message nor put into an `orientation` / `rotation` may carry three angles on
    purpose, and is left alone), and only components written one by one or as constructor arguments:
    `q.x, q.y, q.z = angles` is not read. An angle reaching the component through a project helper
    (`interpolate(rpy[0], table)`) or a container is not followed. A name such as `roll` alone in
    one component is not enough. A `Pose` or `Imu` used on purpose to carry three angles to a
    node of the same project is flagged too: every other reader of the message takes it for a
    rotation. For pybullet, a name alone is enough (a value given whole, not one component): a
    quaternion named `rpy` or `euler` that is a parameter or an attribute is flagged although it is
    right. Lists of quaternions built elsewhere (`orientations.append(rpy)` before the call) and
    pybullet calls on a client object whose Euler angles carry no telling name are not followed.
    """

    code = "GEO307"
    name = "euler-angles-in-quaternion"
    triggers = AllOf(
        r"_msgs|Orientation|loadURDF|multiplyTransforms|invertTransform|calculateInverseKinematics",
        r"[Ee]uler|RollPitchYaw|roll|pitch|yaw|rpy",
    )

    VALID = [
        # the conversion the quaternion needs
        Valid(
            "from geometry_msgs.msg import Pose\nfrom tf.transformations import euler_from_quaternion, quaternion_from_euler\n"
            "def f(q):\n    roll, pitch, yaw = euler_from_quaternion(q)\n    x, y, z, w = quaternion_from_euler(roll, pitch, 0.0)\n"
            "    pose = Pose()\n    pose.orientation.x = x\n    pose.orientation.y = y\n    pose.orientation.z = z\n    pose.orientation.w = w\n    return pose\n"
        ),
        # a half-angle formula: sin(yaw / 2) is a component, yaw is not
        Valid(
            "import math\nfrom geometry_msgs.msg import Quaternion\nfrom tf.transformations import euler_from_quaternion\n"
            "def f(q):\n    yaw = euler_from_quaternion(q)[2]\n    return Quaternion(x=0.0, y=0.0, z=math.sin(yaw / 2), w=math.cos(yaw / 2))\n"
        ),
        # a Quaternion message carrying three angles, published as such: not an orientation
        Valid(
            "from geometry_msgs.msg import Quaternion\nfrom tf.transformations import euler_from_quaternion\n"
            "def f(pub, q):\n    rpy = euler_from_quaternion(q)\n    msg = Quaternion()\n    msg.x = rpy[0]\n    msg.y = rpy[1]\n    msg.z = rpy[2]\n    pub.publish(msg)\n"
        ),
        # one name alone is no evidence
        Valid("from geometry_msgs.msg import Pose\ndef f(yaw):\n    pose = Pose()\n    pose.orientation.z = yaw\n    pose.orientation.w = 1.0\n    return pose\n"),
        # pybullet: the angles converted, and a quaternion whose name mentions the angles it came from
        Valid("import pybullet as p\np.createVisualShapeArray(shapeTypes=k, visualFrameOrientations=[p.getQuaternionFromEuler(v.rpy) for v in vs])\n"),
        Valid("import pybullet as p\nstart_euler = p.getQuaternionFromEuler(rpy)\np.resetBasePositionAndOrientation(body, pos, start_euler)\n"),
    ]
    INVALID = [
        Invalid(
            "from sensor_msgs.msg import Imu\ndef f(imu):\n    rpy = imu.getRollPitchYaw()\n    msg = Imu()\n    msg.orientation.x = rpy[0]\n"
            "    msg.orientation.y = rpy[1]\n    msg.orientation.z = rpy[2]\n    return msg\n",
            message="`msg.orientation.x` is given `rpy[0]` (and y = `rpy[1]`, z = `rpy[2]`), an Euler angle (roll: `controller.InertialUnit.getRollPitchYaw` returns them); a quaternion's components are not angles: use `getQuaternion()` (x, y, z, w) and set all four",
            range=(5, 5, 5, 22),
        ),
        Invalid(
            "from geometry_msgs.msg import Pose, Quaternion\nfrom tf_transformations import euler_from_quaternion\n"
            "def f(q):\n    roll, pitch, yaw = euler_from_quaternion(q)\n    return Pose(orientation=Quaternion(x=roll, y=-pitch, z=yaw, w=1.0))\n"
        ),
        # names only, but three components from roll, pitch and yaw
        Invalid(
            "from geometry_msgs.msg import PoseStamped\ndef f(roll, pitch, yaw):\n    p = PoseStamped()\n    p.pose.orientation.x = roll\n"
            "    p.pose.orientation.y = pitch\n    p.pose.orientation.z = yaw\n    return p\n"
        ),
        # pybullet: URDF roll-pitch-yaw triples as the shapes' frame quaternions
        Invalid("import pybullet as p\np.createVisualShapeArray(shapeTypes=k, visualFrameOrientations=[v.origin_rpy for v in vs])\n"),
    ]

    def run(self) -> None:
        facts = self.facts
        if "_msgs" in self.context.source:
            self._check_messages()
        for call in facts.index.nodes(Call):
            if isinstance(call, Call) and (last_name(call.func) or "") in PYBULLET_QUATERNION_CALLS:
                self._check_pybullet(call)

    def _check_messages(self) -> None:
        facts = self.facts
        types = facts.shared(MessageTypes)
        for scope in facts.index.scopes.values():
            stores: dict[str, list[tuple[str, ast.expr, Attribute]]] = {}
            for target, value in scope.attribute_stores:
                if target.attr in _COMPONENTS:
                    path = dotted_name(target.value)
                    if path is not None:
                        stores.setdefault(path, []).append((target.attr, value, target))
            for path, written in stores.items():
                quaternion = written[0][2].value
                if self._is_quaternion(types, quaternion) and self._read_as_rotation(quaternion):
                    self._check(path, [(component, value) for component, value, _ in written], written[0][2])
        for call in facts.index.nodes(Call):
            if facts.called_name(call.func) == "Quaternion" and holds_quaternion_components(facts.qualified_name(call.func)):  # type: ignore[attr-defined]
                given = [(component, value) for component, value in zip(_COMPONENTS, positional_args(call))]  # type: ignore[arg-type]
                given += [(item.arg, item.value) for item in call.keywords if item.arg in _COMPONENTS]  # type: ignore[attr-defined]
                if given and self._placed_as_rotation(call):  # type: ignore[arg-type]
                    self._check(f"{facts.code_of(call.func)}(...)", given, call)  # type: ignore[attr-defined,arg-type]

    def _check_pybullet(self, call: Call) -> None:
        """An Euler triple where pybullet takes a quaternion: `visualFrameOrientations=[v.rpy for v in shapes]`."""
        for parameter, value in pybullet_quaternion_values(call):
            source = self._euler_source(value, 0)
            if source is None or not source.strong and self._names_a_quaternion(value):
                continue
            frame = parameter != "orientation"  # a shape's or a link's frame: pybullet ignores a wrong length
            slot = f"`{parameter}`" if frame else "its orientation argument"
            ignored = " (pybullet ignores a sequence that is not four long here)" if frame else ""
            self.report(
                value,
                f"`{self.code_of(value)}` holds Euler angles ({source.evidence}), but pybullet's `{last_name(call.func)}` reads "
                f"{slot} as a quaternion (x, y, z, w): three angles are no quaternion{ignored}; "
                "convert them with `getQuaternionFromEuler`",
            )

    def _names_a_quaternion(self, value: ast.expr) -> bool:
        """A name bound to a call that makes a quaternion (`euler_q = p.getQuaternionFromEuler(euler)`)."""
        bound = self.facts.bindings(value) if isinstance(value, Name) else None
        return any(
            isinstance(part, Call) and "quat" in (last_name(part.func) or "").lower()
            for binding in bound or []
            if isinstance(binding, ast.expr)
            for part in ast.walk(binding)
        )

    def _check(self, quaternion: str, given: list[tuple[str, ast.expr]], anchor: AST) -> None:
        angles = [(component, value, self._angle(value, 0)) for component, value in given]
        found = [(component, value, angle) for component, value, angle in angles if angle is not None]
        strong = [item for item in found if item[2].strong]
        if not strong and len({angle.label for _, _, angle in found}) < 2:
            return  # a name alone (`q.z = yaw`) is no evidence
        component, value, angle = (strong or found)[0]
        others = [f"{c} = `{self.code_of(v)}`" for c, v, _ in found if v is not value]
        also = f" (and {', '.join(others)})" if others else ""
        instead = f"use `{angle.instead})" if angle.instead else "convert the angles (`quaternion_from_euler(roll, pitch, yaw)`)"
        self.report(
            anchor,
            f"{_slot(quaternion, component)} is given `{self.code_of(value)}`{also}, an Euler angle ({angle.label}: {angle.evidence}); "
            f"a quaternion's components are not angles: {instead} and set all four",
        )

    def _is_quaternion(self, types: MessageTypes, node: ast.expr) -> bool:
        """A Quaternion message: a field the fact base knows (`msg.orientation` of an `Imu()`), or a name
        bound only to `Quaternion()`."""
        if isinstance(node, Attribute):
            return holds_quaternion_components(types.class_of(node))
        if not isinstance(node, Name):
            return False
        bound = self.facts.bindings(node) or []
        facts = self.facts
        return bool(bound) and all(
            isinstance(binding, Call) and holds_quaternion_components(facts.qualified_name(binding.func)) for binding in bound
        )

    # -- where the quaternion goes ------------------------------------------------------------------

    def _read_as_rotation(self, quaternion: ast.expr) -> bool:
        """A field of a known message (`msg.orientation`), or a Quaternion message built alone and
        then put into an orientation (not a carrier of three numbers)."""
        if isinstance(quaternion, Attribute):
            return True  # the class says Quaternion only through a known message's field or `self.q` built here
        if not isinstance(quaternion, Name):
            return False
        scope = self.facts.index.scope_of(quaternion)
        for node in self._uses(quaternion.id, scope):
            if self._placed_as_rotation(node):
                return True
        return False

    @staticmethod
    def _uses(name: str, scope: Scope) -> list[Name]:
        return [node for node in walk_within(scope.node) if isinstance(node, Name) and node.id == name and isinstance(node.ctx, Load)]

    def _placed_as_rotation(self, node: ast.expr) -> bool:
        """`pose.orientation = node`, `Pose(orientation=node)`, `Transform(rotation=node)`."""
        parent = self.facts.parent(node)
        if isinstance(parent, ast.keyword):
            return parent.arg in _ORIENTATION_FIELDS
        if isinstance(parent, Assign) and parent.value is node:
            return any(isinstance(target, Attribute) and target.attr in _ORIENTATION_FIELDS for target in parent.targets)
        return False

    # -- what the value is --------------------------------------------------------------------------

    def _angle(self, node: ast.expr, depth: int) -> _Angle | None:
        """Why `node` is an Euler angle, or None."""
        if depth > _MAX_DEPTH:
            return None
        if isinstance(node, UnaryOp) and isinstance(node.op, (USub, UAdd)):
            return self._angle(node.operand, depth + 1)
        if isinstance(node, BinOp) and isinstance(node.op, (Add, Sub)):
            if number(node.right) is not None:
                return self._angle(node.left, depth + 1)  # `yaw + 0.1`, still an angle (not `yaw / 2`)
            return None
        if isinstance(node, Call):
            called = self.facts.called_name(node.func)
            arguments = positional_args(node)
            if len(arguments) == 1 and not node.keywords and (called == "float" or called in _UNIT_CALLS):
                return self._angle(arguments[0], depth + 1)
            return None
        if isinstance(node, Subscript):
            position = number(node.slice)
            if position is None or position != int(position):
                return None
            return self._element(node.value, int(position), depth + 1)
        if isinstance(node, Name):
            return self._angle_of_name(node, depth)
        if isinstance(node, Attribute):
            return self._angle_of_attribute(node, depth)
        return None

    def _angle_of_name(self, node: Name, depth: int) -> _Angle | None:
        """Every binding an angle a library returned, or (weak) a name that says roll, pitch or yaw."""
        facts = self.facts
        if node.id in facts.index.scope_of(node).augmented:
            return None
        bound = facts.bindings(node) or []
        found = [self._bound_angle(binding, depth + 1) for binding in bound]
        if found and all(angle is not None and angle.strong for angle in found):
            return found[0]
        return self._named(node.id, bound)

    def _angle_of_attribute(self, node: Attribute, depth: int) -> _Angle | None:
        """`self.yaw` as its stores say; `rpy.z`, a component of named angles; or the attribute's name."""
        if isinstance(node.value, Name) and node.value.id == "self":
            stores = self.facts.index.self_attribute_stores.get(node.attr, [])
            found = [self._angle(store, depth + 1) for store in stores]
            if found and all(angle is not None and angle.strong for angle in found):
                return found[0]
            return self._named(node.attr, stores)
        if node.attr in _COMPONENTS[:3]:
            return self._component_of_angles(node)
        return self._named(node.attr, [])

    @staticmethod
    def _component_of_angles(node: Attribute) -> _Angle | None:
        """Weak evidence: `rpy.x`, `self.euler.z`, a component of a 3-vector whose name says Euler angles."""
        owner = node.value
        name = owner.attr if isinstance(owner, Attribute) else owner.id if isinstance(owner, Name) else None
        words = _words(name or "")
        if words & _SEQUENCE_WORDS and not words & _NOT_AN_ANGLE:
            return _Angle(f"`{name}.{node.attr}`", f"the name `{name}` says Euler angles", False)
        return None

    def _bound_angle(self, binding: object, depth: int) -> _Angle | None:
        if isinstance(binding, UnpackBinding):
            return self._element(binding.value, binding.position, depth)  # `roll, pitch, yaw = euler_from_quaternion(q)`
        return self._angle(binding, depth) if isinstance(binding, ast.expr) else None

    def _element(self, sequence: ast.expr, position: int, depth: int) -> _Angle | None:
        """Element `position` of `sequence`, when `sequence` holds Euler angles."""
        source = self._euler_source(sequence, depth)
        if source is None:
            return None
        names = source.names
        label = names[position] if 0 <= position < len(names) else f"element {position} of `{self.code_of(sequence)}`"
        return _Angle(label, source.evidence, source.strong, source.instead)

    def _euler_source(self, node: ast.expr, depth: int) -> _Source | None:
        """The angles' names when known, why, and whether a library says so, for a value holding Euler angles."""
        if depth > _MAX_DEPTH:
            return None
        if isinstance(node, Call):
            return self._euler_source_of_call(node)
        if isinstance(node, Name):
            bound = self.facts.bindings(node) or []
            values = [binding for binding in bound if isinstance(binding, ast.expr)]
            return self._euler_source_of_values(node.id, values, len(values) == len(bound), depth)
        if isinstance(node, Attribute):  # `self.rpy` as its stores say, or another object's (`visual.origin_rpy`)
            is_self = isinstance(node.value, Name) and node.value.id == "self"
            stores = self.facts.index.self_attribute_stores.get(node.attr, []) if is_self else []
            return self._euler_source_of_values(node.attr, stores, True, depth)
        return None

    def _euler_source_of_call(self, node: Call) -> _Source | None:
        """A library call that returns Euler angles (`euler_from_quaternion(q)`, `r.as_euler("xyz")`)."""
        facts = self.facts
        api = library_calls.called_api(facts, node)
        if api is not None and library_calls.returns_euler_angles(facts, node):  # the knowledge base (stubs/)
            return _Source((), f"`{api.qualified_name}` returns Euler angles", True)
        func = node.func
        if isinstance(func, Attribute):
            method = EULER_METHOD_NAMES.get(func.attr)
            if method is not None and not node.args:
                _, names, twin = RETURNED_EULER_METHODS[method]
                return _Source(names, f"`{method}` returns them", True, twin)
        return None

    def _euler_source_of_values(self, name: str, values: Sequence[ast.expr], every_value_known: bool, depth: int) -> _Source | None:
        """Values that all hold angles a library returned, or (weak) a name that says Euler angles
        and is never bound to a trigonometric formula."""
        found = [self._euler_source(value, depth + 1) for value in values]
        if found and every_value_known and all(source is not None and source.strong for source in found):
            return found[0]
        words = _words(name)
        if words & _SEQUENCE_WORDS and not words & _NOT_AN_ANGLE and not any(_trig(value) for value in values):
            return _Source((), f"the name `{name}` says Euler angles", False)
        return None

    @staticmethod
    def _named(name: str, bound: Sequence[object]) -> _Angle | None:
        """Weak evidence: a name that says roll, pitch or yaw, never bound to a trigonometric formula."""
        words = _words(name)
        said = [word for word in _ANGLE_WORDS if word in words]
        if len(said) != 1 or words & _NOT_AN_ANGLE or words & _SEQUENCE_WORDS:
            return None
        if any(isinstance(binding, ast.expr) and _trig(binding) for binding in bound):
            return None
        return _Angle(said[0], f"the name `{name}` says so", False)


def _slot(quaternion: str, component: str) -> str:
    return f"`{quaternion}`'s {component}" if quaternion.endswith("(...)") else f"`{quaternion}.{component}`"


def _words(name: str) -> set[str]:
    return {word.lower() for word in re.findall(r"[A-Z]?[a-z]+|[A-Z]+(?![a-z])|\d+", name)}


def _trig(node: ast.expr) -> bool:
    """A formula with sin or cos in it (a quaternion component computed from angles)."""
    return any(
        isinstance(part, Call) and (getattr(part.func, "attr", None) or getattr(part.func, "id", None)) in TRIG_FUNCTIONS
        for part in ast.walk(node)
    )

