"""The semantic model the rules share: what an expression is (point, direction, transform,
rotation), which frames it lives in, and whether it is a homogeneous 4-vector built from
something else.

Evidence comes from names (`geolint.semantic.names`), known library calls, and simple flow
within a function (assignments, aliasing, slices, loops) and across the functions of one
module (a helper whose every return has the same kind). Every question answers None when the
evidence is missing or contradictory: rules only fire on positive evidence.

One `SemanticModel` exists per (module, config) and memoises its answers, so N rules do not
recompute them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, TypeVar

import libcst as cst

from geolint.lint_types import Config
from geolint.semantic.facts import (
    Binding,
    LoopBinding,
    ModuleFacts,
    ParamBinding,
)
from geolint.semantic.names import Kind, NameFrames, frames_of_name, kind_of_name, same_frame, states_geometry

_T = TypeVar("_T")

# Module aliases that are never geometric values themselves (`np.random.normal` is not a normal).
MODULE_LIKE = frozenset({"np", "numpy", "math", "random", "torch", "scipy", "stats", "tf", "jnp", "cp", "os", "sys"})
DIRECTION_ATTRIBUTES = frozenset({"normals", "vertex_normals", "face_normals", "normal"})
POINT_ATTRIBUTES = frozenset({"vertices", "points", "centroid", "origin", "position"})
# Calls that return their first argument's value, reshaped or copied.
PASSTHROUGH_FUNCTIONS = frozenset(
    {"asarray", "array", "copy", "asanyarray", "ascontiguousarray", "atleast_1d", "atleast_2d", "squeeze", "float64", "float32"}
)
PASSTHROUGH_METHODS = frozenset({"copy", "astype", "reshape", "squeeze", "flatten", "ravel"})
# Calls that return a unit vector.
UNIT_FUNCTIONS = frozenset({"unitize", "normalize", "normalized", "unit_vector", "norm_vector", "normalize_vector"})
INVERSE_FUNCTIONS = frozenset({"inv", "invert_transform", "inverse_transform", "invert", "pinv"})
INVERSE_METHODS = frozenset({"inv", "inverse", "Inverse", "inverted", "inverse_transform"})
NUMPY_PREFIXES = ("np.", "numpy.")


@dataclass(frozen=True)
class Homogeneous:
    """A homogeneous 4-vector (or N x 4 array) built from `inner` with the constant `w`.

    `construction` is the expression that builds it and `fixed` the same expression with the
    other w (0 <-> 1), ready to be a fix's replacement.
    """

    inner: cst.BaseExpression
    w: int
    construction: cst.BaseExpression
    fixed: cst.BaseExpression
    # False when only the use can tell a homogeneous w from a padded coordinate
    # (`np.column_stack((xy, np.zeros(n)))` lifts 2D points to z = 0).
    explicit: bool = True


@dataclass(frozen=True)
class MatMul:
    """An application or composition `left @ right` in any spelling (`@`, `.dot`, `np.dot`, `np.matmul`)."""

    node: cst.BaseExpression
    left: cst.BaseExpression
    right: cst.BaseExpression


def dotted_name(node: cst.CSTNode) -> str | None:
    """`np.linalg.norm` for the expression `np.linalg.norm`, None for anything not a plain dotted name."""
    if isinstance(node, cst.Name):
        return node.value
    if isinstance(node, cst.Attribute):
        base = dotted_name(node.value)
        return None if base is None else f"{base}.{node.attr.value}"
    return None


def last_name(node: cst.CSTNode) -> str | None:
    """The last component of a dotted name (`norm` for `np.linalg.norm`)."""
    if isinstance(node, cst.Name):
        return node.value
    if isinstance(node, cst.Attribute):
        return node.attr.value
    return None


def int_literal(node: cst.CSTNode) -> int | float | None:
    """The value of a numeric literal (with an optional unary minus), else None."""
    if isinstance(node, cst.UnaryOperation) and isinstance(node.operator, cst.Minus):
        inner = int_literal(node.expression)
        return None if inner is None else -inner
    if isinstance(node, cst.Integer):
        return int(node.evaluated_value)
    if isinstance(node, cst.Float):
        return float(node.evaluated_value)
    return None


def slice_parts(node: cst.Subscript) -> list[cst.BaseSlice]:
    return [element.slice for element in node.slice]


def is_slice_upto(part: cst.BaseSlice, stop: int) -> bool:
    """`:3` or `0:3` (with no step)."""
    if not isinstance(part, cst.Slice) or part.step is not None:
        return False
    if part.lower is not None and int_literal(part.lower) != 0:
        return False
    return part.upper is not None and int_literal(part.upper) == stop


def is_index(part: cst.BaseSlice, *values: int) -> bool:
    return isinstance(part, cst.Index) and int_literal(part.value) in values


def is_full_slice(part: cst.BaseSlice) -> bool:
    return isinstance(part, cst.Slice) and part.lower is None and part.upper is None and part.step is None


class SemanticModel:
    """Answers what expressions of one module are, under one config. Build with `model_for`."""

    def __init__(self, facts: ModuleFacts, config: Config) -> None:
        self.facts = facts
        self.config = config
        self._memo: dict[tuple[str, cst.CSTNode], object] = {}
        self._active: set[tuple[str, cst.CSTNode]] = set()

    # -- plumbing ----------------------------------------------------------------------
    def _cached(self, tag: str, node: cst.CSTNode, compute: Callable[[], _T]) -> _T | None:
        key = (tag, node)
        if key in self._memo:
            return self._memo[key]  # type: ignore[return-value]
        if key in self._active or len(self._active) > 60:
            return None  # a cycle (`x = x + v`) or runaway depth: no evidence
        self._active.add(key)
        try:
            value = compute()
        finally:
            self._active.discard(key)
        self._memo[key] = value
        return value

    def parent(self, node: cst.CSTNode) -> cst.CSTNode | None:
        return self.facts.parent(node)

    def bindings(self, name: cst.Name) -> list[Binding] | None:
        return self.facts.lookup(name.value, self.facts.scope_of(name))

    def qualified_name(self, node: cst.CSTNode) -> str | None:
        """The dotted name with its first component resolved through the module's imports."""
        dotted = dotted_name(node)
        if dotted is None:
            return None
        head, _, rest = dotted.partition(".")
        resolved = self.facts.imports.get(head)
        if resolved is None:
            return dotted
        return f"{resolved}.{rest}" if rest else resolved

    def is_numpy(self, func: cst.CSTNode, *names: str) -> bool:
        """Whether `func` is `numpy.<one of names>` (through `np`, `numpy` or an import)."""
        qualified = self.qualified_name(func)
        if qualified is None:
            return False
        if qualified.startswith("numpy."):
            return qualified[len("numpy.") :] in names
        dotted = dotted_name(func) or ""
        return dotted.startswith(NUMPY_PREFIXES) and dotted.split(".", 1)[1] in names

    def is_module_like(self, node: cst.CSTNode) -> bool:
        """`np`, `np.linalg`, `scipy.spatial`: a (dotted) module name, never a value."""
        if isinstance(node, cst.Attribute):
            return self.is_module_like(node.value) and node.attr.value not in ("T",)
        return isinstance(node, cst.Name) and (node.value in MODULE_LIKE or node.value in self.facts.imported_modules)

    def is_norm_call(self, node: cst.CSTNode) -> bool:
        """`np.linalg.norm(x, ...)`, `norm(x)`, possibly indexed (`[:, None]`)."""
        if isinstance(node, cst.Subscript):
            node = node.value
        return isinstance(node, cst.Call) and last_name(node.func) in {"norm", "vector_norm"}

    def expects_failure(self, node: cst.CSTNode) -> bool:
        """Whether `node` is inside `with pytest.raises(...)` / `self.assertRaises(...)`."""
        current = self.parent(node)
        while current is not None:
            if isinstance(current, cst.With):
                for item in current.items:
                    call = item.item
                    if isinstance(call, cst.Call) and last_name(call.func) in ("raises", "assertRaises", "assertRaisesRegex"):
                        return True
            current = self.parent(current)
        return False

    # -- matrix products -----------------------------------------------------------------
    def matmul(self, node: cst.CSTNode) -> MatMul | None:
        """`a @ b`, `a.dot(b)`, `np.dot(a, b)`, `np.matmul(a, b)` as (left, right); else None."""
        if isinstance(node, cst.BinaryOperation) and isinstance(node.operator, cst.MatrixMultiply):
            return MatMul(node, node.left, node.right)
        if isinstance(node, cst.Call):
            positional = [arg.value for arg in node.args if arg.keyword is None and not arg.star]
            if isinstance(node.func, cst.Attribute) and node.func.attr.value == "dot" and len(positional) == 1:
                if not self.is_module_like(node.func.value):
                    return MatMul(node, node.func.value, positional[0])
            if len(positional) == 2 and len(node.args) == 2 and self.is_numpy(node.func, "dot", "matmul"):
                return MatMul(node, positional[0], positional[1])
        return None

    # -- kind ----------------------------------------------------------------------------
    def kind_of(self, node: cst.CSTNode) -> Kind | None:
        """The geometric kind of an expression, or None."""
        return self._cached("kind", node, lambda: self._kind(node))

    def _kind(self, node: cst.CSTNode) -> Kind | None:
        if isinstance(node, cst.Name):
            return self._kind_of_variable(node)
        if isinstance(node, cst.Attribute):
            if self.is_module_like(node.value):
                return None
            attr = node.attr.value
            if attr == "T":
                return self.kind_of(node.value)
            if attr in DIRECTION_ATTRIBUTES:
                return Kind.DIRECTION
            if attr in POINT_ATTRIBUTES:
                return Kind.POINT
            return kind_of_name(attr, self.config)
        if isinstance(node, cst.Subscript):
            base = self.kind_of(node.value)
            if base in (Kind.POINT, Kind.DIRECTION):
                return base
            if base == Kind.TRANSFORM and self.rotation_block_of(node) is not None:
                return Kind.ROTATION
            return None
        if isinstance(node, cst.UnaryOperation) and isinstance(node.operator, cst.Minus):
            kind = self.kind_of(node.expression)
            return kind if kind == Kind.DIRECTION else None
        if isinstance(node, cst.BinaryOperation):
            return self._kind_of_binary(node)
        if isinstance(node, cst.Call):
            return self._kind_of_call(node)
        return None

    def _kind_of_binary(self, node: cst.BinaryOperation) -> Kind | None:
        operator = node.operator
        if isinstance(operator, (cst.MatrixMultiply,)):
            return self._kind_of_product(node)
        left, right = self.kind_of(node.left), self.kind_of(node.right)
        if isinstance(operator, cst.Divide):
            if self.is_norm_call(node.right):
                return Kind.DIRECTION
            return Kind.DIRECTION if left == Kind.DIRECTION and right is None else None
        if isinstance(operator, cst.Multiply):
            if left == Kind.DIRECTION and right is None and not self._is_operator_expr(node.right):
                return Kind.DIRECTION
            if right == Kind.DIRECTION and left is None and not self._is_operator_expr(node.left):
                return Kind.DIRECTION
            return None
        if isinstance(operator, cst.Subtract):
            if left == Kind.POINT and right == Kind.POINT:
                return Kind.DIRECTION
            if left == Kind.POINT and right == Kind.DIRECTION:
                return Kind.POINT
            if left == Kind.DIRECTION and right == Kind.DIRECTION:
                return Kind.DIRECTION
            return None
        if isinstance(operator, cst.Add):
            pair = {left, right}
            if pair == {Kind.POINT, Kind.DIRECTION}:
                return Kind.POINT
            if pair == {Kind.DIRECTION}:
                return Kind.DIRECTION
        return None

    def _is_operator_expr(self, node: cst.CSTNode) -> bool:
        return self.kind_of(node) in (Kind.TRANSFORM, Kind.ROTATION)

    def _kind_of_product(self, node: cst.CSTNode) -> Kind | None:
        product = self.matmul(node)
        if product is None:
            return None
        left, right = self.kind_of(product.left), self.kind_of(product.right)
        if left in (Kind.TRANSFORM, Kind.ROTATION) and right in (Kind.TRANSFORM, Kind.ROTATION):
            return Kind.ROTATION if left == right == Kind.ROTATION else Kind.TRANSFORM
        # A rotation keeps a value's kind; `R @ n`, `n @ R.T`.
        if left == Kind.ROTATION and right in (Kind.POINT, Kind.DIRECTION):
            return right
        if right == Kind.ROTATION and left in (Kind.POINT, Kind.DIRECTION):
            return left
        return None

    def _kind_of_call(self, node: cst.Call) -> Kind | None:
        func = node.func
        positional = [arg.value for arg in node.args if arg.keyword is None and not arg.star]
        if self.is_numpy(func, "cross") or (isinstance(func, cst.Name) and func.value == "cross"):
            return Kind.DIRECTION
        name = last_name(func)
        if name in UNIT_FUNCTIONS:
            return Kind.DIRECTION
        if self.matmul(node) is not None:
            return self._kind_of_product(node)
        if positional and self.is_numpy(func, *PASSTHROUGH_FUNCTIONS):
            return self.kind_of(positional[0])
        if isinstance(func, cst.Attribute) and func.attr.value in PASSTHROUGH_METHODS:
            if not self.is_module_like(func.value):
                return self.kind_of(func.value)
        if isinstance(func, cst.Attribute) and func.attr.value in INVERSE_METHODS:
            kind = self.kind_of(func.value)
            return kind if kind in (Kind.TRANSFORM, Kind.ROTATION) else None
        if name in INVERSE_FUNCTIONS and positional:
            kind = self.kind_of(positional[0])
            return kind if kind in (Kind.TRANSFORM, Kind.ROTATION) else None
        if isinstance(func, cst.Name) and func.value in self.facts.functions:
            return self._kind_of_helper(self.facts.functions[func.value])
        return None

    def _kind_of_helper(self, function: cst.FunctionDef) -> Kind | None:
        """A module-level helper's kind when every `return` has the same kind."""
        scope = self.facts.scopes.get(function)
        if scope is None or not scope.returns:
            return None
        kinds = {self.kind_of(value) for value in scope.returns}
        return kinds.pop() if len(kinds) == 1 else None

    def _kind_of_variable(self, name: cst.Name) -> Kind | None:
        stated = kind_of_name(name.value, self.config)
        bindings = self.bindings(name) or []
        flowed: set[Kind | None] = set()
        for binding in bindings:
            if self._is_non_geometric(binding):
                return None  # `direction = "left"`, `velocity = distance / dt`, `axis=0`
            flowed.add(self._kind_of_binding(binding))
        if stated is not None:
            return None if any(kind not in (None, stated) for kind in flowed) else stated
        if len(flowed) == 1:
            return flowed.pop()
        return None

    def _kind_of_binding(self, binding: Binding) -> Kind | None:
        if isinstance(binding, cst.BaseExpression):
            return self.kind_of(binding)
        if isinstance(binding, LoopBinding):
            iterable = binding.iterable
            if binding.position is None:
                return self._element_kind(iterable)
            if isinstance(iterable, cst.Call) and isinstance(iterable.func, cst.Name):
                args = [arg.value for arg in iterable.args if arg.keyword is None]
                if iterable.func.value == "enumerate" and binding.position == 1 and args:
                    return self._element_kind(args[0])
                if iterable.func.value == "zip" and binding.position < len(args):
                    return self._element_kind(args[binding.position])
        return None

    def _element_kind(self, iterable: cst.BaseExpression) -> Kind | None:
        kind = self.kind_of(iterable)
        return kind if kind in (Kind.POINT, Kind.DIRECTION) else None

    def _is_non_geometric(self, binding: Binding) -> bool:
        """Evidence that a binding holds a scalar, a string or a flag, never a 3-vector."""
        if isinstance(binding, ParamBinding):
            param = binding.param
            if param.default is not None and self._is_non_geometric(param.default):
                return True
            annotation = param.annotation.annotation if param.annotation is not None else None
            return annotation is not None and _is_scalar_annotation(annotation)
        if not isinstance(binding, cst.BaseExpression):
            return False
        if isinstance(
            binding,
            (cst.SimpleString, cst.ConcatenatedString, cst.FormattedString, cst.Integer, cst.Float,
             cst.Imaginary, cst.Comparison, cst.BooleanOperation, cst.Dict, cst.Lambda),
        ):  # fmt: skip
            return True
        if isinstance(binding, cst.Name) and binding.value in ("True", "False"):
            return True
        if isinstance(binding, cst.UnaryOperation):
            return isinstance(binding.operator, cst.Not) or self._is_non_geometric(binding.expression)
        if isinstance(binding, cst.Call):
            name = last_name(binding.func)
            qualified = self.qualified_name(binding.func) or ""
            if name in ("len", "int", "float", "str", "bool", "range", "round", "abs", "sum", "max", "min"):
                return isinstance(binding.func, cst.Name)
            return ".random." in f".{qualified}." or qualified.startswith("random.")
        if isinstance(binding, cst.BinaryOperation) and isinstance(
            binding.operator, (cst.Divide, cst.Multiply, cst.FloorDivide, cst.Modulo, cst.Power)
        ):
            # `velocity = distance / dt`: a ratio of two things that are not geometry.
            if isinstance(binding.left, (cst.List, cst.Tuple)) or isinstance(binding.right, (cst.List, cst.Tuple)):
                return False
            return (
                self.kind_of(binding.left) is None
                and self.kind_of(binding.right) is None
                and not self._may_be_array(binding.left)
                and not self._may_be_array(binding.right)
            )
        return False

    def _may_be_array(self, node: cst.CSTNode) -> bool:
        """Whether an expression visibly builds an array (a numpy call, a subscript, a product)."""
        if isinstance(node, cst.Call):
            dotted = self.qualified_name(node.func) or ""
            return dotted.startswith(("numpy.", "np.")) or isinstance(node.func, cst.Attribute)
        if isinstance(node, (cst.Subscript, cst.List, cst.Tuple)):
            return True
        if isinstance(node, cst.BinaryOperation):
            return self._may_be_array(node.left) or self._may_be_array(node.right)
        return False

    # -- transforms -----------------------------------------------------------------------
    def rotation_block_of(self, node: cst.CSTNode) -> cst.BaseExpression | None:
        """For `M[:3, :3]`, the matrix M; else None."""
        if isinstance(node, cst.Subscript):
            parts = slice_parts(node)
            if len(parts) == 2 and is_slice_upto(parts[0], 3) and is_slice_upto(parts[1], 3):
                return node.value
        return None

    def translation_of(self, node: cst.CSTNode) -> cst.BaseExpression | None:
        """For `M[:3, 3]` (or `M[:3, -1]`, `M[0:3, 3]`), the matrix M; else None."""
        if isinstance(node, cst.Subscript):
            parts = slice_parts(node)
            if len(parts) == 2 and is_slice_upto(parts[0], 3) and is_index(parts[1], 3, -1):
                return node.value
        return None

    def is_translation_like(self, node: cst.CSTNode) -> bool:
        """`t`, `trans`, `translation`, `t_world_cam`, `T[:3, 3]`, `pose.translation`, `tvec`."""
        if self.translation_of(node) is not None:
            return True
        word = last_name(node)
        if word is None:
            return False
        if isinstance(node, cst.Attribute) and word in ("translation", "t", "trans", "p"):
            return not self.is_module_like(node.value)
        if not isinstance(node, cst.Name):
            return False
        first = node.value.strip("_").split("_")[0].lower()
        return first in ("t", "trans", "translation", "tvec", "tran")

    def has_geometric_evidence(self, node: cst.CSTNode) -> bool:
        """Whether a point-like expression is visibly geometric (not a file offset, a cursor
        position or a tuple): a strong or frame-stating name, a mesh attribute, or numpy flow."""
        return bool(self._cached("evidence", node, lambda: self._evidence(node)))

    def _evidence(self, node: cst.CSTNode) -> bool:
        if isinstance(node, cst.Name):
            if states_geometry(node.value, self.config):
                return True
            return any(
                isinstance(binding, cst.BaseExpression) and self.has_geometric_evidence(binding)
                for binding in self.bindings(node) or []
            )
        if isinstance(node, cst.Attribute):
            if node.attr.value == "T":
                return self.has_geometric_evidence(node.value)
            return node.attr.value in ("vertices", "centroid", "vertex_normals", "face_normals") or states_geometry(
                node.attr.value, self.config
            )
        if isinstance(node, cst.Subscript):
            return self.has_geometric_evidence(node.value)
        if isinstance(node, cst.Call):
            qualified = self.qualified_name(node.func) or ""
            return qualified.startswith(("numpy.", "np.")) or self.matmul(node) is not None
        if isinstance(node, cst.BinaryOperation):
            if isinstance(node.operator, cst.MatrixMultiply):
                return True
            return self.has_geometric_evidence(node.left) or self.has_geometric_evidence(node.right)
        return False

    # -- library transforms -----------------------------------------------------------------
    def translating_library_object(self, node: cst.CSTNode) -> str | None:
        """"PyKDL.Frame" or "spatialmath.SE3" when `node` is one (built directly, through a
        variable, or returned by a helper of this module): `*` with them translates vectors."""
        return self._cached("library", node, lambda: self._library_object(node))

    def _library_object(self, node: cst.CSTNode) -> str | None:
        if isinstance(node, cst.Name):
            bindings = self.bindings(node) or []
            found = {self.translating_library_object(b) for b in bindings if isinstance(b, cst.BaseExpression)}
            return found.pop() if len(found) == 1 and len(bindings) == len([b for b in bindings if isinstance(b, cst.BaseExpression)]) else None
        if isinstance(node, cst.BinaryOperation) and isinstance(node.operator, cst.Multiply):
            left, right = self.translating_library_object(node.left), self.translating_library_object(node.right)
            return left if left is not None and left == right else None  # SE3 * SE3 is an SE3
        if not isinstance(node, cst.Call):
            return None
        qualified = self.qualified_name(node.func) or ""
        parts = qualified.split(".")
        if parts[-1] == "Frame" and (parts[0] in ("PyKDL", "kdl") or "PyKDL" in parts):
            return "PyKDL.Frame"
        if "SE3" in parts and (parts[0] == "spatialmath" or parts[0] == "SE3") and parts[-1] not in ("inv",):
            return "spatialmath.SE3"
        if isinstance(node.func, cst.Name) and node.func.value in self.facts.functions:
            scope = self.facts.scopes.get(self.facts.functions[node.func.value])
            if scope is not None and scope.returns:
                found = {self.translating_library_object(value) for value in scope.returns}
                return found.pop() if len(found) == 1 else None
        return None

    # -- frames ---------------------------------------------------------------------------
    def frames_of(self, node: cst.CSTNode) -> NameFrames | None:
        """The frames of an expression (operator: dst/src; value: frame), or None."""
        return self._cached("frames", node, lambda: self._frames(node))

    def _frames(self, node: cst.CSTNode) -> NameFrames | None:
        if isinstance(node, cst.Name):
            stated = frames_of_name(node.value, self.config)
            if stated is not None:
                return stated
            readings = set()
            for binding in self.bindings(node) or []:
                if not isinstance(binding, cst.BaseExpression):
                    return None
                readings.add(self.frames_of(binding))
            return readings.pop() if len(readings) == 1 else None
        if isinstance(node, cst.Attribute):
            if node.attr.value == "T":
                inner = self.frames_of(node.value)
                return inner.inverted() if inner is not None and inner.is_operator else inner
            if self.is_module_like(node.value):
                return None
            return frames_of_name(node.attr.value, self.config)
        if isinstance(node, cst.Subscript):
            inner = self.frames_of(node.value)
            if inner is None:
                return None
            if inner.is_operator:
                if self.rotation_block_of(node) is not None:
                    return NameFrames(dst=inner.dst, src=inner.src, operator="rotation")
                if self.translation_of(node) is not None:
                    return NameFrames(frame=inner.dst)  # the src origin, measured in dst
                return None
            return inner
        if isinstance(node, cst.UnaryOperation) and isinstance(node.operator, cst.Minus):
            inner = self.frames_of(node.expression)
            return inner if inner is not None and not inner.is_operator else None
        if isinstance(node, cst.Call):
            return self._frames_of_call(node)
        if isinstance(node, cst.BinaryOperation):
            if isinstance(node.operator, (cst.Add, cst.Subtract)):
                left, right = self.frames_of(node.left), self.frames_of(node.right)
                if left is not None and not left.is_operator and (right is None or right == left):
                    return left
                if right is not None and not right.is_operator and left is None:
                    return right
                return None
            if isinstance(node.operator, cst.MatrixMultiply):
                return self._frames_of_product(node.left, node.right)
            if isinstance(node.operator, cst.Multiply):
                left = self.frames_of(node.left)
                if left is not None and left.is_operator and left.operator == "transform":
                    return self._frames_of_product(node.left, node.right)
        return None

    def _frames_of_call(self, node: cst.Call) -> NameFrames | None:
        homogeneous = self.homogeneous(node)
        if homogeneous is not None:  # [x, 1] lives where x lives
            inner = self.frames_of(homogeneous.inner)
            return inner if inner is not None and not inner.is_operator else None
        func = node.func
        positional = [arg.value for arg in node.args if arg.keyword is None and not arg.star]
        product = self.matmul(node)
        if product is not None:
            return self._frames_of_product(product.left, product.right)
        if isinstance(func, cst.Attribute) and func.attr.value in INVERSE_METHODS and not self.is_module_like(func.value):
            inner = self.frames_of(func.value)
            return inner.inverted() if inner is not None and inner.is_operator else None
        if last_name(func) in INVERSE_FUNCTIONS and len(positional) == 1:
            inner = self.frames_of(positional[0])
            return inner.inverted() if inner is not None and inner.is_operator else None
        if positional and self.is_numpy(func, *PASSTHROUGH_FUNCTIONS):
            return self.frames_of(positional[0])
        if isinstance(func, cst.Attribute) and func.attr.value in PASSTHROUGH_METHODS and not self.is_module_like(func.value):
            return self.frames_of(func.value)
        return None

    def _frames_of_product(self, left_node: cst.CSTNode, right_node: cst.CSTNode) -> NameFrames | None:
        left, right = self.frames_of(left_node), self.frames_of(right_node)
        if left is None or right is None:
            return None
        if left.is_operator and right.is_operator:
            if same_frame(left.src, right.dst) is True:
                operator = "rotation" if left.operator == right.operator == "rotation" else "transform"
                return NameFrames(dst=left.dst, src=right.src, operator=operator)
            return None
        if left.is_operator and right.frame is not None:
            return NameFrames(frame=left.dst)
        if right.is_operator and left.frame is not None:
            return NameFrames(frame=right.src)  # row vectors: `x @ M` applies M.T
        return None

    # -- homogeneous coordinates ------------------------------------------------------------
    def homogeneous(self, node: cst.CSTNode) -> Homogeneous | None:
        """The homogeneous construction `node` is (directly, or through a variable), or None."""
        return self._cached("homog", node, lambda: self._homogeneous(node))

    def homogeneous_built_by(self, node: cst.CSTNode) -> Homogeneous | None:
        """The homogeneous value whose construction is exactly `node` (including a
        `np.ones(4)` buffer that is filled later), or None."""
        found = self.homogeneous(node)
        if found is None and isinstance(node, cst.Call):
            assign = self.parent(node)
            if isinstance(assign, cst.Assign) and len(assign.targets) == 1 and isinstance(assign.targets[0].target, cst.Name):
                found = self.homogeneous(assign.targets[0].target)
        return found if found is not None and found.construction is node else None

    def _homogeneous(self, node: cst.CSTNode) -> Homogeneous | None:
        if isinstance(node, cst.Name):
            bindings = self.bindings(node) or []
            if len(bindings) != 1 or not isinstance(bindings[0], cst.BaseExpression):
                return None
            direct = self.homogeneous(bindings[0])
            if direct is not None:
                return direct
            return self._filled_buffer(node, bindings[0])
        if isinstance(node, cst.Call):
            return self._homogeneous_call(node)
        if isinstance(node, cst.Subscript) and self.is_numpy(node.value, "r_", "c_"):
            elements = [element.slice for element in node.slice]
            if len(elements) == 2 and all(isinstance(part, cst.Index) for part in elements):
                inner, w_node = elements[0].value, elements[1].value  # type: ignore[union-attr]
                return self._with_w(node, inner, w_node, explicit=False)
        return None

    def _homogeneous_call(self, node: cst.Call) -> Homogeneous | None:
        positional = [arg.value for arg in node.args if arg.keyword is None and not arg.star]
        if self.is_numpy(node.func, "append") and len(positional) == 2 and len(node.args) == 2:
            return self._with_w(node, positional[0], positional[1], explicit=False)
        if self.is_numpy(node.func, "hstack", "column_stack", "concatenate") and positional:
            sequence = positional[0]
            if isinstance(sequence, (cst.List, cst.Tuple)) and len(sequence.elements) == 2:
                first, second = (element.value for element in sequence.elements)
                if not isinstance(first, cst.StarredElement):
                    return self._with_w(node, first, second, explicit=False)
        if self.is_numpy(node.func, "array", "asarray") and positional and isinstance(positional[0], cst.List):
            elements = [element.value for element in positional[0].elements]
            if len(elements) == 4:
                base = _components_of_one_array(elements[:3])
                if base is not None:
                    return self._with_w(node, base, elements[3])
        return None

    def _with_w(
        self, construction: cst.BaseExpression, inner: cst.BaseExpression, w_node: cst.BaseExpression, explicit: bool = True
    ) -> Homogeneous | None:
        w, fixed_w = _w_value(self, w_node)
        if w is None or fixed_w is None:
            return None
        fixed = construction.deep_replace(w_node, fixed_w)
        return Homogeneous(inner=inner, w=w, construction=construction, fixed=fixed, explicit=explicit)  # type: ignore[arg-type]

    def used_as_homogeneous(self, homogeneous: Homogeneous) -> bool:
        """Whether a homogeneous construction is visibly used as one: built explicitly as a
        4-vector, multiplied by a matrix (directly or through the variable holding it), or
        stored under a homogeneous name (`p_h`, `points_hom`)."""
        if homogeneous.explicit:
            return True
        node: cst.CSTNode = homogeneous.construction
        parent = self.parent(node)
        while isinstance(parent, cst.Attribute) and parent.attr.value == "T":
            node, parent = parent, self.parent(parent)
        if isinstance(parent, cst.BinaryOperation) and isinstance(parent.operator, cst.MatrixMultiply):
            return True
        if isinstance(parent, cst.Arg):
            call = self.parent(parent)
            if call is not None and self.matmul(call) is not None:
                return True
        if isinstance(parent, cst.Assign) and len(parent.targets) == 1 and isinstance(parent.targets[0].target, cst.Name):
            target = parent.targets[0].target.value
            if set(target.lower().split("_")) & {"h", "hom", "homog", "homogeneous", "homo"}:
                return True
            return target in self.facts.scope_of(parent).matmul_operands
        return False

    def _filled_buffer(self, name: cst.Name, value: cst.BaseExpression) -> Homogeneous | None:
        """`h = np.ones(4); h[:3] = x` (or `np.ones((n, 4)); h[:, :3] = x`): homogeneous x with w = 1."""
        if not isinstance(value, cst.Call) or not self.is_numpy(value.func, "ones", "zeros"):
            return None
        scope = self.facts.scope_of(name)
        stores = scope.subscript_stores.get(name.value, [])
        fills = [stored for target, stored in stores if _is_xyz_slice(target)]
        if len(fills) != 1 or len(stores) != 1:
            return None
        w = 1 if last_name(value.func) == "ones" else 0
        if not isinstance(value.func, (cst.Attribute, cst.Name)):
            return None
        fixed_func = _swap_ones_zeros(value.func)
        return Homogeneous(inner=fills[0], w=w, construction=value, fixed=value.with_changes(func=fixed_func))


