"""Where a quaternion's component order comes from: producers, reorders and the values in between.

GEO301 (quaternion order) and GEO304 (repeated component) ask two questions of an expression:

- `order_of(x)`: which order its four components are in (`wxyz` from `mat2quat`, `xyzw` from
  scipy's `as_quat()`, a spelled-out `[o.w, o.x, o.y, o.z]`, a name `quat_wxyz`), followed
  through names bound in the same scope, `self.attr` stores, record attributes filled by keyword
  (`Record(quaternion=q)` read back as `record.quaternion`), pass-through calls and reorders.
  Conflicting or missing evidence anywhere on the way gives None.
- `reorder_of(x)`: whether it is a reorder of another 4-vector (`q[..., [3, 0, 1, 2]]`,
  `np.roll(q, 1)`, `[q[3], q[0], q[1], q[2]]`) and by which permutation.
"""

from __future__ import annotations

from typing import Final, TYPE_CHECKING

import ast
from ast import (
    AST, Assign, Attribute, BinOp, Call, ClassDef, Div, Mult, Name, Slice, Starred, Subscript, USub,
    UnaryOp,
)
import re
from dataclasses import dataclass, field

from geolint.factbase.control_flow import runs_unconditionally
from geolint.factbase.index import LoopBinding, ParamBinding, UnpackBinding
from geolint.factbase.memo import NodeMemo
from geolint.factbase.messages import MessageTypes, field_label, field_order, quaternion_field_names
from geolint.factbase.syntax import is_full_slice, keyword, last_name, number, positional_args, string, subscript_parts, walk_within
from geolint.factbase.quaternion_formulas import formula_reads_within
from geolint.factbase.reaching import value_of
from geolint.factbase.quaternion_components import is_ellipsis, named_order, same_base, spelled_components
from geolint.factbase.rotations import (
    SCALAR_FIRST,
    SCALAR_LAST,
    component_writes_of_parameter,
    pybullet_orientation_arguments,
    quaternion_argument,
    quaternion_order,
    quaternion_producer,
)
from geolint.factbase.summaries import Function, Summary, SummaryFamily, agreed, chain, plain_parameters, settled_returns, shifted
from geolint.factbase import library_calls
from geolint.factbase.vocabulary import PASSTHROUGH_FUNCTIONS, PASSTHROUGH_METHODS

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

STANDARD_ORDERS: Final = (SCALAR_FIRST, SCALAR_LAST)
# mujoco's quaternion arrays (w, x, y, z), one row per body/geom/site/camera.
# pybullet calls returning (position, orientation): the orientation is (x, y, z, w).
_PYBULLET_PAIRS: Final = frozenset({"getBasePositionAndOrientation", "multiplyTransforms", "invertTransform"})
_TYPING_WORDS: Final = frozenset(
    {"List", "Sequence", "Iterable", "Iterator", "Optional", "Tuple", "Dict", "Union", "Set", "Collection", "Mapping", "Any", "Type"}
)
_NAME_ORDER: Final = re.compile(r"(?i)(?:^|_|\d)(wxyz|xyzw)(?:$|_|s\b)")
_MAX_DEPTH: Final = 12
def _is_four_column_block(index: ast.expr) -> bool:
    """`[:, 3:7]`: every row, four consecutive columns (the result has two axes)."""
    if not (isinstance(index, ast.Tuple) and len(index.elts) == 2):
        return False
    rows, columns = index.elts
    if not (isinstance(rows, Slice) and rows.lower is None and rows.upper is None and rows.step is None):
        return False
    if not isinstance(columns, Slice) or columns.step is not None:
        return False
    lower = 0 if columns.lower is None else number(columns.lower)
    upper = number(columns.upper) if columns.upper is not None else None
    return isinstance(lower, int) and isinstance(upper, int) and lower >= 0 and upper - lower == 4


_STACK_WORDS: Final = frozenset({"quats", "quaternions", "orientations", "qvecs"})


@dataclass(frozen=True)
class Order:
    """The component order of a quaternion value and why it is known.

    `local` is True when code in the same function decides it (a fix may rely on it); `batch`
    when the value is a stack of quaternions (indexing one row keeps the order).
    """

    order: str
    evidence: str
    local: bool = True
    batch: bool = False


