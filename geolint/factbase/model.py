"""The fact base the rules query: what an expression is (its `algebra.Kind`), which frames it lives in,
and why (the evidence), on CPython's `ast`.

Evidence, strongest first:

1. explicit declarations: `from_frame=` / `to_frame=` keywords (autolab_core `RigidTransform`),
   `.as_frames(from, to)`, tf2 `lookup_transform(target, source, t)`;
2. library semantics, from the tables in `geolint.factbase.vocabulary`, keyed by qualified names
   resolved through the module's imports (`import torch.nn.functional as F`);
3. data flow within a module: assignments, tuple unpacking, loops and comprehensions, `self.x`
   attributes, helpers whose every `return` agrees;
4. names (`geolint.semantic.names`), the weakest, read under the project's naming convention
   (`geolint.factbase.conventions`): where the order of `T_a_b` is not known, a frame question is
   answered under both orders and the rules speak only when both agree.

Every question answers None when the evidence is missing or contradictory.
"""

from __future__ import annotations

import ast
from ast import (
    AST, Add, AnnAssign, Assign, AsyncFunctionDef, AsyncWith, Attribute, BinOp, BoolOp, Call, ClassDef, Compare,
    Constant, Div, FloorDiv, FunctionDef, JoinedStr, Lambda, MatMult, Mod, Mult, Name, Not, Pow, Slice, Starred, Sub,
    Subscript, USub, UnaryOp, With,
)
import builtins
import re
from typing import Callable, Final, Literal, Sequence, TypeVar

from geolint import algebra
from geolint.algebra import FREE, Kind
from geolint.factbase import summaries
from geolint.factbase import vocabulary as vocab
from geolint.factbase.declarations import declared_call_frames
from geolint.factbase.fact_types import DST_FIRST, GEOMETRIC, OPERATORS, SRC_FIRST, FrameFact, Homogeneous, MatMul
from geolint.factbase.spans import LastNameTarget, last_name_target, replace_span
from geolint.factbase.syntax import (
    dotted_name,
    einsum_operands,
    flat_literal,
    is_full_slice,
    is_index,
    is_scalar_annotation,
    is_slice_upto,
    is_transpose,
    is_zero,
    keyword,
    last_name,
    number,
    positional_args,
    statements_under,
    string,
    subscript_parts,
    transposed_value,
    walk_within,
)
from geolint.factbase.kind_summaries import HOMOGENEOUS, KINDS
from geolint.factbase.project_files import may_be_project_import, module_file
from geolint.factbase.summaries import Summary, SummaryFamily
from geolint.factbase.reaching import every_binding_reaches, reaching_bindings
from geolint.factbase.index import (
    Binding,
    LoopBinding,
    ModuleIndex,
    OpaqueBinding,
    ParamBinding,
    UnpackBinding,
)
from geolint.lint_types import Config
from geolint.semantic.names import (
    NameFrames,
    frames_of_name,
    kind_of_name,
    order_dependent,
    same_frame,
    states_geometry,
)

_T = TypeVar("_T")
_A = TypeVar("_A")  # an analysis built on one fact base
_S = TypeVar("_S", bound=Summary)  # a family's summary

# Words that make an extrinsics-named pose a relative one: `init_rel_w2c = inv(c2w_new @ w2c_last)`
# is a world-to-world correction that `w2c_ref @ rel_w2c` applies, named after the pose it corrects.
EXTRINSICS_EVIDENCE: Final = "states camera extrinsics"  # the evidence of a name read by its extrinsics word alone
RELATIVE_WORDS: Final = frozenset({"rel", "relative", "delta", "diff", "residual", "incr", "increment", "update", "correction", "corr"})
_MAX_DEPTH: Final = 60
_MAX_REEXPORTS: Final = 3  # package `__init__` modules followed to the module that defines a helper
_MISSING: Final = object()


_BUILTIN_NAMES: Final = frozenset(dir(builtins))  # `len(x)` under a star import: the builtin, in all but odd code
_MATMUL_CALL_NAMES: Final = frozenset(("dot", "matmul", "bmm", "einsum"))  # what `FactBase.matmul` reads as a product


def valid_kind(outcome: algebra.Outcome | None) -> Kind | None:
    """The kind `geolint.algebra` gives an operation that is valid geometry; None for one it does not judge,
    and for an invalid one (`p + q`: a rule reports it, and its result is no evidence of a kind)."""
    return outcome.kind if outcome is not None and outcome.problem is None else None


