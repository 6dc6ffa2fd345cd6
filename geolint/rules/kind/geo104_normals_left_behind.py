"""GEO104 normals-left-behind: points are moved to a new frame but their normals are not."""

from __future__ import annotations

from typing import Final

import re

from ast import AST, Assign, AsyncFunctionDef, Attribute, Call, FunctionDef, Module

from geolint.rules.base import Invalid, Valid
from geolint.factbase.index import ParamBinding
from geolint.factbase.model import last_name
from geolint.factbase.point_transforms import first_point_transform, read_outside_returns, returned_names
from geolint.rules.fact_rule import FactRule
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
            "    return pw, normals\n",
            message="points `points` are moved to a new frame here, but normals `normals` are returned unrotated",
            range=(2, 10, 2, 30),
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
            if first_point_transform(self.facts, node.value) is None:
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
        returned = returned_names(scope.returns)
        left_behind = [
            name
            for name, bindings in scope.bindings.items()
            if name in returned
            and _NORMAL_TOKENS & set(tokens(name))
            and all(isinstance(binding, ParamBinding) for binding in bindings)
        ]
        if not left_behind:
            return
        found = first_point_transform(self.facts, node, body_only=True, parameters=scope.bindings)
        if found is None:
            return
        for normals in left_behind:
            if read_outside_returns(node, normals):
                continue
            site, points = found
            self.report(
                site,
                f"points `{points}` are moved to a new frame here, but normals `{normals}` are returned unrotated",
            )
            return
