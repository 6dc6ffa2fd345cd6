"""Pixel ray directions, whose construction states the camera axes they are in, and the rotations that
take them to the world.

A ray through pixel (u, v) of a pinhole camera is `[(u - cx) / fx, (v - cy) / fy, 1]` in OpenCV axes
(x right, y down, z forward); NeRF code in OpenGL axes (y up, z back) writes
`[(u - cx) / fx, -(v - cy) / fy, -1]`, PyTorch3D's (x left, y up) `[-(u - cx) / fx, -(v - cy) / fy, 1]`.
The signs are read off the expression: which side of each difference is the principal point (`cx`,
`K[0][2]`, `W * 0.5`; never `px`, often a pixel), an outer minus, a negative constant third component.
Anything else, or a mix of signs no convention uses, states nothing.

The rotations read here are the three spellings of "rotate each ray by R": `sum(d[..., None, :] * R, -1)`,
`d @ R.T` and `R @ d`. A function that rotates rays it builds by (the rotation block of) one of its
parameters expects a camera-to-world pose in the rays' axes there: the `CAMERA_RAYS` summary family
(`geolint.factbase.summaries`), so that a call anywhere in the project is judged by it
(`get_rays(H, W, K, c2w)` written for OpenGL axes, given a COLMAP pose).
"""

from __future__ import annotations

import ast
import re
from ast import Attribute, BinOp, Call, Constant, Div, FloorDiv, Mult, Name, Sub, Subscript, USub, UnaryOp
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Final

from geolint.factbase import dataflow
from geolint.factbase.extrinsics import DATA, OPENCV, OPENGL, POSE, PYTORCH3D, ROTATION, Axes
from geolint.factbase.pose_parts import call_name, int_value, peel_same_value
from geolint.factbase.reaching import value_of
from geolint.factbase.summaries import Function, Summary, SummaryFamily, plain_parameters
from geolint.factbase.syntax import subscript_parts, walk_within

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

# (sign of x, sign of y, sign of z) -> the camera axes
_CONVENTIONS: Final = {(1, 1, 1): OPENCV, (1, -1, -1): OPENGL, (-1, -1, 1): PYTORCH3D}
_STACKS: Final = frozenset({"stack", "array", "asarray", "tensor", "dstack"})
_UNITS: Final = frozenset({"ones_like", "ones"})
_PRINCIPAL_NAME: Final = re.compile(r"(?:.*_)?(?:c[xy]|u0|v0)(?:_.*)?|principal.*")  # not `px`: often a pixel
_IMAGE_SIZE: Final = re.compile(r"(?:img_|image_)?(?:[wh]|width|height|img_[wh]|[WH])")


def ray_axes(facts: FactBase, node: ast.expr, depth: int = 4) -> Axes | None:
    """The camera axes of ray directions `node` builds (through names bound once in a row), or None."""
    node = peel_same_value(node)
    if isinstance(node, Name) and depth:
        value = value_of(facts.index, node)
        return ray_axes(facts, value, depth - 1) if isinstance(value, ast.expr) else None
    if isinstance(node, Call) and call_name(node) in _STACKS and node.args:
        components = node.args[0]
    elif isinstance(node, (ast.List, ast.Tuple)):
        components = node  # `np.array([...])`, peeled to its list
    else:
        return None
    if not isinstance(components, (ast.List, ast.Tuple)) or len(components.elts) != 3:
        return None
    x, y, z = components.elts
    signs = (_offset_sign(x), _offset_sign(y), _unit_sign(z))
    convention = _CONVENTIONS.get(signs)  # type: ignore[arg-type]
    if convention is None:
        return None
    return Axes(convention, f"ray directions `{_short(node)}`", DATA)