@dataclass(frozen=True)
class Reorder:
    """`node` rearranges the last axis of `base`: component i of the result is `base[..., permutation[i]]`."""

    node: ast.expr
    base: ast.expr
    permutation: tuple[int, ...]
    spelling: str  # "index" (`q[..., [3, 0, 1, 2]]`), "roll" or "spelled" (`[q[3], q[0], ...]`)


def permuted(order: str, permutation: tuple[int, ...]) -> str:
    return "".join(order[index] for index in permutation)


def permutation_between(source: str, target: str) -> tuple[int, ...]:
    """The index list that turns components in `source` order into `target` order."""
    return tuple(source.index(letter) for letter in target)


def label(order: str) -> str:
    return f"({', '.join(order)})"


def keyword_states_order(facts: FactBase, call: Call, order: str) -> bool:
    """`PoseTrajectory3D(orientations_quat_wxyz=q)`: the quaternion the API reads (`quaternion_argument`) is
    given by a keyword whose name states `order` (GEO301 checks such a keyword by its name, so once)."""
    argument = quaternion_argument(facts, call)
    return argument is not None and any(
        given.value is argument and given.arg is not None and name_order(given.arg) == order for given in call.keywords
    )


def name_order(name: str) -> str | None:
    """`quat_wxyz`, `orientations_quat_xyzw`: the order a name states in so many words."""
    lowered = name.lower()
    if "wxyz" not in lowered and "xyzw" not in lowered:
        return None  # the regex's words are not there (asked of every name and keyword)
    found = {match.lower() for match in _NAME_ORDER.findall(name)}
    return found.pop() if len(found) == 1 else None


def _words(name: str) -> list[str]:
    return [word.lower() for word in re.findall(r"[A-Z]?[a-z0-9]+|[A-Z]+(?![a-z])", name)]