def _is_xyz_slice(target: cst.Subscript) -> bool:
    parts = slice_parts(target)
    if len(parts) == 1:
        return is_slice_upto(parts[0], 3)
    return len(parts) == 2 and is_full_slice(parts[0]) and is_slice_upto(parts[1], 3)


def _swap_ones_zeros(func: cst.Attribute | cst.Name) -> cst.Attribute | cst.Name:
    swap = {"ones": "zeros", "zeros": "ones", "ones_like": "zeros_like", "zeros_like": "ones_like"}
    if isinstance(func, cst.Attribute):
        return func.with_changes(attr=cst.Name(swap[func.attr.value]))
    return func.with_changes(value=swap[func.value])


def _w_value(model: SemanticModel, node: cst.BaseExpression) -> tuple[int | None, cst.BaseExpression | None]:
    """The constant w a homogeneous construction appends, and the node with the other w."""
    literal = int_literal(node)
    if literal in (0, 1) and isinstance(node, (cst.Integer, cst.Float)):
        other = 1 - int(literal)
        replacement = cst.Integer(str(other)) if isinstance(node, cst.Integer) else cst.Float(f"{other}.0")
        return int(literal), replacement
    if isinstance(node, (cst.List, cst.Tuple)) and len(node.elements) == 1:
        inner = node.elements[0].value
        w, fixed = _w_value(model, inner)
        if w is None or fixed is None:
            return None, None
        return w, node.deep_replace(inner, fixed)  # type: ignore[return-value]
    if isinstance(node, cst.Call) and model.is_numpy(node.func, "ones", "zeros", "ones_like", "zeros_like"):
        assert isinstance(node.func, (cst.Attribute, cst.Name))
        w = 1 if last_name(node.func) in ("ones", "ones_like") else 0
        return w, node.with_changes(func=_swap_ones_zeros(node.func))
    return None, None


