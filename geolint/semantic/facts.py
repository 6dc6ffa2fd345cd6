"""Config-independent facts about one module, gathered in a single traversal.

Parents of every node, the scopes (module, classes, functions) with the bindings made in
each (assignments, parameters, loop targets, `buf[:3] = x` stores), and the import table.
`SemanticFactsProvider` computes them once per file as libcst metadata, so every rule (and
the editor server) shares one copy; `geolint.semantic.model` interprets them.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Union

import libcst as cst
from libcst.metadata import BaseMetadataProvider

ScopeNode = Union[cst.Module, cst.FunctionDef, cst.ClassDef, cst.Lambda]


@dataclass(frozen=True)
class LoopBinding:
    """`for target in iterable`: the name is bound to one element of `iterable`.

    `position` is the index in a tuple target (`for i, n in enumerate(normals)`), else None.
    """

    iterable: cst.BaseExpression
    position: int | None = None


@dataclass(frozen=True)
class ParamBinding:
    """A function parameter (its default and annotation are the only evidence about it)."""

    param: cst.Param


@dataclass(frozen=True)
class OpaqueBinding:
    """A binding the model cannot see through (tuple unpacking, `with ... as`, imports)."""


Binding = Union[cst.BaseExpression, LoopBinding, ParamBinding, OpaqueBinding]


@dataclass
class Scope:
    """The names bound directly in one module, class or function body."""

    node: ScopeNode
    parent: Scope | None
    bindings: dict[str, list[Binding]] = field(default_factory=dict)
    # `buf[:3] = x` and `buf[:, :3] = x`: name -> [(subscript target, value)]
    subscript_stores: dict[str, list[tuple[cst.Subscript, cst.BaseExpression]]] = field(default_factory=dict)
    # `obj.attr = value`: (target attribute, value, the statement)
    attribute_stores: list[tuple[cst.Attribute, cst.BaseExpression]] = field(default_factory=list)
    augmented: set[str] = field(default_factory=set)
    # Names used as an operand of a matrix product (`T @ x`, `x.dot(M)`, `np.dot(T, x.T)`).
    matmul_operands: set[str] = field(default_factory=set)
    returns: list[cst.BaseExpression] = field(default_factory=list)

    def bind(self, name: str, binding: Binding) -> None:
        self.bindings.setdefault(name, []).append(binding)


@dataclass
class ModuleFacts:
    """Everything one traversal of a module learns; shared by all rules of one file."""

    module: cst.Module
    parents: dict[cst.CSTNode, cst.CSTNode]
    scopes: dict[cst.CSTNode, Scope]
    imports: dict[str, str]  # local name -> fully qualified name
    imported_modules: set[str]  # local names bound by `import x` / `import x as y`
    functions: dict[str, cst.FunctionDef]  # module-level functions, by name
    views: dict[object, object] = field(default_factory=dict)  # config -> SemanticModel (model.py)

    @property
    def code(self) -> str:
        """The module's source text (generated once, on first use)."""
        text = self.views.get("__code__")
        if text is None:
            text = self.views["__code__"] = self.module.code
        return text  # type: ignore[return-value]

    def parent(self, node: cst.CSTNode) -> cst.CSTNode | None:
        return self.parents.get(node)

    def scope_of(self, node: cst.CSTNode) -> Scope:
        """The innermost scope whose body contains `node` (a def's own name and defaults excluded)."""
        current: cst.CSTNode | None = self.parents.get(node)
        child: cst.CSTNode = node
        while current is not None:
            if current in self.scopes and (not isinstance(current, cst.FunctionDef) or child is current.body):
                return self.scopes[current]
            if isinstance(current, cst.Lambda) and child is current.body:
                return self.scopes[current]
            child, current = current, self.parents.get(current)
        return self.scopes[self.module]

    def lookup(self, name: str, scope: Scope) -> list[Binding] | None:
        """The bindings `name` resolves to from `scope` (Python's rule: class bodies are skipped)."""
        if name in scope.bindings:
            return scope.bindings[name]
        current = scope.parent
        while current is not None:
            if not isinstance(current.node, cst.ClassDef) and name in current.bindings:
                return current.bindings[name]
            current = current.parent
        return None