class QuaternionFlow:
    """The order and reorder questions, answered on one module's fact base (memoised per node)."""

    def __init__(self, facts: FactBase) -> None:
        self.facts = facts
        self._orders: NodeMemo[Order] = NodeMemo(_MAX_DEPTH)
        self._keyword_stores: dict[tuple[str, str], list[ast.expr | None]] | None = None
        self._module_permutations: set[tuple[int, ...]] | None = None
        self.messages = MessageTypes(facts)

    # -- reorders ------------------------------------------------------------------------
    def reorder_of(self, node: ast.expr, through_names: bool = True) -> Reorder | None:
        facts = self.facts
        node = self._strip(node)
        if isinstance(node, Subscript):
            parts = subscript_parts(node)
            if not parts:
                return None  # `x[()]`
            *leading, last = parts
            if all(is_full_slice(part) or is_ellipsis(part) for part in leading):
                permutation = _index_list(facts, last)
                if permutation is not None:
                    return Reorder(node, node.value, permutation, "index")
            return None
        if isinstance(node, Call):
            rolled = self._roll(node)
            if rolled is not None:
                return rolled
        elements = spelled_components(facts, node)
        if elements is not None:
            spelled = same_base(facts, elements)
            if spelled is not None and sorted(spelled[1]) == [0, 1, 2, 3] and spelled[1] != [0, 1, 2, 3]:
                return Reorder(node, spelled[0], tuple(spelled[1]), "spelled")
            return None
        if through_names and isinstance(node, Name):
            bound = facts.bindings(node) or []
            if len(bound) == 1 and isinstance(bound[0], ast.expr) and not self._modified(node):
                return self.reorder_of(bound[0], through_names=False)
        return None

    def _roll(self, call: Call) -> Reorder | None:
        facts = self.facts
        if not facts.is_array_call(call.func, "roll"):
            return None
        positional = positional_args(call)
        if not positional:
            return None
        shift_node = positional[1] if len(positional) > 1 else getattr(keyword(call, "shift") or keyword(call, "shifts"), "value", None)
        axis_node = positional[2] if len(positional) > 2 else getattr(keyword(call, "axis") or keyword(call, "dims"), "value", None)
        shift = number(shift_node)
        if not isinstance(shift, int) or shift % 4 not in (1, 3):
            return None
        if axis_node is not None and number(axis_node) not in (-1, 1):
            return None
        permutation = (3, 0, 1, 2) if shift % 4 == 1 else (1, 2, 3, 0)
        return Reorder(call, positional[0], permutation, "roll")

    def is_quaternion_stack(self, node: ast.expr) -> bool:
        """`orientations_quat_wxyz`, `quats`, `data.xquat`: a name in the plural of a quaternion word,
        a value known to be a stack (mujoco's per-body arrays), or a block of four columns of a table
        (`poses[:, 3:7]`, the quaternions of stacked (x, y, z, qw, qx, qy, qz) rows)."""
        if isinstance(node, Subscript) and _is_four_column_block(node.slice):
            return True
        name = node.id if isinstance(node, Name) else node.attr if isinstance(node, Attribute) else None
        if name is not None and any(word in _STACK_WORDS for word in _words(name)):
            return True
        order = self.order_of(node)
        return order is not None and order.batch

    def module_applies(self, permutation: tuple[int, ...]) -> bool:
        """Whether the module stores data reordered by `permutation` in a container (`batch["quat"] =
        torch.roll(q, 1, -1)`, `{"quat": q[..., [3, 0, 1, 2]]}`, `sample.quat = ...`), where it may
        travel to other code in that non-standard order."""
        if self._module_permutations is None:
            found: set[tuple[int, ...]] = set()
            for node in self.facts.index.nodes(Subscript, Call, ast.List, ast.Tuple):
                reorder = self.reorder_of(node, through_names=False)  # type: ignore[arg-type]
                if reorder is not None and self._stored_in_container(reorder.node):
                    found.add(reorder.permutation)
            self._module_permutations = found
        return permutation in self._module_permutations

    def scope_applies(self, node: AST, permutation: tuple[int, ...]) -> bool:
        """Whether the function (or module body) holding `node` reorders some data by `permutation`
        (`q = q[:, :, [1, 2, 3, 0]]` before a smoothing that ignores component order)."""
        scope = self.facts.index.scope_of(node).node
        for candidate in self.facts.index.nodes(Subscript, Call):
            if self.facts.index.scope_of(candidate).node is not scope:
                continue
            reorder = self.reorder_of(candidate, through_names=False)  # type: ignore[arg-type]
            if reorder is not None and reorder.permutation == permutation:
                return True
        return False

    def _stored_in_container(self, node: ast.expr) -> bool:
        parent = self.facts.parent(node)
        if isinstance(parent, ast.Dict):
            return any(value is node for value in parent.values)
        if isinstance(parent, Assign) and parent.value is node:
            return any(isinstance(target, (Subscript, Attribute)) for target in parent.targets)
        return False

    # -- orders --------------------------------------------------------------------------
    def order_of(self, node: ast.expr) -> Order | None:
        return self._orders.get(id(node), lambda: self._order(node))

    def _order(self, node: ast.expr) -> Order | None:
        facts = self.facts
        node = self._strip(node)
        if isinstance(node, UnaryOp) and isinstance(node.op, USub):
            return self.order_of(node.operand)
        if isinstance(node, BinOp) and isinstance(node.op, (Div, Mult)):
            # `q / np.linalg.norm(q)`, `q * sign`: scaling keeps the order
            if facts.is_norm_call(node.right) or number(node.right) is not None:
                return self.order_of(node.left)
            return None
        reorder = self.reorder_of(node, through_names=False)
        if reorder is not None:
            base = self.order_of(reorder.base)
            if base is None or base.batch and reorder.spelling == "spelled":  # rows of a stack, not components
                return None
            shown = self.facts.code_of(reorder.node)
            if len(shown) > 60:
                shown = f"{list(reorder.permutation)}"
            return Order(permuted(base.order, reorder.permutation), f"{base.evidence}, reordered by `{shown}`", base.local)
        if isinstance(node, Call):
            return self._order_of_call(node)
        if isinstance(node, Name):
            return self._order_of_name(node)
        if isinstance(node, Attribute):
            return self._order_of_attribute(node)
        if isinstance(node, Subscript):
            return self._order_of_row(node)
        elements = spelled_components(facts, node)
        if elements is not None:
            return self._order_of_spelled(node, elements)
        return None

    def _order_of_spelled(self, node: ast.expr, elements: list[ast.expr]) -> Order | None:
        """`[qw, qx, qy, qz]`, `[o.x, o.y, o.z, o.w]`, or `[q[0], q[1], q[2], q[3]]` of a quaternion `q`."""
        order = named_order(elements)
        order = order if order in STANDARD_ORDERS else None
        if order is not None:
            return Order(order, f"from components spelled out at line {node.lineno}")
        spelled = same_base(self.facts, elements)
        if spelled is not None and spelled[1] == [0, 1, 2, 3]:
            base = self.order_of(spelled[0])
            if base is not None and not base.batch:  # a stack's rows, not components
                return Order(base.order, base.evidence, base.local)
        return None

    def _order_of_call(self, call: Call) -> Order | None:
        facts = self.facts
        produced = quaternion_producer(facts, call)
        if produced is not None:
            return Order(produced, f"from `{facts.code_of(call)}`, line {call.lineno}")
        elements = spelled_components(facts, call)
        if elements is not None:
            return self._order_of_spelled(call, elements)
        if facts.may_have_summary(call):  # a project helper whose every `return` agrees on an order
            summary = facts.summary_of(call, QUATERNIONS)
            if summary is not None and summary.quaternion_order is not None:
                order, evidence, batch = summary.quaternion_order
                return Order(order, f"from `{facts.code_of(call.func)}`, which returns it {evidence}", local=False, batch=batch)
        return None

    def _returned_element(self, call: Call, position: int) -> Order | None:
        """Position `position` of the tuple a project helper returns (`pos, quat = get_pose()`, `get_pose()[1]`)."""
        facts = self.facts
        if not facts.may_have_summary(call):
            return None
        summary = facts.summary_of(call, QUATERNIONS)
        if summary is None or position not in summary.quaternion_elements:
            return None
        order, evidence, batch = summary.quaternion_elements[position]
        return Order(order, f"from `{facts.code_of(call.func)}`, which returns it at position {position} {evidence}", local=False, batch=batch)

    def _order_of_row(self, node: Subscript) -> Order | None:
        """`data.xquat[body_id]` (one row of a stack) and pybullet's `getBasePositionAndOrientation(i)[1]`."""
        index = node.slice
        if isinstance(node.value, Call) and last_name(node.value.func) in _PYBULLET_PAIRS and number(index) == 1:
            return Order(SCALAR_LAST, f"from pybullet's `{last_name(node.value.func)}`, line {node.lineno}")
        position = number(index)
        if isinstance(position, int) and not isinstance(position, bool) and position >= 0:
            returned = node.value
            if isinstance(returned, Name):
                bound = self.facts.bindings(returned) or []
                returned = bound[0] if len(bound) == 1 and isinstance(bound[0], Call) and not self._modified(returned) else returned  # type: ignore[assignment]
            if isinstance(returned, Call):
                element = self._returned_element(returned, position)
                if element is not None:
                    return element
        if isinstance(index, (Slice, ast.Tuple, ast.List, Starred)):
            return None
        base = self.order_of(node.value)
        if base is not None and base.batch:
            return Order(base.order, base.evidence, base.local)
        return None

    def _order_of_name(self, node: Name) -> Order | None:
        facts = self.facts
        stated = name_order(node.id)
        by_name = Order(stated, f"from its name `{node.id}`", local=True) if stated else None
        bound = facts.bindings(node)
        by_value: Order | None = None
        if bound and not self._modified(node):
            found = [self._order_of_binding(binding) for binding in bound]
            if by_name is not None and any(item is not None and item.order != by_name.order for item in found):
                return None  # `q_wxyz = r.as_quat()` then `q_wxyz = q_wxyz[:, [3, 0, 1, 2]]`: the name holds at the end only
            if all(item is not None for item in found):
                orders = {item.order for item in found}  # type: ignore[union-attr]
                if len(orders) == 1:
                    first = found[0]
                    by_value = Order(first.order, first.evidence, all(item.local for item in found), all(item.batch for item in found))  # type: ignore[union-attr]
        if by_name is not None and by_value is not None:
            return by_value if by_value.order == by_name.order else None  # names and code disagree: silence
        return by_value or by_name

    def _order_of_binding(self, binding: object) -> Order | None:
        if isinstance(binding, ast.expr):
            return self.order_of(binding)
        if isinstance(binding, UnpackBinding) and binding.position == 1 and isinstance(binding.value, Call):
            if last_name(binding.value.func) in _PYBULLET_PAIRS:
                return Order(SCALAR_LAST, f"from pybullet's `{last_name(binding.value.func)}`, line {binding.value.lineno}")
        if isinstance(binding, UnpackBinding) and isinstance(binding.value, Call):
            return self._returned_element(binding.value, binding.position)
        if isinstance(binding, LoopBinding) and binding.position is None:
            rows = self.order_of(binding.iterable)
            if rows is not None and rows.batch:
                return Order(rows.order, rows.evidence, rows.local)
        return None

    def _order_of_attribute(self, node: Attribute) -> Order | None:
        facts = self.facts
        attr = node.attr
        held = library_calls.attribute_geometry(facts, node)  # `data.xquat`, `q.elements`: from the stubs
        order = held[1].quaternion_order if held is not None else None
        if held is not None and order is not None:
            return Order(order, f"from {held[0].library}'s `{attr}`", batch=held[1].stacked)
        returned = facts.summary_of_property(node, QUATERNIONS)
        if returned is not None and returned.quaternion_order is not None:
            order, evidence, batch = returned.quaternion_order
            return Order(order, f"from the property `{facts.code_of(node)}`, which returns it {evidence}", local=False, batch=batch)
        if attr in quaternion_field_names():
            cls = self.messages.class_of(node.value)
            order = field_order(cls, attr)
            if cls is not None and order is not None:
                return Order(order, f"from {field_label(cls, attr)}", local=isinstance(node.value, Name))
        stated = name_order(attr)
        by_name = Order(stated, f"from its name `{attr}`", local=False) if stated else None
        if isinstance(node.value, Name) and node.value.id == "self":
            stores: list[ast.expr | None] = list(facts.index.self_attribute_stores.get(attr, []))
            where = f"`self.{attr}`"
        else:
            cls = self._class_of(node.value)
            stores = self._record_stores(cls, attr) if cls is not None else []
            where = f"`{cls}.{attr}`"
        by_value: Order | None = None
        if stores and all(store is not None for store in stores):
            found = [self.order_of(store) for store in stores]  # type: ignore[arg-type]
            if all(item is not None for item in found) and len({item.order for item in found}) == 1:  # type: ignore[union-attr]
                first = found[0]
                by_value = Order(first.order, f"{where} is set {first.evidence}", local=False, batch=first.batch)  # type: ignore[union-attr]
        if by_name is not None and by_value is not None:
            return by_value if by_value.order == by_name.order else None
        return by_value or by_name

    # -- records: `Record(quaternion=q)` read back as `record.quaternion` ------------------------
    def _class_of(self, node: ast.expr, visiting: frozenset[str] = frozenset()) -> str | None:
        """The class of a name's value when every binding says it: a constructor call, a parameter
        annotated with one class (`label: Record`, `labels: List[Record]`), or a loop over such a parameter.
        `visiting`: the names being resolved (`for elem in elem:` loops over its own name)."""
        if not isinstance(node, Name) or node.id in visiting:
            return None
        bound = self.facts.bindings(node) or []
        found = {self._class_of_binding(binding, visiting | {node.id}) for binding in bound}
        return found.pop() if len(found) == 1 and None not in found else None

    def _class_of_binding(self, binding: object, visiting: frozenset[str]) -> str | None:
        if isinstance(binding, Call):
            name = last_name(binding.func)
            return name if name and name[:1].isupper() else None
        if isinstance(binding, ParamBinding) and binding.arg.annotation is not None:
            classes = {
                sub.id if isinstance(sub, Name) else sub.attr
                for sub in ast.walk(binding.arg.annotation)
                if isinstance(sub, (Name, Attribute)) and not (isinstance(sub, Name) and sub.id in _TYPING_WORDS)
                and not isinstance(self.facts.parent(sub), Attribute)
            }
            classes |= {value for sub in ast.walk(binding.arg.annotation) if (value := string(sub)) is not None}
            classes = {name for name in classes if name[:1].isupper() and name not in _TYPING_WORDS}
            return classes.pop() if len(classes) == 1 else None
        if isinstance(binding, LoopBinding) and binding.position is None and isinstance(binding.iterable, Name):
            return self._class_of(binding.iterable, visiting)
        return None

    def _record_stores(self, cls: str, attr: str) -> list[ast.expr | None]:
        """Every value the module stores into `<cls instance>.attr`; None for a store whose value is
        unknown (a positional argument, a receiver of another or unknown class)."""
        if self._keyword_stores is None:
            self._keyword_stores = {}
            facts = self.facts
            for call in facts.index.nodes(Call):
                name = last_name(call.func)  # type: ignore[attr-defined]
                if not name or not name[:1].isupper():
                    continue
                for given in call.keywords:  # type: ignore[attr-defined]
                    if given.arg is not None:
                        self._keyword_stores.setdefault((name, given.arg), []).append(given.value)
                if call.args:  # type: ignore[attr-defined]
                    self._keyword_stores.setdefault((name, "*"), []).append(None)
            for scope in facts.index.scopes.values():
                for target, value in scope.attribute_stores:
                    owner = target.value
                    if isinstance(owner, Name) and owner.id == "self":
                        enclosing: AST | None = scope.node
                        while enclosing is not None and not isinstance(enclosing, ClassDef):
                            enclosing = facts.parent(enclosing)
                        owner_class: str | None = enclosing.name if isinstance(enclosing, ClassDef) else None
                    else:
                        owner_class = self._class_of(owner) if isinstance(owner, Name) else None
                    self._keyword_stores.setdefault((owner_class or "?", target.attr), []).append(value if owner_class else None)
        stores = list(self._keyword_stores.get((cls, attr), []))
        if (cls, "*") in self._keyword_stores or ("?", attr) in self._keyword_stores:
            stores.append(None)  # set positionally, or on a receiver of unknown class: not all stores are known
        return stores

    # -- helpers -------------------------------------------------------------------------
    def _strip(self, node: ast.expr) -> ast.expr:
        """Look through calls that keep the values: `np.asarray(q)`, `q.copy()`, `list(q)`, `q.astype(float)`."""
        facts = self.facts
        for _ in range(8):
            if not isinstance(node, Call):
                return node
            func = node.func
            positional = positional_args(node)
            if isinstance(func, Name) and func.id in ("list", "tuple") and len(node.args) == 1 and func.id not in facts.index.imports:
                node = node.args[0]
            elif (
                isinstance(func, Attribute)
                and len(positional) == 1
                and not isinstance(positional[0], (ast.List, ast.Tuple))
                and facts.is_array_call(func, *PASSTHROUGH_FUNCTIONS)
            ):
                node = positional[0]
            elif isinstance(func, Attribute) and (func.attr in PASSTHROUGH_METHODS or func.attr == "tolist") and not facts.is_module_like(func.value):
                if func.attr in ("reshape", "view") and any(number(arg) not in (-1, 4, 1) for arg in node.args):
                    return node
                node = func.value
            else:
                return node
        return node

    def _modified(self, name: Name) -> bool:
        """`q[0] = ...` / `q += ...` in the name's scope: its components may have been rewritten."""
        scope = self.facts.index.scope_of(name)
        return name.id in scope.subscript_stores or name.id in scope.augmented


