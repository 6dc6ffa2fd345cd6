"""Frame reasoning shared by the GEO2xx rules: which operand pairs of a product carry frames."""

from __future__ import annotations

import libcst as cst

from geolint.semantic.model import MatMul, SemanticModel
from geolint.semantic.names import NameFrames
from geolint.semantic.rule_support import SemanticRule


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



class ProductRule(SemanticRule):
    """A rule about products whose two operands both have known frames (GEO201, GEO202).

    Subclasses implement `check_product`; this base finds the product in any spelling and reads
    both operands' frames once.
    """

    def visit_BinaryOperation(self, node: cst.BinaryOperation) -> None:
        self._visit_product(node)

    def visit_Call(self, node: cst.Call) -> None:
        self._visit_product(node)

    def _visit_product(self, node: cst.CSTNode) -> None:
        product = product_operands(self.model, node)
        if product is None:
            return
        left, right = self.model.frames_of(product.left), self.model.frames_of(product.right)
        if left is not None and right is not None:
            self.check_product(node, product, left, right)

    def check_product(self, node: cst.CSTNode, product: MatMul, left: NameFrames, right: NameFrames) -> None:
        raise NotImplementedError