class _Collector(cst.CSTVisitor):
    def __init__(self, module: cst.Module) -> None:
        super().__init__()
        self.parents: dict[cst.CSTNode, cst.CSTNode] = {}
        self.stack: list[cst.CSTNode] = []
        root = Scope(module, None)
        self.scopes: dict[cst.CSTNode, Scope] = {module: root}
        self.scope_stack: list[Scope] = [root]
        self.imports: dict[str, str] = {}
        self.imported_modules: set[str] = set()
        self.functions: dict[str, cst.FunctionDef] = {}

    # parents ------------------------------------------------------------------------
    def on_visit(self, node: cst.CSTNode) -> bool:
        if self.stack:
            self.parents[node] = self.stack[-1]
        self.stack.append(node)
        return super().on_visit(node)

    def on_leave(self, original_node: cst.CSTNode) -> None:
        super().on_leave(original_node)
        self.stack.pop()

    @property
    def scope(self) -> Scope:
        return self.scope_stack[-1]

    # scopes -------------------------------------------------------------------------
    def _push(self, node: ScopeNode) -> None:
        scope = Scope(node, self.scope)
        self.scopes[node] = scope
        self.scope_stack.append(scope)

    def visit_FunctionDef(self, node: cst.FunctionDef) -> None:
        self.scope.bind(node.name.value, OpaqueBinding())
        if len(self.scope_stack) == 1:
            self.functions[node.name.value] = node
        self._push(node)
        params = node.params
        for param in (*params.posonly_params, *params.params, *params.kwonly_params):
            self.scope.bind(param.name.value, ParamBinding(param))
        for star in (params.star_arg, params.star_kwarg):
            if isinstance(star, cst.Param):
                self.scope.bind(star.name.value, OpaqueBinding())

    def leave_FunctionDef(self, original_node: cst.FunctionDef) -> None:
        self.scope_stack.pop()

    def visit_Lambda(self, node: cst.Lambda) -> None:
        self._push(node)
        for param in node.params.params:
            self.scope.bind(param.name.value, ParamBinding(param))

    def leave_Lambda(self, original_node: cst.Lambda) -> None:
        self.scope_stack.pop()

    def visit_ClassDef(self, node: cst.ClassDef) -> None:
        self.scope.bind(node.name.value, OpaqueBinding())
        self._push(node)

    def leave_ClassDef(self, original_node: cst.ClassDef) -> None:
        self.scope_stack.pop()

    # bindings -----------------------------------------------------------------------
    def _bind_target(self, target: cst.BaseExpression, value: Binding) -> None:
        if isinstance(target, cst.Name):
            self.scope.bind(target.value, value)
        elif isinstance(target, (cst.Tuple, cst.List)):
            for element in target.elements:
                self._bind_target(element.value, OpaqueBinding())
        elif isinstance(target, cst.StarredElement):
            self._bind_target(target.value, OpaqueBinding())
        elif isinstance(target, cst.Subscript) and isinstance(target.value, cst.Name):
            if isinstance(value, cst.BaseExpression):
                self.scope.subscript_stores.setdefault(target.value.value, []).append((target, value))
        elif isinstance(target, cst.Attribute) and isinstance(value, cst.BaseExpression):
            self.scope.attribute_stores.append((target, value))

    def visit_Assign(self, node: cst.Assign) -> None:
        for target in node.targets:
            self._bind_target(target.target, node.value)

    def visit_AnnAssign(self, node: cst.AnnAssign) -> None:
        self._bind_target(node.target, node.value if node.value is not None else OpaqueBinding())

    def visit_AugAssign(self, node: cst.AugAssign) -> None:
        if isinstance(node.target, cst.Name):
            self.scope.augmented.add(node.target.value)
        elif isinstance(node.target, cst.Attribute):
            self.scope.attribute_stores.append((node.target, node.value))

    def visit_NamedExpr(self, node: cst.NamedExpr) -> None:
        self._bind_target(node.target, node.value)

    def visit_For(self, node: cst.For) -> None:
        self._bind_loop(node.target, node.iter)

    def visit_CompFor(self, node: cst.CompFor) -> None:
        self._bind_loop(node.target, node.iter)

    def _bind_loop(self, target: cst.BaseExpression, iterable: cst.BaseExpression) -> None:
        if isinstance(target, cst.Name):
            self.scope.bind(target.value, LoopBinding(iterable))
        elif isinstance(target, (cst.Tuple, cst.List)):
            for position, element in enumerate(target.elements):
                if isinstance(element.value, cst.Name):
                    self.scope.bind(element.value.value, LoopBinding(iterable, position))
                else:
                    self._bind_target(element.value, OpaqueBinding())

    def visit_WithItem(self, node: cst.WithItem) -> None:
        if node.asname is not None:
            self._bind_target(node.asname.name, OpaqueBinding())

    def visit_ExceptHandler(self, node: cst.ExceptHandler) -> None:
        if node.name is not None:
            self._bind_target(node.name.name, OpaqueBinding())

    def visit_BinaryOperation(self, node: cst.BinaryOperation) -> None:
        if isinstance(node.operator, cst.MatrixMultiply):
            self._matmul_operands(node.left, node.right)

    def visit_Call(self, node: cst.Call) -> None:
        func = node.func
        if isinstance(func, cst.Attribute) and func.attr.value in ("dot", "matmul"):
            self._matmul_operands(func.value, *(arg.value for arg in node.args))

    def _matmul_operands(self, *operands: cst.BaseExpression) -> None:
        for operand in operands:
            while isinstance(operand, cst.Attribute) and operand.attr.value == "T":
                operand = operand.value
            if isinstance(operand, cst.Name):
                self.scope.matmul_operands.add(operand.value)

    def visit_Return(self, node: cst.Return) -> None:
        if node.value is not None:
            self.scope.returns.append(node.value)

    def visit_Global(self, node: cst.Global) -> None:
        for item in node.names:
            self.scope.bind(item.name.value, OpaqueBinding())

    def visit_Nonlocal(self, node: cst.Nonlocal) -> None:
        for item in node.names:
            self.scope.bind(item.name.value, OpaqueBinding())

    # imports ------------------------------------------------------------------------
    def visit_Import(self, node: cst.Import) -> None:
        for alias in node.names:
            dotted = _dotted(alias.name)
            if dotted is None:
                continue
            if alias.asname is not None and isinstance(alias.asname.name, cst.Name):
                local = alias.asname.name.value
                self.imports[local] = dotted
            else:
                local = dotted.split(".")[0]
                self.imports[local] = local
            self.imported_modules.add(local)
            self.scope.bind(local, OpaqueBinding())

    def visit_ImportFrom(self, node: cst.ImportFrom) -> None:
        if isinstance(node.names, cst.ImportStar) or node.relative:
            return
        package = _dotted(node.module) if node.module is not None else None
        if package is None:
            return
        for alias in node.names:
            name = _dotted(alias.name)
            if name is None:
                continue
            local = (
                alias.asname.name.value
                if alias.asname is not None and isinstance(alias.asname.name, cst.Name)
                else name
            )
            self.imports[local] = f"{package}.{name}"
            self.scope.bind(local, OpaqueBinding())


def _dotted(node: cst.BaseExpression | cst.CSTNode) -> str | None:
    if isinstance(node, cst.Name):
        return node.value
    if isinstance(node, cst.Attribute):
        base = _dotted(node.value)
        return None if base is None else f"{base}.{node.attr.value}"
    return None


def build_facts(module: cst.Module) -> ModuleFacts:
    collector = _Collector(module)
    module.visit(collector)
    return ModuleFacts(
        module=module,
        parents=collector.parents,
        scopes=collector.scopes,
        imports=collector.imports,
        imported_modules=collector.imported_modules,
        functions=collector.functions,
    )


class SemanticFactsProvider(BaseMetadataProvider[ModuleFacts]):
    """libcst metadata: the `ModuleFacts` of the module, set on the `Module` node, computed once."""

    def _gen_impl(self, module: cst.Module) -> None:
        self.set_metadata(module, build_facts(module))
