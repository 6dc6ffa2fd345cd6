"""What the pose rules ask of an `ast` expression, answered from the code alone (no names needed).

- `LocalValues`: what a local name was last assigned before a use, within one function, when
  straight-line code makes that certain (a name assigned in a loop after the use, or a parameter,
  has no single value);
- `pose_part`: whether an expression is the rotation or the translation of a pose, and of which
  one (`T[:3, :3]` / `T[:3, 3]`, `poses[:, :3, :3]`, `pose.rotation` / `pose.translation`,
  `gt["cam_R_m2c"]` / `gt["cam_t_m2c"]`, `R, t = split_pose(T)`), seen through copies, dtype
  and device moves, broadcasting reshapes and transposes (counted);
- `application`: `R @ x`, `x @ R.T`, `np.dot(R, x)`, `torch.bmm(R, x)`: which rotation is applied
  to what, and whether the rotation or its inverse is what acts on the vector;
- `matrix_shape`: whether an array is known to be a 3x3 rotation or a 4x4 pose from what made it.

One `LocalValues` is built per module, on the fact base's index of it (`geolint.factbase.index_of`:
the same single walk), and shared by the rules that ask (`local_values(tree)`).
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass
from functools import cached_property
from typing import Iterator, Protocol

from geolint.factbase.index import child_nodes

ScopeNode = ast.Module | ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda | ast.ClassDef
_SCOPES = (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)

# Methods and functions that return the same values (copies, dtype/device moves, broadcasting views).
_SAME_VALUE_METHODS = frozenset(
    {"copy", "clone", "detach", "float", "double", "half", "to", "cpu", "cuda", "numpy", "astype",
     "contiguous", "type", "type_as", "reshape", "view", "unsqueeze", "squeeze", "flatten", "ravel",
     "expand", "expand_as", "view_as", "reshape_as"}
)  # fmt: skip
_SAME_VALUE_FUNCTIONS = frozenset(
    {"asarray", "array", "as_tensor", "tensor", "from_numpy", "copy", "deepcopy", "expand_dims", "squeeze",
     "reshape", "float32", "float64", "ascontiguousarray", "atleast_2d", "Tensor", "FloatTensor"}
)  # fmt: skip
_INVERTING_FUNCTIONS = frozenset({"inv", "pinv", "inverse"})


def same_code(first: ast.AST, second: ast.AST) -> bool:
    return ast.unparse(first) == ast.unparse(second)


def int_value(node: ast.AST | None) -> int | None:
    """A literal integer, negatives included."""
    if isinstance(node, ast.Constant) and type(node.value) is int:
        return node.value
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        inner = int_value(node.operand)
        return None if inner is None else -inner
    return None


def call_name(node: ast.AST) -> str | None:
    """The last name of a call's function (`np.linalg.inv(x)` -> "inv")."""
    if not isinstance(node, ast.Call):
        return None
    func = node.func
    if isinstance(func, ast.Attribute):
        return func.attr
    if isinstance(func, ast.Name):
        return func.id
    return None


