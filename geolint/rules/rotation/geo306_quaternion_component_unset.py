"""GEO306 quaternion-component-unset: a quaternion message copied component by component with one left out."""

from __future__ import annotations

from typing import Final

import ast
from ast import (
    AST,
    Assign,
    Attribute,
    Call,
    Constant,
    Load,
    Name,
    Starred,
    Store,
    Subscript,
)

from geolint.factbase import library_calls
from geolint.factbase.angles import EULER_METHOD_NAMES
from geolint.factbase.index import FUNCTION_NODES
from geolint.factbase.messages import MessageTypes, holds_quaternion_components
from geolint.factbase.model import FactBase, dotted_name, number, walk_within
from geolint.factbase.rotations import IDENTITY_NAME
from geolint.rules.fact_rule import FactRule
from geolint.rules.base import Invalid, Valid
from geolint.factbase.quaternion_orders import QuaternionFlow, convention
from geolint.rules.triggers import AllOf

_COMPONENTS: Final = ("x", "y", "z", "w")
# Words that make a source's `.x`, `.y`, `.z` a quaternion's (so it has a `.w` to copy too): a Quaternion
# message misused to carry three angles (`q.x = rpy.x`) leaves w alone on purpose.
_ROTATION_WORDS: Final = frozenset({"rotation", "rot", "orientation", "quat", "quaternion", "attitude", "q"})
_EULER_WORDS: Final = frozenset({"rpy", "euler", "eulers"})
_DEFAULTS: Final = {"w": "0.0 in ROS 1, 1.0 in ROS 2", "x": "0.0", "y": "0.0", "z": "0.0"}


