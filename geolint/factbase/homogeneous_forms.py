"""Homogeneous coordinates: which constructions append a w to a value (`np.append(x, 1)`,
`np.hstack([x, ones])`, `np.pad`, a 4-element array, a filled `np.ones(4)` buffer, a helper that
returns its parameter made homogeneous), with the text of the construction with the other w, and
whether a construction is used as homogeneous."""

from __future__ import annotations

import ast
from ast import AST, Assign, Attribute, BinOp, Call, Constant, MatMult, Name, Slice, Starred, Subscript
import re
from typing import Final, TYPE_CHECKING

from geolint import algebra
from geolint.factbase import vocabulary as vocab
from geolint.factbase.fact_types import Homogeneous
from geolint.factbase.kind_summaries import HOMOGENEOUS
from geolint.factbase.spans import LastNameTarget, last_name_target, replace_span
from geolint.factbase.syntax import (
    components_of_one_array, flat_literal, is_full_slice, is_slice_upto, is_transpose, keyword, last_name, number,
    positional_args, string, subscript_parts, transposed_value,
)  # fmt: skip
from geolint.knowledge import knowledge_base
from geolint.knowledge.markers import ArrayOperation

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

# Calls that apply a transform to a homogeneous argument (`transform(v)`, `apply_pose`, `np.matmul`).
_TRANSFORM_CALL: Final = re.compile(r"transform|xform|apply|rotat|project|matmul|mul|dot", re.IGNORECASE)

_ARRAY_BUILDERS: Final = ("append", "hstack", "column_stack", "concatenate", "cat", "concat", "array", "asarray", "tensor", "as_tensor", "r_", "c_")

# Array makers `_homogeneous_call` (append, joins, 4-element arrays) and `_filled_buffer` read.
_HOMOGENEOUS_MAKERS: Final = frozenset({"append", *vocab.STACKING_FUNCTIONS, "array", "asarray", "tensor", "as_tensor", "ones", "zeros"})

_SWAP: Final = {"ones": "zeros", "zeros": "ones", "ones_like": "zeros_like", "zeros_like": "ones_like"}


def homogeneous(facts: FactBase, node: AST) -> Homogeneous | None:
    """The homogeneous construction `node` is (directly, or through a variable), or None."""
    return facts.cached("homog", node, _homogeneous)


def homogenized(facts: FactBase, homogeneous: Homogeneous) -> algebra.Outcome | None:
    """What `algebra.homogenize` makes of a construction `[x; w]` from x's kind (None: x's kind is unknown)."""
    kind = facts.kind_of(homogeneous.inner)
    return None if kind is None else algebra.homogenize(kind, homogeneous.w)


def homogeneous_built_by(facts: FactBase, node: AST) -> Homogeneous | None:
    """The homogeneous value whose construction is exactly `node` (including an `np.ones(4)`
    buffer filled later), or None."""
    return facts.cached("built", node, _homogeneous_built_by)


def _homogeneous_built_by(facts: FactBase, node: AST) -> Homogeneous | None:
    if not _may_build_homogeneous(facts, node):
        return None
    found = homogeneous(facts, node)
    if found is None and isinstance(node, Call):
        assign = facts.parent(node)
        if isinstance(assign, Assign) and len(assign.targets) == 1 and isinstance(assign.targets[0], Name):
            found = homogeneous(facts, assign.targets[0])
    return found if found is not None and found.construction is node else None


def _may_build_homogeneous(facts: FactBase, node: AST) -> bool:
    """False when `node` certainly builds no homogeneous value: a call that is none of the array
    makers `_homogeneous_call` and `_filled_buffer` know and cannot reach a helper's summary (it
    feeds no product), a subscript other than `np.r_`/`np.c_`. Rules ask this of every call and
    subscript of a module, so it is decided before any fact is looked up."""
    kind = type(node)
    if kind is Subscript:
        return facts.is_array_call(node.value, "r_", "c_")  # type: ignore[attr-defined]
    if kind is not Call:
        return True
    func = node.func  # type: ignore[attr-defined]
    if facts.called_name(func) in _HOMOGENEOUS_MAKERS:
        qualified = facts.qualified_name(func)
        if qualified is not None:
            module, _, name = qualified.rpartition(".")
            if name in _HOMOGENEOUS_MAKERS and knowledge_base().is_namespace_module(module):
                return True
    return type(func) in (Name, Attribute) and _feeds_a_product(facts, node)


