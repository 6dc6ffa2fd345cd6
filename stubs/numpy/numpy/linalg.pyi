from typing import Annotated

from geolint.knowledge.markers import ArrayOperation

def inv(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.INVERSE]:
    """Source: numpy numpy.linalg.inv (2.4.6 documentation): "Compute the inverse of a matrix"; "Broadcasting rules apply" to stacks (checked numerically: inv(R) @ R is the identity)."""

def pinv(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.INVERSE]:
    """Source: numpy numpy.linalg.pinv (2.4.6 documentation): "Compute the (Moore-Penrose) pseudo-inverse of a matrix", the inverse of an invertible one."""

def matmul(x1: object, x2: object, /) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: numpy numpy.linalg.matmul (2.4.6 documentation): the same product as numpy.matmul."""
