"""GEO301 quaternion-order: quaternion components passed in the other convention."""

from __future__ import annotations

import ast

from geolint.rules.base import Invalid, Valid
from geolint.factbase.model import FactBase, positional_args, replace_span, string
from geolint.factbase.rotations import SCALAR_FIRST, SCALAR_LAST, api_label, quaternion_order
from geolint.factbase.rule_support import FactRule

_COMPONENTS = "wxyz"


class QuaternionOrder(FactRule):
    """Quaternion components are listed in the order of the other convention.

    ## What it does
    Flags a quaternion spelled out component by component (`[q.w, q.x, q.y, q.z]`,
    `[qx, qy, qz, qw]`) and passed to an API that expects the other order: scipy
    `Rotation.from_quat` (x, y, z, w unless `scalar_first=True`), transforms3d `quat2*`,
    pytransform3d `*_from_quaternion`, pyquaternion `Quaternion` and spatialmath
    `UnitQuaternion` (w, x, y, z), ROS `tf.transformations` (x, y, z, w).

    ## Why is this bad?
    Both orders give a valid unit quaternion, so nothing fails: the rotation is just wrong (the
    scalar part is read as an axis component). ROS messages and scipy put w last, most math
    libraries put it first; the bug appears at every boundary between the two.

    ## Example
    ```python
    rotation = Rotation.from_quat([msg.w, msg.x, msg.y, msg.z])
    ```

    ## Use instead
    ```python
    rotation = Rotation.from_quat([msg.x, msg.y, msg.z, msg.w])
    ```

    ## Fix safety
    Reordering the components to the API's convention is safe: the spelled-out names say which
    component is which.
    """

    code = "GEO301"
    name = "quaternion-order"

    VALID = [
        Valid("from scipy.spatial.transform import Rotation\nr = Rotation.from_quat([q.x, q.y, q.z, q.w])\n"),
        Valid(
            "from scipy.spatial.transform import Rotation\n"
            "r = Rotation.from_quat([q.w, q.x, q.y, q.z], scalar_first=True)\n"
        ),
        Valid("from transforms3d.quaternions import quat2mat\nm = quat2mat([q.w, q.x, q.y, q.z])\n"),
        Valid("from pyquaternion import Quaternion\nq2 = Quaternion(q.w, q.x, q.y, q.z)\n"),
        Valid("from geometry_msgs.msg import Quaternion\nq2 = Quaternion(q.x, q.y, q.z, q.w)\n"),
        Valid("from pyquaternion import Quaternion as PQ\nq2 = PQ(q.w, q.x, q.y, q.z)\n"),
        Valid("from scipy.spatial.transform import Rotation\nr = Rotation.from_quat([a, b, c, d])\n"),
    ]
    INVALID = [
        Invalid(
            "from scipy.spatial.transform import Rotation\nr = Rotation.from_quat([q.w, q.x, q.y, q.z])\n",
            expected_fix="from scipy.spatial.transform import Rotation\nr = Rotation.from_quat([q.x, q.y, q.z, q.w])\n",
        ),
        Invalid(
            "from transforms3d.quaternions import quat2mat\nm = quat2mat([q.x, q.y, q.z, q.w])\n",
            expected_fix="from transforms3d.quaternions import quat2mat\nm = quat2mat([q.w, q.x, q.y, q.z])\n",
        ),
        Invalid(
            "from pyquaternion import Quaternion\nq2 = Quaternion(q.x, q.y, q.z, q.w)\n",
            expected_fix="from pyquaternion import Quaternion\nq2 = Quaternion(q.w, q.x, q.y, q.z)\n",
        ),
        Invalid(
            "from scipy.spatial.transform import Rotation as R\nr = R.from_quat((qw, qx, qy, qz))\n",
            expected_fix="from scipy.spatial.transform import Rotation as R\nr = R.from_quat((qx, qy, qz, qw))\n",
        ),
        Invalid(
            "import pytransform3d.rotations as pr\nm = pr.matrix_from_quaternion([ori.x, ori.y, ori.z, ori.w])\n",
            expected_fix="import pytransform3d.rotations as pr\nm = pr.matrix_from_quaternion([ori.w, ori.x, ori.y, ori.z])\n",
        ),
    ]

    def run(self) -> None:
        facts = self.facts
        for node in facts.index.nodes(ast.Call):
            self._check(node)  # type: ignore[arg-type]

    def _check(self, node: ast.Call) -> None:
        facts = self.facts
        expected = quaternion_order(facts, node)
        if expected is None:
            return
        positional = positional_args(node)
        if len(positional) == 4 and len(node.args) == 4 and not node.keywords:
            order = _order(facts, positional)
            if order is not None and order != expected and _is_other_convention(order, expected):
                self._report(node, node, positional, order, expected)
            return
        if not positional or not isinstance(positional[0], (ast.List, ast.Tuple)):
            return
        sequence = positional[0]
        elements = list(sequence.elts)
        if len(elements) != 4 or any(isinstance(element, ast.Starred) for element in elements):
            return
        order = _order(facts, elements)
        if order is None or order == expected or not _is_other_convention(order, expected):
            return
        self._report(sequence, node, elements, order, expected)

    def _report(self, reported: ast.expr, call: ast.Call, items: list[ast.expr], order: str, expected: str) -> None:
        by_component = {component: item for component, item in zip(order, items)}
        edits = [(item, self.facts.index.segment(by_component[component])) for item, component in zip(items, expected)]
        self.report(
            reported,
            f"quaternion components are in ({', '.join(order)}) order, but "
            f"`{self.code_of(call.func)}` expects {api_label(expected)}",
            replacement=replace_span(self.facts.index, reported, edits),  # type: ignore[arg-type]
            fix_description=f"reorder to {', '.join(expected)}",
        )


def _is_other_convention(order: str, expected: str) -> bool:
    return {order, expected} == {SCALAR_FIRST, SCALAR_LAST}


def _order(facts: FactBase, values: list[ast.expr]) -> str | None:
    """'wxyz' for `[q.w, q.x, q.y, q.z]` (attributes of one object, or names like qw/q_w/w)."""
    components = [_component(facts, value) for value in values]
    if any(component is None for component in components):
        return None
    letters = "".join(component[0] for component in components)  # type: ignore[index]
    owners = {component[1] for component in components}  # type: ignore[index]
    if sorted(letters) != sorted(_COMPONENTS) or len(owners) != 1:
        return None
    return letters


def _component(facts: FactBase, value: ast.expr) -> tuple[str, str] | None:
    """The quaternion component a value names, with what it belongs to."""
    if isinstance(value, ast.Attribute) and value.attr in _COMPONENTS:
        return value.attr, ast.dump(value.value)
    if isinstance(value, ast.Subscript):
        key = string(value.slice)
        if key is not None and key in _COMPONENTS and len(key) == 1:
            return key, ast.dump(value.value)
    if not isinstance(value, ast.Name):
        return None
    lowered = value.id.lower()
    if lowered in _COMPONENTS and len(lowered) == 1:
        return lowered, ""
    for prefix in ("q", "q_", "quat_", "quat", "rot_", "orientation_", "ori_"):
        rest = lowered[len(prefix) :]
        if lowered.startswith(prefix) and len(rest) == 1 and rest in _COMPONENTS:
            return rest, prefix
    return None