def _index_list(facts: FactBase, node: AST) -> tuple[int, ...] | None:
    """`[3, 0, 1, 2]` (or `np.array([...])`) as an index: a non-identity permutation of 0..3."""
    if isinstance(node, Call) and facts.is_array_call(node.func, "array", "asarray", "tensor") and len(node.args) == 1:
        node = node.args[0]
    if not isinstance(node, ast.List) or len(node.elts) != 4:
        return None
    values = [number(element) for element in node.elts]
    if any(not isinstance(value, int) or isinstance(value, bool) for value in values):
        return None
    permutation = tuple(int(value) % 4 for value in values if value is not None and -4 <= value <= 3)
    if len(permutation) != 4 or sorted(permutation) != [0, 1, 2, 3] or permutation == (0, 1, 2, 3):
        return None
    return permutation


def convention(order: str) -> str:
    return "scalar-first (w, x, y, z)" if order == SCALAR_FIRST else "scalar-last (x, y, z, w)" if order == SCALAR_LAST else label(order)


# --- the summaries of quaternion orders: what a helper returns and what it reads its parameters in -


@dataclass
class QuaternionSummary(Summary):
    # the quaternion order every `return` agrees on: (order, evidence, a stack of quaternions)
    quaternion_order: tuple[str, str, bool] | None = None
    # `return pos, quat`: tuple position -> the quaternion order every `return` agrees on there
    quaternion_elements: dict[int, tuple[str, str, bool]] = field(default_factory=dict)
    # parameter index -> (quaternion order, where): parameters passed as they are, unconditionally, as
    # the quaternion of an API that reads that order (`Rotation.from_quat(q)`), directly or through helpers
    reads_quaternion: dict[int, tuple[str, str]] = field(default_factory=dict)