def _homogeneous(facts: FactBase, node: AST) -> Homogeneous | None:
    if isinstance(node, Name):
        bindings = facts.bindings(node) or []
        if len(bindings) != 1 or not isinstance(bindings[0], ast.expr):
            return None
        direct = homogeneous(facts, bindings[0])
        if direct is not None:
            return direct
        return _filled_buffer(facts, node, bindings[0])
    if isinstance(node, Call):
        return _homogeneous_call(facts, node)
    if isinstance(node, Subscript) and facts.is_array_call(node.value, "r_", "c_"):
        index = node.slice
        if isinstance(index, ast.Tuple) and len(index.elts) == 2 and not any(isinstance(e, Slice) for e in index.elts):
            return _with_w(facts, node, index.elts[0], index.elts[1], explicit=False)
    return None


def _homogeneous_call(facts: FactBase, node: Call) -> Homogeneous | None:
    positional = positional_args(node)
    if facts.called_name(node.func) == "pad":
        return _padded_with_w(facts, node, positional)
    if facts.is_array_call(node.func, "append") and len(positional) == 2 and len(node.args) == 2:
        return _with_w(facts, node, positional[0], positional[1], explicit=False)
    if facts.is_array_call(node.func, *vocab.STACKING_FUNCTIONS) and positional:
        sequence = positional[0]
        if isinstance(sequence, (ast.List, ast.Tuple)) and len(sequence.elts) == 2:
            first, second = sequence.elts
            if not isinstance(first, Starred) and _last_axis(facts, node):
                return _with_w(facts, node, first, second, explicit=False)
    if facts.is_array_call(node.func, "array", "asarray", "tensor", "as_tensor") and positional and isinstance(positional[0], ast.List):
        elements = positional[0].elts
        if len(elements) == 4:
            base = components_of_one_array(elements[:3])
            if base is not None:
                return _with_w(facts, node, base, elements[3])
    if (
        isinstance(node.func, (Name, Attribute))
        and _feeds_a_product(facts, node)  # only then is a helper's w worth looking up
        and not facts.is_array_call(node.func, *_ARRAY_BUILDERS)
    ):
        summary = facts.summary_of(node, HOMOGENEOUS)
        if summary is not None and summary.homogenizes:
            index, w = next(iter(summary.homogenizes.items()))
            if index < len(positional):  # `to_homogeneous(normals)`: the helper appends w
                return Homogeneous(inner=positional[index], w=w, construction=node, fixed=None, explicit=True)
    return None


def _feeds_a_product(facts: FactBase, node: AST) -> bool:
    """Whether a value is a matrix product's operand, directly (through `.T`) or through the
    name it is assigned to, or is stored under a homogeneous name (`p_h`)."""
    parent = facts.parent(node)
    while parent is not None and transposed_value(parent) is node:
        node, parent = parent, facts.parent(parent)
    if isinstance(parent, BinOp) and isinstance(parent.op, MatMult):
        return True
    if isinstance(parent, Call) and facts.matmul(parent) is not None:
        return True
    return _stored_for_a_product(facts, parent)


def _stored_for_a_product(facts: FactBase, parent: AST | None) -> bool:
    """Whether `parent` assigns a value to one name that says it is homogeneous (`p_h`) or that
    its scope later uses as a matrix product's operand."""
    if not (isinstance(parent, Assign) and len(parent.targets) == 1 and isinstance(parent.targets[0], Name)):
        return False
    target = parent.targets[0].id
    if set(target.lower().split("_")) & {"h", "hom", "homog", "homogeneous", "homo"}:
        return True
    return target in facts.index.scope_of(parent).matmul_operands


def _last_axis(facts: FactBase, call: Call) -> bool:
    """Whether a concatenation joins along the last axis (`axis=-1`/`dim=-1`/`axis=1`, or hstack/column_stack)."""
    name = last_name(call.func)
    if name in ("hstack", "column_stack"):
        return True
    axis = keyword(call, "axis") or keyword(call, "dim")
    positional = positional_args(call)
    value = axis.value if axis is not None else (positional[1] if len(positional) > 1 else None)
    if value is None:
        return name == "append"
    return number(value) in (-1, 1)