class FactBase:
    """What the expressions of one module are, under one config. Built once per file."""

    def __init__(
        self,
        index: ModuleIndex,
        config: Config,
        path: str = "<string>",
        orders: tuple[str, ...] = (DST_FIRST, SRC_FIRST),
        order_names_mixed: bool = False,
        cross_module: bool = True,
        project: summaries.ProjectSummaries | None = None,
        names_stated: bool = False,
    ) -> None:
        self.index = index
        self.config = config
        self.path = path
        # the naming orders `T_a_b` may be read in; one when the project's convention is known
        self.orders = orders
        # the project declares `T_a_b` names in both orders: such a name alone is no evidence
        self.order_names_mixed = order_names_mixed
        # the naming convention is stated (config, or the project's declarations in one order): a
        # frame finding may rest on names alone; otherwise one side must be declared
        self.names_stated = names_stated
        # whether helpers imported from other project modules are summarised
        self.cross_module = cross_module
        # the summaries of the project's helpers this module's lint reads (shared with the fact
        # bases of the other modules they come from)
        if project is None:
            project = summaries.ProjectSummaries(config, FactBase)
            project.adopt(self)
        self.project = project
        self._memo: dict[tuple[str, int, str], object] = {}
        self._qualified: dict[int, object] = {}
        # facts of the module's text alone (`module_fact`), shared with this fact base's scratch copies
        self._module_facts: dict[str, object] = {}
        self._active: set[tuple[str, int, str]] = set()

    def scratch(self) -> FactBase:
        """A fact base of the same module with no memoised facts (qualified names and the facts of the
        module's text, which no summary changes, are shared): a summary computed in it keeps nothing
        derived from a provisional one."""
        fresh = FactBase(
            self.index, self.config, self.path, self.orders, self.order_names_mixed, self.cross_module, self.project, self.names_stated
        )
        fresh._qualified = self._qualified
        fresh._module_facts = self._module_facts
        return fresh

    def module_fact(self, tag: str, compute: Callable[[], _T]) -> _T:
        """`compute()` once per module, for a fact read from the module's text and flow alone (no kind, no
        summary): every scratch copy a summary computes in reads the same answer instead of walking the
        module again."""
        facts = self._module_facts
        if tag not in facts:
            facts[tag] = compute()
        return facts[tag]  # type: ignore[return-value]

    # -- plumbing -------------------------------------------------------------------------
    def shared(self, analysis: Callable[[FactBase], _A]) -> _A:
        """The one instance of an analysis built on this fact base (`AngleUnits`, `QuaternionFlow`):
        every rule that asks gets it, and with it what it has memoised already. The analysis refers
        back to this fact base: `close` breaks that cycle."""
        return self.memoised("analysis", analysis, lambda: analysis(self))  # type: ignore[arg-type]

    def close(self) -> None:
        """Forget the memoised facts and shared analyses (which refer back to this fact base, a cycle
        only the cycle collector would otherwise free, with the syntax tree it keeps alive)."""
        self._memo.clear()
        self._module_facts = {}  # a scratch copy's close leaves the module's own facts to it

    def _cached(self, tag: str, node: AST, compute: Callable[..., _T], order: str = "") -> _T | None:
        """`compute(self, node)` (with `order`, when given) once per node, tag and order, guarded
        against cycles. `compute` is the class's function, not a closure: nothing is allocated on
        a hit (asked hundreds of thousands of times a run)."""
        key = (tag, id(node), order)
        value = self._memo.get(key, _MISSING)  # one lookup on a hit
        if value is not _MISSING:
            return value  # type: ignore[return-value]
        active = self._active
        if key in active or len(active) > _MAX_DEPTH:
            return None  # a cycle (`x = x + v`) or runaway depth: no evidence
        active.add(key)
        try:
            value = compute(self, node, order) if order else compute(self, node)
        finally:
            active.discard(key)
        self._memo[key] = value
        return value  # type: ignore[return-value]

    def _of_bindings(self, tag: str, name: Name, compute: Callable[[FactBase, str, Sequence[Binding], str], _T], order: str = "") -> _T | None:
        """`compute(self, name.id, bindings, order)` over the bindings that reach `name`. For a name
        bound more often than flow order is kept for, every use reads all of them: then once per
        name and scope, every use reading that answer (and a use in one of those bindings, `T = T @ D`,
        a cycle: None), so a scope costs its size, not its uses times its bindings."""
        bindings = self.bindings(name) or ()
        if not every_binding_reaches(bindings):
            return compute(self, name.id, bindings, order)
        return self._cached(tag, bindings, lambda facts, *_: compute(facts, name.id, bindings, order), order)  # type: ignore[arg-type]

    def memoised(self, tag: str, node: AST, compute: Callable[[], _T]) -> _T:
        """`compute()` once per `node` and `tag` for this module (no cycle guard: for facts that ask no others)."""
        key = (tag, id(node), "")
        if key not in self._memo:
            self._memo[key] = compute()
        return self._memo[key]  # type: ignore[return-value]

    def parent(self, node: AST) -> AST | None:
        return self.index.parents.get(node)

    def code_of(self, node: AST) -> str:
        return self.index.code_of(node)

    def bindings(self, name: Name) -> Sequence[Binding] | None:
        """The bindings of `name` that can reach it: in its own scope, in order (`reaching`);
        from an enclosing scope, all of them (a list its uses share: never change it)."""
        scope = self.index.scope_of(name)
        own = scope.bindings.get(name.id)
        if own is not None:
            return reaching_bindings(self.index, scope, name, own)
        return self.index.lookup(name.id, scope)

    def qualified_name(self, node: AST) -> str | None:
        """The dotted name with its first component resolved through the module's imports."""
        key = id(node)
        known = self._qualified.get(key, _MISSING)
        if known is _MISSING:
            known = self._qualified[key] = self._qualify(node)
        return known  # type: ignore[return-value]

    def called_name(self, func: AST) -> str | None:
        """The last part of `qualified_name(func)`, without resolving it: `PQ` imported by `from
        pyquaternion import Quaternion as PQ` is `Quaternion`, `np.cos` is `cos`. A cheap first test
        for the rules' tables of API names."""
        kind = type(func)
        if kind is Attribute:
            return func.attr  # type: ignore[attr-defined,no-any-return]
        if kind is Name:
            imported = self.index.imports.get(func.id)  # type: ignore[attr-defined]
            return func.id if imported is None else imported.rpartition(".")[2]  # type: ignore[attr-defined,no-any-return]
        return None

    def _qualify(self, node: AST) -> str | None:
        dotted = dotted_name(node)
        if dotted is None:
            return None
        head, _, rest = dotted.partition(".")
        resolved = self.index.imports.get(head)
        if resolved is None:
            resolved = vocab.CONVENTIONAL_ALIASES.get(head) if head not in self._local_names() else None
            if resolved is None:
                return dotted
        return f"{resolved}.{rest}" if rest else resolved

    def _local_names(self) -> set[str]:
        return self.module_fact("local names", lambda: {name for scope in self.index.scopes.values() for name in scope.bindings})

    def is_array_call(self, func: AST, *names: str) -> bool:
        """Whether `func` is `<array library>.<one of names>` (numpy, torch, jax.numpy, cupy)."""
        if self.called_name(func) not in names:
            return False
        qualified = self.qualified_name(func)
        if qualified is None:
            return False
        module, _, name = qualified.rpartition(".")
        return name in names and module in vocab.ARRAY_MODULES

    def is_module_like(self, node: AST) -> bool:
        """`np`, `np.linalg`, `scipy.spatial`: a (dotted) module name, never a value."""
        if isinstance(node, Attribute):
            return node.attr not in ("T", "mT") and self.is_module_like(node.value)
        return isinstance(node, Name) and (node.id in vocab.MODULE_LIKE or node.id in self.index.imported_modules)

    def is_norm_call(self, node: AST) -> bool:
        """`np.linalg.norm(x, ...)`, `torch.norm(x)`, `x.norm(dim=-1)`, possibly indexed (`[:, None]`)."""
        if isinstance(node, Subscript):
            node = node.value
        return isinstance(node, Call) and last_name(node.func) in vocab.NORM_FUNCTIONS

    def expects_failure(self, node: AST) -> bool:
        """Whether `node` is inside `with pytest.raises(...)` / `self.assertRaises(...)`."""
        current = self.parent(node)
        while current is not None:
            if isinstance(current, (With, AsyncWith)):
                for item in current.items:
                    call = item.context_expr
                    if isinstance(call, Call) and last_name(call.func) in ("raises", "assertRaises", "assertRaisesRegex"):
                        return True
            current = self.parent(current)
        return False

    # -- matrix products -------------------------------------------------------------------
    def matmul(self, node: AST) -> MatMul | None:
        """`a @ b`, `a.dot(b)`, `np.dot(a, b)`, `np.matmul(a, b)`, `torch.matmul/bmm(a, b)`."""
        kind = type(node)
        if kind is BinOp:
            return MatMul(node, node.left, node.right) if type(node.op) is MatMult else None  # type: ignore[attr-defined,arg-type]
        # asked of every call by several rules: the callee's last name rules out nearly all at once
        if isinstance(node, Call) and self.called_name(node.func) in _MATMUL_CALL_NAMES:
            positional = positional_args(node)
            func = node.func
            if isinstance(func, Attribute) and func.attr in ("dot", "matmul") and len(positional) == 1 and not node.keywords:
                if not self.is_module_like(func.value):
                    return MatMul(node, func.value, positional[0])
            if len(positional) == 2 and len(node.args) == 2 and self.is_array_call(func, "dot", "matmul", "bmm"):
                return MatMul(node, positional[0], positional[1])
            if len(positional) == 3 and len(node.args) == 3 and self.is_array_call(func, "einsum"):
                operands = einsum_operands(positional[0], positional[1], positional[2])
                if operands is not None:
                    return MatMul(node, *operands)
        return None

    # -- kind --------------------------------------------------------------------------------
    def kind_of(self, node: AST) -> Kind | None:
        """The geometric kind of an expression, or None."""
        return self._cached("kind", node, FactBase._kind)

    def is_free(self, node: AST) -> bool:
        """A free vector (direction, normal, velocity...): rotated only, never translated."""
        return self.kind_of(node) in FREE

    def _kind(self, node: AST) -> Kind | None:
        if isinstance(node, Name):
            return self._kind_of_variable(node)
        if isinstance(node, Attribute):
            if self.is_module_like(node.value):
                return None
            attr = node.attr
            if attr in ("T", "mT"):
                return self.kind_of(node.value)
            if attr in messages.VECTOR_FIELD_NAMES:  # `odometry.twist.twist.linear`: the message type says
                declared = self.shared(messages.MessageTypes).field_kind(node)
                if declared is not None:
                    return declared
            if attr in vocab.DIRECTION_ATTRIBUTES:
                return Kind.DIRECTION
            if attr in vocab.POINT_ATTRIBUTES:
                return Kind.POINT
            if isinstance(node.value, Name) and node.value.id == "self":
                flowed = self._kind_of_self_attribute(attr)
                if flowed is not None:
                    return flowed
            return self._name_kind(attr)
        if isinstance(node, Subscript):
            base = self.kind_of(node.value)
            if base in GEOMETRIC:
                return base
            if base == Kind.TRANSFORM and self.rotation_block_of(node) is not None:
                return Kind.ROTATION
            return None
        if isinstance(node, UnaryOp) and isinstance(node.op, USub):
            kind = self.kind_of(node.operand)
            return None if kind is None else valid_kind(algebra.negate(kind))
        if isinstance(node, (ast.List, ast.Tuple)) and _origin_and_axis_tips(node):
            return Kind.POINT
        if isinstance(node, (ast.List, ast.Tuple)) and len(node.elts) == 3:  # `[v.x, v.y, v.z]` is what v is
            whole = self._components_of_one_array(node.elts)
            return None if whole is None else self.kind_of(whole)
        if isinstance(node, BinOp):
            return self._kind_of_binary(node)
        if isinstance(node, Call):
            return self._kind_of_call(node)
        return None

    def _name_kind(self, name: str) -> Kind | None:
        return kind_of_name(name, self.config)

    def _kind_of_self_attribute(self, attr: str) -> Kind | None:
        """`self.x`: the kind every `self.x = value` of the module agrees on."""
        stores = self.index.self_attribute_stores.get(attr)
        if not stores:
            return None
        kinds = {self.kind_of(value) for value in stores}
        return kinds.pop() if len(kinds) == 1 else None

    def _kind_of_binary(self, node: BinOp) -> Kind | None:
        """What `geolint.algebra` makes of the operands' kinds. An operand of no known kind next to one of a
        known kind is read as the scalar of `*` and `/`; a division by a norm normalises."""
        op = node.op
        if isinstance(op, MatMult):
            return self._kind_of_product(node)
        left, right = self.kind_of(node.left), self.kind_of(node.right)
        if isinstance(op, Div) and self.is_norm_call(node.right):
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

    def _kind_of_product(self, node: AST) -> Kind | None:
        product = self.matmul(node)
        if product is None:
            return None
        left, right = self.kind_of(product.left), self.kind_of(product.right)
        if left is None or right is None:
            return None
        if left == Kind.TRANSFORM and right not in OPERATORS:
            # a 4x4 matrix reaches homogeneous 4-vectors only (`homogeneous` reads those); the table's
            # `T @ p` is the runtime's Transform, which a kind alone does not tell from a matrix
            return None
        if left in OPERATORS:
            return valid_kind(algebra.apply(left, right))
        return valid_kind(algebra.apply_rows(left, right))

    def _kind_of_call(self, node: Call) -> Kind | None:
        func = node.func
        positional = positional_args(node)
        name = last_name(func)
        if self.is_array_call(func, "cross") or (isinstance(func, Name) and func.id == "cross"):
            return Kind.DIRECTION
        if name in vocab.UNIT_FUNCTIONS:
            return Kind.DIRECTION
        if self.matmul(node) is not None:
            return self._kind_of_product(node)
        if positional and self.is_array_call(func, *vocab.PASSTHROUGH_FUNCTIONS):
            return self.kind_of(positional[0])
        tips = positional and isinstance(positional[0], ast.List) and _origin_and_axis_tips(positional[0])
        if tips and self.is_array_call(func, "array", "asarray", "tensor", "as_tensor"):
            return Kind.POINT  # `np.array([[0, 0, 0], [l, 0, 0], ...])`: the origin and axis tips
        if isinstance(func, Attribute) and not self.is_module_like(func.value):
            if func.attr in vocab.PASSTHROUGH_METHODS:
                return self.kind_of(func.value)
            if func.attr in vocab.INVERSE_METHODS:
                kind = self.kind_of(func.value)
                return kind if kind in OPERATORS else None
        if name in vocab.INVERSE_FUNCTIONS and positional:
            kind = self.kind_of(positional[0])
            return kind if kind in OPERATORS else None
        qualified = self.qualified_name(func) or ""
        library = vocab.LIBRARY_KINDS.get(qualified)
        if library is not None:
            return library
        summary = self.summary_of(node, KINDS)
        return None if summary is None else summary.returns

    def may_have_summary(self, call: Call) -> bool:
        """A cheap test: whether the callee can be a function of this module or of a project module."""
        func = call.func
        if type(func) is Name:
            if func.id in self.index.functions:
                return True
        elif type(func) is Attribute and type(func.value) is Name and func.value.id == "self":  # type: ignore[attr-defined]
            return func.attr in self.index.methods  # type: ignore[attr-defined]
        if not self.cross_module:
            return False
        root = func
        while type(root) is Attribute:
            root = root.value  # type: ignore[attr-defined]
        if type(root) is not Name:
            return False
        imported = self.index.imports.get(root.id)  # type: ignore[attr-defined]
        if imported is None:
            return root is func and bool(self.index.star_imports) and self._star_imported_callee(func) is not None  # type: ignore[arg-type]
        # `from numpy import array` then `array(x)`: a third-party function has no summary either,
        # nor one of a package the project's folders do not hold (`gym.make`, `time.sleep`)
        return may_be_project_import(imported, self.path)

    def summary_of(self, call: Call, family: SummaryFamily[_S]) -> _S | None:
        """What the called helper does, as far as `family` asks (`KINDS`, `ANGLE_UNITS`...): a function of
        this module, or of a project module it imports. Only the families asked are computed."""
        return self._cached("summary", call, FactBase._summary_of_call, family.tag)  # type: ignore[return-value]

    def _summary_of_call(self, call: Call, tag: str) -> Summary | None:
        family = summaries.family_of(tag)
        found = self.called_function(call)
        if found is not None:
            return self.project.summary(found[0], found[1], family)
        method = self.own_method(call)
        if method is None:
            return None
        summary = self.project.summary(self, method, family)
        return None if summary is None else family.bound(summary)

    def own_method(self, call: Call) -> FunctionDef | AsyncFunctionDef | None:
        """For `self.helper(...)` inside a method: the one `helper` of the same class, when it takes
        `self` (not a static or class method); else None."""
        func = call.func
        if not (isinstance(func, Attribute) and isinstance(func.value, Name) and func.value.id == "self"):
            return None
        candidates = self.index.methods.get(func.attr, [])
        if not candidates:
            return None
        enclosing = self.parent(call)
        while enclosing is not None and not isinstance(enclosing, ClassDef):
            enclosing = self.parent(enclosing)
        if enclosing is None:
            return None
        own = [method for method in candidates if self.parent(method) is enclosing]
        if len(own) != 1 or own[0].decorator_list or not (own[0].args.posonlyargs or own[0].args.args):
            return None  # overloads, properties, static/class methods: no plain bound method
        return own[0]

    def called_function(self, call: Call) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
        """The project function a call runs (of this module, or of a project module it imports,
        through aliases, relative imports and package `__init__` re-exports) and the fact base of
        the module that defines it."""
        if not self.may_have_summary(call):
            return None
        func = call.func
        if isinstance(func, Name) and func.id in self.index.functions:
            return self, self.index.functions[func.id]
        if not self.cross_module:
            return None
        head = func.id if isinstance(func, Name) else dotted_name(func)
        if head is None:
            return None
        if head.split(".")[0] not in self.index.imports:
            return self._star_imported_callee(func) if isinstance(func, Name) else None
        return self._imported_function(self.qualified_name(func) or "", self.path)

    def _star_imported_callee(self, func: Name) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
        """`star_imported_function` for a called name that no scope around the call binds."""
        return None if self.index.lookup(func.id, self.index.scope_of(func)) else self.star_imported_function(func.id)

    def star_imported_function(self, name: str) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
        """The project function a module-level `name` is when the module neither binds nor imports it
        there and exactly one of its star imports of project modules (`from ..collision import *`)
        defines it."""
        if not self.cross_module or name in _BUILTIN_NAMES or name in self.index.imports or name in self.index.scopes[self.index.tree].bindings:
            return None

        def find() -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
            found = [defined for module in self.index.star_imports if (defined := self._imported_function(f"{module}.{name}", self.path)) is not None]
            return found[0] if len(found) == 1 else None

        return self.module_fact(f"star-imported function {name}", find)

    def _imported_function(self, qualified: str, importer: str) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
        for _ in range(_MAX_REEXPORTS):
            found = self.defining_module(qualified, importer)
            if found is None:
                return None
            other, name = found
            if name in other.index.functions:
                return other, other.index.functions[name]
            qualified = other.index.imports.get(name, "")  # `from .points import to_h` in a package's __init__
            importer = other.path
        return None

    def defining_module(self, qualified: str, importer: str) -> tuple[FactBase, str] | None:
        """For `pkg.mod.name` (or `.mod.name`) imported by `importer`: the fact base of the project module
        `pkg.mod` and `name`; None for a third-party or unresolved module."""
        module, _, name = qualified.rpartition(".")
        if not module.strip(".") or not name or module.lstrip(".").split(".")[0] in vocab.THIRD_PARTY_ROOTS:
            return None
        level = len(module) - len(module.lstrip("."))
        file = module_file(module.lstrip("."), importer, level)
        other = None if file is None else self.project.facts_of(file)
        return None if other is None else (other, name)

    def _kind_of_variable(self, name: Name) -> Kind | None:
        return self._of_bindings("variable kind", name, FactBase._kind_of_bindings)

    def _kind_of_bindings(self, name: str, bindings: Sequence[Binding], order: str = "") -> Kind | None:
        stated = self._name_kind(name)
        flowed: set[Kind | None] = set()
        for binding in bindings:
            if self.is_non_geometric(binding):
                return None  # `direction = "left"`, `velocity = distance / dt`, `axis=0`
            flowed.add(self._kind_of_binding(binding))
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

    def _kind_of_binding(self, binding: Binding) -> Kind | None:
        if isinstance(binding, ast.expr):
            return self.kind_of(binding)
        if isinstance(binding, LoopBinding):
            iterable = binding.iterable
            if binding.position is None:
                return self._element_kind(iterable)
            if isinstance(iterable, Call) and isinstance(iterable.func, Name):
                args = positional_args(iterable)
                if iterable.func.id == "enumerate" and binding.position == 1 and args:
                    return self._element_kind(args[0])
                if iterable.func.id == "zip" and binding.position < len(args):
                    return self._element_kind(args[binding.position])
        if isinstance(binding, UnpackBinding):
            value = binding.value
            if isinstance(value, (ast.Tuple, ast.List)) and binding.position < len(value.elts):
                return self.kind_of(value.elts[binding.position])
        return None

    def _element_kind(self, iterable: ast.expr) -> Kind | None:
        kind = self.kind_of(iterable)
        return kind if kind in GEOMETRIC else None

    def is_non_geometric(self, binding: Binding) -> bool:
        """Evidence that a binding holds a scalar, a string or a flag, never a 3-vector."""
        if isinstance(binding, ParamBinding):
            if binding.default is not None and self.is_non_geometric(binding.default):
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
            return isinstance(binding.op, Not) or self.is_non_geometric(binding.operand)
        if isinstance(binding, Call):
            name = last_name(binding.func)
            qualified = self.qualified_name(binding.func) or ""
            if name in ("len", "int", "float", "str", "bool", "range", "round", "abs", "sum", "max", "min"):
                return isinstance(binding.func, Name)
            if qualified in vocab.FEATURE_FUNCTIONS:
                return True  # a feature map sampled at points, not their coordinates
            return ".random." in f".{qualified}." or qualified.startswith("random.")
        if isinstance(binding, BinOp) and isinstance(binding.op, (Div, Mult, FloorDiv, Mod, Pow)):
            # `velocity = distance / dt`: a ratio of two things that are not geometry
            if isinstance(binding.left, (ast.List, ast.Tuple)) or isinstance(binding.right, (ast.List, ast.Tuple)):
                return False
            return (
                self.kind_of(binding.left) is None
                and self.kind_of(binding.right) is None
                and not self._may_be_array(binding.left)
                and not self._may_be_array(binding.right)
            )
        return False

    def _may_be_array(self, node: AST) -> bool:
        """Whether an expression visibly builds an array (an array call, a subscript, a product)."""
        if isinstance(node, Call):
            qualified = self.qualified_name(node.func) or ""
            return qualified.split(".")[0] in vocab.ARRAY_ROOTS or isinstance(node.func, Attribute)
        if isinstance(node, (Subscript, ast.List, ast.Tuple)):
            return True
        if isinstance(node, BinOp):
            return self._may_be_array(node.left) or self._may_be_array(node.right)
        return False

    # -- blocks of transforms ----------------------------------------------------------------
    def rotation_block_of(self, node: AST) -> ast.expr | None:
        """For `M[:3, :3]` (or `M[..., :3, :3]`, `M[:, :3, :3]`), the matrix M; else None."""
        if isinstance(node, Subscript):
            parts = _drop_batch(subscript_parts(node))
            if len(parts) == 2 and is_slice_upto(parts[0], 3) and is_slice_upto(parts[1], 3):
                return node.value
        return None

    def translation_of(self, node: AST) -> ast.expr | None:
        """For `M[:3, 3]` (or `M[:3, -1]`, `M[0:3, 3]`, `M[..., :3, 3]`), the matrix M; else None."""
        if isinstance(node, Subscript):
            parts = _drop_batch(subscript_parts(node))
            if len(parts) == 2 and is_slice_upto(parts[0], 3) and is_index(parts[1], 3, -1):
                return node.value
        return None

    def is_translation_like(self, node: AST) -> bool:
        """`t`, `trans`, `translation`, `t_world_cam`, `T[:3, 3]`, `pose.translation`, `tvec`."""
        if self.translation_of(node) is not None:
            return True
        word = last_name(node)
        if word is None:
            return False
        if isinstance(node, Attribute) and word in ("translation", "t", "trans", "p"):
            return not self.is_module_like(node.value)
        if not isinstance(node, Name):
            return False
        first = node.id.strip("_").split("_")[0].lower()
        return first in ("t", "trans", "translation", "tvec", "tran")

    def has_geometric_evidence(self, node: AST) -> bool:
        """Whether a point-like expression is visibly geometric (not a file offset, a cursor
        position or a tuple): a strong or frame-stating name, a mesh attribute, or array flow."""
        return bool(self._cached("evidence", node, FactBase._evidence))

    def _evidence(self, node: AST) -> bool:
        if isinstance(node, Name):
            if states_geometry(node.id, self.config):
                return True
            return bool(self._of_bindings("variable evidence", node, FactBase._evidence_of_bindings))
        if isinstance(node, Attribute):
            if node.attr in ("T", "mT"):
                return self.has_geometric_evidence(node.value)
            return node.attr in ("vertices", "centroid", "vertex_normals", "face_normals") or states_geometry(node.attr, self.config)
        if isinstance(node, Subscript):
            return self.has_geometric_evidence(node.value)
        if isinstance(node, Call):
            qualified = self.qualified_name(node.func) or ""
            return qualified.split(".")[0] in vocab.ARRAY_ROOTS or self.matmul(node) is not None
        if isinstance(node, BinOp):
            if isinstance(node.op, MatMult):
                return True
            return self.has_geometric_evidence(node.left) or self.has_geometric_evidence(node.right)
        return False

    def _evidence_of_bindings(self, name: str, bindings: Sequence[Binding], order: str = "") -> bool:
        return any(isinstance(binding, ast.expr) and self.has_geometric_evidence(binding) for binding in bindings)

    # -- library transforms ------------------------------------------------------------------
    def translating_library_object(self, node: AST) -> str | None:
        """"PyKDL.Frame" or "spatialmath.SE3" when `node` is one (built directly, through a
        variable, or returned by a helper of this module): `*` with them translates vectors."""
        return self._cached("library", node, FactBase._library_object)

    def _library_object(self, node: AST) -> str | None:
        if isinstance(node, Name):
            return self._of_bindings("variable library", node, FactBase._library_object_of_bindings)
        if isinstance(node, BinOp) and isinstance(node.op, Mult):
            left, right = self.translating_library_object(node.left), self.translating_library_object(node.right)
            return left if left is not None and left == right else None  # SE3 * SE3 is an SE3
        if not isinstance(node, Call):
            return None
        qualified = self.qualified_name(node.func) or ""
        parts = qualified.split(".")
        if parts[-1] == "Frame" and (parts[0] in ("PyKDL", "kdl") or "PyKDL" in parts):
            return "PyKDL.Frame"
        if "SE3" in parts and parts[0] in ("spatialmath", "SE3") and parts[-1] != "inv":
            return "spatialmath.SE3"
        if isinstance(node.func, Name) and node.func.id in self.index.functions:
            scope = self.index.scopes.get(self.index.functions[node.func.id])
            if scope is not None and scope.returns:
                found = {self.translating_library_object(value) for value in scope.returns}
                return found.pop() if len(found) == 1 else None
        return None

    def _library_object_of_bindings(self, name: str, bindings: Sequence[Binding], order: str = "") -> str | None:
        values = [b for b in bindings if isinstance(b, ast.expr)]
        found = {self.translating_library_object(b) for b in values}
        return found.pop() if len(found) == 1 and len(bindings) == len(values) else None

    # -- frames ------------------------------------------------------------------------------
    def frames_of(self, node: AST, order: str = DST_FIRST) -> NameFrames | None:
        """The frames of an expression (operator: dst/src; value: frame) with `T_a_b` names read
        in `order`, or None."""
        fact = self.frame_fact(node, order)
        return None if fact is None else fact.frames

    def frame_fact(self, node: AST, order: str = DST_FIRST) -> FrameFact | None:
        return self._cached("frames", node, FactBase._frames, order)

    def readings(self) -> tuple[str, ...]:
        """The orders a rule must check: a frame problem is reported only when every reading has it."""
        return self.orders

    def name_frames(self, name: str, order: str) -> FrameFact | None:
        """What a name states, read in `order` (only `T_a_b` / `R_a_b` depend on it)."""
        stated = frames_of_name(name, self.config)
        if stated is None:
            return self._extrinsics_frames(name)
        if "_tform_" in name:
            return bosdyn.name_fact(name, stated)  # Boston Dynamics' `odom_tform_body` states its direction
        if self.order_names_mixed and order_dependent(name):
            return None
        if order == SRC_FIRST and stated.is_operator and order_dependent(name):
            return FrameFact(stated.inverted(), (f"name `{name}` (src-first)",))
        return FrameFact(stated, (f"name `{name}`" + (" (dst-first)" if order_dependent(name) else ""),))

    def _extrinsics_frames(self, name: str) -> FrameFact | None:
        """`c2w`, `pose_w2c`, `"cam_R_w2c"`: a camera-extrinsics word that states its direction."""
        declared = vocab.DECLARING_ATTRIBUTES.get(name)
        if declared is not None:
            return FrameFact(declared, (f"`{name}` ({vocab.DECLARING_ATTRIBUTE_SOURCES[name]})",), True)
        parts = name.lower().split("_")
        if RELATIVE_WORDS.intersection(parts):
            return None  # `rel_w2c`, `delta_c2w`: a correction named after the pose it corrects (world to world)
        found = {vocab.EXTRINSICS_TOKENS[part] for part in parts if part in vocab.EXTRINSICS_TOKENS}
        if len(found) == 1 and len(parts) <= 3:
            return FrameFact(found.pop(), (f"`{name}` {EXTRINSICS_EVIDENCE}",))
        return None

    def _frames(self, node: AST, order: str) -> FrameFact | None:
        if isinstance(node, Name):
            return self._frames_of_variable(node, order)
        if isinstance(node, Attribute):
            if node.attr in ("T", "mT"):
                inner = self.frame_fact(node.value, order)
                if inner is not None and inner.frames.is_operator:
                    return FrameFact(inner.frames.inverted(), inner.evidence, inner.declared)
                return inner
            if self.is_module_like(node.value):
                return None
            declared = vocab.DECLARING_ATTRIBUTES.get(node.attr)
            if declared is not None:
                return FrameFact(declared, (f"`.{node.attr}` ({vocab.DECLARING_ATTRIBUTE_SOURCES[node.attr]})",), True)
            return self.name_frames(node.attr, order)
        if isinstance(node, Subscript):
            key = string(node.slice)
            if key is not None:  # `meta["c2w"]`, `info["cam_R_w2c"]`: the key states the convention
                if key in vocab.DECLARING_ATTRIBUTES:
                    return self._extrinsics_frames(key)
                return self.name_frames(key, order) if key.isidentifier() else None
            inner = self.frame_fact(node.value, order)
            if inner is None:
                return None
            frames = inner.frames
            if frames.is_operator:
                if self.rotation_block_of(node) is not None:
                    return FrameFact(NameFrames(dst=frames.dst, src=frames.src, operator="rotation"), inner.evidence, inner.declared)
                if self.translation_of(node) is not None:
                    return FrameFact(NameFrames(frame=frames.dst), inner.evidence, inner.declared)
                return None
            return inner
        if isinstance(node, UnaryOp) and isinstance(node.op, USub):
            inner = self.frame_fact(node.operand, order)
            return inner if inner is not None and not inner.frames.is_operator else None
        if isinstance(node, Call):
            return self._frames_of_call(node, order)
        if isinstance(node, BinOp):
            if isinstance(node.op, (Add, Sub)):
                left, right = self.frame_fact(node.left, order), self.frame_fact(node.right, order)
                if left is not None and not left.frames.is_operator and (right is None or right.frames == left.frames):
                    return left
                if right is not None and not right.frames.is_operator and left is None:
                    return right
                return None
            if isinstance(node.op, MatMult):
                return self._frames_of_product(node.left, node.right, order)
            if isinstance(node.op, Mult):
                left = self.frame_fact(node.left, order)
                if left is not None and left.frames.is_operator and left.frames.operator == "transform":
                    return self._frames_of_product(node.left, node.right, order)
        return None

    def _frames_of_variable(self, node: Name, order: str) -> FrameFact | None:
        return self._of_bindings("variable frames", node, FactBase._frames_of_bindings, order)

    def _frames_of_bindings(self, name: str, bindings: Sequence[Binding], order: str) -> FrameFact | None:
        if any(self._rebinds_own_inverse(name, binding) for binding in bindings):
            return None  # `world2cam = inv(world2cam)`: the name holds both directions
        declared = [fact for fact in (self._declared_frames(b) for b in bindings if isinstance(b, ast.expr)) if fact is not None]
        declared += [fact for fact in (self._typed_frames(name, b) for b in bindings) if fact is not None]
        if declared:
            frames = {fact.frames for fact in declared}
            return declared[0] if len(frames) == 1 else None
        stated = self.name_frames(name, order)
        if stated is not None:
            return stated
        readings = set()
        facts = []
        for binding in bindings:
            if not isinstance(binding, ast.expr):
                return None
            fact = self.frame_fact(binding, order)
            facts.append(fact)
            readings.add(None if fact is None else fact.frames)
        if len(readings) == 1 and facts and facts[0] is not None:
            return facts[0]
        return None

    def _rebinds_own_inverse(self, name: str, binding: Binding) -> bool:
        if not isinstance(binding, Call):
            return False
        inner = None
        if last_name(binding.func) in vocab.INVERSE_FUNCTIONS and binding.args:
            inner = binding.args[0]
        elif isinstance(binding.func, Attribute) and binding.func.attr in vocab.INVERSE_METHODS:
            inner = binding.func.value
        return isinstance(inner, Name) and inner.id == name

    def _typed_frames(self, name: str, binding: Binding) -> FrameFact | None:
        """Frames a geolint type states for a parameter or an annotated assignment
        (`T: TransformMatrix["world", "cam"]`, `p: Point[Camera] = ...`)."""
        if isinstance(binding, ParamBinding):
            annotation = binding.arg.annotation
        else:
            statement = self.parent(binding) if isinstance(binding, ast.expr) else None
            annotated = isinstance(statement, AnnAssign) and isinstance(statement.target, Name)
            annotation = statement.annotation if annotated and statement.target.id == name else None  # type: ignore[union-attr]
        if not isinstance(annotation, Subscript) or not (self.qualified_name(annotation.value) or "").startswith("geolint"):
            return None
        from geolint.factbase import typed

        frames = typed.typed_frames(annotation, self._frame_classes(annotation))
        if frames is None:
            return None
        return FrameFact(frames, (f"annotation `{ast.unparse(annotation)}` at line {annotation.lineno}",), True)

    def _frame_classes(self, annotation: AST) -> dict[str, str]:
        """The `Frame` subclasses an annotation may name: this module's, and those it imports from project
        modules (`from arm.frames import Base`, where `class Base(Frame, name="base_link")`)."""
        from geolint.factbase import typed

        classes = self.module_fact("frame_classes", lambda: typed.frame_classes(self.index.tree))
        imported = {
            node.id: self.index.imports[node.id]
            for node in ast.walk(annotation)
            if isinstance(node, Name) and node.id not in classes and node.id in self.index.imports
        }
        if not imported or not self.cross_module:
            return classes
        found = dict(classes)
        for local, qualified in imported.items():
            defining = self.defining_module(qualified, self.path)
            if defining is not None:
                other, name = defining
                declared = other.module_fact("frame_classes", lambda: typed.frame_classes(other.index.tree)).get(name)  # noqa: B023
                if declared is not None:
                    found[local] = declared
        return found

    def _declared_frames(self, value: ast.expr) -> FrameFact | None:
        """Frames a call states explicitly: `from_frame=`/`to_frame=`, `.as_frames(a, b)`, `lookup_transform(target, source, t)`."""
        if not isinstance(value, Call):
            return None
        declared = declared_call_frames(value)
        if declared is None:
            return None
        frames, how = declared
        return FrameFact(frames, (f"{how} at line {value.lineno}",), True)

    def _frames_of_call(self, node: Call, order: str) -> FrameFact | None:
        declared = self._declared_frames(node) or bosdyn.helper_frames(self, node)
        if declared is not None:
            return declared
        homogeneous = self.homogeneous(node)
        if homogeneous is not None:  # [x, 1] lives where x lives
            inner = self.frame_fact(homogeneous.inner, order)
            return inner if inner is not None and not inner.frames.is_operator else None
        func = node.func
        positional = positional_args(node)
        product = self.matmul(node)
        if product is not None:
            return self._frames_of_product(product.left, product.right, order)
        if isinstance(func, Attribute) and func.attr in vocab.INVERSE_METHODS and not self.is_module_like(func.value):
            inner = self.frame_fact(func.value, order)
            return FrameFact(inner.frames.inverted(), inner.evidence, inner.declared) if inner is not None and inner.frames.is_operator else None
        if last_name(func) in vocab.INVERSE_FUNCTIONS and len(positional) == 1:
            inner = self.frame_fact(positional[0], order)
            return FrameFact(inner.frames.inverted(), inner.evidence, inner.declared) if inner is not None and inner.frames.is_operator else None
        if positional and self.is_array_call(func, *vocab.PASSTHROUGH_FUNCTIONS):
            return self.frame_fact(positional[0], order)
        if isinstance(func, Attribute) and func.attr in vocab.PASSTHROUGH_METHODS and not self.is_module_like(func.value):
            return self.frame_fact(func.value, order)
        return None

    def _frames_of_product(self, left_node: AST, right_node: AST, order: str) -> FrameFact | None:
        left_fact, right_fact = self.frame_fact(left_node, order), self.frame_fact(right_node, order)
        if left_fact is None or right_fact is None:
            return None
        left, right = left_fact.frames, right_fact.frames
        evidence = left_fact.evidence + right_fact.evidence
        # a result is declared when the operands its frames come from are
        if left.is_operator and right.is_operator:
            composed = algebra.compose_frames(_algebra_frames(left), _algebra_frames(right), same=_known_same)
            if composed.problem is not None:
                return None
            declared = left_fact.declared and right_fact.declared
            return FrameFact(NameFrames(dst=composed.frames.dst, src=composed.frames.src, operator=_composed_operator(left, right)), evidence, declared)
        if left.is_operator and right.frame is not None:
            applied = algebra.apply_frames(_algebra_frames(left), _algebra_frames(right)).frames
            return FrameFact(NameFrames(frame=applied.frame), evidence, left_fact.declared)
        if right.is_operator and left.frame is not None:
            # row vectors: `x @ M` applies M.T
            applied = algebra.apply_frames(_algebra_frames(right).inverted(), _algebra_frames(left)).frames
            return FrameFact(NameFrames(frame=applied.frame), evidence, right_fact.declared)
        return None

    # -- homogeneous coordinates ---------------------------------------------------------------
    def homogeneous(self, node: AST) -> Homogeneous | None:
        """The homogeneous construction `node` is (directly, or through a variable), or None."""
        return self._cached("homog", node, FactBase._homogeneous)

    def homogenized(self, homogeneous: Homogeneous) -> algebra.Outcome | None:
        """What `algebra.homogenize` makes of a construction `[x; w]` from x's kind (None: x's kind is unknown)."""
        kind = self.kind_of(homogeneous.inner)
        return None if kind is None else algebra.homogenize(kind, homogeneous.w)

    def homogeneous_built_by(self, node: AST) -> Homogeneous | None:
        """The homogeneous value whose construction is exactly `node` (including an `np.ones(4)`
        buffer filled later), or None."""
        return self._cached("built", node, FactBase._homogeneous_built_by)

    def _homogeneous_built_by(self, node: AST) -> Homogeneous | None:
        if not self._may_build_homogeneous(node):
            return None
        found = self.homogeneous(node)
        if found is None and isinstance(node, Call):
            assign = self.parent(node)
            if isinstance(assign, Assign) and len(assign.targets) == 1 and isinstance(assign.targets[0], Name):
                found = self.homogeneous(assign.targets[0])
        return found if found is not None and found.construction is node else None

    def _may_build_homogeneous(self, node: AST) -> bool:
        """False when `node` certainly builds no homogeneous value: a call that is none of the array
        makers `_homogeneous_call` and `_filled_buffer` know and cannot reach a helper's summary (it
        feeds no product), a subscript other than `np.r_`/`np.c_`. Rules ask this of every call and
        subscript of a module, so it is decided before any fact is looked up."""
        kind = type(node)
        if kind is Subscript:
            return self.is_array_call(node.value, "r_", "c_")  # type: ignore[attr-defined]
        if kind is not Call:
            return True
        func = node.func  # type: ignore[attr-defined]
        if self.called_name(func) in _HOMOGENEOUS_MAKERS:
            qualified = self.qualified_name(func)
            if qualified is not None:
                module, _, name = qualified.rpartition(".")
                if name in _HOMOGENEOUS_MAKERS and module in vocab.ARRAY_MODULES:
                    return True
        return type(func) in (Name, Attribute) and self._feeds_a_product(node)

    def _homogeneous(self, node: AST) -> Homogeneous | None:
        if isinstance(node, Name):
            bindings = self.bindings(node) or []
            if len(bindings) != 1 or not isinstance(bindings[0], ast.expr):
                return None
            direct = self.homogeneous(bindings[0])
            if direct is not None:
                return direct
            return self._filled_buffer(node, bindings[0])
        if isinstance(node, Call):
            return self._homogeneous_call(node)
        if isinstance(node, Subscript) and self.is_array_call(node.value, "r_", "c_"):
            index = node.slice
            if isinstance(index, ast.Tuple) and len(index.elts) == 2 and not any(isinstance(e, Slice) for e in index.elts):
                return self._with_w(node, index.elts[0], index.elts[1], explicit=False)
        return None

    def _homogeneous_call(self, node: Call) -> Homogeneous | None:
        positional = positional_args(node)
        if self.called_name(node.func) == "pad":
            return self._padded_with_w(node, positional)
        if self.is_array_call(node.func, "append") and len(positional) == 2 and len(node.args) == 2:
            return self._with_w(node, positional[0], positional[1], explicit=False)
        if self.is_array_call(node.func, *vocab.STACKING_FUNCTIONS) and positional:
            sequence = positional[0]
            if isinstance(sequence, (ast.List, ast.Tuple)) and len(sequence.elts) == 2:
                first, second = sequence.elts
                if not isinstance(first, Starred) and self._last_axis(node):
                    return self._with_w(node, first, second, explicit=False)
        if self.is_array_call(node.func, "array", "asarray", "tensor", "as_tensor") and positional and isinstance(positional[0], ast.List):
            elements = positional[0].elts
            if len(elements) == 4:
                base = self._components_of_one_array(elements[:3])
                if base is not None:
                    return self._with_w(node, base, elements[3])
        if (
            isinstance(node.func, (Name, Attribute))
            and self._feeds_a_product(node)  # only then is a helper's w worth looking up
            and not self.is_array_call(node.func, *_ARRAY_BUILDERS)
        ):
            summary = self.summary_of(node, HOMOGENEOUS)
            if summary is not None and summary.homogenizes:
                index, w = next(iter(summary.homogenizes.items()))
                if index < len(positional):  # `to_homogeneous(normals)`: the helper appends w
                    return Homogeneous(inner=positional[index], w=w, construction=node, fixed=None, explicit=True)
        return None

    def _feeds_a_product(self, node: AST) -> bool:
        """Whether a value is a matrix product's operand, directly (through `.T`) or through the
        name it is assigned to, or is stored under a homogeneous name (`p_h`)."""
        parent = self.parent(node)
        while parent is not None and transposed_value(parent) is node:
            node, parent = parent, self.parent(parent)
        if isinstance(parent, BinOp) and isinstance(parent.op, MatMult):
            return True
        if isinstance(parent, Call) and self.matmul(parent) is not None:
            return True
        return self._stored_for_a_product(parent)

    def _stored_for_a_product(self, parent: AST | None) -> bool:
        """Whether `parent` assigns a value to one name that says it is homogeneous (`p_h`) or that
        its scope later uses as a matrix product's operand."""
        if not (isinstance(parent, Assign) and len(parent.targets) == 1 and isinstance(parent.targets[0], Name)):
            return False
        target = parent.targets[0].id
        if set(target.lower().split("_")) & {"h", "hom", "homog", "homogeneous", "homo"}:
            return True
        return target in self.index.scope_of(parent).matmul_operands

    def _last_axis(self, call: Call) -> bool:
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

    def _with_w(self, construction: ast.expr, inner: ast.expr, w_node: ast.expr, explicit: bool = True) -> Homogeneous | None:
        w, fixed_w = self._w_value(w_node)
        if w is None or fixed_w is None:
            return None
        fixed = replace_span(self.index, construction, fixed_w)  # None when w is set outside the span
        return Homogeneous(inner=inner, w=w, construction=construction, fixed=fixed, explicit=explicit)

    def _padded_with_w(self, node: Call, positional: list[ast.expr]) -> Homogeneous | None:
        """`F.pad(x, (0, 1), value=1.0)` (torch) or `np.pad(x, ((0, 0), (0, 1)), constant_values=1)`: x with
        one constant appended along its last axis, 0 unless a value is given (both libraries' default)."""
        if len(positional) < 2 or len(positional) != len(node.args):
            return None
        qualified = self.qualified_name(node.func)
        widths = [number(width) for width in flat_literal(positional[1])]
        if qualified == "torch.nn.functional.pad":  # (left, right) of the last axis first
            appends_one = len(widths) >= 2 and widths[:2] == [0, 1] and not any(widths[2:])
            mode: ast.expr | None = positional[2] if len(positional) > 2 else None
            value: ast.expr | None = positional[3] if len(positional) > 3 else None
            value_word = "value"
        elif qualified is not None and qualified.rpartition(".")[0] in vocab.ARRAY_MODULES:
            # numpy's per-axis pairs, the last axis last; a bare `(0, 1)` pads every axis
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
        return self._with_w(node, positional[0], value, explicit=False)

    def _w_value(self, node: ast.expr) -> tuple[int | None, list[tuple[AST | LastNameTarget, str]] | None]:
        """The constant w a construction appends, and the edits (node, new text) that give the other w."""
        literal = number(node)
        if literal in (0, 1) and isinstance(node, Constant):
            other = 1 - int(literal)  # type: ignore[arg-type]
            return int(literal), [(node, str(other) if isinstance(node.value, int) else f"{other}.0")]  # type: ignore[arg-type]
        if isinstance(node, (ast.List, ast.Tuple)) and len(node.elts) == 1:
            return self._w_value(node.elts[0])
        if isinstance(node, Name):  # `ones = np.ones((n, 1)); np.hstack([x, ones])`
            bindings = self.bindings(node) or []
            if len(bindings) == 1 and isinstance(bindings[0], Call):
                return self._w_value(bindings[0])
        if isinstance(node, Call) and self.is_array_call(node.func, "ones", "zeros", "ones_like", "zeros_like"):
            w = 1 if last_name(node.func) in ("ones", "ones_like") else 0
            return w, [(last_name_target(node.func), _SWAP[last_name(node.func) or ""])]
        if isinstance(node, Call) and isinstance(node.func, Attribute) and node.func.attr in ("type_as", "to", "astype", "float", "double"):
            return self._w_value(node.func.value)
        return None, None

    def used_as_homogeneous(self, homogeneous: Homogeneous) -> bool:
        """Whether a construction is visibly used as homogeneous: built explicitly as a 4-vector,
        multiplied by a matrix (directly or through the variable holding it), or stored under a
        homogeneous name (`p_h`, `points_hom`). A literal 4-vector (`np.array([p.x, p.y, p.z, 0])`)
        counts only when it reaches a product or a transform call: one only stored (appended to a
        list), or whose last slot is written later, is a record with a 4th field, not w."""
        if homogeneous.explicit:
            return not _is_literal_four_vector(homogeneous.construction) or self._literal_reaches_a_transform(homogeneous.construction)
        node: AST = homogeneous.construction
        parent = self.parent(node)
        while parent is not None and is_transpose(parent):
            node, parent = parent, self.parent(parent)
        if isinstance(parent, BinOp) and isinstance(parent.op, MatMult):
            return True
        if isinstance(parent, Call) and node in parent.args and self.matmul(parent) is not None:
            return True
        return self._stored_for_a_product(parent)

    def _literal_reaches_a_transform(self, construction: ast.expr) -> bool:
        """`T @ np.array([p.x, p.y, p.z, 1])`, `v = np.array([...]); T.dot(v)`, `transform(v)`; not
        `history.append(np.array([...]))` nor `v = np.array([...]); v[3] = gain`."""
        parent = self.parent(construction)
        if self._transform_use(construction, parent):
            return True
        if not (isinstance(parent, Assign) and len(parent.targets) == 1 and isinstance(parent.targets[0], Name)):
            return False
        name, scope = parent.targets[0].id, self.index.scope_of(parent)
        if any(_is_last_slot(target) for target, _ in scope.subscript_stores.get(name, [])):
            return False  # the 4th slot is a field of its own
        if self._stored_for_a_product(parent):
            return True
        return any(
            self.index.scope_of(call) is scope and self._transform_use(argument, call)
            for call in self.index.nodes(Call)
            for argument in call.args  # type: ignore[attr-defined]
            if isinstance(argument, Name) and argument.id == name
        )

    def _transform_use(self, node: AST, parent: AST | None) -> bool:
        """Whether `node` is an operand of a matrix product or an argument of a transform call."""
        if isinstance(parent, BinOp) and isinstance(parent.op, MatMult):
            return True
        if isinstance(parent, Attribute) and parent.attr == "dot":
            return True
        if not (isinstance(parent, Call) and node in parent.args):
            return False
        if self.matmul(parent) is not None:
            return True
        name = last_name(parent.func) or ""
        return _TRANSFORM_CALL.search(name) is not None and "quat" not in name.lower()

    def _filled_buffer(self, name: Name, value: ast.expr) -> Homogeneous | None:
        """`h = np.ones(4); h[:3] = x` (or `np.ones((n, 4)); h[:, :3] = x`): homogeneous x with w = 1."""
        if not isinstance(value, Call) or not self.is_array_call(value.func, "ones", "zeros"):
            return None
        scope = self.index.scope_of(name)
        stores = scope.subscript_stores.get(name.id, [])
        fills = [stored for target, stored in stores if _is_xyz_slice(target)]
        if len(fills) != 1 or len(stores) != 1:
            return None
        w = 1 if last_name(value.func) == "ones" else 0
        fixed = replace_span(self.index, value, [(last_name_target(value.func), _SWAP[last_name(value.func) or ""])])
        if fixed is None:
            return None
        return Homogeneous(inner=fills[0], w=w, construction=value, fixed=fixed)

    def _components_of_one_array(self, elements: list[ast.expr]) -> ast.expr | None:
        """For `[x[0], x[1], x[2]]` or `[x.x, x.y, x.z]` (a ROS Vector3 or Point, a PyKDL Vector), the
        expression x; else None."""
        bases = []
        for position, element in enumerate(elements):
            if isinstance(element, Subscript) and is_index(element.slice, position):
                bases.append(element.value)
            elif isinstance(element, Attribute) and element.attr == "xyz"[position]:
                bases.append(element.value)
            else:
                return None
        codes = {ast.dump(base) for base in bases}
        return bases[0] if len(codes) == 1 else None


