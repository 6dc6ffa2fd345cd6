"""What kind of geometric value an expression is (`algebra.Kind`: point, vector, direction, rotation,
transform), from library semantics, data flow, the kinds `geolint.algebra` gives operations, project
helpers' summaries and names; and the evidence that a point-like value is geometry at all."""

from __future__ import annotations

import ast
from ast import (
    AST, Add, Attribute, BinOp, BoolOp, Call, Compare, Constant, Div, FloorDiv, JoinedStr, Lambda, MatMult,
    Mod, Mult, Name, Not, Pow, Sub, Subscript, USub, UnaryOp,
)  # fmt: skip
from typing import Sequence, TYPE_CHECKING

from geolint import algebra
from geolint.algebra import FREE, Kind
from geolint.factbase import messages
from geolint.factbase import vocabulary as vocab
from geolint.factbase.fact_types import GEOMETRIC, OPERATORS
from geolint.factbase.index import Binding, LoopBinding, ParamBinding, UnpackBinding
from geolint.factbase.kind_summaries import KINDS
from geolint.factbase.library_calls import returned_kind
from geolint.factbase.syntax import components_of_one_array, is_scalar_annotation, last_name, number, positional_args
from geolint.knowledge import knowledge_base
from geolint.knowledge.markers import ArrayOperation
from geolint.semantic.names import kind_of_name, states_geometry

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase


def kind_of(facts: FactBase, node: AST) -> Kind | None:
    """The geometric kind of an expression, or None."""
    return facts.cached("kind", node, _kind)


def is_free(facts: FactBase, node: AST) -> bool:
    """A free vector (direction, normal, velocity...): rotated only, never translated."""
    return kind_of(facts, node) in FREE


def _kind(facts: FactBase, node: AST) -> Kind | None:
    if isinstance(node, Name):
        return _kind_of_variable(facts, node)
    if isinstance(node, Attribute):
        if facts.is_module_like(node.value):
            return None
        attr = node.attr
        if attr in ("T", "mT"):
            return kind_of(facts, node.value)
        if attr in messages.vector_field_names():  # `odometry.twist.twist.linear`: the message type says
            declared = facts.shared(messages.MessageTypes).field_kind(node)
            if declared is not None:
                return declared
        if attr in vocab.DIRECTION_ATTRIBUTES:
            return Kind.DIRECTION
        if attr in vocab.POINT_ATTRIBUTES:
            return Kind.POINT
        returned = facts.summary_of_property(node, KINDS)
        if returned is not None and returned.returns is not None:
            return returned.returns  # `robot.pose`: a `@property` of the project's class
        if isinstance(node.value, Name) and node.value.id == "self":
            flowed = _kind_of_self_attribute(facts, attr)
            if flowed is not None:
                return flowed
        return _name_kind(facts, attr)
    if isinstance(node, Subscript):
        base = kind_of(facts, node.value)
        if base in GEOMETRIC:
            return base
        if base == Kind.TRANSFORM and facts.rotation_block_of(node) is not None:
            return Kind.ROTATION
        return None
    if isinstance(node, UnaryOp) and isinstance(node.op, USub):
        kind = kind_of(facts, node.operand)
        return None if kind is None else valid_kind(algebra.negate(kind))
    if isinstance(node, (ast.List, ast.Tuple)) and _origin_and_axis_tips(node):
        return Kind.POINT
    if isinstance(node, (ast.List, ast.Tuple)) and len(node.elts) == 3:  # `[v.x, v.y, v.z]` is what v is
        whole = components_of_one_array(node.elts)
        return None if whole is None else kind_of(facts, whole)
    if isinstance(node, BinOp):
        return _kind_of_binary(facts, node)
    if isinstance(node, Call):
        return _kind_of_call(facts, node)
    return None


def _name_kind(facts: FactBase, name: str) -> Kind | None:
    return kind_of_name(name, facts.config)


def _kind_of_self_attribute(facts: FactBase, attr: str) -> Kind | None:
    """`self.x`: the kind every `self.x = value` of the module agrees on."""
    stores = facts.index.self_attribute_stores.get(attr)
    if not stores:
        return None
    kinds = {kind_of(facts, value) for value in stores}
    return kinds.pop() if len(kinds) == 1 else None


def _kind_of_binary(facts: FactBase, node: BinOp) -> Kind | None:
    """What `geolint.algebra` makes of the operands' kinds. An operand of no known kind next to one of a
    known kind is read as the scalar of `*` and `/`; a division by a norm normalises."""
    op = node.op
    if isinstance(op, MatMult):
        return _kind_of_product(facts, node)
    left, right = kind_of(facts, node.left), kind_of(facts, node.right)
    if isinstance(op, Div) and facts.is_norm_call(node.right):
        return valid_kind(algebra.normalize(left or Kind.UNKNOWN))
    if isinstance(op, (Mult, Div)):
        if left is not None and right is None:
            return valid_kind(algebra.scale(left))
        if right is not None and left is None and isinstance(op, Mult):
            return valid_kind(algebra.scale(right))
        return None
    if left is None or right is None:
        return None
    if isinstance(op, Sub):
        return valid_kind(algebra.sub(left, right))
    if isinstance(op, Add):
        return valid_kind(algebra.add(left, right))
    return None