def _summarize_quaternions(facts: FactBase, function: Function, params: tuple[str, ...]) -> QuaternionSummary:
    """The order a function returns its quaternions in, and the order it reads each parameter in."""
    summary = QuaternionSummary(parameters=params)
    scope = facts.index.scopes.get(function)
    if scope is None:
        return summary
    plain = plain_parameters(scope, params)
    returns = settled_returns(facts, scope, QUATERNIONS)
    if returns:
        summary.quaternion_order = _returned_order(facts, returns)
        summary.quaternion_elements = _returned_element_orders(facts, returns)
    for node in walk_within(function):
        if isinstance(node, Call) and node.args:
            _record_quaternion_reads(facts, node, positional_args(node), params, plain, summary)
        if isinstance(node, Call) and node.keywords:
            _record_keyword_quaternions(facts, node, params, plain, summary)
    _record_formula_reads(facts, function, plain, summary)
    if plain and scope.attribute_stores:
        _record_component_writes(facts, scope.attribute_stores, plain, summary)
    return summary


def _record_quaternion_reads(
    facts: FactBase, call: Call, arguments: list[ast.expr], params: tuple[str, ...], plain: set[str], summary: QuaternionSummary
) -> None:
    """What a call inside the function reads the function's own parameters as (its `positional_args`):
    a project helper that reads a quaternion order, an API that does (`Rotation.from_quat(q)`)."""
    passed = {index: params.index(arg.id) for index, arg in enumerate(arguments) if isinstance(arg, Name) and arg.id in plain}
    if not passed:
        return
    if facts.may_have_summary(call):
        callee = facts.summary_of(call, QUATERNIONS)
        if callee is not None:
            for index, (order, where) in callee.reads_quaternion.items():
                if index in passed and order:
                    _add_quaternion_read(summary, passed[index], order, chain(f"`{facts.code_of(call.func)}`", where))
            return
    for index, own in passed.items():
        read_order = quaternion_read_by(facts, call, arguments[index])
        if read_order is not None:
            _add_quaternion_read(summary, own, read_order, f"`{facts.code_of(call.func)}`")