def _algebra_frames(frames: NameFrames) -> algebra.Frames:
    return algebra.Frames(dst=frames.dst, src=frames.src, frame=frames.frame)


def _known_same(first: str | None, second: str | None) -> bool:
    """Frames a composition joins: the same by `same_frame`; two it cannot compare join nothing."""
    return same_frame(first, second) is True


_OPERATOR_KINDS: Final = {"rotation": Kind.ROTATION, "transform": Kind.TRANSFORM}


def _composed_operator(left: NameFrames, right: NameFrames) -> Literal["rotation", "transform"]:
    """What `algebra.apply` makes of two composed operators; one of unknown size composes as a transform."""
    kinds = [_OPERATOR_KINDS.get(frames.operator or "", Kind.TRANSFORM) for frames in (left, right)]
    return "rotation" if valid_kind(algebra.apply(*kinds)) == Kind.ROTATION else "transform"


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


# Calls that apply a transform to a homogeneous argument (`transform(v)`, `apply_pose`, `np.matmul`).
_TRANSFORM_CALL: Final = re.compile(r"transform|xform|apply|rotat|project|matmul|mul|dot", re.IGNORECASE)


def _is_literal_four_vector(node: ast.expr) -> bool:
    """`np.array([a, b, c, w])`: four elements written out in one array call."""
    if not (isinstance(node, Call) and node.args and isinstance(node.args[0], ast.List)):
        return False
    return len(node.args[0].elts) == 4 and last_name(node.func) in ("array", "asarray", "tensor", "as_tensor")