def _kind_of_product(facts: FactBase, node: AST) -> Kind | None:
    product = facts.matmul(node)
    if product is None:
        return None
    left, right = kind_of(facts, product.left), kind_of(facts, product.right)
    if left is None or right is None:
        return None
    if left == Kind.TRANSFORM and right not in OPERATORS:
        # a 4x4 matrix reaches homogeneous 4-vectors only (`homogeneous` reads those); the table's
        # `T @ p` is the runtime's Transform, which a kind alone does not tell from a matrix
        return None
    if left in OPERATORS:
        return valid_kind(algebra.apply(left, right))
    return valid_kind(algebra.apply_rows(left, right))


def _kind_of_call(facts: FactBase, node: Call) -> Kind | None:
    func = node.func
    positional = positional_args(node)
    name = last_name(func)
    if facts.is_array_call(func, "cross") or (isinstance(func, Name) and func.id == "cross"):
        return Kind.DIRECTION
    if name in vocab.UNIT_FUNCTIONS:
        return Kind.DIRECTION
    if facts.matmul(node) is not None:
        return _kind_of_product(facts, node)
    if positional and facts.is_array_call(func, *vocab.PASSTHROUGH_FUNCTIONS):
        return kind_of(facts, positional[0])
    tips = positional and isinstance(positional[0], ast.List) and _origin_and_axis_tips(positional[0])
    if tips and facts.is_array_call(func, "array", "asarray", "tensor", "as_tensor"):
        return Kind.POINT  # `np.array([[0, 0, 0], [l, 0, 0], ...])`: the origin and axis tips
    if isinstance(func, Attribute) and not facts.is_module_like(func.value):
        if func.attr in vocab.PASSTHROUGH_METHODS:
            return kind_of(facts, func.value)
        if func.attr in vocab.INVERSE_METHODS:
            kind = kind_of(facts, func.value)
            return kind if kind in OPERATORS else None
    if name in vocab.INVERSE_FUNCTIONS and positional:
        kind = kind_of(facts, positional[0])
        return kind if kind in OPERATORS else None
    library = returned_kind(facts, node)
    if library is not None:
        return library
    summary = facts.summary_of(node, KINDS)
    return None if summary is None else summary.returns


def _kind_of_variable(facts: FactBase, name: Name) -> Kind | None:
    return facts.of_bindings("variable kind", name, _kind_of_bindings)


def _kind_of_bindings(facts: FactBase, name: str, bindings: Sequence[Binding], order: str = "") -> Kind | None:
    stated = _name_kind(facts, name)
    flowed: set[Kind | None] = set()
    for binding in bindings:
        if is_non_geometric(facts, binding):
            return None  # `direction = "left"`, `velocity = distance / dt`, `axis=0`
        flowed.add(_kind_of_binding(facts, binding))
    if stated is not None:
        # a free vector named as a point (or the reverse) by its own flow: the flow wins
        known = {kind for kind in flowed if kind is not None}
        if known and known != {stated} and not (known <= FREE and stated in FREE):
            return None
        return stated
    if len(flowed) == 1:
        return flowed.pop()
    if None not in flowed and flowed and flowed <= FREE:
        return Kind.VECTOR
    return None


def _kind_of_binding(facts: FactBase, binding: Binding) -> Kind | None:
    if isinstance(binding, ast.expr):
        return kind_of(facts, binding)
    if isinstance(binding, LoopBinding):
        iterable = binding.iterable
        if binding.position is None:
            return _element_kind(facts, iterable)
        if isinstance(iterable, Call) and isinstance(iterable.func, Name):
            args = positional_args(iterable)
            if iterable.func.id == "enumerate" and binding.position == 1 and args:
                return _element_kind(facts, args[0])
            if iterable.func.id == "zip" and binding.position < len(args):
                return _element_kind(facts, args[binding.position])
    if isinstance(binding, UnpackBinding):
        value = binding.value
        if isinstance(value, (ast.Tuple, ast.List)) and binding.position < len(value.elts):
            return kind_of(facts, value.elts[binding.position])
    return None


def _element_kind(facts: FactBase, iterable: ast.expr) -> Kind | None:
    kind = kind_of(facts, iterable)
    return kind if kind in GEOMETRIC else None


