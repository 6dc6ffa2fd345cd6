"""GEO104 normals-left-behind: points are moved to a new frame but their normals are not."""

from __future__ import annotations

import re

import libcst as cst

from geolint.rules.base import Invalid, Valid
from geolint.semantic.facts import ParamBinding
from geolint.semantic.model import last_name
from geolint.semantic.names import Kind, tokens
from geolint.semantic.prefilter import Trigger, may_leave_normals
from geolint.semantic.rule_support import SemanticRule

_NORMAL_TOKENS = frozenset({"normal", "normals", "nrm", "nrms"})
_MENTIONS_NORMAL_FIELDS = re.compile(r"normal_x")


class NormalsLeftBehind(SemanticRule):
    """Points are transformed in a scope that leaves their normals in the old frame.

    ## What it does
    Flags, within one function: a cloud's `.points` replaced by transformed points while its
    `.normals` are never updated; a function that transforms its `points` argument but returns
    its `normals` argument untouched; and ROS `do_transform_cloud` on a cloud that carries
    `normal_x/normal_y/normal_z` fields (it moves x, y, z and copies the normal fields
    unrotated).

    ## Why is this bad?
    Points and their normals describe one surface. After moving only the points, every normal
    still points the way it did in the old frame: shading, grasp approach directions and
    point-to-plane ICP are silently wrong for any rotation.

    ## Example
    ```python
    def to_world(points, normals, T_world_cam):
        points_world = points @ T_world_cam[:3, :3].T + T_world_cam[:3, 3]
        return points_world, normals
    ```

    ## Use instead
    ```python
    def to_world(points, normals, T_world_cam):
        points_world = points @ T_world_cam[:3, :3].T + T_world_cam[:3, 3]
        normals_world = normals @ T_world_cam[:3, :3].T
        return points_world, normals_world
    ```

    ## Fix safety
    No fix is offered: the rotation to apply to the normals has to be chosen by a person.
    """

    code = "GEO104"
    name = "normals-left-behind"
    triggers = Trigger("normals and transformed points, or do_transform_cloud", may_leave_normals)

    VALID = [
        Valid(
            "def to_world(points, normals, T):\n"
            "    pw = points @ T[:3, :3].T + T[:3, 3]\n"
            "    nw = normals @ T[:3, :3].T\n"
            "    return pw, nw\n"
        ),
        Valid(
            "import open3d as o3d\n"
            "def move(pcd, T):\n"
            "    pcd.transform(T)\n"
            "    return pcd\n"
        ),
        Valid(
            "def move(pcd, R, t):\n"
            "    pcd.points = o3d.utility.Vector3dVector(np.asarray(pcd.points) @ R.T + t)\n"
            "    pcd.normals = o3d.utility.Vector3dVector(np.asarray(pcd.normals) @ R.T)\n"
        ),
        Valid(
            "from tf2_sensor_msgs.tf2_sensor_msgs import do_transform_cloud\n"
            "cloud_out = do_transform_cloud(cloud_xyz, transform)\n"
        ),
    ]
    INVALID = [
        Invalid(
            "def to_world(points, normals, T):\n"
            "    pw = points @ T[:3, :3].T + T[:3, 3]\n"
            "    return pw, normals\n"
        ),
        Invalid(
            "import numpy as np\n"
            "def move(pcd, R, t):\n"
            "    pcd.points = o3d.utility.Vector3dVector(np.asarray(pcd.points) @ R.T + t)\n"
            "    return np.asarray(pcd.normals)\n"
        ),
        Invalid(
            "from tf2_sensor_msgs.tf2_sensor_msgs import do_transform_cloud\n"
            "fields = ['x', 'y', 'z', 'normal_x', 'normal_y', 'normal_z']\n"
            "cloud_out = do_transform_cloud(cloud, transform)\n"
        ),
    ]

    # do_transform_cloud -----------------------------------------------------------------
    def visit_Call(self, node: cst.Call) -> None:
        if last_name(node.func) != "do_transform_cloud" or not node.args:
            return
        cloud = node.args[0].value
        carries_normals = bool(_MENTIONS_NORMAL_FIELDS.search(self.model.facts.code)) or bool(
            _NORMAL_TOKENS & set(tokens(last_name(cloud) or ""))
        )
        if carries_normals:
            self.report(
                node,
                f"`do_transform_cloud` moves x, y, z of `{self.code_of(cloud)}` but copies its normal_x/y/z "
                "fields unrotated; rotate the normal fields too",
            )

    # obj.points = <transformed>, obj.normals untouched -------------------------------------
    def visit_Assign(self, node: cst.Assign) -> None:
        for target in node.targets:
            store = target.target
            if not isinstance(store, cst.Attribute) or store.attr.value != "points":
                continue
            if not self._contains_transform(node.value):
                continue
            base = self.code_of(store.value)
            if not self._module_reads_normals_of(base):
                continue
            scope = self.model.facts.scope_of(node)
            if any(
                stored.attr.value in ("normals", "vertex_normals") and self.code_of(stored.value) == base
                for stored, _ in scope.attribute_stores
            ):
                continue
            if self._scope_calls_method(scope.node, base, "transform"):
                continue
            self.report(
                store,
                f"`{base}.points` move to a new frame here, but `{base}.normals` stay in the old one",
            )

    def _module_reads_normals_of(self, base: str) -> bool:
        code = self.model.facts.code
        return re.search(rf"{re.escape(base)}\s*\.\s*normals\b", code) is not None

    def _scope_calls_method(self, scope_node: cst.CSTNode, base: str, method: str) -> bool:
        code = self.model.facts.module.code_for_node(scope_node)
        return re.search(rf"{re.escape(base)}\s*\.\s*{method}\s*\(", code) is not None

    def _contains_transform(self, node: cst.CSTNode) -> bool:
        finder = _TransformFinder(self)
        node.visit(finder)
        return finder.found is not None

    # def f(points, normals, T): ... return moved_points, normals ---------------------------
    def visit_FunctionDef(self, node: cst.FunctionDef) -> None:
        scope = self.model.facts.scopes.get(node)
        if scope is None:
            return
        returned = _returned_names(scope.returns)
        left_behind = [
            name
            for name, bindings in scope.bindings.items()
            if name in returned
            and _NORMAL_TOKENS & set(tokens(name))
            and all(isinstance(binding, ParamBinding) for binding in bindings)
        ]
        if not left_behind:
            return
        finder = _TransformFinder(self, params_only=scope.bindings)
        node.body.visit(finder)
        if finder.found is None:
            return
        for normals in left_behind:
            if _uses_outside_returns(node.body, normals):
                continue
            site, points = finder.found
            self.report(
                site,
                f"points `{points}` are moved to a new frame here, but normals `{normals}` are returned unrotated",
            )
            return