def dotted(node: ast.AST) -> str | None:
    """`np.linalg.inv` for a chain of names and attributes."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        inner = dotted(node.value)
        return None if inner is None else f"{inner}.{node.attr}"
    return None


def subscript_indices(node: ast.Subscript) -> list[ast.expr]:
    return list(node.slice.elts) if isinstance(node.slice, ast.Tuple) else [node.slice]


def is_slice_upto(node: ast.expr, stop: int) -> bool:
    """`:3` or `0:3` (a step of 1)."""
    if not isinstance(node, ast.Slice) or node.step is not None:
        return False
    start = 0 if node.lower is None else int_value(node.lower)
    return start == 0 and int_value(node.upper) == stop


def is_full_slice(node: ast.expr) -> bool:
    return isinstance(node, ast.Slice) and node.lower is None and node.upper is None and node.step is None


def is_batch_index(node: ast.expr) -> bool:
    """`:`, `...` or a new axis (`None`) ahead of the matrix indices of a stack of matrices."""
    return is_full_slice(node) or (isinstance(node, ast.Constant) and (node.value is Ellipsis or node.value is None))


def is_stack_index(node: ast.expr) -> bool:
    """An index that picks among stacked matrices: `:`, `...`, `None`, `head:tail`, `i`, `0`."""
    if isinstance(node, ast.Slice):
        return node.step is None
    if isinstance(node, ast.Constant):
        return node.value is Ellipsis or node.value is None or type(node.value) is int
    return isinstance(node, (ast.Name, ast.Attribute))


def matrix_indices(node: ast.Subscript) -> tuple[list[ast.expr], ast.expr, ast.expr] | None:
    """(batch indices, row index, column index) of a subscript with at least two indices."""
    indices = subscript_indices(node)
    if len(indices) < 2 or not all(is_stack_index(index) for index in indices[:-2]):
        return None
    return indices[:-2], indices[-2], indices[-1]


def stack_key(batch: list[ast.expr]) -> str:
    """Which matrices of a stack the batch indices pick, as text: new axes dropped, `...` read as `:`."""
    picked = []
    for index in batch:
        if isinstance(index, ast.Constant) and index.value is None:
            continue
        picked.append(":" if is_batch_index(index) else ast.unparse(index))
    return ", ".join(picked)


# ---------------------------------------------------------------------------------------------
# Local values


@dataclass(frozen=True)
class Unpacked:
    """`R, t = split_pose(T)`: element `index` of a value that was unpacked into several names."""

    value: ast.expr
    index: int
    names: tuple[str, ...]
    statement: ast.stmt


class LocalValues:
    """Local assignments of one module (indexed per scope on first use), on the module's shared index."""

    def __init__(self, tree: ast.Module) -> None:
        from geolint.factbase import index_of

        self.tree = tree
        self.index = index_of(tree)
        # the index's parents of every node (shared: `x -= t` adds the parents of the `x - t` it stands for)
        self.parents: dict[ast.AST, ast.AST] = self.index.parents
        self._assignments: dict[tuple[int, str], list[tuple[ast.stmt, ast.expr | Unpacked | None]]] = {}
        self._indexed: set[int] = set()
        self._names_of_scope: dict[int, set[str]] = {}
        self.parameters: dict[tuple[int, str], ast.arg] = {}

    @cached_property
    def nodes(self) -> list[ast.AST]:
        """Every node of the module (leaves such as `Load` aside), each after its parent, level by level.
        Rules had better ask the index for the types they look at (`values.index.nodes(ast.Call)`)."""
        nodes: list[ast.AST] = [self.tree]
        position = 0
        while position < len(nodes):
            nodes.extend(child_nodes(nodes[position]))
            position += 1
        return nodes

    # -- indexing ------------------------------------------------------------------------------

    def _index_scope(self, scope: ScopeNode) -> None:
        """Record the assignments made directly in `scope` (not in the functions or classes it defines)."""
        if id(scope) in self._indexed:
            return
        self._indexed.add(id(scope))
        if not isinstance(scope, (ast.Module, ast.ClassDef)):
            for argument in _all_arguments(scope.args):
                self.parameters[(id(scope), argument.arg)] = argument
        body = [scope.body] if isinstance(scope, ast.Lambda) else list(scope.body)
        stack: list[tuple[ast.AST, ast.stmt | None]] = [(node, None) for node in reversed(body)]
        while stack:
            node, statement = stack.pop()
            if isinstance(node, ast.stmt):
                statement = node
                self._record(node, scope)
                if isinstance(node, _SCOPES):
                    continue
            elif isinstance(node, ast.NamedExpr) and statement is not None and isinstance(node.target, ast.Name):
                self._add(scope, node.target.id, statement, node.value)
            elif isinstance(node, ast.comprehension) and statement is not None:
                for name in _names_in(node.target):
                    self._add(scope, name, statement, None)
            elif isinstance(node, ast.Lambda):
                continue
            stack.extend((child, statement) for child in reversed(child_nodes(node)))
        for name in self._names_of_scope.pop(id(scope), ()):
            self._assignments[(id(scope), name)].sort(key=lambda assignment: (assignment[0].lineno, assignment[0].col_offset))

    def _record(self, statement: ast.stmt, scope: ScopeNode) -> None:
        if isinstance(statement, ast.Assign):
            for target in statement.targets:
                self._bind_target(target, statement.value, statement, scope)
        elif isinstance(statement, ast.AnnAssign) and statement.value is not None:
            self._bind_target(statement.target, statement.value, statement, scope)
        elif isinstance(statement, ast.AugAssign) and isinstance(statement.target, ast.Name):
            # `x -= t` is `x = x - t`: the Load copy of x resolves to x's value before this statement.
            current = ast.Name(id=statement.target.id, ctx=ast.Load())
            ast.copy_location(current, statement.target)
            value = ast.BinOp(left=current, op=statement.op, right=statement.value)
            ast.copy_location(value, statement)
            self.parents[value] = statement
            self.parents[current] = value
            self._add(scope, statement.target.id, statement, value)
        elif isinstance(statement, (ast.For, ast.AsyncFor)):
            for name in _names_in(statement.target):
                self._add(scope, name, statement, None)
        elif isinstance(statement, (ast.With, ast.AsyncWith)):
            for item in statement.items:
                if item.optional_vars is not None:
                    for name in _names_in(item.optional_vars):
                        self._add(scope, name, statement, None)
        elif isinstance(statement, (ast.Import, ast.ImportFrom)):
            for alias in statement.names:
                self._add(scope, (alias.asname or alias.name).split(".")[0], statement, None)
        elif isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            self._add(scope, statement.name, statement, None)
        elif isinstance(statement, (ast.Global, ast.Nonlocal)):
            for name in statement.names:
                self._add(scope, name, statement, None)

    def _bind_target(self, target: ast.expr, value: ast.expr, statement: ast.stmt, scope: ScopeNode) -> None:
        if isinstance(target, ast.Name):
            self._add(scope, target.id, statement, value)
        elif isinstance(target, (ast.Tuple, ast.List)):
            names = tuple(element.id if isinstance(element, ast.Name) else "" for element in target.elts)
            same_length = isinstance(value, (ast.Tuple, ast.List)) and len(value.elts) == len(target.elts)
            for index, element in enumerate(target.elts):
                if isinstance(element, ast.Starred):
                    for name in _names_in(element):
                        self._add(scope, name, statement, None)
                    continue
                if same_length:
                    self._bind_target(element, value.elts[index], statement, scope)  # type: ignore[union-attr]
                elif isinstance(element, ast.Name):
                    self._add(scope, element.id, statement, Unpacked(value, index, names, statement))
                else:
                    for name in _names_in(element):
                        self._add(scope, name, statement, None)
        elif isinstance(target, ast.Starred):
            for name in _names_in(target):
                self._add(scope, name, statement, None)

    def _add(self, scope: ScopeNode, name: str, statement: ast.stmt, value: ast.expr | Unpacked | None) -> None:
        self._names_of_scope.setdefault(id(scope), set()).add(name)
        self._assignments.setdefault((id(scope), name), []).append((statement, value))

    # -- queries -------------------------------------------------------------------------------

    def scope_of(self, node: ast.AST) -> ScopeNode | None:
        """The function, lambda, class body or module whose local names `node` reads."""
        child, parent = node, self.parents.get(node)
        while parent is not None:
            if isinstance(parent, _SCOPES) and not _is_signature_part(parent, child):
                return parent  # type: ignore[return-value]
            if isinstance(parent, ast.Module):
                return parent
            child, parent = parent, self.parents.get(parent)
        return None

    def statement_of(self, node: ast.AST) -> ast.stmt | None:
        while node is not None and not isinstance(node, ast.stmt):
            node = self.parents.get(node)  # type: ignore[assignment]
        return node

    def ancestors(self, node: ast.AST) -> Iterator[ast.AST]:
        parent = self.parents.get(node)
        while parent is not None:
            yield parent
            parent = self.parents.get(parent)

    def assignments(self, scope: ScopeNode, name: str) -> list[tuple[ast.stmt, ast.expr | Unpacked | None]]:
        self._index_scope(scope)
        return self._assignments.get((id(scope), name), [])

    def is_parameter(self, name: ast.Name) -> bool:
        """`name` reads a parameter of its function that nothing assigned before."""
        scope = self.scope_of(name)
        if scope is None:
            return False
        self._index_scope(scope)
        return (id(scope), name.id) in self.parameters and self.value_of(name) is None and not any(
            _ends_before(statement, self.statement_of(name)) for statement, _ in self.assignments(scope, name.id)  # type: ignore[arg-type]
        )

    def value_of(self, name: ast.Name) -> ast.expr | Unpacked | None:
        """The value `name` certainly holds where it is read, or None when that is not certain."""
        scope = self.scope_of(name)
        use = self.statement_of(name)
        if scope is None or use is None:
            return None
        found = self.assignments(scope, name.id)
        before = [(statement, value) for statement, value in found if _ends_before(statement, use)]
        if not before:
            return None
        statement, value = before[-1]
        if len(found) > 1:
            if not self.dominates(statement, use):
                return None
            if any(self._reaches_back(other, use, statement) for other, _ in found if not _ends_before(other, use)):
                return None
        return value

    def binding_of(self, name: ast.Name) -> object:
        """Which assignment (or parameter) `name` reads, as a comparable token; None if unknown."""
        scope = self.scope_of(name)
        use = self.statement_of(name)
        if scope is None or use is None:
            return None
        found = self.assignments(scope, name.id)
        before = [statement for statement, _ in found if _ends_before(statement, use)]
        if not before:
            return ("param", id(scope), name.id) if (id(scope), name.id) in self.parameters else ("free", name.id)
        if len(found) == 1 or self.dominates(before[-1], use):
            return id(before[-1])
        return None

    def resolve(self, node: ast.expr, depth: int = 8) -> ast.expr | Unpacked:
        """Follow local names to the value they certainly hold (the node itself when unknown)."""
        while isinstance(node, ast.Name) and depth > 0:
            value = self.value_of(node)
            if value is None:
                return node
            if isinstance(value, Unpacked):
                return value
            node = value
            depth -= 1
        return node

    def dominates(self, statement: ast.stmt, use: ast.stmt) -> bool:
        """`statement` runs whenever `use` does: it sits in a block that encloses `use`."""
        block_owner = self.parents.get(statement)
        return block_owner is not None and any(ancestor is block_owner for ancestor in self.ancestors(use))

    def _reaches_back(self, later: ast.stmt, use: ast.stmt, chosen: ast.stmt) -> bool:
        """A later assignment in a loop around `use` reaches it on the next iteration, unless the
        chosen assignment (which dominates `use`) sits in that loop too and overwrites it first."""
        for loop in self.ancestors(use):
            if isinstance(loop, (ast.For, ast.AsyncFor, ast.While)):
                if any(ancestor is loop for ancestor in self.ancestors(later)) or later is loop:
                    if not any(ancestor is loop for ancestor in self.ancestors(chosen)):
                        return True
        return False


