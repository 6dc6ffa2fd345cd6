"""A fast `ast` pre-pass that tells, per rule, whether a file MAY hold a finding.

libcst parsing plus the semantic model costs far more than CPython's `ast.parse`, and most
Python files (numpy's source, say) contain no geometry at all. One `FileSummary` per source
text records, from real code only (never docstrings or comments), the candidate expressions
the rules look for: matrix products, homogeneous constructions, `+` of two possibly-point
values, names in frame conventions, rotation API calls. Each rule's `triggers` is a
`Trigger` predicate over that summary; the engine calls `rule.triggers.search(source)` and
skips the parse when no enabled rule can fire.

Soundness: every predicate over-approximates what its rule can flag (kinds and frames are
read from names with the default vocabulary; see `Trigger.search_with` for extra names).
"""

from __future__ import annotations

import ast
import threading
from dataclasses import dataclass, field
from typing import Callable

from geolint.lint_types import Config
from geolint.semantic.names import Kind, frames_of_name, kind_of_name

_TRANSLATION_HEADS = frozenset({"t", "trans", "translation", "tvec", "tran"})
_POINT_ATTRIBUTES = frozenset({"vertices", "points", "centroid", "origin", "position"})
_HOMOGENEOUS_STACKS = frozenset({"hstack", "column_stack", "concatenate"})
_ONES_ZEROS = frozenset({"ones", "zeros", "ones_like", "zeros_like"})
_NORMAL_TOKENS = frozenset({"normal", "normals", "nrm", "nrms"})
_HOMOGENEOUS_TOKENS = frozenset({"h", "hom", "homog", "homogeneous", "homo"})


@dataclass
class FileSummary:
    """What one pass over a module's `ast` saw (code only)."""

    names: set[str] = field(default_factory=set)  # identifiers: variables, attributes, params, defs
    called: set[str] = field(default_factory=set)  # last component of every called name
    has_matmul: bool = False
    has_multiply: bool = False
    has_homogeneous: bool = False  # a construction that can only be homogeneous (np.ones buffer, [x[0], x[1], x[2], 1])
    has_padding: bool = False  # `np.append(x, 1)`, `np.hstack([x, ones])`: homogeneous only if used so
    has_homogeneous_name: bool = False  # an assignment to `p_h`, `points_hom`, ...
    fills_xyz: bool = False  # `buf[:3] = x`: with an np.ones/np.zeros buffer, homogeneous
    homogeneous_inners: list[ast.expr] = field(default_factory=list)  # the x of every construction
    stores_points_attribute: bool = False  # `obj.points = ...`
    returns_normals_parameter: bool = False  # `def f(..., normals): ... return ..., normals`

    def may_be_homogeneous(self) -> bool:
        """Whether some homogeneous construction may be used as one (see `used_as_homogeneous`)."""
        return (
            self.has_homogeneous
            or (self.fills_xyz and bool(self.called & _ONES_ZEROS))
            or (self.has_padding and (self.has_matmul or self.has_homogeneous_name))
        )
    rotation_block_product: bool = False
    add_after_rotation_translation: bool = False  # `<matmul> + t`
    add_operands: list[tuple[ast.expr, ast.expr]] = field(default_factory=list)
    assignments: list[tuple[str, ast.expr]] = field(default_factory=list)  # name = value
    returns: dict[str, list[ast.expr]] = field(default_factory=dict)  # function -> returned values
    transposed: set[str] = field(default_factory=set)  # X in `X.T`
    trig_literal: bool = False
    parse_failed: bool = False
    _point_names: set[str] | None = None

    def point_names(self, config: Config) -> set[str]:
        """Names that can hold a point: by name, or assigned from something that mentions one."""
        if self._point_names is not None and config == Config():
            return self._point_names
        found = self._closure({name for name in self.names if kind_of_name(name, config) == Kind.POINT} | _POINT_ATTRIBUTES)
        if config == Config():
            self._point_names = found
        return found

    def geometric_names(self, config: Config) -> set[str]:
        """Names that can hold a point or a direction (by name, attribute, maker call, or flow)."""
        seeds = {name for name in self.names if kind_of_name(name, config) in (Kind.POINT, Kind.DIRECTION)}
        seeds |= _POINT_ATTRIBUTES | {"normals", "vertex_normals", "face_normals", "normal"}
        seeds |= {_CALLED + maker for maker in _DIRECTION_MAKERS}
        return self._closure(seeds)

    def may_be_geometric_homogeneous(self, config: Config) -> bool:
        if not self.may_be_homogeneous():
            return False
        names = self.geometric_names(config)
        return any(_may_carry(inner, names) for inner in self.homogeneous_inners)

    def _closure(self, seeds: set[str]) -> set[str]:
        found = set(seeds)
        for _ in range(3):  # flow through a few assignments and helper returns
            before = len(found)
            for target, value in self.assignments:
                if target not in found and _may_carry(value, found):
                    found.add(target)
            for function, values in self.returns.items():
                if _CALLED + function not in found and any(_may_carry(value, found) for value in values):
                    found.add(_CALLED + function)
            if len(found) == before:
                break
        return found

    def has_point_sum(self, config: Config) -> bool:
        points = self.point_names(config)
        return any(_may_carry(left, points) and _may_carry(right, points) for left, right in self.add_operands)

    def has_kind_word(self, kind: Kind, config: Config) -> bool:
        return any(kind_of_name(name, config) == kind for name in self.names)

    def has_frame_operator(self, config: Config) -> bool:
        return any((frames := frames_of_name(name, config)) is not None and frames.is_operator for name in self.names)

    def has_frame_name(self, config: Config) -> bool:
        return any(frames_of_name(name, config) is not None for name in self.names)

    def has_transposed_transform(self, config: Config) -> bool:
        return any(
            (frames := frames_of_name(name, config)) is not None and frames.operator == "transform"
            for name in self.transposed
        )


