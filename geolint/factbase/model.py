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

`FactBase` holds one module's memo and answers the questions about names (qualified names, array
calls, bindings); the other questions are each a module of functions of the fact base, which the
methods here delegate to, so that a rule asks `facts.kind_of(x)` whichever module answers it:
`kinds`, `frames`, `homogeneous_forms`, `products`, `transform_blocks`, `calls` (which project
function a call runs, and its summaries).
"""

from __future__ import annotations

import ast
from ast import AST, AsyncFunctionDef, AsyncWith, Attribute, Call, FunctionDef, Name, Subscript, With
from typing import Callable, Final, Sequence, TypeVar

from geolint import algebra
from geolint.algebra import Kind
from geolint.factbase import calls, frames, homogeneous_forms, kinds, library_calls, pose_parts, products, summaries, transform_blocks
from geolint.factbase import vocabulary as vocab
from geolint.factbase.declarations import declared_call_frames
from geolint.factbase.frames import EXTRINSICS_EVIDENCE
from geolint.factbase.fact_types import DST_FIRST, GEOMETRIC, OPERATORS, SRC_FIRST, FrameFact, Homogeneous, MatMul
from geolint.factbase.spans import LastNameTarget, last_name_target, replace_span
from geolint.factbase.syntax import (
    dotted_name,
    einsum_operands,
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
from geolint.factbase.summaries import Summary, SummaryFamily
from geolint.factbase.reaching import every_binding_reaches, reaching_bindings
from geolint.factbase.index import Binding, ModuleIndex, OpaqueBinding
from geolint.knowledge import knowledge_base
from geolint.lint_types import Config
from geolint.semantic.names import NameFrames

_T = TypeVar("_T")
_A = TypeVar("_A")  # an analysis built on one fact base
_S = TypeVar("_S", bound=Summary)  # a family's summary

_MAX_DEPTH: Final = 60
_MISSING: Final = object()


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

    def cached(self, tag: str, node: AST, compute: Callable[..., _T], order: str = "") -> _T | None:
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

    def of_bindings(self, tag: str, name: Name, compute: Callable[[FactBase, str, Sequence[Binding], str], _T], order: str = "") -> _T | None:
        """`compute(self, name.id, bindings, order)` over the bindings that reach `name`. For a name
        bound more often than flow order is kept for, every use reads all of them: then once per
        name and scope, every use reading that answer (and a use in one of those bindings, `T = T @ D`,
        a cycle: None), so a scope costs its size, not its uses times its bindings."""
        bindings = self.bindings(name) or ()
        if not every_binding_reaches(bindings):
            return compute(self, name.id, bindings, order)
        return self.cached(tag, bindings, lambda facts, *_: compute(facts, name.id, bindings, order), order)  # type: ignore[arg-type]

    def memoised(self, tag: str, node: AST, compute: Callable[[], _T]) -> _T:
        """`compute()` once per `node` and `tag` for this module (no cycle guard: for facts that ask no
        others)."""
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
            resolved = knowledge_base().conventional_array_module(head) if head not in self._local_names() else None
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
        return name in names and knowledge_base().is_namespace_module(module)

    def is_module_like(self, node: AST) -> bool:
        """`np`, `np.linalg`, `scipy.spatial`: a (dotted) module name, never a value."""
        if isinstance(node, Attribute):
            return node.attr not in ("T", "mT") and self.is_module_like(node.value)
        return isinstance(node, Name) and (vocab.is_module_name(node.id) or node.id in self.index.imported_modules)

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
        return products.matmul(self, node)

    def transposed(self, node: AST) -> ast.expr | None:
        """For a swap of the last two axes (`x.T`, `x.mT`, `x.t()`, `x.transpose(-1, -2)`, `x.permute(1, 0)`,
        `np.transpose(x)`, `torch.swapaxes(x, -2, -1)`, `tf.linalg.matrix_transpose(x)`), x; else None."""
        return pose_parts.transpose_of(node) if isinstance(node, ast.expr) else None

    # -- kind --------------------------------------------------------------------------------
    def kind_of(self, node: AST) -> Kind | None:
        """The geometric kind of an expression, or None."""
        return kinds.kind_of(self, node)

    def is_free(self, node: AST) -> bool:
        """A free vector (direction, normal, velocity...): rotated only, never translated."""
        return kinds.is_free(self, node)

    # -- calls of project functions, and their summaries -------------------------------------
    def may_have_summary(self, call: Call) -> bool:
        """A cheap test: whether the callee can be a function of this module or of a project module."""
        return calls.may_have_summary(self, call)

    def summary_of(self, call: Call, family: SummaryFamily[_S]) -> _S | None:
        """What the called helper does, as far as `family` asks (`KINDS`, `ANGLE_UNITS`...): a function of
        this module, or of a project module it imports. Only the families asked are computed."""
        return calls.summary_of(self, call, family)

    def summary_of_property(self, read: Attribute, family: SummaryFamily[_S]) -> _S | None:
        """What reading a property of a project class returns (its `@property` getter's summary)."""
        return calls.summary_of_property(self, read, family)

    def own_method(self, call: Call) -> FunctionDef | AsyncFunctionDef | None:
        """For `self.helper(...)` inside a method: the one `helper` of the same class, when it takes `self`
        (not a static or class method); else None."""
        return calls.own_method(self, call)

    def called_function(self, call: Call) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
        """The project function a call runs (of this module, or of a project module it imports, through
        aliases, relative imports and package `__init__` re-exports) and the fact base of the module that
        defines it."""
        return calls.called_function(self, call)

    def star_imported_function(self, name: str) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
        """The project function a module-level `name` is when the module neither binds nor imports it there
        and exactly one of its star imports of project modules (`from ..collision import *`) defines it."""
        return calls.star_imported_function(self, name)

    def defining_module(self, qualified: str, importer: str) -> tuple[FactBase, str] | None:
        """For `pkg.mod.name` (or `.mod.name`) imported by `importer`: the fact base of the project module
        `pkg.mod` and `name`; None for a third-party or unresolved module."""
        return calls.defining_module(self, qualified, importer)

    def is_non_geometric(self, binding: Binding) -> bool:
        """Evidence that a binding holds a scalar, a string or a flag, never a 3-vector."""
        return kinds.is_non_geometric(self, binding)

    # -- blocks of transforms ----------------------------------------------------------------
    def rotation_block_of(self, node: AST) -> ast.expr | None:
        """For `M[:3, :3]` (or `M[..., :3, :3]`, `M[:, :3, :3]`), the matrix M; else None."""
        return transform_blocks.rotation_block_of(self, node)

    def translation_of(self, node: AST) -> ast.expr | None:
        """For `M[:3, 3]` (or `M[:3, -1]`, `M[0:3, 3]`, `M[..., :3, 3]`, `M[..., :3, 3:]`), the matrix M; else None."""
        return transform_blocks.translation_of(self, node)

    def is_translation_like(self, node: AST) -> bool:
        """`t`, `trans`, `translation`, `t_world_cam`, `T[:3, 3]`, `pose.translation`, `tvec`."""
        return transform_blocks.is_translation_like(self, node)

    def has_geometric_evidence(self, node: AST) -> bool:
        """Whether a point-like expression is visibly geometric (not a file offset, a cursor position or a
        tuple): a strong or frame-stating name, a mesh attribute, or array flow."""
        return kinds.has_geometric_evidence(self, node)

    # -- library transforms ------------------------------------------------------------------
    def translating_library_object(self, node: AST) -> str | None:
        """The library class of `node` (`PyKDL.Frame`, `spatialmath.SE3`) when `*` with it moves what it
        multiplies as a point, R p + t (built directly, through a variable, or returned by a helper of this
        module), by the stubs."""
        return library_calls.translating_product(self, node)

    # -- frames ------------------------------------------------------------------------------
    def frames_of(self, node: AST, order: str = DST_FIRST) -> NameFrames | None:
        """The frames of an expression (operator: dst/src; value: frame) with `T_a_b` names read in `order`,
        or None."""
        return frames.frames_of(self, node, order)

    def frame_fact(self, node: AST, order: str = DST_FIRST) -> FrameFact | None:
        return frames.frame_fact(self, node, order)

    def readings(self) -> tuple[str, ...]:
        """The orders a rule must check: a frame problem is reported only when every reading has it."""
        return self.orders

    def name_frames(self, name: str, order: str) -> FrameFact | None:
        """What a name states, read in `order` (only `T_a_b` / `R_a_b` depend on it)."""
        return frames.name_frames(self, name, order)

    # -- homogeneous coordinates ---------------------------------------------------------------
    def homogeneous(self, node: AST) -> Homogeneous | None:
        """The homogeneous construction `node` is (directly, or through a variable), or None."""
        return homogeneous_forms.homogeneous(self, node)

    def homogenized(self, homogeneous: Homogeneous) -> algebra.Outcome | None:
        """What `algebra.homogenize` makes of a construction `[x; w]` from x's kind (None: x's kind is
        unknown)."""
        return homogeneous_forms.homogenized(self, homogeneous)

    def homogeneous_built_by(self, node: AST) -> Homogeneous | None:
        """The homogeneous value whose construction is exactly `node` (including an `np.ones(4)` buffer filled
        later), or None."""
        return homogeneous_forms.homogeneous_built_by(self, node)

    def used_as_homogeneous(self, homogeneous: Homogeneous) -> bool:
        """Whether a construction is visibly used as homogeneous: built explicitly as a 4-vector, multiplied
        by a matrix (directly or through the variable holding it), or stored under a homogeneous name
        (`p_h`, `points_hom`). A literal 4-vector (`np.array([p.x, p.y, p.z, 0])`) counts only when it
        reaches a product or a transform call: one only stored (appended to a list), or whose last slot is
        written later, is a record with a 4th field, not w."""
        return homogeneous_forms.used_as_homogeneous(self, homogeneous)


__all__ = [
    "DST_FIRST", "EXTRINSICS_EVIDENCE", "FactBase", "FrameFact", "GEOMETRIC", "Homogeneous", "LastNameTarget",
    "MatMul", "OPERATORS", "OpaqueBinding", "SRC_FIRST", "declared_call_frames", "dotted_name",
    "einsum_operands", "is_full_slice", "is_index", "is_scalar_annotation", "is_slice_upto", "is_transpose",
    "is_zero", "keyword", "last_name", "last_name_target", "number", "positional_args", "replace_span",
    "statements_under", "string", "subscript_parts", "transposed_value", "walk_within",
]  # fmt: skip