def is_non_geometric(facts: FactBase, binding: Binding) -> bool:
    """Evidence that a binding holds a scalar, a string or a flag, never a 3-vector."""
    if isinstance(binding, ParamBinding):
        if binding.default is not None and is_non_geometric(facts, binding.default):
            return True
        annotation = binding.arg.annotation
        return annotation is not None and is_scalar_annotation(annotation)
    if not isinstance(binding, ast.expr):
        return False
    if isinstance(binding, Constant):
        return binding.value is not None and binding.value is not Ellipsis
    if isinstance(binding, (JoinedStr, Compare, BoolOp, ast.Dict, Lambda)):
        return True
    if isinstance(binding, UnaryOp):
        return isinstance(binding.op, Not) or is_non_geometric(facts, binding.operand)
    if isinstance(binding, Call):
        name = last_name(binding.func)
        qualified = facts.qualified_name(binding.func) or ""
        if name in ("len", "int", "float", "str", "bool", "range", "round", "abs", "sum", "max", "min"):
            return isinstance(binding.func, Name)
        if knowledge_base().array_operation(qualified) == ArrayOperation.FEATURES:
            return True  # a feature map sampled at points, not their coordinates
        return ".random." in f".{qualified}." or qualified.startswith("random.")
    if isinstance(binding, BinOp) and isinstance(binding.op, (Div, Mult, FloorDiv, Mod, Pow)):
        # `velocity = distance / dt`: a ratio of two things that are not geometry
        if isinstance(binding.left, (ast.List, ast.Tuple)) or isinstance(binding.right, (ast.List, ast.Tuple)):
            return False
        return (
            kind_of(facts, binding.left) is None
            and kind_of(facts, binding.right) is None
            and not _may_be_array(facts, binding.left)
            and not _may_be_array(facts, binding.right)
        )
    return False


def _may_be_array(facts: FactBase, node: AST) -> bool:
    """Whether an expression visibly builds an array (an array call, a subscript, a product)."""
    if isinstance(node, Call):
        qualified = facts.qualified_name(node.func) or ""
        return knowledge_base().in_array_library(qualified) or isinstance(node.func, Attribute)
    if isinstance(node, (Subscript, ast.List, ast.Tuple)):
        return True
    if isinstance(node, BinOp):
        return _may_be_array(facts, node.left) or _may_be_array(facts, node.right)
    return False


def has_geometric_evidence(facts: FactBase, node: AST) -> bool:
    """Whether a point-like expression is visibly geometric (not a file offset, a cursor
    position or a tuple): a strong or frame-stating name, a mesh attribute, or array flow."""
    return bool(facts.cached("evidence", node, _evidence))


def _evidence(facts: FactBase, node: AST) -> bool:
    if isinstance(node, Name):
        if states_geometry(node.id, facts.config):
            return True
        return bool(facts.of_bindings("variable evidence", node, _evidence_of_bindings))
    if isinstance(node, Attribute):
        if node.attr in ("T", "mT"):
            return has_geometric_evidence(facts, node.value)
        return node.attr in ("vertices", "centroid", "vertex_normals", "face_normals") or states_geometry(node.attr, facts.config)
    if isinstance(node, Subscript):
        return has_geometric_evidence(facts, node.value)
    if isinstance(node, Call):
        qualified = facts.qualified_name(node.func) or ""
        return knowledge_base().in_array_library(qualified) or facts.matmul(node) is not None
    if isinstance(node, BinOp):
        if isinstance(node.op, MatMult):
            return True
        return has_geometric_evidence(facts, node.left) or has_geometric_evidence(facts, node.right)
    return False


def _evidence_of_bindings(facts: FactBase, name: str, bindings: Sequence[Binding], order: str = "") -> bool:
    return any(isinstance(binding, ast.expr) and has_geometric_evidence(facts, binding) for binding in bindings)


def valid_kind(outcome: algebra.Outcome | None) -> Kind | None:
    """The kind `geolint.algebra` gives an operation that is valid geometry; None for one it does not judge,
    and for an invalid one (`p + q`: a rule reports it, and its result is no evidence of a kind)."""
    return outcome.kind if outcome is not None and outcome.problem is None else None


def _origin_and_axis_tips(node: ast.List | ast.Tuple) -> bool:
    """`[[0, 0, 0], [l, 0, 0], [0, l, 0], [0, 0, l]]`: the origin next to points along the axes (a
    drawn frame's tips). A set of points whatever its name: the origin has no meaning as a direction."""
    rows = node.elts
    if len(rows) < 2 or not all(isinstance(row, (ast.List, ast.Tuple)) for row in rows):
        return False
    if any(len(row.elts) != 3 for row in rows):  # type: ignore[attr-defined]
        return False  # rows of x, y, z (`[[0, a], [0, b], [0, 0]]` holds its points in columns)
    zeros = [sum(number(value) == 0 for value in row.elts) for row in rows]  # type: ignore[attr-defined]
    return zeros.count(3) == 1 and all(count >= 2 for count in zeros)