_PASSTHROUGH = frozenset(
    {"asarray", "array", "copy", "asanyarray", "ascontiguousarray", "atleast_1d", "atleast_2d", "squeeze",
     "float64", "float32", "astype", "reshape", "flatten", "ravel", "inv", "inverse", "Inverse", "inverted",
     "invert_transform", "pinv", "dot", "matmul", "enumerate", "zip"}
)  # fmt: skip


# Marks a callable in a name set: `()cross` means "calling cross gives a geometric value",
# so `np.random.normal(...)` is not mistaken for the attribute `mesh.normal`.
_CALLED = "()"


def _may_carry(node: ast.AST | None, names: set[str]) -> bool:
    """Whether the semantic model could give this expression the kind of one of `names`: it
    propagates kinds only through names, attributes, subscripts, arithmetic and pass-through calls."""
    if isinstance(node, ast.Name):
        return node.id in names
    if isinstance(node, ast.Attribute):
        return node.attr in names or (node.attr == "T" and _may_carry(node.value, names))
    if isinstance(node, (ast.Subscript, ast.Starred)):
        return _may_carry(node.value, names)
    if isinstance(node, ast.UnaryOp):
        return _may_carry(node.operand, names)
    if isinstance(node, ast.BinOp):
        return _may_carry(node.left, names) or _may_carry(node.right, names)
    if isinstance(node, ast.Call):
        name = _last(node.func)
        if name is not None and _CALLED + name in names:  # a maker (np.cross) or a helper of this module
            return True
        if name in _PASSTHROUGH:
            receiver = node.func.value if isinstance(node.func, ast.Attribute) else None
            return _may_carry(receiver, names) or any(_may_carry(arg, names) for arg in node.args)
        return False
    if isinstance(node, (ast.Tuple, ast.List)):
        return any(_may_carry(element, names) for element in node.elts)
    return False


def _last(node: ast.AST) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return node.attr
    return None


def _is_int(node: ast.AST, *values: int) -> bool:
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        return _is_int(node.operand, *(-value for value in values))
    return isinstance(node, ast.Constant) and type(node.value) in (int, float) and node.value in values


def _is_w(node: ast.AST) -> bool:
    """A constant homogeneous coordinate: 0, 1, [1], np.ones(...), np.zeros(...)."""
    if _is_int(node, 0, 1):
        return True
    if isinstance(node, (ast.List, ast.Tuple)) and len(node.elts) == 1:
        return _is_int(node.elts[0], 0, 1)
    return isinstance(node, ast.Call) and _last(node.func) in _ONES_ZEROS


def _is_upto3(node: ast.AST | None) -> bool:
    """`:3` or `0:3`."""
    if not isinstance(node, ast.Slice) or node.step is not None or node.upper is None:
        return False
    return (node.lower is None or _is_int(node.lower, 0)) and _is_int(node.upper, 3)