def _ends_before(statement: ast.stmt, use: ast.stmt) -> bool:
    end = (statement.end_lineno or statement.lineno, statement.end_col_offset or 0)
    return statement is not use and end <= (use.lineno, use.col_offset)


def _all_arguments(arguments: ast.arguments) -> list[ast.arg]:
    found = [*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs]
    found += [argument for argument in (arguments.vararg, arguments.kwarg) if argument is not None]
    return found


def _is_signature_part(function: ast.AST, child: ast.AST) -> bool:
    if isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef)):
        return child in function.decorator_list or child is function.returns or child is function.args
    if isinstance(function, ast.ClassDef):
        return child in function.decorator_list or child in function.bases or child in function.keywords
    return isinstance(function, ast.Lambda) and child is function.args


def _names_in(target: ast.AST) -> list[str]:
    return [node.id for node in ast.walk(target) if isinstance(node, ast.Name)]


def local_values(tree: ast.Module) -> LocalValues:
    """The module's `LocalValues`, built once (on the module's index) and shared by every rule that asks."""
    from geolint.factbase import index_of

    index = index_of(tree)
    values = index.local_values
    if not isinstance(values, LocalValues):
        values = index.local_values = LocalValues(tree)
    return values


# ---------------------------------------------------------------------------------------------
# Rotation and translation of one pose


@dataclass(frozen=True)
class PosePart:
    """`kind` ("rotation" or "translation") of the pose identified by `pose`; `transposed` counts inversions."""

    kind: str
    pose: str
    transposed: bool = False
    batched: bool = False

    def flipped(self) -> PosePart:
        return PosePart(self.kind, self.pose, not self.transposed, self.batched)


_ROTATION_WORDS = frozenset({"r", "rot", "rotation", "rotmat", "rmat", "rotation_matrix"})
_TRANSLATION_WORDS = frozenset({"t", "trans", "translation", "tvec", "transl"})
_ROTATION_ATTRIBUTES = frozenset({"rotation", "R", "rot", "rotation_matrix", "rotmat"})
_TRANSLATION_ATTRIBUTES = frozenset({"translation", "t", "trans", "tvec"})