class _TransformFinder(cst.CSTVisitor):
    """Finds the first place where a point-like value is multiplied by a matrix or transformed."""

    def __init__(self, rule: NormalsLeftBehind, params_only: dict | None = None) -> None:
        super().__init__()
        self.rule = rule
        self.params_only = params_only
        self.found: tuple[cst.CSTNode, str] | None = None

    def visit_FunctionDef(self, node: cst.FunctionDef) -> bool:
        return False  # a nested function is another scope

    def _point(self, node: cst.CSTNode) -> str | None:
        model = self.rule.model
        while isinstance(node, (cst.Attribute, cst.Call)):
            if isinstance(node, cst.Attribute) and node.attr.value == "T":
                node = node.value
            elif isinstance(node, cst.Call) and last_name(node.func) in ("asarray", "array") and node.args:
                node = node.args[0].value
            else:
                break
        if model.kind_of(node) != Kind.POINT:
            return None
        if self.params_only is not None:
            if not isinstance(node, cst.Name):
                return None
            bindings = self.params_only.get(node.value, [])
            if not bindings or not all(isinstance(binding, ParamBinding) for binding in bindings):
                return None
        return self.rule.code_of(node)

    def on_visit(self, node: cst.CSTNode) -> bool:
        if self.found is not None:
            return False
        model = self.rule.model
        product = model.matmul(node)
        if product is not None:
            for value, matrix in ((product.left, product.right), (product.right, product.left)):
                points = self._point(value)
                if points is not None and model.kind_of(matrix) not in (Kind.POINT, Kind.DIRECTION):
                    self.found = (node, points)
                    return False
        if isinstance(node, cst.Call) and last_name(node.func) == "transform_points" and node.args:
            points = self._point(node.args[0].value)
            if points is not None:
                self.found = (node, points)
                return False
        return super().on_visit(node)


def _returned_names(returns: list[cst.BaseExpression]) -> set[str]:
    names: set[str] = set()
    for value in returns:
        elements = value.elements if isinstance(value, (cst.Tuple, cst.List)) else [value]
        for element in elements:
            inner = element.value if isinstance(element, cst.BaseElement) else element
            if isinstance(inner, cst.Name):
                names.add(inner.value)
    return names


def _uses_outside_returns(body: cst.CSTNode, name: str) -> bool:
    """Whether `name` is read anywhere in `body` other than directly in a `return`."""

    class Uses(cst.CSTVisitor):
        found = False

        def visit_Return(self, node: cst.Return) -> bool:
            return False

        def visit_Name(self, node: cst.Name) -> None:
            if node.value == name:
                self.found = True

    uses = Uses()
    body.visit(uses)
    return uses.found
