"""Pixel ray directions and the camera axes their signs state (geolint.factbase.camera_rays), the rotations
that take them to the world, and the summary of a helper that rotates rays by its parameter."""

from __future__ import annotations

import ast
import textwrap

import pytest

from geolint.factbase import facts_for_module
from geolint.factbase.camera_rays import CAMERA_RAYS, ray_axes, rotated_rays
from geolint.factbase.extrinsics import OPENCV, OPENGL, POSE, PYTORCH3D, ROTATION
from geolint.factbase.model import FactBase
from geolint.lint_types import Config


def facts_of(code: str) -> tuple[ast.Module, FactBase]:
    source = textwrap.dedent(code)
    tree = ast.parse(source)
    return tree, facts_for_module(tree, source, "<test>", Config())


def returned_convention(code: str) -> str | None:
    tree, facts = facts_of(code)
    value = [node for node in ast.walk(tree) if isinstance(node, ast.Return)][-1].value
    assert value is not None
    axes = ray_axes(facts, value)
    return None if axes is None else axes.convention


@pytest.mark.parametrize(
    ("directions", "expected"),
    [
        ("np.stack([(u - cx) / fx, (v - cy) / fy, np.ones_like(u)], -1)", OPENCV),
        ("torch.stack([(i - K[0][2]) / K[0][0], -(j - K[1][2]) / K[1][1], -torch.ones_like(i)], -1)", OPENGL),
        ("np.stack([(i - W * 0.5) / focal, -(j - H * .5) / focal, -np.ones_like(i)], -1)", OPENGL),
        ("np.stack([(i - K[0, 2]) / K[0, 0], (j - K[1, 2]) / K[1, 1], np.ones_like(i)], -1)", OPENCV),
        ("np.stack([(cx - u) / fx, (cy - v) / fy, np.ones_like(u)], -1)", PYTORCH3D),
        ("np.stack([(u - self.cx) / self.fx, (v - self.cy) / -self.fy, -1 * np.ones_like(u)], -1)", OPENGL),
        ("np.array([(u + 0.5 - cx) / fx, (v + 0.5 - cy) / fy, 1.0])", OPENCV),
    ],
)
def test_signs_state_the_camera_axes(directions: str, expected: str) -> None:
    assert returned_convention(f"def f(u, v, i, j, K, W, H, fx, fy, cx, cy, focal):\n    return {directions}\n") == expected


@pytest.mark.parametrize(
    "directions",
    [
        "np.stack([(u - cx) / fx, -(v - cy) / fy, np.ones_like(u)], -1)",  # left-handed: no convention
        "np.stack([u / fx, v / fy, np.ones_like(u)], -1)",  # no principal point
        "np.stack([(u - v) / fx, (v - cy) / fy, np.ones_like(u)], -1)",  # neither side a principal point
        "np.stack([(u - cx) / fx, (v - cy) / fy, depth], -1)",  # not unit depth
        "np.stack([x, y, z], -1)",
        "np.stack([(u - cx) / fx, (v - cy) / fy], -1)",
    ],
)
def test_other_stacks_state_nothing(directions: str) -> None:
    assert returned_convention(f"def f(u, v, fx, fy, cx, cy, depth, x, y, z):\n    return {directions}\n") is None


@pytest.mark.parametrize(
    "rotation",
    [
        "np.sum(dirs[..., None, :] * c2w[:3, :3], -1)",
        "torch.sum(dirs[..., np.newaxis, :] * c2w[:3, :3], dim=-1)",
        "(c2w[:3, :3] * dirs[:, None, :]).sum(-1)",
        "dirs @ c2w[:3, :3].T",
        "c2w[:3, :3] @ dirs",
    ],
)
def test_rotations_of_rays_in_their_spellings(rotation: str) -> None:
    tree, facts = facts_of(
        "def f(u, v, fx, fy, cx, cy, c2w):\n    dirs = np.stack([(u - cx) / fx, (v - cy) / fy, np.ones_like(u)], -1)\n"
        f"    return {rotation}\n"
    )
    value = [node for node in ast.walk(tree) if isinstance(node, ast.Return)][-1].value
    assert value is not None
    found = rotated_rays(facts, value)
    assert found is not None
    directions, rotated_by = found
    assert ast.unparse(directions) == "dirs" and ast.unparse(rotated_by) == "c2w[:3, :3]"


def test_a_sum_over_another_axis_is_no_rotation() -> None:
    tree, facts = facts_of("def f(dirs, c2w):\n    return np.sum(dirs[..., None, :] * c2w[:3, :3], 0)\n")
    value = [node for node in ast.walk(tree) if isinstance(node, ast.Return)][-1].value
    assert value is not None and rotated_rays(facts, value) is None


def summary_of_last_call(code: str) -> dict[int, tuple[str, str]]:
    tree, facts = facts_of(code)
    call = [node for node in ast.walk(tree) if isinstance(node, ast.Call) and isinstance(node.func, ast.Name)][-1]
    summary = facts.summary_of(call, CAMERA_RAYS)
    assert summary is not None
    return {index: (part, axes.convention) for index, (part, axes) in summary.rotates_rays.items()}


def test_a_helper_that_rotates_rays_by_a_parameter_states_its_axes() -> None:
    helper = (
        "def get_rays(i, j, K, c2w):\n"
        "    dirs = np.stack([(i - K[0][2]) / K[0][0], -(j - K[1][2]) / K[1][1], -np.ones_like(i)], -1)\n"
        "    R = c2w[:3, :3]\n    return np.sum(dirs[..., None, :] * R, -1)\n"
        "def rotate(i, j, K, R):\n"
        "    return np.stack([(i - K[0][2]) / K[0][0], (j - K[1][2]) / K[1][1], np.ones_like(i)], -1) @ R.T\n"
    )
    assert summary_of_last_call(helper + "get_rays(i, j, K, pose)\n") == {3: (POSE, OPENGL)}
    assert summary_of_last_call(helper + "rotate(i, j, K, pose)\n") == {3: (ROTATION, OPENCV)}


def test_a_parameter_edited_in_place_or_rotating_two_conventions_states_nothing() -> None:
    edited = (
        "def get_rays(i, j, K, c2w):\n    c2w[:3, 1:3] *= -1\n"
        "    dirs = np.stack([(i - K[0][2]) / K[0][0], (j - K[1][2]) / K[1][1], np.ones_like(i)], -1)\n"
        "    return dirs @ c2w[:3, :3].T\n"
        "get_rays(i, j, K, pose)\n"
    )
    both = (
        "def get_rays(i, j, K, c2w):\n"
        "    a = np.stack([(i - K[0][2]) / K[0][0], (j - K[1][2]) / K[1][1], np.ones_like(i)], -1) @ c2w[:3, :3].T\n"
        "    b = np.stack([(i - K[0][2]) / K[0][0], -(j - K[1][2]) / K[1][1], -np.ones_like(i)], -1) @ c2w[:3, :3].T\n"
        "    return a, b\n"
        "get_rays(i, j, K, pose)\n"
    )
    assert summary_of_last_call(edited) == {}
    assert summary_of_last_call(both) == {}