def _is_rotation_block(node: ast.AST) -> bool:
    if isinstance(node, ast.Attribute) and node.attr == "T":
        node = node.value
    if not isinstance(node, ast.Subscript) or not isinstance(node.slice, ast.Tuple) or len(node.slice.elts) != 2:
        return False
    first, second = node.slice.elts
    return _is_upto3(first) and _is_upto3(second)


def _is_matmul(node: ast.AST) -> bool:
    if isinstance(node, ast.Attribute) and node.attr == "T":
        node = node.value
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.MatMult):
        return True
    return isinstance(node, ast.Call) and _last(node.func) in ("dot", "matmul")


def _is_translation_like(node: ast.AST) -> bool:
    if isinstance(node, ast.Subscript) and isinstance(node.slice, ast.Tuple) and len(node.slice.elts) == 2:
        return _is_upto3(node.slice.elts[0]) and _is_int(node.slice.elts[1], 3, -1)
    if isinstance(node, ast.Attribute):
        return node.attr in ("translation", "t", "trans", "p")
    return isinstance(node, ast.Name) and node.id.strip("_").split("_")[0].lower() in _TRANSLATION_HEADS


def summarize(source: str) -> FileSummary:
    from geolint.engine import cached_ast  # the engine's syntax check parsed this text already

    summary = FileSummary()
    try:
        tree = cached_ast(source)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        summary.parse_failed = True
        return summary
    names = summary.names
    functions: list[tuple[ast.FunctionDef, list[ast.expr]]] = []
    # A hand-rolled depth-first walk: it skips operator and context leaves and knows the
    # enclosing function (for returns) without re-walking each function body.
    stack: list[tuple[ast.AST, list[ast.expr] | None]] = [(tree, None)]
    pop, push = stack.pop, stack.append
    while stack:
        node, returned = pop()
        kind = type(node)
        if kind is ast.Name:
            names.add(node.id)  # type: ignore[attr-defined]
            continue
        if kind is ast.Constant:
            continue
        if kind is ast.Attribute:
            names.add(node.attr)  # type: ignore[attr-defined]
            if node.attr == "T":  # type: ignore[attr-defined]
                inner = _last(node.value)  # type: ignore[attr-defined]
                if inner is not None:
                    summary.transposed.add(inner)
        elif kind is ast.arg:
            names.add(node.arg)  # type: ignore[attr-defined]
        elif kind is ast.BinOp:
            _binop(summary, node)  # type: ignore[arg-type]
        elif kind is ast.Call:
            _call(summary, node)  # type: ignore[arg-type]
        elif kind is ast.Assign or kind is ast.AnnAssign or kind is ast.NamedExpr:
            _assignment(summary, node)
        elif kind is ast.For or kind is ast.comprehension or kind is ast.AsyncFor:
            for target in ast.walk(node.target):  # type: ignore[attr-defined]
                if isinstance(target, ast.Name):
                    summary.assignments.append((target.id, node.iter))  # type: ignore[attr-defined]
        elif kind is ast.FunctionDef or kind is ast.AsyncFunctionDef:
            names.add(node.name)  # type: ignore[attr-defined]
            returned = summary.returns.setdefault(node.name, [])  # type: ignore[attr-defined]
            functions.append((node, returned))  # type: ignore[arg-type]
        elif kind is ast.Lambda or kind is ast.ClassDef:
            returned = None
        elif kind is ast.Return:
            if returned is not None and node.value is not None:  # type: ignore[attr-defined]
                returned.append(node.value)  # type: ignore[attr-defined]
        elif kind is ast.Subscript:
            _subscript(summary, node)  # type: ignore[arg-type]
        elif kind is ast.ImportFrom or kind is ast.Import:
            # `from pyquaternion import Quaternion as PQ` calls `PQ(...)`: count the real name as called.
            for alias in node.names:  # type: ignore[attr-defined]
                summary.called.add(alias.name.rsplit(".", 1)[-1])
        for field_name in _child_fields(kind):
            value = getattr(node, field_name, None)
            if type(value) is list:
                for item in value:
                    if isinstance(item, ast.AST):
                        push((item, returned))
            elif isinstance(value, ast.AST):
                push((value, returned))
    for function, returned in functions:
        _check_returned_normals(summary, function, returned)
    return summary


_SKIPPED_FIELDS = frozenset({"ctx", "op", "type_comment", "kind", "type_ignores"})
_CHILD_FIELDS: dict[type, tuple[str, ...]] = {}