def _with_w(facts: FactBase, construction: ast.expr, inner: ast.expr, w_node: ast.expr, explicit: bool = True) -> Homogeneous | None:
    w, fixed_w = _w_value(facts, w_node)
    if w is None or fixed_w is None:
        return None
    fixed = replace_span(facts.index, construction, fixed_w)  # None when w is set outside the span
    return Homogeneous(inner=inner, w=w, construction=construction, fixed=fixed, explicit=explicit)


def _padded_with_w(facts: FactBase, node: Call, positional: list[ast.expr]) -> Homogeneous | None:
    """`F.pad(x, (0, 1), value=1.0)` (torch) or `np.pad(x, ((0, 0), (0, 1)), constant_values=1)`: x with
    one constant appended along its last axis, 0 unless a value is given (both libraries' default)."""
    if len(positional) < 2 or len(positional) != len(node.args):
        return None
    qualified = facts.qualified_name(node.func)
    widths = [number(width) for width in flat_literal(positional[1])]
    operation = knowledge_base().array_operation(qualified) if qualified is not None else None
    if operation == ArrayOperation.PAD_LAST_AXIS_FIRST:
        appends_one = len(widths) >= 2 and widths[:2] == [0, 1] and not any(widths[2:])
        mode: ast.expr | None = positional[2] if len(positional) > 2 else None
        value: ast.expr | None = positional[3] if len(positional) > 3 else None
        value_word = "value"
    elif operation == ArrayOperation.PAD_PER_AXIS:  # a bare `(0, 1)` pads every axis
        pairs = positional[1].elts if isinstance(positional[1], (ast.Tuple, ast.List)) else []
        appends_one = len(pairs) >= 2 and all(isinstance(pair, (ast.Tuple, ast.List)) for pair in pairs) and widths == [0] * (2 * len(pairs) - 1) + [1]
        mode, value, value_word = positional[2] if len(positional) > 2 else None, None, "constant_values"
    else:
        return None
    mode_keyword, value_keyword = keyword(node, "mode"), keyword(node, value_word)
    mode = mode_keyword.value if mode_keyword is not None else mode
    value = value_keyword.value if value_keyword is not None else value
    if not appends_one or (mode is not None and string(mode) != "constant"):
        return None
    if value is None:
        return Homogeneous(inner=positional[0], w=0, construction=node, fixed=None, explicit=False)
    return _with_w(facts, node, positional[0], value, explicit=False)


def _w_value(facts: FactBase, node: ast.expr) -> tuple[int | None, list[tuple[AST | LastNameTarget, str]] | None]:
    """The constant w a construction appends, and the edits (node, new text) that give the other w."""
    literal = number(node)
    if literal in (0, 1) and isinstance(node, Constant):
        other = 1 - int(literal)  # type: ignore[arg-type]
        return int(literal), [(node, str(other) if isinstance(node.value, int) else f"{other}.0")]  # type: ignore[arg-type]
    if isinstance(node, (ast.List, ast.Tuple)) and len(node.elts) == 1:
        return _w_value(facts, node.elts[0])
    if isinstance(node, Name):  # `ones = np.ones((n, 1)); np.hstack([x, ones])`
        bindings = facts.bindings(node) or []
        written = facts.index.scope_of(node).subscript_stores.get(node.id)  # `pad[..., -1] = 1.0`: not the zeros any more
        if len(bindings) == 1 and isinstance(bindings[0], Call) and not written:
            return _w_value(facts, bindings[0])
    if isinstance(node, Call) and facts.is_array_call(node.func, "ones", "zeros", "ones_like", "zeros_like"):
        w = 1 if last_name(node.func) in ("ones", "ones_like") else 0
        return w, [(last_name_target(node.func), _SWAP[last_name(node.func) or ""])]
    if isinstance(node, Call) and isinstance(node.func, Attribute) and node.func.attr in ("type_as", "to", "astype", "float", "double"):
        return _w_value(facts, node.func.value)
    return None, None