def rotated_rays(facts: FactBase, node: ast.expr) -> tuple[ast.expr, ast.expr] | None:
    """(directions, rotation) when `node` rotates directions by a matrix: `sum(d[..., None, :] * R, -1)`
    (also `(...).sum(-1)`), `d @ R.T`, `R @ d`. Which operand is which is told by the directions' form."""
    if isinstance(node, Call) and call_name(node) == "sum":
        summed = _summed_over_last_axis(facts, node)
        if isinstance(summed, BinOp) and isinstance(summed.op, Mult):
            for directions, rotation in ((summed.left, summed.right), (summed.right, summed.left)):
                if _is_row_broadcast(directions):
                    return peel_same_value(directions), rotation
        return None
    product = facts.matmul(node)
    if product is None:
        return None
    left, right = product.left, product.right
    if isinstance(right, Attribute) and right.attr in ("T", "mT") and ray_axes(facts, left) is not None:
        return left, right.value
    if ray_axes(facts, right) is not None:
        return right, left
    return None


@dataclass
class RaySummary(Summary):
    # parameter index -> (part, axes): the function rotates ray directions built in `axes` by that parameter
    # (POSE: by its rotation block `c2w[:3, :3]`; ROTATION: by the parameter itself)
    rotates_rays: dict[int, tuple[str, Axes]] = field(default_factory=dict)


def _summarize_rays(facts: FactBase, function: Function, params: tuple[str, ...]) -> RaySummary:
    summary = RaySummary(parameters=params)
    scope = facts.index.scopes.get(function)
    if scope is None:
        return summary
    plain = plain_parameters(scope, params)
    found: dict[int, set[tuple[str, Axes]]] = {}
    for node in walk_within(function):
        rotated = rotated_rays(facts, node) if isinstance(node, (Call, BinOp)) else None
        if rotated is None:
            continue
        directions, rotation = rotated
        axes = ray_axes(facts, directions)
        parameter = _rotating_parameter(facts, rotation)
        if axes is None or parameter is None or parameter[0] not in plain:
            continue
        name, part = parameter
        if dataflow.writes_into(facts.index, scope, name):
            continue  # edited in place: what the caller passes is not what rotates the rays
        found.setdefault(params.index(name), set()).add((part, Axes(axes.convention, f"{axes.source} at line {node.lineno}", DATA)))  # type: ignore[attr-defined]
    for index, stated in found.items():
        if len({(part, axes.convention) for part, axes in stated}) == 1:
            summary.rotates_rays[index] = min(stated, key=lambda entry: entry[1].source)
    return summary


def _rotating_parameter(facts: FactBase, rotation: ast.expr) -> tuple[str, str] | None:
    """(name, part) when the rotation is a name's rotation block (`c2w[:3, :3]`, also through a local
    `R = c2w[:3, :3]`) or the name itself."""
    rotation = peel_same_value(rotation)
    if isinstance(rotation, Name):
        value = value_of(facts.index, rotation)
        if isinstance(value, Subscript) and facts.rotation_block_of(value) is not None:
            rotation = value
        else:
            return rotation.id, ROTATION
    matrix = facts.rotation_block_of(rotation)
    return (matrix.id, POSE) if isinstance(matrix, Name) else None


def _bound_rays(summary: RaySummary) -> RaySummary:
    return RaySummary(
        parameters=summary.parameters[1:],
        rotates_rays={index - 1: stated for index, stated in summary.rotates_rays.items() if index > 0},
        pending=summary.pending,
    )


CAMERA_RAYS: Final = SummaryFamily("camera rays", RaySummary, _summarize_rays, _bound_rays)


def _summed_over_last_axis(facts: FactBase, call: Call) -> ast.expr | None:
    """What `np.sum(x, -1)`, `torch.sum(x, dim=-1)` or `x.sum(-1)` sums, when it sums over the last axis."""
    func = call.func
    if isinstance(func, Attribute) and not facts.is_module_like(func.value):
        summed: ast.expr | None = func.value
        positional = call.args
    else:
        summed = call.args[0] if call.args else None
        positional = call.args[1:]
    axis = positional[0] if positional else next((keyword.value for keyword in call.keywords if keyword.arg in ("axis", "dim")), None)
    return summed if axis is not None and int_value(axis) == -1 else None


