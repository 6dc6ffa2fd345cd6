"""GEO102 point-not-translated: a point-like value is only rotated by a full transform."""

from __future__ import annotations

from typing import Final

import re

import ast
from ast import AST, Add, AnnAssign, Assign, BinOp, Call, Constant, Module, Name, Return, Sub, Subscript

from geolint.rules.base import Invalid, Valid
from geolint import algebra
from geolint.algebra import FREE, LOCATED, Kind, Problem
from geolint.factbase import library_calls
from geolint.factbase.model import keyword, last_name, positional_args, transposed_value
from geolint.rules.fact_rule import FactRule


class PointNotTranslated(FactRule):
    """A point (position, vertex, centroid) loses the translation of a transform.

    ## What it does
    Flags a point-like value given w = 0 (`np.append(point, 0)`), rotated by only the rotation
    block of a full transform (`T_world_cam[:3, :3] @ p_cam` with no `+ T[:3, 3]`), or passed
    to a library call that drops the translation (`trimesh.transform_points(points, T,
    translate=False)`, pytransform3d `vector_to_direction(point)`).

    ## Why is this bad?
    A point is a location: changing frames must rotate AND translate it. With w = 0 or with the
    rotation block alone, the result is the point's position relative to the old origin, rotated:
    off by the full translation between the frames.

    ## Example
    ```python
    p_world = T_world_cam[:3, :3] @ p_cam
    ```

    ## Use instead
    ```python
    p_world = T_world_cam[:3, :3] @ p_cam + T_world_cam[:3, 3]
    ```

    ## Fix safety
    Changing w from 0 to 1 is offered as an unsafe fix: the value may be meant as a displacement
    that happens to have a point-like name.

    ## Known problems
    A 4-vector written out element by element (`np.array([p.x, p.y, p.z, 0])`) is taken as
    homogeneous only when it reaches a matrix product or a transform call (a call named like
    `transform`, `apply`, `rotate`, `project`, `dot` or `mul`), directly or through the variable
    holding it: one only stored (`history.append(...)`) or whose 4th slot is written later is a
    record with a 4th field. So such a vector handed to a project helper named otherwise is not
    checked.
    """

    code = "GEO102"
    name = "point-not-translated"

    VALID = [
        Valid("import numpy as np\np_h = np.append(point, 1)\n"),
        Valid("import numpy as np\nn_h = np.append(normal, 0)\n"),
        Valid("p_world = T_world_cam[:3, :3] @ p_cam + T_world_cam[:3, 3]\n"),
        Valid("n_world = T_world_cam[:3, :3] @ normal_cam\n"),
        Valid("p_rot = R @ point\n"),
        Valid("q = T_world_cam[:3, :3] @ p_cam\nq += T_world_cam[:3, 3]\n"),
        Valid("import trimesh\nn = trimesh.transform_points(normals, T, translate=False)\n"),
        Valid("rotated = np.dot(pose[:3, :3], points.T)\nbox = rotated.max(axis=1) + pose[:3, 3]\n"),
        Valid("import numpy as np\nxyz = np.column_stack((points_2d, np.zeros(len(points_2d))))\n"),
        Valid(
            "import numpy as np\nfrom tf import transformations as tr\ndef rotate(point, quat):\n"
            "    v = np.array([point[0], point[1], point[2], 0.0])\n"
            "    return tr.quaternion_multiply(tr.quaternion_multiply(quat, v), tr.quaternion_inverse(quat))[:3]\n"
        ),  # a pure quaternion for the product q v q*, not a homogeneous point
        Valid(
            "import numpy as np\ndef record(history, position, gain):\n"
            "    history.append(np.array([position.x, position.y, position.z, 0]))\n"
            "    history[-1][-1] = gain\n"
        ),  # a record whose 4th slot is a score: stored, never transformed
        Valid(
            "import numpy as np\ndef record(history, position, gain):\n"
            "    entry = np.array([position.x, position.y, position.z, 0])\n"
            "    entry[3] = gain\n    return entry\n"
        ),
    ]
    INVALID = [
        Invalid(
            "import numpy as np\np_h = np.append(point, 0)\n",
            expected_fix="import numpy as np\np_h = np.append(point, 1)\n",
            message="point `point` is given w = 0, so a transform will not translate it; points take w = 1",
            range=(2, 7, 2, 26),
        ),
        Invalid(
            "import numpy as np\np_world = T_world_cam @ np.array([position.x, position.y, position.z, 0])\n",
            expected_fix="import numpy as np\np_world = T_world_cam @ np.array([position.x, position.y, position.z, 1])\n",
        ),
        Invalid("p_world = T_world_cam[:3, :3] @ p_cam\n"),
        Invalid("pts_w = points @ pose[:3, :3].T\n"),
        Invalid("import trimesh\nv = trimesh.transform_points(mesh.vertices, T, translate=False)\n"),
        Invalid(
            "from pytransform3d.transformations import vector_to_direction\nd = vector_to_direction(centroid)\n",
            message="`vector_to_direction` gives w = 0, but `centroid` is a point; use `vector_to_point`",
            range=(2, 5, 2, 34),
        ),
        Invalid(
            "from pytorch3d.transforms import Transform3d\nv = Transform3d(matrix=M).transform_normals(mesh.vertices)\n",
            message="`transform_normals` drops the translation, but `mesh.vertices` holds points; use `transform_points`",
            range=(2, 5, 2, 59),
        ),
    ]

    def run(self) -> None:
        facts = self.facts
        for node in facts.index.nodes(Call, Subscript, BinOp):
            if isinstance(node, Subscript):
                self._check_homogeneous(node)
            elif isinstance(node, BinOp):
                self._check_product(node)
            else:
                self._check_homogeneous(node)  # type: ignore[arg-type]
                self._check_product(node)  # type: ignore[arg-type]
                self._check_library_call(node)  # type: ignore[arg-type]

    def _check_homogeneous(self, node: ast.expr) -> None:
        facts = self.facts
        homogeneous = facts.homogeneous_built_by(node)
        if homogeneous is None:
            return
        outcome = facts.homogenized(homogeneous)
        if outcome is None or outcome.problem != Problem.POINT_NOT_TRANSLATED or not facts.used_as_homogeneous(homogeneous):
            return
        if self._is_pure_quaternion(node):
            return
        self.report(
            node,
            f"point `{self.code_of(homogeneous.inner)}` is given w = 0, so a transform will not translate it; "
            "points take w = 1",
            replacement=homogeneous.fixed,
            applicability="unsafe",
            fix_description="use w = 1 for the point",
        )

    def _is_pure_quaternion(self, construction: ast.expr) -> bool:
        """`v = [p[0], p[1], p[2], 0]` handed to quaternion algebra (`quaternion_multiply(q, v)`) is the
        pure quaternion of the sandwich product q v q*, which rotates the point on purpose."""
        facts = self.facts
        parent = facts.parent(construction)
        if isinstance(parent, Call) and construction in parent.args:
            return _is_quaternion_call(parent)
        if not (isinstance(parent, Assign) and len(parent.targets) == 1 and isinstance(parent.targets[0], Name)):
            return False
        name, scope = parent.targets[0].id, facts.index.scope_of(parent).node
        return any(
            _is_quaternion_call(call) and facts.index.scope_of(call).node is scope
            and any(isinstance(argument, Name) and argument.id == name for argument in call.args)  # type: ignore[attr-defined]
            for call in facts.index.nodes(Call)
        )

    def _check_product(self, node: ast.expr) -> None:
        facts = self.facts
        product = facts.matmul(node)
        if product is None:
            return
        for block, value in ((product.left, product.right), _row_form(product.left, product.right)):
            if block is None or value is None:
                continue
            matrix = facts.rotation_block_of(block)
            if matrix is None or facts.kind_of(matrix) != Kind.TRANSFORM:
                continue
            if not _loses_translation(facts.kind_of(value)) or self._translated_later(node, matrix):
                continue
            self.report(
                node,
                f"point `{self.code_of(value)}` gets only the rotation of `{self.code_of(matrix)}`; "
                f"add its translation `{self.code_of(matrix)}[:3, 3]`",
            )
            return

    def _translated_later(self, node: AST, matrix: ast.expr) -> bool:
        """Whether the product is part of a sum, its target is added to afterwards (`q += t`),
        or the same scope reads the matrix's translation column (added after a reduction)."""
        facts = self.facts
        scope = facts.index.scope_of(node)
        if self._reads_translation_column(scope.node, self.code_of(matrix)):
            return True
        parent = facts.parent(node)
        while parent is not None and transposed_value(parent) is node:
            node, parent = parent, facts.parent(parent)
        if isinstance(parent, BinOp) and isinstance(parent.op, (Add, Sub)):
            return True
        if isinstance(parent, Assign):
            scope = facts.index.scope_of(parent)
            for target in parent.targets:
                if isinstance(target, Name) and target.id in scope.augmented:
                    return True
        return not isinstance(parent, (Assign, Return, Call, AnnAssign, ast.List, ast.Tuple))

    def _reads_translation_column(self, scope_node: AST, matrix: str) -> bool:
        """Whether the scope's text reads `matrix[:3, 3]` (one scan per scope, remembered)."""
        cache = self.__dict__.setdefault("_columns", {})
        read = cache.get(id(scope_node))
        if read is None:
            read = cache[id(scope_node)] = {m.group(1) for m in _TRANSLATION_COLUMN.finditer(_scope_text(self.facts, scope_node))}
        if matrix in read:
            return True
        if re.fullmatch(r"[\w.]+", matrix):
            return False
        key = (id(scope_node), matrix)
        if key not in cache:
            column = rf"{re.escape(matrix)}\s*\[\s*(?:0\s*)?:\s*3\s*,\s*(?:3|-1)\s*\]"  # `poses[i][:3, 3]`
            cache[key] = re.search(column, _scope_text(self.facts, scope_node)) is not None
        return cache[key]  # type: ignore[no-any-return]

    def _check_library_call(self, node: Call) -> None:
        facts = self.facts
        for argument, moved_as in library_calls.moved_arguments(facts, node):  # the knowledge base (stubs/)
            if moved_as in FREE and facts.kind_of(argument) == Kind.POINT:
                self._report_untranslated(node, argument)

    def _report_untranslated(self, node: Call, argument: ast.expr) -> None:
        """A library call that moves `argument`, a point, as a free vector: say what drops the translation."""
        facts, called, code = self.facts, last_name(node.func), self.code_of(argument)
        chosen = library_calls.choosing_keywords(facts, node)
        fix = library_calls.moving_as(facts, node, argument, LOCATED - FREE)
        if chosen:
            self.report(node, f"`{code}` holds points, but `{chosen[0]}` drops the translation")
        elif library_calls.homogenizes(facts, node):
            self.report(node, f"`{called}` gives w = 0, but `{code}` is a point" + (f"; use `{fix[1]}`" if fix else ""))
        else:
            self.report(node, f"`{called}` drops the translation, but `{code}` holds points" + (f"; use `{fix[1]}`" if fix else ""))


