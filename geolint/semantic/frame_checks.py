"""Frame reasoning shared by the GEO2xx rules: which operand pairs of a product carry frames."""

from __future__ import annotations

import libcst as cst

from geolint.semantic.model import MatMul, SemanticModel


def product_operands(model: SemanticModel, node: cst.CSTNode) -> MatMul | None:
    """A matrix product in any spelling, plus `A * B` when an operand is a named transform
    (spatialmath `SE3 * SE3`, PyKDL `Frame * Vector`)."""
    product = model.matmul(node)
    if product is not None:
        return product
    if isinstance(node, cst.BinaryOperation) and isinstance(node.operator, cst.Multiply):
        left = model.frames_of(node.left)
        if left is not None and left.is_operator and left.operator == "transform":
            return MatMul(node, node.left, node.right)
    return None