def _is_row_broadcast(node: ast.expr) -> bool:
    """`d[..., None, :]`, `d[:, None, :]`: each ray as a row, broadcast against the rows of R."""
    if not isinstance(node, Subscript):
        return False
    parts = subscript_parts(node)
    if len(parts) < 2:
        return False
    new_axis = parts[-2]
    return isinstance(new_axis, Constant) and new_axis.value is None or isinstance(new_axis, Attribute) and new_axis.attr == "newaxis"


def _offset_sign(node: ast.expr) -> int | None:
    """+1 for `(u - cx) / fx`, -1 for `-(u - cx) / fx` or `(cx - u) / fx`; None when it is not such a term."""
    if isinstance(node, UnaryOp) and isinstance(node.op, USub):
        inner = _offset_sign(node.operand)
        return -inner if inner is not None else None
    if isinstance(node, BinOp) and isinstance(node.op, (Div, Mult)):
        scale = node.right if isinstance(node.op, Div) or _is_difference(node.left) else node.left
        offset = node.left if scale is node.right else node.right
        inner = _offset_sign(offset)
        if inner is None:
            return None
        return -inner if isinstance(scale, UnaryOp) and isinstance(scale.op, USub) else inner
    if isinstance(node, BinOp) and isinstance(node.op, Sub):
        left, right = _is_principal(node.left), _is_principal(node.right)
        if right and not left:
            return 1
        if left and not right:
            return -1
    return None


def _is_difference(node: ast.expr) -> bool:
    while isinstance(node, UnaryOp) and isinstance(node.op, USub):
        node = node.operand
    return isinstance(node, BinOp) and isinstance(node.op, Sub)


def _is_principal(node: ast.expr) -> bool:
    """`cx`, `self.cy`, `K[0][2]`, `K[1, 2]`, `intrinsics[..., 0, 2]`, `W * 0.5`, `W / 2`, `0.5 * W`."""
    if isinstance(node, Name):
        return _PRINCIPAL_NAME.fullmatch(node.id.lower()) is not None
    if isinstance(node, Attribute):
        return _PRINCIPAL_NAME.fullmatch(node.attr.lower()) is not None
    if isinstance(node, Subscript):
        indices = [int_value(part) for part in subscript_parts(node)]
        if isinstance(node.value, Subscript):  # K[0][2]
            indices = [int_value(part) for part in subscript_parts(node.value)] + indices
        return indices[-2:] in ([0, 2], [1, 2])
    if isinstance(node, BinOp) and isinstance(node.op, (Mult, Div, FloorDiv)):
        size, factor = (node.left, node.right) if isinstance(node.op, (Div, FloorDiv)) or not _is_half(node.left) else (node.right, node.left)
        named = size.id if isinstance(size, Name) else size.attr if isinstance(size, Attribute) else None
        halves = factor.value == 2 if isinstance(node.op, (Div, FloorDiv)) and isinstance(factor, Constant) else _is_half(factor)
        return bool(halves) and named is not None and _IMAGE_SIZE.fullmatch(named) is not None
    return False


def _is_half(node: ast.expr) -> bool:
    return isinstance(node, Constant) and node.value == 0.5


def _unit_sign(node: ast.expr) -> int | None:
    """+1 for `1`, `ones_like(u)`; -1 for their negatives (`-np.ones_like(i)`, `-1.0`)."""
    if isinstance(node, UnaryOp) and isinstance(node.op, USub):
        inner = _unit_sign(node.operand)
        return -inner if inner is not None else None
    if isinstance(node, Constant) and not isinstance(node.value, bool) and node.value == 1:
        return 1
    if isinstance(node, Call) and call_name(node) in _UNITS:
        return 1
    if isinstance(node, BinOp) and isinstance(node.op, Mult):
        signs = [_unit_sign(node.left), _unit_sign(node.right)]
        if None not in signs:
            return signs[0] * signs[1]  # type: ignore[operator]
    return None


def _short(node: ast.expr) -> str:
    text = ast.unparse(node)
    return text if len(text) <= 60 else text[:57] + "..."