_TRANSLATION_COLUMN: Final = re.compile(r"([\w.]+)\s*\[\s*(?:0\s*)?:\s*3\s*,\s*(?:3|-1)\s*\]")


def _scope_text(facts, scope_node: AST) -> str:  # type: ignore[no-untyped-def]
    return facts.index.source if isinstance(scope_node, Module) else facts.index.segment(scope_node)


def _is_quaternion_call(call: AST) -> bool:
    """`quaternion_multiply`, `quat_mul`, `qmult`, `Quaternion(...)`: quaternion algebra."""
    name = (last_name(call.func) or "").lower()  # type: ignore[attr-defined]
    return "quat" in name or name in ("qmult", "qmul")


def _loses_translation(kind: Kind | None) -> bool:
    """Whether a value of `kind` is wrong under a transform's rotation block alone (`algebra.rotate_only`)."""
    outcome = None if kind is None else algebra.rotate_only(kind)
    return outcome is not None and outcome.problem == Problem.POINT_NOT_TRANSLATED


def _row_form(left: ast.expr, right: ast.expr) -> tuple[ast.expr | None, ast.expr | None]:
    """`p @ M[:3, :3].T` as (block, value); (None, None) when the right side is not a transposed block."""
    inner = transposed_value(right)
    if inner is not None:
        return inner, left
    return None, None