def _child_fields(kind: type) -> tuple[str, ...]:
    fields = _CHILD_FIELDS.get(kind)
    if fields is None:
        fields = tuple(name for name in getattr(kind, "_fields", ()) if name not in _SKIPPED_FIELDS)
        _CHILD_FIELDS[kind] = fields
    return fields


def _assignment(summary: FileSummary, node: ast.AST) -> None:
    targets = node.targets if isinstance(node, ast.Assign) else [node.target]  # type: ignore[attr-defined]
    value = node.value  # type: ignore[attr-defined]
    for target in targets:
        if isinstance(target, ast.Name) and value is not None:
            summary.assignments.append((target.id, value))
            if _HOMOGENEOUS_TOKENS & set(target.id.lower().split("_")):
                summary.has_homogeneous_name = True
        elif isinstance(target, ast.Subscript) and value is not None:
            _subscript_store(summary, target, value)
        elif isinstance(target, ast.Attribute) and target.attr == "points":
            summary.stores_points_attribute = True


def _binop(summary: FileSummary, node: ast.BinOp) -> None:
    op = type(node.op)
    if op is ast.MatMult:
        summary.has_matmul = True
        if _is_rotation_block(node.left) or _is_rotation_block(node.right):
            summary.rotation_block_product = True
    elif op is ast.Add:
        summary.add_operands.append((node.left, node.right))
        for rotated, other in ((node.left, node.right), (node.right, node.left)):
            if _is_matmul(rotated) and _is_translation_like(other):
                summary.add_after_rotation_translation = True
    elif op is ast.Mult:
        summary.has_multiply = True


def _call(summary: FileSummary, node: ast.Call) -> None:
    name = _last(node.func)
    if name is None:
        return
    summary.called.add(name)
    args = node.args
    if name in ("dot", "matmul"):
        summary.has_matmul = True
        if any(_is_rotation_block(arg) for arg in args) or (
            isinstance(node.func, ast.Attribute) and _is_rotation_block(node.func.value)
        ):
            summary.rotation_block_product = True
    elif name == "append" and len(args) == 2 and _is_w(args[1]):
        summary.has_padding = True
        summary.homogeneous_inners.append(args[0])
    elif name in _HOMOGENEOUS_STACKS and args and isinstance(args[0], (ast.List, ast.Tuple)):
        if len(args[0].elts) == 2 and _is_w(args[0].elts[1]):
            summary.has_padding = True
            summary.homogeneous_inners.append(args[0].elts[0])
    elif name in ("array", "asarray") and args and isinstance(args[0], ast.List) and len(args[0].elts) == 4:
        first_three = args[0].elts[:3]
        if _is_w(args[0].elts[3]) and all(
            isinstance(element, ast.Subscript) and _is_int(element.slice, index)
            for index, element in enumerate(first_three)
        ):
            summary.has_homogeneous = True
            summary.homogeneous_inners.append(first_three[0])
    elif name in ("sin", "cos", "tan") and len(args) == 1 and isinstance(args[0], (ast.Constant, ast.UnaryOp)):
        summary.trig_literal = True


def _check_returned_normals(summary: FileSummary, node: ast.FunctionDef, returned: list[ast.expr]) -> None:
    arguments = node.args
    params = {arg.arg for arg in (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs)}
    normals = {param for param in params if _NORMAL_TOKENS & set(param.lower().split("_"))}
    if not normals:
        return
    for value in returned:
        elements = value.elts if isinstance(value, (ast.Tuple, ast.List)) else [value]
        if any(isinstance(element, ast.Name) and element.id in normals for element in elements):
            summary.returns_normals_parameter = True


def _subscript(summary: FileSummary, node: ast.Subscript) -> None:
    if _last(node.value) in ("r_", "c_") and isinstance(node.slice, ast.Tuple) and len(node.slice.elts) == 2:
        if _is_w(node.slice.elts[1]):
            summary.has_padding = True
            summary.homogeneous_inners.append(node.slice.elts[0])


def _subscript_store(summary: FileSummary, target: ast.Subscript, value: ast.expr) -> None:
    """`buf[:3] = x` / `buf[:, :3] = x`: a buffer filled with xyz (the w comes from np.ones)."""
    index = target.slice
    if _is_upto3(index) or (isinstance(index, ast.Tuple) and len(index.elts) == 2 and _is_upto3(index.elts[1])):
        summary.fills_xyz = True
        summary.homogeneous_inners.append(value)