def _components_of_one_array(elements: list[cst.BaseExpression]) -> cst.BaseExpression | None:
    """For `[x[0], x[1], x[2]]`, the expression x; else None."""
    bases = []
    for index, element in enumerate(elements):
        if not isinstance(element, cst.Subscript) or len(element.slice) != 1:
            return None
        if not is_index(element.slice[0].slice, index):
            return None
        bases.append(element.value)
    codes = {cst.Module([]).code_for_node(base) for base in bases}
    return bases[0] if len(codes) == 1 else None


def _is_scalar_annotation(annotation: cst.BaseExpression) -> bool:
    text = cst.Module([]).code_for_node(annotation)
    words = {word for word in text.replace("|", " ").replace("[", " ").replace("]", " ").replace(",", " ").split()}
    scalar = {"int", "float", "str", "bool", "SupportsIndex", "None", "Optional", "typing.Optional", "Literal"}
    return bool(words) and words <= scalar | {word for word in words if word.startswith(("'", '"'))}


def model_for(facts: ModuleFacts, config: Config) -> SemanticModel:
    """The one `SemanticModel` of this module under this config (created on first use)."""
    model = facts.views.get(config)
    if model is None:
        model = SemanticModel(facts, config)
        facts.views[config] = model
    return model  # type: ignore[return-value]