def _record_keyword_quaternions(facts: FactBase, call: Call, params: tuple[str, ...], plain: set[str], summary: QuaternionSummary) -> None:
    """`XFormPrim(path, orientation=q)`, `loadURDF(path, baseOrientation=q)`: a parameter passed by keyword
    as an API's quaternion."""
    for given in call.keywords:
        value = given.value
        if isinstance(value, Name) and value.id in plain:
            order = quaternion_read_by(facts, call, value)
            if order is not None:
                _add_quaternion_read(summary, params.index(value.id), order, f"`{facts.code_of(call.func)}`")


def _record_formula_reads(facts: FactBase, function: Function, plain: set[str], summary: QuaternionSummary) -> None:
    """A parameter whose components an unconditional textbook formula reads (`atan2(2 * (q[3] * q[2] + ...`)
    is read in that formula's order, as if handed to an API."""
    for read in formula_reads_within(facts, function):
        base = read.base
        if not (isinstance(base, Name) and base.id in plain) or facts.index.scope_of(base).node is not function:
            continue
        if runs_unconditionally(facts, read.node):
            _add_quaternion_read(summary, summary.parameters.index(base.id), read.order, read.evidence(facts))


def _record_component_writes(facts: FactBase, stores: list[tuple[Attribute, ast.expr]], plain: set[str], summary: QuaternionSummary) -> None:
    """`msg.x = q[0]` ... `msg.w = q[3]` on a parameter `q`: read in that order, as if handed to an API."""
    for name, order, where in component_writes_of_parameter(facts, stores, plain):
        _add_quaternion_read(summary, summary.parameters.index(name), order, where)


