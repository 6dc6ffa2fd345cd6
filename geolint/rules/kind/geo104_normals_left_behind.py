"""GEO104 normals-left-behind: points are moved to a new frame but their normals are not."""

from __future__ import annotations

from typing import Final

import re

import ast
from ast import AST, Assign, AsyncFunctionDef, Attribute, Call, FunctionDef, Module, Name, Return

from geolint.rules.base import Invalid, Valid
from geolint.algebra import Kind
from geolint.factbase.index import ParamBinding
from geolint.factbase.model import GEOMETRIC, last_name, transposed_value, walk_within
from geolint.factbase.rule_support import FactRule
from geolint.semantic.names import tokens

_NORMAL_TOKENS: Final = frozenset({"normal", "normals", "nrm", "nrms"})
_MENTIONS_NORMAL_FIELDS: Final = re.compile(r"normal_x")


class NormalsLeftBehind(FactRule):
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

    def run(self) -> None:
        facts = self.facts
        for node in facts.index.nodes(Call):
            self._check_cloud_call(node)  # type: ignore[arg-type]
        for node in facts.index.nodes(Assign):
            self._check_points_store(node)  # type: ignore[arg-type]
        for node in facts.index.nodes(FunctionDef, AsyncFunctionDef):
            self._check_function(node)

    # do_transform_cloud -----------------------------------------------------------------
    def _check_cloud_call(self, node: Call) -> None:
        if last_name(node.func) != "do_transform_cloud" or not node.args:
            return
        cloud = node.args[0]
        carries_normals = bool(_MENTIONS_NORMAL_FIELDS.search(self.facts.index.source)) or bool(
            _NORMAL_TOKENS & set(tokens(last_name(cloud) or ""))
        )
        if carries_normals:
            self.report(
                node,
                f"`do_transform_cloud` moves x, y, z of `{self.code_of(cloud)}` but copies its normal_x/y/z "
                "fields unrotated; rotate the normal fields too",
            )

    # obj.points = <transformed>, obj.normals untouched -------------------------------------
    def _check_points_store(self, node: Assign) -> None:
        facts = self.facts
        for store in node.targets:
            if not isinstance(store, Attribute) or store.attr != "points":
                continue
            if _TransformFinder(self).first(node.value) is None:
                continue
            base = self.code_of(store.value)
            if not self._module_reads_normals_of(base):
                continue
            scope = facts.index.scope_of(node)
            if any(
                stored.attr in ("normals", "vertex_normals") and self.code_of(stored.value) == base
                for stored, _ in scope.attribute_stores
            ):
                continue
            if self._scope_calls_method(scope.node, base, "(?:transform|rotate)"):
                continue  # Open3D's transform/rotate move the normals with the points
            self.report(
                store,
                f"`{base}.points` move to a new frame here, but `{base}.normals` stay in the old one",
            )

    def _module_reads_normals_of(self, base: str) -> bool:
        return re.search(rf"{re.escape(base)}\s*\.\s*normals\b", self.facts.index.source) is not None

    def _scope_calls_method(self, scope_node: AST, base: str, method: str) -> bool:
        code = self.facts.index.source if isinstance(scope_node, Module) else self.facts.index.segment(scope_node)
        return re.search(rf"{re.escape(base)}\s*\.\s*{method}\s*\(", code) is not None

    # def f(points, normals, T): ... return moved_points, normals ---------------------------
    def _check_function(self, node: AST) -> None:
        scope = self.facts.index.scopes.get(node)
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
        found = _TransformFinder(self, params_only=scope.bindings).first(node, body_only=True)
        if found is None:
            return
        for normals in left_behind:
            if _uses_outside_returns(node, normals):
                continue
            site, points = found
            self.report(
                site,
                f"points `{points}` are moved to a new frame here, but normals `{normals}` are returned unrotated",
            )
            return


class _TransformFinder:
    """Finds the first place where a point-like value is multiplied by a matrix or transformed."""

    def __init__(self, rule: FactRule, params_only: dict | None = None) -> None:  # type: ignore[type-arg]
        self.rule = rule
        self.params_only = params_only

    def _point(self, node: AST) -> str | None:
        facts = self.rule.facts
        while isinstance(node, (Attribute, Call)):
            inner = transposed_value(node)
            if inner is not None:
                node = inner
            elif isinstance(node, Call) and last_name(node.func) in ("asarray", "array") and node.args:
                node = node.args[0]
            else:
                break
        if facts.kind_of(node) != Kind.POINT:
            return None
        if self.params_only is not None:
            if not isinstance(node, Name):
                return None
            bindings = self.params_only.get(node.id, [])
            if not bindings or not all(isinstance(binding, ParamBinding) for binding in bindings):
                return None
        return self.rule.code_of(node)

    def first(self, root: AST, body_only: bool = False) -> tuple[AST, str] | None:
        """The first (in source order) product or `transform_points` call on a point inside `root`."""
        facts = self.rule.facts
        nodes = [root] if not body_only else []
        nodes += sorted(walk_within(root), key=lambda n: (getattr(n, "lineno", 0), getattr(n, "col_offset", 0)))
        for node in nodes:
            product = facts.matmul(node)
            if product is not None:
                for value, matrix in ((product.left, product.right), (product.right, product.left)):
                    points = self._point(value)
                    if points is not None and facts.kind_of(matrix) not in GEOMETRIC:
                        return node, points
            if isinstance(node, Call) and last_name(node.func) == "transform_points" and node.args:
                points = self._point(node.args[0])
                if points is not None:
                    return node, points
        return None


def _returned_names(returns: list[ast.expr]) -> set[str]:
    names: set[str] = set()
    for value in returns:
        elements = value.elts if isinstance(value, (ast.Tuple, ast.List)) else [value]
        for element in elements:
            if isinstance(element, Name):
                names.add(element.id)
    return names


def _uses_outside_returns(function: AST, name: str) -> bool:
    """Whether `name` is read anywhere in the function's body other than directly in a `return`."""
    stack = list(getattr(function, "body", []))
    while stack:
        node = stack.pop()
        if isinstance(node, Return):
            continue
        if isinstance(node, Name) and node.id == name:
            return True
        stack.extend(ast.iter_child_nodes(node))
    return False