def pose_part(node: ast.expr, values: LocalValues, depth: int = 12) -> PosePart | None:
    """Which pose's rotation or translation `node` is, if the code says so; None otherwise."""
    if depth <= 0:
        return None
    inner = peel_same_value(node)
    if inner is not node:
        return pose_part(inner, values, depth - 1)
    transposed = transposed_operand(node)
    if transposed is not None:
        part = pose_part(transposed, values, depth - 1)
        return part.flipped() if part is not None and part.kind == "rotation" else None
    if isinstance(node, ast.Name):
        value = values.resolve(node)
        if isinstance(value, Unpacked):
            return _unpacked_part(value)
        return None if value is node else pose_part(value, values, depth - 1)
    if isinstance(node, ast.Subscript):
        return _sliced_part(node, values) or _keyed_part(node, values)
    if isinstance(node, ast.Attribute):
        if node.attr == "rotation_matrix" and _quaternion_of(node.value) is not None:
            return _quaternion_part(node.value, values, depth)
        return _named_part(node.attr, node.value, values)
    if isinstance(node, ast.Call):
        name = call_name(node)
        if isinstance(node.func, ast.Attribute) and not node.args and not node.keywords:
            if name == "as_matrix" or name == "as_dcm":
                return _from_rotation_object(node.func.value, values, depth)
            if name in ("rotation", "translation", "rotationMatrix", "matrix"):
                return _named_part("rotation" if name != "translation" else "translation", node.func.value, values)
        if name in ("quat2mat", "quaternion_to_matrix", "quaternion_to_rotation_matrix") and len(node.args) == 1:
            source = pose_part(node.args[0], values, depth - 1)
            return source if source is not None and source.kind == "rotation" else None
    return None


def _from_rotation_object(node: ast.expr, values: LocalValues, depth: int) -> PosePart | None:
    """`Rotation.from_quat(pose.rotation).as_matrix()`: the pose's rotation as a matrix."""
    if isinstance(node, ast.Name):
        resolved = values.resolve(node)
        if isinstance(resolved, Unpacked) or resolved is node:
            return None
        node = resolved
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
        if node.func.attr == "inv" and not node.args:
            part = _from_rotation_object(node.func.value, values, depth - 1)
            return part.flipped() if part is not None else None
        if node.func.attr.startswith("from_") and len(node.args) == 1 and not node.keywords:
            part = pose_part(node.args[0], values, depth - 1)
            return part if part is not None and part.kind == "rotation" else None
    return None


def _quaternion_of(node: ast.expr) -> ast.expr | None:
    """`Quaternion(x)` (pyquaternion), possibly `.inverse`: the argument."""
    if isinstance(node, ast.Attribute) and node.attr in ("inverse", "conjugate"):
        return _quaternion_of(node.value)
    if isinstance(node, ast.Call) and call_name(node) == "Quaternion" and len(node.args) == 1 and not node.keywords:
        return node.args[0]
    return None


def _quaternion_part(node: ast.expr, values: LocalValues, depth: int) -> PosePart | None:
    inverted = False
    while isinstance(node, ast.Attribute):
        inverted = not inverted
        node = node.value
    source = pose_part(node.args[0], values, depth - 1)  # type: ignore[attr-defined]
    if source is None or source.kind != "rotation":
        return None
    return source.flipped() if inverted else source


def _sliced_part(node: ast.Subscript, values: LocalValues) -> PosePart | None:
    """`T[:3, :3]` / `T[:3, 3]` (`3:`, `-1`, `3:4`), and with batch indices `poses[:, :3, :3]`."""
    indices = matrix_indices(node)
    if indices is None:
        return None
    batch, row, column = indices
    if not is_slice_upto(row, 3):
        return None
    if is_slice_upto(column, 3):
        kind = "rotation"
    elif int_value(column) in (3, -1) or _is_column_slice_from(column, 3):
        kind = "translation"
    else:
        return None
    key = pose_key(node.value, values)
    return PosePart(kind, f"{key}[{stack_key(batch)}]" if batch else key, batched=bool(batch))


def _is_column_slice_from(node: ast.expr, start: int) -> bool:
    if not isinstance(node, ast.Slice) or node.step is not None or int_value(node.lower) != start:
        return False
    return node.upper is None or int_value(node.upper) == start + 1


def _keyed_part(node: ast.Subscript, values: LocalValues) -> PosePart | None:
    """`pose["rotation"]` / `pose["translation"]`, `gt["cam_R_m2c"]` / `gt["cam_t_m2c"]`."""
    key = node.slice
    if not (isinstance(key, ast.Constant) and isinstance(key.value, str)):
        return None
    return _named_part(key.value, node.value, values)


def _named_part(word: str, base: ast.expr, values: LocalValues) -> PosePart | None:
    """Split a name such as `cam_R_w2c` into its part word (R) and the rest (cam_w2c), which names the pose."""
    if word in _ROTATION_ATTRIBUTES:
        return PosePart("rotation", pose_key(base, values))
    if word in _TRANSLATION_ATTRIBUTES:
        return PosePart("translation", pose_key(base, values))
    tokens = word.split("_")
    for position, token in enumerate(tokens):
        lowered = token if token in ("R", "t", "T") else token.lower()
        kind = (
            "rotation" if lowered in ("R", "rot", "rotation")
            else "translation" if lowered in ("t", "trans", "translation")
            else None
        )  # fmt: skip
        if kind is not None and len(tokens) > 1:
            rest = "_".join(tokens[:position] + ["*"] + tokens[position + 1 :])
            return PosePart(kind, f"{pose_key(base, values)}.{rest}")
    return None


def _unpacked_part(value: Unpacked) -> PosePart | None:
    """`R, t = split(T)`: the names say which element is which; both must be named."""
    kinds = [_kind_of_local_name(name) for name in value.names]
    if "rotation" not in kinds or "translation" not in kinds:
        return None
    kind = kinds[value.index]
    if kind is None:
        return None
    return PosePart(kind, f"<unpacked at {id(value.statement)}>")


def _kind_of_local_name(name: str) -> str | None:
    lowered = name.lower()
    words = lowered.split("_")
    if name in ("R", "Rot") or lowered in _ROTATION_WORDS or words[0] in ("r", "rot", "rotation") or words[-1] in ("r", "rot", "rotation"):
        return "rotation"
    if name == "t" or lowered in _TRANSLATION_WORDS or words[0] in ("t", "trans", "translation") or words[-1] in ("t", "trans", "translation", "tvec"):
        return "translation"
    return None