class QuaternionComponentUnset(FactRule):
    """A quaternion message is copied component by component and one component is never set.

    ## What it does
    Flags a function that builds a ROS message holding a quaternion (`Pose()`, `PoseWithCovariance()`,
    `Odometry()`, `TransformStamped()`, `Imu()`, `Quaternion()`; no arguments, so its defaults are
    known), copies three of the quaternion's components from one source
    (`msg.pose.orientation.x = rotation.x`, `.y = rotation.y`, `.z = rotation.z`) and never sets
    the fourth, neither by itself nor by replacing the whole quaternion or a message around it.
    Also flags x, y and z written from three elements in a row of one sequence (`s[0]`, `s[1]`,
    `s[2]`, each maybe through the same call, `f(s[0], table)`) with w never set: whether `s` holds
    three angles or a quaternion, the message's quaternion is wrong. And flags a message whose name
    says identity (`no_rotation`, `identity`) with only `x`, `y` or `z` set to 1 and w never set
    (`no_rotation.rotation.x = 1.0`): the identity written in w, x, y, z order into an x, y, z, w message.

    ## Why is this bad?
    The missing component keeps the message's default: w is 0.0 in ROS 1 (genpy) and 1.0 in ROS 2
    (`geometry_msgs/msg/Quaternion.msg`), x, y and z are 0.0. The message then carries a quaternion
    that is not the source's (with w = 0, a rotation by 180 degrees about (x, y, z), not unit length),
    and consumers normalise or reject it without a word.

    ## Example
    ```python
    def to_pose(rotation):
        pose = Pose()
        pose.orientation.x = rotation.x
        pose.orientation.y = rotation.y
        pose.orientation.z = rotation.z
        return pose
    ```

    ## Use instead
    ```python
    def to_pose(rotation):
        pose = Pose()
        pose.orientation.x = rotation.x
        pose.orientation.y = rotation.y
        pose.orientation.z = rotation.z
        pose.orientation.w = rotation.w
        return pose
    ```

    ## Fix safety
    Copying the missing component from the same source, after the last copied one, is offered as an
    unsafe fix: the source is assumed to have that component.

    ## Known problems
    Only messages built in the same function with no arguments are checked, and only while the
    message is not handed anywhere (a call, another name) before the last component is copied: a
    helper may set the missing one. When w is the one missing, the source's name must say it is a
    rotation (`rotation`, `orientation`, `quat`, `q`...), since a Quaternion message is sometimes
    used to carry three angles; elements in a row of a sequence are flagged whatever its name, as
    only a known message's field (`Imu.orientation`, `Pose.orientation`, `Transform.rotation`) is
    checked, never a bare Quaternion message. Components copied through a helper, or from
    different sources, are not looked at. A lone `x = 1` is flagged only under a name that says
    identity: a deliberate half turn about x (ROS 1's w default is 0) is written the same way.
    """

    code = "GEO306"
    name = "quaternion-component-unset"
    triggers = AllOf(r"\.[xyzw]\s*=[^=]", r"_msgs|Quaternion")

    VALID = [
        Valid("from geometry_msgs.msg import Transform\ndef f():\n    no_rotation = Transform()\n    no_rotation.rotation.w = 1.0\n    return no_rotation\n"),
        Valid("from geometry_msgs.msg import Transform\ndef f():\n    flipped = Transform()\n    flipped.rotation.x = 1.0\n    return flipped\n"),
        Valid(
            "from geometry_msgs.msg import Pose\ndef f(rotation):\n    pose = Pose()\n    pose.orientation.x = rotation.x\n"
            "    pose.orientation.y = rotation.y\n    pose.orientation.z = rotation.z\n    pose.orientation.w = rotation.w\n    return pose\n"
        ),
        # a Quaternion message carrying three angles: the source says no rotation
        Valid(
            "from geometry_msgs.msg import Quaternion\ndef f(rpy):\n    q = Quaternion()\n    q.x = rpy.x\n    q.y = rpy.y\n    q.z = rpy.z\n    return q\n"
        ),
        # elements of a sequence with w set from it too
        Valid(
            "from geometry_msgs.msg import Pose\ndef f(q):\n    pose = Pose()\n    pose.orientation.x = q[0]\n"
            "    pose.orientation.y = q[1]\n    pose.orientation.z = q[2]\n    pose.orientation.w = q[3]\n    return pose\n"
        ),
        # elements not in a row (a different mistake, if any)
        Valid(
            "from geometry_msgs.msg import Pose\ndef f(q):\n    pose = Pose()\n    pose.orientation.x = q[0]\n"
            "    pose.orientation.y = q[0]\n    pose.orientation.z = q[2]\n    return pose\n"
        ),
        # handed to a helper before the components are copied: it may set w
        Valid(
            "from geometry_msgs.msg import Pose\ndef f(rotation):\n    pose = Pose()\n    init_pose(pose)\n    pose.orientation.x = rotation.x\n"
            "    pose.orientation.y = rotation.y\n    pose.orientation.z = rotation.z\n    return pose\n"
        ),
        # w set through another name
        Valid(
            "from geometry_msgs.msg import Pose\ndef f(rotation):\n    pose = Pose()\n    pose.orientation.x = rotation.x\n"
            "    pose.orientation.y = rotation.y\n    pose.orientation.z = rotation.z\n    o = pose.orientation\n    o.w = rotation.w\n    return pose\n"
        ),
        # not built here: its w may be set already
        Valid(
            "from geometry_msgs.msg import Pose\ndef f(pose: Pose, rotation):\n    pose.orientation.x = rotation.x\n"
            "    pose.orientation.y = rotation.y\n    pose.orientation.z = rotation.z\n    return pose\n"
        ),
    ]
    INVALID = [
        Invalid(
            "from geometry_msgs.msg import Transform\ndef f():\n    no_rotation = Transform()\n    no_rotation.rotation.x = 1.0\n    return no_rotation\n",
            expected_fix="from geometry_msgs.msg import Transform\ndef f():\n    no_rotation = Transform()\n    no_rotation.rotation.w = 1.0\n    return no_rotation\n",
            message="`no_rotation.rotation` is named for the identity, but only `x` is set to 1 and w keeps `Transform()`'s default (0.0 in ROS 1, 1.0 in ROS 2): (x, y, z, w) = (1, 0, 0, 0) is a half turn about x in ROS 1, and (1, 0, 0, 1) is no unit quaternion in ROS 2; the identity is w = 1 (1 comes first only in the w, x, y, z order)",
            range=(4, 5, 4, 33),
        ),
        # three values of a sequence in a row, w never set (an inertial unit's roll, pitch, yaw)
        Invalid(
            "from sensor_msgs.msg import Imu\ndef f(unit):\n    values = unit.getValues()\n    msg = Imu()\n"
            "    msg.orientation.x = scale(values[0], 1.0)\n    msg.orientation.y = scale(values[1], 1.0)\n"
            "    msg.orientation.z = scale(values[2], 1.0)\n    return msg\n",
            message="`msg.orientation.w` is never set: x, y, z are `scale` of `values[0]`, `values[1]`, `values[2]`, three values in a row, and w keeps `Imu()`'s default (0.0 in ROS 1, 1.0 in ROS 2): whether these are three angles or three components of a quaternion, a quaternion needs its w",
            range=(5, 5, 5, 46),
        ),
        # the same with the evidence that the three are Euler angles, or a quaternion's first three components
        Invalid(
            "from sensor_msgs.msg import Imu\ndef f(unit):\n    rpy = unit.getRollPitchYaw()\n    msg = Imu()\n"
            "    msg.orientation.x = rpy[0]\n    msg.orientation.y = rpy[1]\n    msg.orientation.z = rpy[2]\n    return msg\n",
            message="`msg.orientation.w` is never set: x, y, z are `rpy[0]`, `rpy[1]`, `rpy[2]`, three values in a row, and w keeps `Imu()`'s default (0.0 in ROS 1, 1.0 in ROS 2): three angles (roll, pitch, yaw; `controller.InertialUnit.getRollPitchYaw` returns them) are no quaternion, and a quaternion needs its w",
            range=(5, 5, 5, 31),
        ),
        Invalid(
            "from geometry_msgs.msg import Pose\nfrom scipy.spatial.transform import Rotation\ndef f(R):\n"
            "    q = Rotation.from_matrix(R).as_quat()\n    pose = Pose()\n    pose.orientation.x = q[0]\n"
            "    pose.orientation.y = q[1]\n    pose.orientation.z = q[2]\n    return pose\n",
            message="`pose.orientation.w` is never set: x, y, z are `q[0]`, `q[1]`, `q[2]`, three values in a row, and w keeps `Pose()`'s default (0.0 in ROS 1, 1.0 in ROS 2): `q` is a quaternion, scalar-last (x, y, z, w) (from `Rotation.from_matrix(R).as_quat()`, line 4), and a quaternion needs all four of its components",
            range=(6, 5, 6, 30),
        ),
        Invalid(
            "from geometry_msgs.msg import PoseWithCovariance\ndef f(tform):\n    msg = PoseWithCovariance()\n"
            "    msg.pose.orientation.x = tform.rotation.x\n    msg.pose.orientation.y = tform.rotation.y\n"
            "    msg.pose.orientation.z = tform.rotation.z\n    return msg\n",
            expected_fix="from geometry_msgs.msg import PoseWithCovariance\ndef f(tform):\n    msg = PoseWithCovariance()\n"
            "    msg.pose.orientation.x = tform.rotation.x\n    msg.pose.orientation.y = tform.rotation.y\n"
            "    msg.pose.orientation.z = tform.rotation.z\n    msg.pose.orientation.w = tform.rotation.w\n    return msg\n",
            message="`msg.pose.orientation.w` is never set: x, y, z are copied from `tform.rotation`, and w keeps `PoseWithCovariance()`'s default (0.0 in ROS 1, 1.0 in ROS 2), so the quaternion is not `tform.rotation`'s",
            range=(6, 5, 6, 46),
        ),
        Invalid(
            "from geometry_msgs.msg import TransformStamped\ndef f(q):\n    t = TransformStamped()\n"
            "    t.transform.rotation.w = q.w\n    t.transform.rotation.y = q.y\n    t.transform.rotation.z = q.z\n    return t\n",
            message="`t.transform.rotation.x` is never set: w, y, z are copied from `q`, and x keeps `TransformStamped()`'s default (0.0), so the quaternion is not `q`'s",
            range=(6, 5, 6, 33),
        ),
    ]

    def run(self) -> None:
        index = self.facts.index
        for scope_node, scope in index.scopes.items():
            if not isinstance(scope_node, FUNCTION_NODES):
                continue
            copies: dict[str, list[Attribute]] = {}  # the quaternion's path -> its component stores
            for target, _ in scope.attribute_stores:
                if target.attr in _COMPONENTS:
                    path = dotted_name(target.value)
                    if path is not None:
                        copies.setdefault(path, []).append(target)
            for path, targets in copies.items():
                if len(targets) == 3 and len({target.attr for target in targets}) == 3:
                    self._check(scope_node, path, targets)
                elif len(targets) == 1 and targets[0].attr != "w":
                    self._check_identity(scope_node, path, targets[0])

    def _check_identity(self, function: AST, path: str, target: Attribute) -> None:
        """`no_rotation = Transform()` then `no_rotation.rotation.x = 1.0` and nothing else: the identity
        written w-first into x; w keeps its default, so the quaternion is a half turn about x (ROS 1) or
        not of unit length (ROS 2). Only when a name of the message or its path says identity."""
        facts = self.facts
        statement = facts.parent(target)
        if not isinstance(statement, Assign) or len(statement.targets) != 1 or number(statement.value) != 1:
            return
        if IDENTITY_NAME.search(path.replace(".", "_")) is None:
            return
        root = target.value
        while isinstance(root, Attribute):
            root = root.value
        if not isinstance(root, Name):
            return
        built = self._built_here(root, target.value)
        if built is None or not self._untouched(function, root.id, path, "w", built, statement):
            return
        vector = ", ".join("1" if component == target.attr else "0" for component in "xyz")
        self.report(
            statement,
            f"`{path}` is named for the identity, but only `{target.attr}` is set to 1 and w keeps `{built}`'s default "
            f"({_DEFAULTS['w']}): (x, y, z, w) = ({vector}, 0) is a half turn about {target.attr} in ROS 1, and ({vector}, 1) "
            "is no unit quaternion in ROS 2; the identity is w = 1 (1 comes first only in the w, x, y, z order)",
            replacement=f"{facts.code_of(statement).rsplit('.' + target.attr, 1)[0]}.w = 1.0" if "\n" not in facts.code_of(statement) else None,
            applicability="unsafe",
            fix_description="set w to 1 instead",
        )

    def _check(self, function: AST, path: str, targets: list[Attribute]) -> None:
        facts = self.facts
        statements = [facts.parent(target) for target in targets]
        if not all(isinstance(statement, Assign) and len(statement.targets) == 1 for statement in statements):
            return
        assignments: list[Assign] = statements  # type: ignore[assignment]
        block = facts.parent(assignments[0])
        if any(facts.parent(statement) is not block for statement in assignments) or not _one_block(block, assignments):
            return  # in different arms of an `if`: the fourth may be set in a third
        missing = next(component for component in _COMPONENTS if component not in {target.attr for target in targets})
        sources = {_source(target, statement.value) for target, statement in zip(targets, assignments)}
        elements = None
        if len(sources) != 1 or None in sources:
            elements = _elements(facts, targets, assignments) if missing == "w" else None
            if elements is None:
                return  # not `o.x = s.x`, `o.y = s.y`, `o.z = s.z` from one `s`, nor `s[0]`, `s[1]`, `s[2]`
            source = elements
        else:
            source = sources.pop()  # type: ignore[assignment]
            assert source is not None
            if missing == "w" and not _ROTATION_WORDS & set(source.rsplit(".", 1)[-1].lower().split("_")):
                return
        root = targets[0].value
        while isinstance(root, Attribute):
            root = root.value
        assert isinstance(root, Name)
        built = self._built_here(root, targets[0].value)
        if built is None:
            return
        last = max(assignments, key=lambda statement: (statement.lineno, statement.col_offset))
        if not self._untouched(function, root.id, path, missing, built, last):
            return
        indent = " " * last.col_offset
        text = facts.code_of(last)
        if elements is not None:
            first = min(assignments, key=lambda statement: (statement.lineno, statement.col_offset))
            self.report(
                first,  # no fix to insert after the last copy: the three values go in from the first one (as GEO307 reports)
                f"`{path}.w` is never set: x, y, z are {elements}, three values in a row, and w keeps `{built}`'s default "
                f"({_DEFAULTS['w']}): {self._what_the_values_are(assignments[0].value)}",
            )
            return
        fix = f"{text}\n{indent}{path}.{missing} = {source}.{missing}" if "\n" not in text else None
        self.report(
            last,
            f"`{path}.{missing}` is never set: {', '.join(sorted(t.attr for t in targets))} are copied from `{source}`, "
            f"and {missing} keeps `{built}`'s default ({_DEFAULTS[missing]}), so the quaternion is not `{source}`'s",
            replacement=fix,
            applicability="unsafe",
            fix_description=f"copy `{source}.{missing}` too",
        )

    def _what_the_values_are(self, first_value: ast.expr) -> str:
        """Why three values in a row of `s` (`first_value` is `s[i]` or `f(s[i], ...)`) are no quaternion,
        saying only what the evidence shows: Euler angles, three components of a quaternion, or neither."""
        facts = self.facts
        sequence = first_value.args[0] if isinstance(first_value, Call) else first_value
        assert isinstance(sequence, Subscript)  # `_elements` matched it
        order = facts.shared(QuaternionFlow).order_of(sequence.value)
        if order is not None and not order.batch:
            return (
                f"`{facts.code_of(sequence.value)}` is a quaternion, {convention(order.order)} ({order.evidence}), "
                "and a quaternion needs all four of its components"
            )
        angles = _euler_angles(facts, sequence.value)
        if angles is not None:
            return f"three angles (roll, pitch, yaw; {angles}) are no quaternion, and a quaternion needs its w"
        return "whether these are three angles or three components of a quaternion, a quaternion needs its w"

    def _built_here(self, root: Name, quaternion: ast.expr) -> str | None:
        """`Cls()` when the message at `root` is built in this function with no arguments and `quaternion`
        (a path from it) is its Quaternion field (so the missing component's default is known)."""
        facts = self.facts
        bindings = facts.index.scope_of(root).bindings.get(root.id, [])
        if len(bindings) != 1 or not isinstance(bindings[0], Call):
            return None
        call = bindings[0]
        if call.args or call.keywords or not isinstance(facts.parent(call), Assign):
            return None
        if not holds_quaternion_components(facts.shared(MessageTypes).class_of(quaternion)):
            return None  # the fact base's message classes, field by field from the constructor
        return f"{facts.code_of(call.func)}()"

    def _untouched(self, function: AST, root: str, path: str, missing: str, built: str, last: Assign) -> bool:
        """Nothing else can have set the missing component: no store to it or to anything around it, no
        `setattr`, and the message not handed anywhere before the last copy (only written into)."""
        facts = self.facts
        prefixes = {".".join(path.split(".")[:depth]) for depth in range(2, path.count(".") + 2)}
        for node in walk_within(function):
            kind = type(node)
            if kind is Attribute:
                context = type(node.ctx)  # type: ignore[attr-defined]
                if context is Store and (node.attr == missing or dotted_name(node) in prefixes):  # type: ignore[attr-defined]
                    return False  # `x.w = ...` anywhere (an alias of the quaternion), or a part replaced
                if context is Load and dotted_name(node) == path and not isinstance(facts.parent(node), Attribute):
                    return False  # the quaternion itself handed on (a helper may normalise or complete it)
            elif kind is Name:
                if node.id == root and _before(node, last) and not _writes_into(facts, node):  # type: ignore[attr-defined, arg-type]
                    return False  # the message handed on before the copy is complete
            elif kind is Call and isinstance(node.func, Name) and node.func.id == "setattr":  # type: ignore[attr-defined]
                return False
        return True


