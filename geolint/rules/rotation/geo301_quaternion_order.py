"""GEO301 quaternion-order: quaternion components passed in the other convention."""

from __future__ import annotations

import libcst as cst

from geolint.rules.base import Invalid, Valid
from geolint.semantic.conventions import SCALAR_FIRST, SCALAR_LAST, api_label, quaternion_order
from geolint.semantic.model import last_name
from geolint.semantic.prefilter import Trigger, may_pass_quaternion
from geolint.semantic.rule_support import SemanticRule

_COMPONENTS = "wxyz"


class QuaternionOrder(SemanticRule):
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
    triggers = Trigger("a call to a quaternion API", may_pass_quaternion)

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

    def visit_Call(self, node: cst.Call) -> None:
        expected = quaternion_order(self.model, node)
        if expected is None:
            return
        positional = [arg for arg in node.args if arg.keyword is None and not arg.star]
        if len(positional) == 4 and len(node.args) == 4:
            order = _order([arg.value for arg in positional])
            if order is not None and order != expected and _is_other_convention(order, expected):
                replacement = node.with_changes(args=_reordered(list(node.args), order, expected))
                self._report(node, order, expected, replacement)
            return
        if not positional or not isinstance(positional[0].value, (cst.List, cst.Tuple)):
            return
        sequence = positional[0].value
        elements = list(sequence.elements)
        if len(elements) != 4 or any(isinstance(element, cst.StarredElement) for element in elements):
            return
        order = _order([element.value for element in elements])
        if order is None or order == expected or not _is_other_convention(order, expected):
            return
        # The reported span excludes the sequence's own parentheses, so the replacement must too.
        fixed = sequence.with_changes(elements=_reordered(elements, order, expected), lpar=[], rpar=[])
        self._report(sequence, order, expected, fixed)

    def _report(self, node: cst.CSTNode, order: str, expected: str, replacement: cst.CSTNode) -> None:
        self.report(
            node,
            f"quaternion components are in ({', '.join(order)}) order, but "
            f"`{self.code_of(node.func) if isinstance(node, cst.Call) else self._callee(node)}` expects "
            f"{api_label(expected)}",
            replacement=replacement,
            fix_description=f"reorder to {', '.join(expected)}",
        )

    def _callee(self, node: cst.CSTNode) -> str:
        call = self.model.parent(self.model.parent(node) or node)
        return self.code_of(call.func) if isinstance(call, cst.Call) else "the call"


def _is_other_convention(order: str, expected: str) -> bool:
    return {order, expected} == {SCALAR_FIRST, SCALAR_LAST}


def _reordered(items: list, order: str, expected: str) -> list:
    """Move the values so that position i holds component expected[i]; commas stay in place."""
    values = {component: item.value for component, item in zip(order, items)}
    return [item.with_changes(value=values[component]) for item, component in zip(items, expected)]


def _order(values: list[cst.BaseExpression]) -> str | None:
    """'wxyz' for `[q.w, q.x, q.y, q.z]` (attributes of one object, or names like qw/q_w/w)."""
    components = [_component(value) for value in values]
    if any(component is None for component in components):
        return None
    letters = "".join(component[0] for component in components)  # type: ignore[index]
    owners = {component[1] for component in components}  # type: ignore[index]
    if sorted(letters) != sorted(_COMPONENTS) or len(owners) != 1:
        return None
    return letters


def _component(value: cst.BaseExpression) -> tuple[str, str] | None:
    """The quaternion component a value names, with what it belongs to."""
    if isinstance(value, cst.Attribute) and value.attr.value in _COMPONENTS:
        return value.attr.value, cst.Module([]).code_for_node(value.value)
    if isinstance(value, cst.Subscript) and len(value.slice) == 1:
        index = value.slice[0].slice
        if isinstance(index, cst.Index) and isinstance(index.value, cst.SimpleString):
            key = index.value.evaluated_value
            if key in _COMPONENTS:
                return str(key), cst.Module([]).code_for_node(value.value)
    name = last_name(value) if isinstance(value, cst.Name) else None
    if name is None:
        return None
    lowered = name.lower()
    if lowered in _COMPONENTS:
        return lowered, ""
    for prefix in ("q", "q_", "quat_", "quat", "rot_", "orientation_", "ori_"):
        rest = lowered[len(prefix) :]
        if lowered.startswith(prefix) and rest in _COMPONENTS:
            return rest, prefix
    return None