def quaternion_read_by(facts: FactBase, call: Call, argument: ast.expr) -> str | None:
    """The component order `call` reads `argument` in, when it is the call's whole quaternion (scipy
    `from_quat(q)`, pybullet's orientation arguments...) and the call runs whenever its function does."""
    if any(found is argument for found in pybullet_orientation_arguments(call)):
        order: str | None = SCALAR_LAST
    else:
        order = quaternion_order(facts, call)
        if order is None or quaternion_argument(facts, call) is not argument:
            return None
    return order if runs_unconditionally(facts, call) else None


def _add_quaternion_read(summary: QuaternionSummary, index: int, order: str, where: str) -> None:
    known = summary.reads_quaternion.get(index)
    if known is None:
        summary.reads_quaternion[index] = (order, where)
    elif known[0] != order:
        summary.reads_quaternion[index] = ("", "")  # read in both orders: no evidence


def _returned_order(facts: FactBase, returns: list[ast.expr]) -> tuple[str, str, bool] | None:
    found = agreed([facts.shared(QuaternionFlow).order_of(value) for value in returns], "order")
    return None if found is None else (found[0].order, found[0].evidence, all(order.batch for order in found))


def _returned_element_orders(facts: FactBase, returns: list[ast.expr]) -> dict[int, tuple[str, str, bool]]:
    """`return pos, quat_wxyz`: the order of each position of the returned tuple, when every `return`
    is a tuple of one length and all of them agree on that position."""
    if not all(isinstance(value, ast.Tuple) for value in returns) or len({len(value.elts) for value in returns}) != 1:  # type: ignore[attr-defined]
        return {}
    flow = facts.shared(QuaternionFlow)
    found: dict[int, tuple[str, str, bool]] = {}
    for position in range(len(returns[0].elts)):  # type: ignore[attr-defined]
        orders = agreed([flow.order_of(value.elts[position]) for value in returns], "order")  # type: ignore[attr-defined]
        if orders is not None:
            found[position] = (orders[0].order, orders[0].evidence, all(order.batch for order in orders))
    return found