def _source(target: Attribute, value: ast.expr) -> str | None:
    """`s` for a store `o.x = s.x` (the same component of one source), else None."""
    if isinstance(value, Attribute) and value.attr == target.attr:
        return dotted_name(value.value)
    return None


def _elements(facts: FactBase, targets: list[Attribute], assignments: list[Assign]) -> str | None:
    """For `o.x = s[i]`, `o.y = s[i + 1]`, `o.z = s[i + 2]` (each maybe through one call `f(s[k], *rest)`
    with the same `f` and the same other arguments): how the finding names the three; else None."""
    shapes = set()
    for target, statement in zip(targets, assignments):
        value = statement.value
        wrapper = None
        if isinstance(value, Call) and value.args and not isinstance(value.args[0], Starred):
            rest = [facts.code_of(argument) for argument in value.args[1:]] + [facts.code_of(item) for item in value.keywords]
            wrapper = (facts.code_of(value.func), tuple(rest))
            value = value.args[0]
        if not isinstance(value, Subscript) or not isinstance(value.slice, Constant) or type(value.slice.value) is not int:
            return None
        sequence = dotted_name(value.value)
        if sequence is None:
            return None
        shapes.add((sequence, wrapper, value.slice.value - "xyz".index(target.attr)))
    if len(shapes) != 1:
        return None
    sequence, wrapper, offset = shapes.pop()
    if offset < 0:
        return None
    elements = f"`{sequence}[{offset}]`, `{sequence}[{offset + 1}]`, `{sequence}[{offset + 2}]`"
    return elements if wrapper is None else f"`{wrapper[0]}` of {elements}"