def pose_key(base: ast.expr, values: LocalValues) -> str:
    """Text of the pose expression, plus which assignment its root name reads (a rebound T is another pose)."""
    root = base
    while isinstance(root, (ast.Attribute, ast.Subscript)):
        root = root.value
    if isinstance(root, ast.Name):
        binding = values.binding_of(root)
        if binding is not None:
            return f"{ast.unparse(base)}@{binding}"
    return ast.unparse(base)


_AGGREGATES = frozenset({"mean", "median", "average", "nanmean"})


def translation_source(node: ast.expr, values: LocalValues, depth: int = 8) -> PosePart | None:
    """The pose translation a value is made of: the translation itself, its mean over a stack
    (`poses[:, :3, 3].mean(0)`, `torch.mean(t, dim=0)`), its negation or a scaling of it. A local
    name counts when every value it is ever given in its function is such a value or zeros."""
    if depth <= 0:
        return None
    part = pose_part(node, values)
    if part is not None:
        return part if part.kind == "translation" else None
    inner = peel_same_value(node)
    if inner is not node:
        return translation_source(inner, values, depth - 1)
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        return translation_source(node.operand, values, depth - 1)
    if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Mult, ast.Div)):
        for side, other in ((node.left, node.right), (node.right, node.left)):
            if isinstance(other, (ast.Constant, ast.Name, ast.Attribute)) and (side is node.left or isinstance(node.op, ast.Mult)):
                found = translation_source(side, values, depth - 1)
                if found is not None and pose_part(other, values) is None:
                    return found
        return None
    if isinstance(node, ast.Call) and call_name(node) in _AGGREGATES:
        func = node.func
        if isinstance(func, ast.Attribute) and dotted(func.value) in ("np", "numpy", "torch", "jnp"):
            return translation_source(node.args[0], values, depth - 1) if node.args else None
        return translation_source(func.value, values, depth - 1) if isinstance(func, ast.Attribute) else None
    if isinstance(node, ast.IfExp):
        return _every_source([node.body, node.orelse], values, depth)
    if isinstance(node, ast.Name):
        scope = values.scope_of(node)
        if scope is None:
            return None
        return _every_source([value for _, value in values.assignments(scope, node.id)], values, depth)
    return None


def _every_source(candidates: list, values: LocalValues, depth: int) -> PosePart | None:
    """The translation all candidate values come from, zeros aside; None if one comes from elsewhere."""
    found = None
    for value in candidates:
        if isinstance(value, ast.Call) and call_name(value) in ("zeros_like", "zeros"):
            continue
        source = translation_source(value, values, depth - 1) if isinstance(value, ast.expr) else None
        if source is None:
            return None
        found = found or source
    return found


def peel_same_value(node: ast.expr) -> ast.expr:
    """`t.copy()`, `t.to(device)`, `t[:, None]`, `t.reshape(3, 1)`, `np.asarray(t)`: the same values."""
    if isinstance(node, ast.Call):
        func = node.func
        if isinstance(func, ast.Attribute) and func.attr in _SAME_VALUE_METHODS:
            return func.value
        if call_name(node) in _SAME_VALUE_FUNCTIONS and node.args and not isinstance(node.args[0], ast.Starred):
            return node.args[0]
    if isinstance(node, ast.Subscript) and _is_broadcast_index(node):
        return node.value
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.UAdd):
        return node.operand
    return node


def _is_broadcast_index(node: ast.Subscript) -> bool:
    """`x[:, None]`, `x[None]`, `x[..., np.newaxis]`: only new axes and full slices."""
    indices = subscript_indices(node)
    has_new_axis = False
    for index in indices:
        if (isinstance(index, ast.Constant) and index.value is None) or dotted(index) in ("np.newaxis", "numpy.newaxis"):
            has_new_axis = True
        elif not is_batch_index(index):
            return False
    return has_new_axis


def transposed_operand(node: ast.expr) -> ast.expr | None:
    """The matrix a transpose (or inverse) is taken of: `R.T`, `R.mT`, `R.t()`, `R.transpose(1, 2)`,
    `R.permute(0, 2, 1)`, `np.transpose(R)`, `torch.transpose(R, -1, -2)`, `np.linalg.inv(R)`."""
    if isinstance(node, ast.Attribute) and node.attr in ("T", "mT"):
        return node.value
    if not isinstance(node, ast.Call) or node.keywords:
        return None
    func = node.func
    name = call_name(node)
    if isinstance(func, ast.Attribute) and name in ("t", "transpose", "permute", "swapaxes", "inverse"):
        axes = [int_value(argument) for argument in node.args]
        if name == "inverse" and not axes:
            return func.value
        if name in ("t", "transpose") and not axes:
            return func.value
        if name in ("transpose", "swapaxes") and len(axes) == 2 and _swaps_last_two(axes):
            return func.value
        if name == "permute" and len(axes) >= 2 and _permutes_last_two(axes):
            return func.value
        if name in ("transpose", "swapaxes") and len(node.args) >= 1:
            # np.transpose(R) / torch.transpose(R, 1, 2) called through a module
            if dotted(func.value) in ("np", "numpy", "torch", "jnp") and not isinstance(node.args[0], ast.Starred):
                rest = [int_value(argument) for argument in node.args[1:]]
                if not rest or _swaps_last_two(rest):
                    return node.args[0]
    if name in _INVERTING_FUNCTIONS and len(node.args) == 1 and isinstance(func, ast.Attribute):
        if dotted(func.value) in ("np.linalg", "numpy.linalg", "torch.linalg", "torch", "la", "linalg", "scipy.linalg"):
            return node.args[0]
    return None


def _swaps_last_two(axes: list[int | None]) -> bool:
    return sorted(axes) in ([-2, -1], [1, 2], [0, 1]) if None not in axes else False  # type: ignore[type-var]


def _permutes_last_two(axes: list[int | None]) -> bool:
    if None in axes:
        return False
    count = len(axes)
    return axes == [*range(count - 2), count - 1, count - 2]


# ---------------------------------------------------------------------------------------------
# Applying a rotation


