"""Frame reasoning shared by the GEO2xx rules: operand pairs of products and how to describe frames."""

from __future__ import annotations

import libcst as cst

from geolint.semantic.model import MatMul, SemanticModel
from geolint.semantic.names import NameFrames


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


def describe(frames: NameFrames) -> str:
    if frames.is_operator:
        return f"maps {frames.src} into {frames.dst}"
    return f"is in {frames.frame}"
