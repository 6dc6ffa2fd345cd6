from typing import Annotated

from geolint.knowledge.markers import ArrayOperation

def inv(A: object, *, out: object = ...) -> Annotated[object, ArrayOperation.INVERSE]:
    """Source: torch torch.linalg.inv (PyTorch 2.x documentation): "Computes the inverse of a square matrix if it exists"; "Supports ... batches of matrices"."""

def pinv(A: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.INVERSE]:
    """Source: torch torch.linalg.pinv (PyTorch 2.x documentation): "Computes the pseudoinverse (Moore-Penrose inverse) of a matrix"."""

def matmul(input: object, other: object, *, out: object = ...) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: torch torch.linalg.matmul (PyTorch 2.x documentation): "Alias for torch.matmul()"."""