@dataclass(frozen=True)
class Application:
    """`rotation` acting on `operand`; `inverse` when the inverse (transpose) is what acts."""

    node: ast.expr
    product: ast.expr
    rotation: PosePart
    operand: ast.expr
    inverse: bool


_MATMUL_FUNCTIONS = frozenset({"dot", "matmul", "bmm", "mm"})


def matmul_operands(node: ast.AST) -> tuple[ast.expr, ast.expr] | None:
    """(left, right) of `a @ b`, `np.dot(a, b)`, `a.dot(b)`, `torch.matmul(a, b)`, `torch.bmm(a, b)`."""
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.MatMult):
        return node.left, node.right
    if not isinstance(node, ast.Call) or node.keywords or call_name(node) not in _MATMUL_FUNCTIONS:
        return None
    func = node.func
    if not isinstance(func, ast.Attribute):
        return None
    if dotted(func.value) in ("np", "numpy", "torch", "jnp", "tf", "cp"):
        return (node.args[0], node.args[1]) if len(node.args) == 2 and not _has_starred(node.args) else None
    if len(node.args) == 1 and not _has_starred(node.args):
        return func.value, node.args[0]
    return None


def _has_starred(arguments: list[ast.expr]) -> bool:
    return any(isinstance(argument, ast.Starred) for argument in arguments)


def application(node: ast.expr, values: LocalValues) -> Application | None:
    """A pose's rotation applied to something: column form `R @ x` or row form `x @ R.T`.

    A transpose of the whole product (`(R @ x.T).T`) applies the same rotation.
    """
    outer = node
    for _ in range(8):
        if isinstance(node, ast.Name):
            value = values.resolve(node)
            if isinstance(value, Unpacked) or value is node:
                return None
            node = value
            continue
        inner = peel_same_value(node)
        transposed = transposed_operand(inner) if inner is node else None
        if inner is not node:
            node = inner
        elif transposed is not None and matmul_operands(transposed):
            node = transposed
        else:
            break
    operands = matmul_operands(node)
    if operands is None:
        return None
    left, right = operands
    rotation = pose_part(left, values)
    if rotation is not None and rotation.kind == "rotation":
        return Application(outer, node, rotation, right, rotation.transposed)
    rotation = pose_part(right, values)
    if rotation is not None and rotation.kind == "rotation":
        # x @ R applies R's transpose to each row x.
        return Application(outer, node, rotation, left, not rotation.transposed)
    return None


def difference_with(node: ast.expr, values: LocalValues, depth: int = 6) -> tuple[ast.expr, PosePart] | None:
    """`x - t` (seen through names, copies, reshapes, transposes): x and the translation part t."""
    for _ in range(depth):
        peeled = peel_same_value(node)
        transposed = transposed_operand(peeled)
        if peeled is not node:
            node = peeled
        elif transposed is not None:
            node = transposed
        elif isinstance(node, ast.Name):
            value = values.resolve(node)
            if isinstance(value, Unpacked) or value is node:
                return None
            node = value
        else:
            break
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Sub):
        part = pose_part(node.right, values)
        if part is not None and part.kind == "translation":
            return node.left, part
    return None


# ---------------------------------------------------------------------------------------------
# Matrix shapes


ROTATION_MAKERS = frozenset(
    {"quat2mat", "euler2mat", "axangle2mat", "quaternion_to_matrix", "euler_angles_to_matrix",
     "axis_angle_to_matrix", "matrix_from_quaternion", "matrix_from_euler", "active_matrix_from_angle",
     "matrix_from_axis_angle"}
)  # fmt: skip
_POSE_MAKERS = frozenset(
    {"quaternion_matrix", "euler_matrix", "translation_matrix", "rotation_matrix", "compose_matrix",
     "transform_from", "transform_from_pq", "homogeneous_matrix", "make_transform", "pose_to_matrix"}
)  # fmt: skip
_SIZE_MAKERS = frozenset({"eye", "identity"})
_FILLED_MAKERS = frozenset({"zeros", "ones", "empty", "full"})


def matrix_shape(node: ast.expr, values: LocalValues) -> int | None:
    """3 for an array certainly made as a single 3x3 matrix, 4 for a single 4x4; else None.

    Only makers that fix the shape count: `np.eye(3)`, a literal 3x3, `T[:3, :3]`,
    transforms3d `quat2mat`, `cv2.Rodrigues(r)[0]`, pyquaternion `.rotation_matrix`,
    `.reshape(3, 3)` (3); `np.eye(4)`, `np.zeros((4, 4))`, tf `quaternion_matrix`, pyquaternion
    `.transformation_matrix` (4). A copy or transpose keeps the shape.
    """
    shape = square_shape(node, values)
    return shape[0] if shape is not None and not shape[1] else None