def _is_last_slot(target: Subscript) -> bool:
    """`v[3]`, `v[-1]`: the 4th slot of a 4-vector."""
    return number(target.slice) in (3, -1)


_ARRAY_BUILDERS: Final = ("append", "hstack", "column_stack", "concatenate", "cat", "concat", "array", "asarray", "tensor", "as_tensor", "r_", "c_")
# Array makers `_homogeneous_call` (append, joins, 4-element arrays) and `_filled_buffer` read.
_HOMOGENEOUS_MAKERS: Final = frozenset({"append", *vocab.STACKING_FUNCTIONS, "array", "asarray", "tensor", "as_tensor", "ones", "zeros"})
_SWAP: Final = {"ones": "zeros", "zeros": "ones", "ones_like": "zeros_like", "zeros_like": "ones_like"}


def _drop_batch(parts: list[ast.expr]) -> list[ast.expr]:
    """`M[..., :3, :3]` and `M[:, :3, :3]` index a batch of matrices like `M[:3, :3]` indexes one."""
    if len(parts) == 3 and (isinstance(parts[0], Constant) and parts[0].value is Ellipsis or is_full_slice(parts[0])):
        return parts[1:]
    return parts


def _is_xyz_slice(target: Subscript) -> bool:
    parts = subscript_parts(target)
    if len(parts) == 1:
        return is_slice_upto(parts[0], 3)
    return len(parts) == 2 and is_full_slice(parts[0]) and is_slice_upto(parts[1], 3)


__all__ = [
    "DST_FIRST", "EXTRINSICS_EVIDENCE", "FactBase", "FrameFact", "GEOMETRIC", "Homogeneous", "LastNameTarget",
    "MatMul", "OPERATORS", "OpaqueBinding", "SRC_FIRST", "declared_call_frames", "dotted_name",
    "einsum_operands", "is_full_slice", "is_index", "is_scalar_annotation", "is_slice_upto", "is_transpose",
    "is_zero", "keyword", "last_name", "last_name_target", "number", "positional_args", "replace_span",
    "statements_under", "string", "subscript_parts", "transposed_value", "walk_within",
]  # fmt: skip


# Imported last: the message tables read this module's helpers (no cycle at run time, only at import).
from geolint.factbase import bosdyn, messages  # noqa: E402
