"""Matrix products in any spelling: `a @ b`, `a.dot(b)`, `np.dot(a, b)`, `np.matmul`, `torch.matmul` /
`bmm`, and an `einsum` that is a matrix acting on an operand. Functions are the ones the stubs mark as
products (`torch.mm`, `np.linalg.matmul`, `tf.linalg.matmul`); methods of an array are read by name."""

from __future__ import annotations

from ast import AST, Attribute, BinOp, Call, MatMult
from functools import cache
from typing import Final, TYPE_CHECKING

from geolint.factbase.fact_types import MatMul
from geolint.factbase.syntax import einsum_operands, positional_args
from geolint.knowledge import knowledge_base
from geolint.knowledge.markers import ArrayOperation

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

# `a.dot(b)`, `a.mm(b)`: an array's product methods, read by their spelling
_PRODUCT_METHODS: Final = frozenset(("dot", "matmul", "mm", "bmm"))


@cache
def _product_names() -> frozenset[str]:
    """Every last name a product can be called by: asked of every call by several rules, it rules out
    nearly all at once."""
    return knowledge_base().array_operation_names(ArrayOperation.MATMUL, ArrayOperation.EINSUM) | _PRODUCT_METHODS


def matmul(facts: FactBase, node: AST) -> MatMul | None:
    """`a @ b`, `a.dot(b)`, `a.mm(b)`, and the functions the stubs mark as products (`np.dot(a, b)`,
    `np.matmul`, `torch.mm/bmm`, `tf.linalg.matmul`) or as an `einsum`."""
    kind = type(node)
    if kind is BinOp:
        return MatMul(node, node.left, node.right) if type(node.op) is MatMult else None  # type: ignore[attr-defined,arg-type]
    if not isinstance(node, Call) or facts.called_name(node.func) not in _product_names():
        return None
    positional = positional_args(node)
    func = node.func
    if isinstance(func, Attribute) and func.attr in _PRODUCT_METHODS and len(positional) == 1 and not node.keywords:
        if not facts.is_module_like(func.value):
            return MatMul(node, func.value, positional[0])
    qualified = facts.qualified_name(func)
    operation = knowledge_base().array_operation(qualified) if qualified is not None else None
    if operation == ArrayOperation.MATMUL and len(positional) == 2 and len(node.args) == 2:
        return MatMul(node, positional[0], positional[1])
    if operation == ArrayOperation.EINSUM and len(positional) == 3 and len(node.args) == 3:
        operands = einsum_operands(positional[0], positional[1], positional[2])
        if operands is not None:
            return MatMul(node, *operands)
    return None
