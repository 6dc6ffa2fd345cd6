"""geolint.factbase.pose_parts: which pose a rotation or translation belongs to, through the values
that reach a use (geolint.factbase.reaching), and shapes."""

from __future__ import annotations

import ast

import pytest

from geolint.factbase.index import ModuleIndex
from geolint.factbase.pose_parts import application, difference_with, matrix_shape, pose_part, square_shape
from geolint.factbase.reaching import value_of


def last_expression(source: str) -> tuple[ast.expr, ModuleIndex]:
    """The value of the module's (or its last function's) last statement, and the module's index."""
    tree = ast.parse(source)
    body = tree.body
    while isinstance(body[-1], ast.FunctionDef):
        body = body[-1].body
    statement = body[-1]
    assert isinstance(statement, (ast.Expr, ast.Return, ast.Assign))
    return statement.value, ModuleIndex(tree, source)  # type: ignore[return-value]


@pytest.mark.parametrize(
    ("source", "kind", "transposed"),
    [
        ("T[:3, :3]", "rotation", False),
        ("T[0:3, 0:3].T", "rotation", True),
        ("T[:3, 3]", "translation", False),
        ("T[:3, 3:4]", "translation", False),
        ("T[:3, -1].reshape(3, 1)", "translation", False),
        ("poses[:, :3, :3].transpose(1, 2)", "rotation", True),
        ("poses[..., :3, :3].mT", "rotation", True),
        ("poses[:, None, :3, 3]", "translation", False),
        ("pose.rotation", "rotation", False),
        ("np.linalg.inv(pose.rotation)", "rotation", True),
        ("pose['translation']", "translation", False),
        ("gt['cam_R_m2c']", "rotation", False),
        ("Quaternion(pose['rotation']).inverse.rotation_matrix", "rotation", True),
        ("def f(T):\n    R, t = T[:3, :3], T[:3, 3]\n    return R", "rotation", False),
        ("def f(T):\n    R = T[:3, :3]\n    Rt = R.T.copy()\n    return Rt", "rotation", True),
    ],
)
def test_pose_part_kind_and_transpose(source: str, kind: str, transposed: bool) -> None:
    node, index = last_expression(source)
    part = pose_part(node, index)
    assert part is not None and (part.kind, part.transposed) == (kind, transposed)


@pytest.mark.parametrize(
    "source",
    ["T[:3, :2]", "T[1:3, 3]", "x.rotate", "def f(R):\n    return R", "def f(T):\n    for R in T:\n        pass\n    return R"],
)
def test_not_a_pose_part(source: str) -> None:
    node, index = last_expression(source)
    assert pose_part(node, index) is None


def test_parts_of_one_pose_share_a_key_and_a_rebound_pose_does_not() -> None:
    tree = ast.parse("def f(T, S):\n    R = T[:3, :3]\n    t = T[:3, 3]\n    T = S\n    u = T[:3, 3]\n    return R, t, u\n")
    index = ModuleIndex(tree, "")
    returned = tree.body[0].body[-1].value.elts  # type: ignore[attr-defined]
    rotation, translation, other = (pose_part(node, index) for node in returned)
    assert rotation.pose == translation.pose != other.pose  # type: ignore[union-attr]


def test_unpacked_call_needs_both_names_to_say_which_is_which() -> None:
    tree = ast.parse("def f(T):\n    R, t = split(T)\n    A, b = solve(T)\n    return R, t, A, b\n")
    index = ModuleIndex(tree, "")
    parts = [pose_part(node, index) for node in tree.body[0].body[-1].value.elts]  # type: ignore[attr-defined]
    assert [part and part.kind for part in parts] == ["rotation", "translation", None, None]


def test_a_value_assigned_in_one_branch_is_not_certain() -> None:
    source = "def f(T, flag):\n    R = T[:3, :3]\n    if flag:\n        R = other()\n    return R\n"
    node, index = last_expression(source)
    assert pose_part(node, index) is None


def test_a_later_assignment_in_the_loop_reaches_the_next_iteration() -> None:
    source = "def f(T, n):\n    x = T[:3, 3]\n    for _ in range(n):\n        y = x\n        x = step(x)\n    return y\n"
    tree = ast.parse(source)
    index = ModuleIndex(tree, source)
    loop = tree.body[0].body[1]  # type: ignore[attr-defined]
    read = loop.body[0].value
    assert value_of(index, read) is None


def test_an_assignment_that_dominates_the_read_inside_the_loop_kills_the_back_edge() -> None:
    source = "def f(T, xs):\n    for x in xs:\n        y = x - T[:3, 3]\n        y = y @ T[:3, :3]\n    return y\n"
    tree = ast.parse(source)
    index = ModuleIndex(tree, source)
    read = tree.body[0].body[0].body[1].value.left  # type: ignore[attr-defined]
    assert isinstance(value_of(index, read), ast.BinOp)


def test_augmented_assignment_is_a_difference_of_the_previous_value() -> None:
    source = "def f(x, T):\n    x -= T[:3, 3]\n    return x\n"
    node, index = last_expression(source)
    removed = difference_with(node, index)
    assert removed is not None and removed[1].kind == "translation"


@pytest.mark.parametrize(
    ("source", "inverse"),
    [
        ("T[:3, :3] @ p", False),
        ("T[:3, :3].T @ p", True),
        ("p @ T[:3, :3]", True),
        ("p @ T[:3, :3].T", False),
        ("(T[:3, :3].T @ p.T).T", True),
        ("np.dot(T[:3, :3], p)", False),
        ("T[:3, :3].T.dot(p)", True),
        ("torch.bmm(poses[:, :3, :3], x)", False),
    ],
)
def test_application_says_which_way_the_rotation_acts(source: str, inverse: bool) -> None:
    node, index = last_expression(source)
    applied = application(node, index)
    assert applied is not None and applied.inverse is inverse


@pytest.mark.parametrize(
    ("source", "shape"),
    [
        ("np.eye(3)", 3),
        ("np.zeros((4, 4))", 4),
        ("np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1]])", 3),
        ("quat2mat(q)", 3),
        ("Quaternion(q).rotation_matrix", 3),
        ("Quaternion(q).transformation_matrix", 4),
        ("cv2.Rodrigues(r)[0]", 3),
        ("np.array(x).reshape(3, 3)", 3),
        ("T[:3, :3].copy()", 3),
        ("np.eye(3)[None]", None),  # stacked
        ("np.zeros(3)", None),
        ("R", None),
    ],
)
def test_matrix_shape(source: str, shape: int | None) -> None:
    node, index = last_expression(source)
    assert matrix_shape(node, index) == shape


@pytest.mark.parametrize(
    ("source", "shape"),
    [
        ("torch.eye(4).repeat(n, 1, 1)", (4, True)),
        ("np.tile(np.eye(4), (n, 1, 1))", (4, True)),
        ("torch.zeros(n, 4, 4)", (4, True)),
        ("np.eye(4)", (4, False)),
    ],
)
def test_stacked_square_shape(source: str, shape: tuple[int, bool]) -> None:
    node, index = last_expression(source)
    assert square_shape(node, index) == shape
