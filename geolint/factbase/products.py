"""Matrix products in any spelling: `a @ b`, `a.dot(b)`, `np.dot(a, b)`, `np.matmul`, `torch.matmul` /
`bmm`, and an `einsum` that is a matrix acting on an operand."""

from __future__ import annotations

from ast import AST, Attribute, BinOp, Call, MatMult
from typing import Final, TYPE_CHECKING

from geolint.factbase.fact_types import MatMul
from geolint.factbase.syntax import einsum_operands, positional_args

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

_MATMUL_CALL_NAMES: Final = frozenset(("dot", "matmul", "bmm", "einsum"))  # what `FactBase.matmul` reads as a product


def matmul(facts: FactBase, node: AST) -> MatMul | None:
    """`a @ b`, `a.dot(b)`, `np.dot(a, b)`, `np.matmul(a, b)`, `torch.matmul/bmm(a, b)`."""
    kind = type(node)
    if kind is BinOp:
        return MatMul(node, node.left, node.right) if type(node.op) is MatMult else None  # type: ignore[attr-defined,arg-type]
    # asked of every call by several rules: the callee's last name rules out nearly all at once
    if isinstance(node, Call) and facts.called_name(node.func) in _MATMUL_CALL_NAMES:
        positional = positional_args(node)
        func = node.func
        if isinstance(func, Attribute) and func.attr in ("dot", "matmul") and len(positional) == 1 and not node.keywords:
            if not facts.is_module_like(func.value):
                return MatMul(node, func.value, positional[0])
        if len(positional) == 2 and len(node.args) == 2 and facts.is_array_call(func, "dot", "matmul", "bmm"):
            return MatMul(node, positional[0], positional[1])
        if len(positional) == 3 and len(node.args) == 3 and facts.is_array_call(func, "einsum"):
            operands = einsum_operands(positional[0], positional[1], positional[2])
            if operands is not None:
                return MatMul(node, *operands)
    return None