def _bound_quaternion_summary(summary: QuaternionSummary) -> QuaternionSummary:
    return QuaternionSummary(
        parameters=summary.parameters[1:],
        quaternion_order=summary.quaternion_order,
        quaternion_elements=summary.quaternion_elements,
        reads_quaternion=shifted(summary.reads_quaternion),
        pending=summary.pending,
    )


QUATERNIONS: Final = SummaryFamily("quaternions", QuaternionSummary, _summarize_quaternions, _bound_quaternion_summary)


# --- flags that name an order: `def quat_mul(a, b, w_last)` ----------------------------------------

ORDER_FLAGS: Final = frozenset({"w_last", "w_first", "scalar_first", "scalar_last", "wxyz", "xyzw", "is_wxyz", "is_xyzw"})
_ORDER_FLAG_WORDS: Final = ("w_last", "w_first", "scalar_first", "scalar_last", "is_wxyz", "is_xyzw")
_ORDER_FLAG_TEXT: Final = re.compile(rf"\b(?:{'|'.join(_ORDER_FLAG_WORDS)})\b")


def mentions_order_flag(source: str) -> bool:
    """`_ORDER_FLAG_TEXT` in `source`, its words looked for first (a regex led by an alternation has no
    literal to scan for, and this runs on every module)."""
    return any(word in source for word in _ORDER_FLAG_WORDS) and _ORDER_FLAG_TEXT.search(source) is not None
# project operations that return a quaternion in the order their flag names (isaacgym-style
# `quat_mul(a, b, w_last)`), as opposed to ones returning vectors or angles (`quat_rotate`, `calc_heading`)
_QUATERNION_RESULT: Final = re.compile(
    r"^(?:quat_(?:mul|mul_norm|multiply|product|conjugate|inv|inverse|unit|normalize|pos|identity(?:_like)?|from_\w+)|"
    r"\w+_to_quat(?:ernion)?|quaternion_(?:multiply|product|invert|conjugate|raw_multiply))$"
)


def flag_ordered_producer(facts: FactBase, node: ast.expr, flag: str) -> Call | None:
    """The call `node` certainly holds when it is a quaternion operation handed the order flag."""
    for _ in range(4):
        if isinstance(node, Name):
            bound = value_of(facts.index, node)
            if not isinstance(bound, ast.expr):
                return None
            node = bound
            continue
        break
    if not isinstance(node, Call) or not _QUATERNION_RESULT.match(last_name(node.func) or ""):
        return None
    passed = [*node.args, *(given.value for given in node.keywords)]
    return node if any(isinstance(arg, Name) and arg.id == flag for arg in passed) else None