def used_as_homogeneous(facts: FactBase, homogeneous: Homogeneous) -> bool:
    """Whether a construction is visibly used as homogeneous: built explicitly as a 4-vector,
    multiplied by a matrix (directly or through the variable holding it), or stored under a
    homogeneous name (`p_h`, `points_hom`). A literal 4-vector (`np.array([p.x, p.y, p.z, 0])`)
    counts only when it reaches a product or a transform call: one only stored (appended to a
    list), or whose last slot is written later, is a record with a 4th field, not w."""
    if homogeneous.explicit:
        return not _is_literal_four_vector(homogeneous.construction) or _literal_reaches_a_transform(facts, homogeneous.construction)
    node: AST = homogeneous.construction
    parent = facts.parent(node)
    while parent is not None and is_transpose(parent):
        node, parent = parent, facts.parent(parent)
    if isinstance(parent, BinOp) and isinstance(parent.op, MatMult):
        return True
    if isinstance(parent, Call) and node in parent.args and facts.matmul(parent) is not None:
        return True
    return _stored_for_a_product(facts, parent)


def _literal_reaches_a_transform(facts: FactBase, construction: ast.expr) -> bool:
    """`T @ np.array([p.x, p.y, p.z, 1])`, `v = np.array([...]); T.dot(v)`, `transform(v)`; not
    `history.append(np.array([...]))` nor `v = np.array([...]); v[3] = gain`."""
    parent = facts.parent(construction)
    if _transform_use(facts, construction, parent):
        return True
    if not (isinstance(parent, Assign) and len(parent.targets) == 1 and isinstance(parent.targets[0], Name)):
        return False
    name, scope = parent.targets[0].id, facts.index.scope_of(parent)
    if any(_is_last_slot(target) for target, _ in scope.subscript_stores.get(name, [])):
        return False  # the 4th slot is a field of its own
    if _stored_for_a_product(facts, parent):
        return True
    return any(
        facts.index.scope_of(call) is scope and _transform_use(facts, argument, call)
        for call in facts.index.nodes(Call)
        for argument in call.args  # type: ignore[attr-defined]
        if isinstance(argument, Name) and argument.id == name
    )


def _transform_use(facts: FactBase, node: AST, parent: AST | None) -> bool:
    """Whether `node` is an operand of a matrix product or an argument of a transform call."""
    if isinstance(parent, BinOp) and isinstance(parent.op, MatMult):
        return True
    if isinstance(parent, Attribute) and parent.attr == "dot":
        return True
    if not (isinstance(parent, Call) and node in parent.args):
        return False
    if facts.matmul(parent) is not None:
        return True
    name = last_name(parent.func) or ""
    return _TRANSFORM_CALL.search(name) is not None and "quat" not in name.lower()


def _filled_buffer(facts: FactBase, name: Name, value: ast.expr) -> Homogeneous | None:
    """`h = np.ones(4); h[:3] = x` (or `np.ones((n, 4)); h[:, :3] = x`): homogeneous x with w = 1."""
    if not isinstance(value, Call) or not facts.is_array_call(value.func, "ones", "zeros"):
        return None
    scope = facts.index.scope_of(name)
    stores = scope.subscript_stores.get(name.id, [])
    fills = [stored for target, stored in stores if _is_xyz_slice(target)]
    if len(fills) != 1 or len(stores) != 1:
        return None
    w = 1 if last_name(value.func) == "ones" else 0
    fixed = replace_span(facts.index, value, [(last_name_target(value.func), _SWAP[last_name(value.func) or ""])])
    if fixed is None:
        return None
    return Homogeneous(inner=fills[0], w=w, construction=value, fixed=fixed)


def _is_literal_four_vector(node: ast.expr) -> bool:
    """`np.array([a, b, c, w])`: four elements written out in one array call."""
    if not (isinstance(node, Call) and node.args and isinstance(node.args[0], ast.List)):
        return False
    return len(node.args[0].elts) == 4 and last_name(node.func) in ("array", "asarray", "tensor", "as_tensor")


def _is_last_slot(target: Subscript) -> bool:
    """`v[3]`, `v[-1]`: the 4th slot of a 4-vector."""
    return number(target.slice) in (3, -1)


def _is_xyz_slice(target: Subscript) -> bool:
    parts = subscript_parts(target)
    if len(parts) == 1:
        return is_slice_upto(parts[0], 3)
    return len(parts) == 2 and is_full_slice(parts[0]) and is_slice_upto(parts[1], 3)