def square_shape(node: ast.expr, values: LocalValues, depth: int = 8) -> tuple[int, bool] | None:
    """(3 or 4, stacked): the size of the last two axes of an array of square matrices, and whether
    there are batch axes ahead of them (`np.zeros((n, 4, 4))`, `torch.eye(4).repeat(n, 1, 1)`)."""
    if depth <= 0:
        return None
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
        method = node.func.attr
        if method in ("reshape", "view") and node.args:
            sizes = [int_value(argument) for argument in node.args]
            if len(sizes) == 1 and isinstance(node.args[0], (ast.Tuple, ast.List)):
                sizes = [int_value(element) for element in node.args[0].elts]
            return _square_of_sizes(sizes)
        if method in ("tile", "repeat", "broadcast_to") and node.args and dotted(node.func.value) in ("np", "numpy", "torch"):
            inner = square_shape(node.args[0], values, depth - 1)
            return (inner[0], True) if inner is not None else None
        if method in ("repeat", "expand") or (method == "unsqueeze" and int_value(node.args[0] if node.args else None) == 0):
            inner = square_shape(node.func.value, values, depth - 1)
            return (inner[0], True) if inner is not None else None
    if isinstance(node, ast.Subscript) and _is_broadcast_index(node) and int_value(subscript_indices(node)[0]) is None:
        inner = square_shape(node.value, values, depth - 1)
        return (inner[0], True) if inner is not None else None
    inner = peel_same_value(node)
    if inner is not node and not _reshapes(node):
        return square_shape(inner, values, depth - 1)
    transposed = transposed_operand(node)
    if transposed is not None:
        return square_shape(transposed, values, depth - 1)
    if isinstance(node, ast.Name):
        value = values.resolve(node)
        if isinstance(value, Unpacked) or value is node:
            return None
        return square_shape(value, values, depth - 1)
    if isinstance(node, (ast.List, ast.Tuple)):
        size = _literal_square(node)
        return (size, False) if size is not None else None
    if isinstance(node, ast.Subscript):
        indices = matrix_indices(node)
        if indices is not None and is_slice_upto(indices[1], 3) and is_slice_upto(indices[2], 3):
            return (3, bool(indices[0]))
        if call_name(node.value) == "Rodrigues" and int_value(node.slice) == 0:
            return (3, False)
        return None
    if isinstance(node, ast.Attribute):
        if _quaternion_of(node.value) is not None and node.attr in ("rotation_matrix", "transformation_matrix"):
            return (3 if node.attr == "rotation_matrix" else 4, False)
        return None
    if isinstance(node, ast.Call):
        name = call_name(node)
        if name in (_SIZE_MAKERS | _FILLED_MAKERS) and not _array_module_call(node):
            return None  # sympy's `eye(3)` / `zeros(3, 3)` make matrices with flat indexing (`s[3]`)
        if name in _SIZE_MAKERS and len(node.args) == 1:
            size = int_value(node.args[0])
            return (size, False) if size in (3, 4) else None
        if name in _FILLED_MAKERS and node.args:
            shape = node.args[0]
            if isinstance(shape, (ast.Tuple, ast.List)):
                return _square_of_sizes([int_value(element) for element in shape.elts])
            if (dotted(node.func) or "").split(".")[0] != "torch":
                return None  # sizes as separate arguments: torch's signature, not numpy's
            return _square_of_sizes([int_value(argument) for argument in node.args])
        if name in ROTATION_MAKERS:
            return (3, False) if not _stacks(node) else None
        if name in _POSE_MAKERS and _is_tf_style_maker(node):
            return (4, False)
    return None


# Module names under which `eye`/`zeros`/... are array makers (as written, or as conventionally imported).
_ARRAY_MODULE_ROOTS = frozenset({"np", "numpy", "torch", "jnp", "jax", "cp", "cupy", "onp"})


def _array_module_call(node: ast.Call) -> bool:
    """`np.eye(3)`, `torch.zeros(4, 4)`, `numpy.identity(4)`: a maker called through an array module."""
    return (dotted(node.func) or "").split(".")[0] in _ARRAY_MODULE_ROOTS


def _square_of_sizes(sizes: list[int | None]) -> tuple[int, bool] | None:
    """(4, True) for sizes (n, 4, 4); (3, False) for (3, 3)."""
    if len(sizes) < 2 or sizes[-1] != sizes[-2] or sizes[-1] not in (3, 4):
        return None
    return (sizes[-1], len(sizes) > 2)  # type: ignore[return-value]


def _reshapes(node: ast.expr) -> bool:
    return isinstance(node, ast.Call) and call_name(node) in ("reshape", "view", "unsqueeze", "squeeze", "flatten", "ravel", "expand", "expand_dims")


def _stacks(node: ast.Call) -> bool:
    """A torch maker (pytorch3d `quaternion_to_matrix`) keeps the batch shape of its input: not known 2-D."""
    return call_name(node) in ("quaternion_to_matrix", "euler_angles_to_matrix", "axis_angle_to_matrix")


def _is_tf_style_maker(node: ast.Call) -> bool:
    """tf.transformations / transforms3d style 4x4 makers, not a method of some object."""
    return call_name(node) != "rotation_matrix" or dotted(node.func) in ("tf.transformations.rotation_matrix", "tft.rotation_matrix", "transformations.rotation_matrix")


def _literal_square(node: ast.expr) -> int | None:
    if not isinstance(node, (ast.List, ast.Tuple)) or len(node.elts) not in (3, 4):
        return None
    size = len(node.elts)
    if all(isinstance(row, (ast.List, ast.Tuple)) and len(row.elts) == size for row in node.elts):
        return size
    return None



class AllOf:
    """A rule trigger: the source matches every pattern (a cheap gate before any tree is walked).

    A pattern is a regex, or an object with `search(text)` (`POSE_PART_TEXT`). A regex is searched
    one top-level alternative at a time, a plain word with `in`: the regex engine scans quickly
    for a pattern's first characters, and an alternation of many has no first character to scan for.
    """

    def __init__(self, *patterns: str | TextTest) -> None:
        self.patterns = tuple(_text_test(pattern) for pattern in patterns)
        self._last: tuple[str, bool] | None = None  # rules sharing a trigger ask about the same text in a row

    def search(self, source: str, /) -> bool:
        last = self._last
        if last is not None and last[0] is source:
            return last[1]
        found = all(pattern.search(source) for pattern in self.patterns)
        self._last = (source, found)
        return found

    def search_with(self, source: str, config: object, /) -> bool:
        """The engine's prefilter entry point (no configuration read)."""
        return self.search(source)


class TextTest(Protocol):
    pattern: str

    def search(self, source: str, /) -> object: ...


class _AnyAlternative:
    """A regex as its top-level alternatives, each searched on its own (plain words with `in`)."""

    def __init__(self, pattern: str) -> None:
        self.pattern = pattern
        alternatives = _top_level_alternatives(pattern)
        self.words = tuple(part for part in alternatives if part and re.escape(part) == part)
        self.regexes = tuple(_regex_test(part) for part in alternatives if not (part and re.escape(part) == part))

    def search(self, source: str, /) -> bool:
        return any(word in source for word in self.words) or any(regex.search(source) for regex in self.regexes)


