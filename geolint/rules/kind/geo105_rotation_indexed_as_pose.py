"""GEO105 rotation-indexed-as-pose: a 3x3 rotation matrix indexed as if it were a 4x4 pose."""

from __future__ import annotations

import ast
from ast import Assign, Attribute, Call, Module, Name, Slice, Subscript

from geolint.factbase import ModuleIndex, index_of
from geolint.factbase.model import subscript_parts
from geolint.factbase.pose_parts import ROTATION_MAKERS, call_name, int_value, matrix_shape
from geolint.factbase.reaching import scope_of
from geolint.rules.base import AstRule, Invalid, Valid
from geolint.rules.triggers import AllOf


class RotationIndexedAsPose(AstRule):
    """A 3x3 rotation matrix is indexed as a 4x4 pose (its translation column or bottom row).

    ## What it does
    Flags `R[:3, 3]`, `R[3, :3]`, `R[:3, 3:]` or `R[3]` (read or written) where R is
    certainly a single 3x3 matrix: made by `np.eye(3)` / `np.zeros((3, 3))`, a literal 3x3,
    a `[:3, :3]` slice, `.reshape(3, 3)`, transforms3d `quat2mat` / `euler2mat`, pytransform3d
    `matrix_from_quaternion`, pyquaternion `Quaternion(...).rotation_matrix` or
    `cv2.Rodrigues(r)[0]`, with no reassignment in between.

    ## Why is this bad?
    A rotation has no translation column and no homogeneous row. Indexing past its third row or
    column raises `IndexError` the first time the line runs, and a slice such as `R[:3, 3:]` is
    silently empty, so the translation the code means to read or store goes nowhere. Usually the
    code meant the 4x4 pose the rotation came from, or should build one (`T = np.eye(4);
    T[:3, :3] = R; T[:3, 3] = t`).

    ## Example
    ```python
    R = Quaternion(pose["rotation"]).rotation_matrix
    R[:3, 3] = pose["translation"]
    ```

    ## Use instead
    ```python
    T = np.eye(4)
    T[:3, :3] = Quaternion(pose["rotation"]).rotation_matrix
    T[:3, 3] = pose["translation"]
    ```

    ## Fix safety
    There is no automatic fix: the code needs a 4x4 array that does not exist yet.

    ## Known problems
    Only arrays whose maker fixes the shape are checked; a rotation that arrives as a parameter
    or from a project function is not. An array resized in place (`R.resize((4, 4))`) is skipped.
    """

    code = "GEO105"
    name = "rotation-indexed-as-pose"
    triggers = AllOf(
        r"eye\(\s*3|zeros\(\s*\(\s*3\s*,\s*3|\[\s*\[|:\s*3\s*,\s*:\s*3|reshape\(\s*3\s*,\s*3|2mat\(|matrix_from_|rotation_matrix|Rodrigues",
        r"\[[^\]\n]*(?:\b3\s*[\],]|3\s*:)",
    )

    VALID = [
        Valid("from sympy import zeros\ns = zeros(3, 3)\ns[3] = 1\n"),  # sympy: flat indexing
        Valid("import numpy as np\nT = np.eye(4)\nT[:3, 3] = t\n"),
        Valid("import numpy as np\nR = np.eye(3)\nR[:2, 2] = t\n"),  # a 2-D homogeneous transform
        Valid("def f(R, t):\n    R[:3, 3] = t\n"),  # shape unknown
        Valid("import numpy as np\nR = np.eye(3)\nR = np.hstack([R, t[:, None]])\nx = R[:3, 3]\n"),
        Valid("def f(T):\n    R = T[:3, :3]\n    return T[:3, 3], R[2, 2]\n"),
        Valid("import numpy as np\nR = np.eye(3)\nR.resize((4, 4), refcheck=False)\nR[3, 3] = 1\n"),
        Valid("import numpy as np\nR = np.eye(3)\nblock = R[:4, :4]\n"),  # slicing past the end clamps
        Valid("def f(poses):\n    R = poses[:, :3, :3]\n    return R[3]\n"),  # the fourth rotation of a stack
    ]
    INVALID = [
        Invalid(
            "import numpy as np\nR = np.eye(3)\nR[:3, 3] = t\n",
            message="`R` is a 3x3 rotation, but `R[:3, 3]` indexes it as a 4x4 pose (there is no row or column 3): use the 4x4 pose it came from, or build one",
            range=(3, 1, 3, 9),
        ),
        Invalid("def f(pose):\n    R = Quaternion(pose['rotation']).rotation_matrix\n    return R[3, :3]\n"),
        Invalid("def f(T):\n    R = T[:3, :3].copy()\n    return R[:3, 3:]\n"),
        Invalid("from transforms3d.quaternions import quat2mat\nR = quat2mat(q)\nt = R[0:3, 3]\n"),
        Invalid("import cv2\ndef f(rvec):\n    R = cv2.Rodrigues(rvec)[0]\n    return R[3, 3]\n"),
    ]

    def check(self, tree: Module) -> None:
        candidates: list[tuple[Subscript, Name]] = []
        square_names: set[str] = set()  # names some assignment may make 3x3 (a cheap first cut)
        index = index_of(tree)
        for assign in index.nodes(Assign):
            if _may_make_square(assign.value):  # type: ignore[attr-defined]
                square_names.update(target.id for target in assign.targets if isinstance(target, Name))  # type: ignore[attr-defined]
        for node in index.nodes(Subscript):
            if not isinstance(node, Subscript) or not isinstance(node.value, Name):
                continue
            indices = subscript_parts(node)
            if len(indices) <= 2 and any(_past_third(part) for part in indices[:2]):
                candidates.append((node, node.value))
        for node, matrix in candidates:
            if matrix.id not in square_names:
                continue
            if matrix_shape(matrix, index) != 3 or _resized_in_place(matrix, index):
                continue
            self.report(
                node,
                f"`{matrix.id}` is a 3x3 rotation, but `{ast.unparse(node)}` indexes it as a 4x4 pose "
                "(there is no row or column 3): use the 4x4 pose it came from, or build one",
            )


_SQUARE_CALLS = frozenset({"eye", "identity", "zeros", "empty", "array", "asarray", "tensor", "reshape", "Rodrigues"}) | ROTATION_MAKERS


def _may_make_square(value: ast.expr) -> bool:
    """A cheap first cut of `matrix_shape`: a 3x3 maker, a copy or transpose of one, a slice, a literal, an alias."""
    while isinstance(value, Call) and isinstance(value.func, Attribute) and call_name(value) not in _SQUARE_CALLS:
        value = value.func.value  # R.copy(), R.T.astype(...)
    while isinstance(value, Attribute) and value.attr in ("T", "mT"):
        value = value.value
    if isinstance(value, Call):
        return call_name(value) in _SQUARE_CALLS
    if isinstance(value, Attribute):
        return value.attr == "rotation_matrix"
    return isinstance(value, (Subscript, ast.List, Name))


def _past_third(index: ast.expr) -> bool:
    """3 (or more), `3:`: an index that only exists in a 4x4 matrix (a slice past the end clamps)."""
    value = int_value(index)
    if value is not None:
        return value >= 3
    return isinstance(index, Slice) and (int_value(index.lower) or 0) >= 3


def _resized_in_place(name: Name, index: ModuleIndex) -> bool:
    scope = scope_of(index, name).node
    return any(
        isinstance(node, Call)
        and isinstance(node.func, Attribute)
        and node.func.attr in ("resize", "resize_")
        and isinstance(node.func.value, Name)
        and node.func.value.id == name.id
        for node in ast.walk(scope)
    )