def _euler_angles(facts: FactBase, sequence: ast.expr) -> str | None:
    """Why `sequence` holds Euler angles (a library call that returns them, or a name that says so), or None."""
    bound = facts.bindings(sequence) if isinstance(sequence, Name) else None
    if bound is not None and len(bound) == 1 and isinstance(bound[0], Call):
        call = bound[0]
        api = library_calls.called_api(facts, call)
        if api is not None and library_calls.returns_euler_angles(facts, call):  # the knowledge base (stubs/)
            return f"`{api.qualified_name}` returns Euler angles"
        method = EULER_METHOD_NAMES.get(call.func.attr) if isinstance(call.func, Attribute) and not call.args else None
        if method is not None:
            return f"`{method}` returns them"
    name = sequence.id if isinstance(sequence, Name) else sequence.attr if isinstance(sequence, Attribute) else ""
    if _EULER_WORDS & set(name.lower().split("_")):
        return f"the name `{name}` says Euler angles"
    return None


def _one_block(block: AST | None, statements: list[Assign]) -> bool:
    """The statements all sit in one statement list of `block` (not in its `if` and `else` arms)."""
    for field in ("body", "orelse", "finalbody"):
        body = getattr(block, field, None)
        if isinstance(body, list) and all(statement in body for statement in statements):
            return True
    return False


def _before(node: AST, statement: ast.stmt) -> bool:
    return (node.lineno, node.col_offset) < (statement.lineno, statement.col_offset)  # type: ignore[attr-defined]


def _writes_into(facts: object, name: Name) -> bool:
    """`name` is the root of a store target (`msg.pose.position.x = ...`) or the binding itself."""
    if isinstance(name.ctx, Store):
        return True
    node: AST = name
    parent = facts.parent(node)  # type: ignore[attr-defined]
    while isinstance(parent, Attribute):
        node, parent = parent, facts.parent(parent)  # type: ignore[attr-defined]
    return isinstance(node, Attribute) and isinstance(node.ctx, Store)