def _regex_test(pattern: str) -> re.Pattern[str] | _LeftContext:
    r"""The regex, or for one led by `\b` or `\w\s*` the rest of it with that lead checked in Python:
    the regex engine scans quickly for the rest's first characters (`inv(`, `[`), and not at all for
    a lead that can start anywhere."""
    for lead, check in ((r"\b", _at_word_boundary), (r"\w\s*", _after_word_and_spaces)):
        rest = pattern[len(lead) :]
        if pattern.startswith(lead) and rest and rest[0] not in "*+?{|" and not rest.startswith(r"\s"):
            return _LeftContext(re.compile(rest), check)
    return re.compile(pattern)


class _LeftContext:
    """`lead + rest` searched as `rest`, each match kept when `accept(source, start)` holds for its lead."""

    def __init__(self, rest: re.Pattern[str], accept) -> None:  # type: ignore[no-untyped-def]
        self.rest = rest
        self.accept = accept

    def search(self, source: str) -> bool:
        return _any_at(self.rest, source, lambda text, match: self.accept(text, match.start()))


def _at_word_boundary(source: str, at: int) -> bool:
    r"""`\b` at `at`: a word character on exactly one side."""
    before = at > 0 and _is_word_character(source[at - 1])
    return before != (at < len(source) and _is_word_character(source[at]))


def _after_word_and_spaces(source: str, at: int) -> bool:
    r"""`\w\s*` ends at `at`: past any whitespace before it, a word character."""
    at -= 1
    while at >= 0 and source[at].isspace():
        at -= 1
    return at >= 0 and _is_word_character(source[at])


def _text_test(pattern: str | TextTest) -> TextTest:
    return _AnyAlternative(pattern) if isinstance(pattern, str) else pattern


def _top_level_alternatives(pattern: str) -> list[str]:
    """`a|b(c|d)|[|]` -> ["a", "b(c|d)", "[|]"]: split at `|` outside groups and character classes."""
    parts, current, depth, position = [], [], 0, 0
    in_class = False
    while position < len(pattern):
        character = pattern[position]
        if character == "\\":
            current.append(pattern[position : position + 2])
            position += 2
            continue
        if in_class:
            if character == "]" and not _opens_class_at(pattern, position):
                in_class = False
        elif character == "[":
            in_class = True
        elif character == "(":
            depth += 1
        elif character == ")":
            depth -= 1
        elif character == "|" and depth == 0:
            parts.append("".join(current))
            current = []
            position += 1
            continue
        current.append(character)
        position += 1
    parts.append("".join(current))
    return parts


def _opens_class_at(pattern: str, position: int) -> bool:
    """A `]` right after `[` or `[^` is a literal member of the class, not its end."""
    return pattern[position - 1] == "[" or (pattern[position - 2 : position] == "[^")


class _PosePartText:
    """Source text that can hold a pose's rotation or translation: a `[:3, 3]`-style slice, a part
    attribute or key, or `R, t` unpacked together. `search` answers as `pattern` would, faster
    (the unpacking alternative starts at every word and backtracks through it)."""

    pattern = (
        r"\[[^\]\n]*:\s*3\s*,\s*(?:3|-1|3:)|\.(?:rotation|translation|R|t|rot|trans|tvec)\b"
        r"|['\"]\w*(?:_R_|_t_|rotation|translation)\w*['\"]|['\"](?:R|t)['\"]"
        r"|\b\w*(?:R|rot|rotation)\w*\s*,\s*\w*(?:t|trans|translation)\w*\s*="
    )
    _SLICE_OR_ATTRIBUTE = re.compile(r"\[[^\]\n]*:\s*3\s*,\s*(?:3|-1|3:)|\.(?:rotation|translation|R|t|rot|trans|tvec)\b")
    _QUOTED_LETTER = tuple(f"{a}{letter}{b}" for letter in "Rt" for a in "'\"" for b in "'\"")
    _KEY_WORD = re.compile(r"_R_|_t_|rotation|translation")
    _UNPACKED_SECOND = re.compile(r",\s*\w*t\w*\s*=")

    def search(self, source: str, /) -> bool:
        return (
            self._SLICE_OR_ATTRIBUTE.search(source) is not None
            or any(text in source for text in self._QUOTED_LETTER)
            or _any_at(self._KEY_WORD, source, _inside_quoted_word)
            or _any_at(self._UNPACKED_SECOND, source, _after_rotation_word)
        )


def _is_word_character(character: str) -> bool:
    return character == "_" or character.isalnum()  # exactly `\w` for str patterns


def _any_at(pattern: re.Pattern[str], source: str, accept) -> bool:  # type: ignore[no-untyped-def]
    """Whether `accept(source, match)` holds for a match starting anywhere (overlapping ones included)."""
    match = pattern.search(source)
    while match is not None:
        if accept(source, match):
            return True
        match = pattern.search(source, match.start() + 1)
    return False


def _inside_quoted_word(source: str, match: re.Match[str]) -> bool:
    r"""`['"]\w*<match>\w*['"]`: the word around the match is quoted on both sides."""
    start, end = match.start(), match.end()
    while start > 0 and _is_word_character(source[start - 1]):
        start -= 1
    while end < len(source) and _is_word_character(source[end]):
        end += 1
    return start > 0 and source[start - 1] in "'\"" and end < len(source) and source[end] in "'\""


def _after_rotation_word(source: str, match: re.Match[str]) -> bool:
    r"""`\b\w*(?:R|rot)\w*\s*` right before the comma: the word before it names a rotation."""
    end = match.start()
    while end > 0 and source[end - 1].isspace():
        end -= 1
    start = end
    while start > 0 and _is_word_character(source[start - 1]):
        start -= 1
    word = source[start:end]
    return "R" in word or "rot" in word


POSE_PART_TEXT = _PosePartText()
MATMUL_TEXT = r"@|\.dot\(|matmul\(|bmm\("