# The engine asks every rule's trigger about the same text in a row: summarise it once.
_last_summary: threading.local = threading.local()


def summary_of(source: str) -> FileSummary:
    cached = getattr(_last_summary, "value", None)
    if cached is not None and cached[0] is source:
        return cached[1]
    summary = summarize(source)
    _last_summary.value = (source, summary)
    return summary


class Trigger:
    """A rule's prefilter. Duck-types the `re.Pattern.search` the engine calls.

    `search(source)` uses the default vocabulary; `search_with(source, config)` also counts
    the config's extra direction/point names. A file that `ast` cannot parse always
    matches, so the engine reports it rather than skipping it.
    """

    def __init__(self, description: str, predicate: Callable[[FileSummary, Config], bool]) -> None:
        self.pattern = description  # shown where a regex would show its pattern
        self._predicate = predicate

    def search(self, source: str) -> bool:
        return self.search_with(source, Config())

    def search_with(self, source: str, config: Config) -> bool:
        summary = summary_of(source)
        return summary.parse_failed or self._predicate(summary, config)

    def __repr__(self) -> str:
        return f"Trigger({self.pattern!r})"



# --- the predicates the rules use -----------------------------------------------------------

# Calls the model gives a direction kind (keep in step with model.UNIT_FUNCTIONS and is_norm_call).
_DIRECTION_MAKERS = frozenset(
    {"cross", "norm", "vector_norm", "unitize", "normalize", "normalized", "unit_vector", "norm_vector", "normalize_vector"}
)
_QUATERNION_CALLS = frozenset({"from_quat", "Quaternion", "UnitQuaternion", "check_quaternion"})
_EULER_CALLS = frozenset(
    {"from_euler", "from_rotvec", "Rx", "Ry", "Rz", "RPY", "Eul", "rotx", "roty", "rotz", "trotx", "troty", "trotz",
     "rpy2r", "eul2r", "rpy2tr", "eul2tr", "quaternion_from_euler"}
)  # fmt: skip


def may_translate_direction(summary: FileSummary, config: Config) -> bool:
    return (
        summary.may_be_geometric_homogeneous(config)
        or summary.add_after_rotation_translation
        or bool(summary.called & {"transform_points", "vector_to_point"})
        or ("matrix_world" in summary.names and summary.has_matmul)
        or (summary.has_multiply and bool(summary.called & {"Frame", "SE3"} or "SE3" in summary.names))
    )


def may_drop_point_translation(summary: FileSummary, config: Config) -> bool:
    return (
        summary.may_be_geometric_homogeneous(config)
        or summary.rotation_block_product
        or bool(summary.called & {"transform_points", "vector_to_direction"})
    )


def may_add_points(summary: FileSummary, config: Config) -> bool:
    return summary.has_point_sum(config)


def may_leave_normals(summary: FileSummary, config: Config) -> bool:
    if "do_transform_cloud" in summary.called:
        return True
    moved = summary.has_matmul or "transform_points" in summary.called
    return moved and (
        (summary.stores_points_attribute and "normals" in summary.names) or summary.returns_normals_parameter
    )


def may_mix_frames_in_product(summary: FileSummary, config: Config) -> bool:
    return (summary.has_matmul or summary.has_multiply) and summary.has_frame_operator(config)


def may_mislabel_frames(summary: FileSummary, config: Config) -> bool:
    return any(frames_of_name(target, config) is not None for target, _ in summary.assignments)


def may_transpose_transform(summary: FileSummary, config: Config) -> bool:
    # `pose = T_world_cam; pose.T`: the transposed name need not state frames itself.
    return bool(summary.transposed) and any(
        (frames := frames_of_name(name, config)) is not None and frames.operator == "transform"
        for name in summary.names
    )


def may_pass_quaternion(summary: FileSummary, config: Config) -> bool:
    return any(
        name in _QUATERNION_CALLS or name.startswith("quat2") or name.endswith("_from_quaternion") or "quaternion" in name
        for name in summary.called
    )


def may_pass_degrees(summary: FileSummary, config: Config) -> bool:
    return summary.trig_literal or any(
        name in _EULER_CALLS
        or name.startswith(("euler2", "axangle2"))
        or name.endswith(("_from_euler", "_from_angle"))
        for name in summary.called
    )
