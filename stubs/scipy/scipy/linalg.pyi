from typing import Annotated

from geolint.knowledge.markers import ArrayOperation

def inv(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.INVERSE]:
    """Source: scipy/linalg/_basic.py (1.17.1), inv: "Compute the inverse of a matrix"."""

def pinv(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.INVERSE]:
    """Source: scipy/linalg/_basic.py (1.17.1), pinv: "Compute the (Moore-Penrose) pseudo-inverse of a matrix"."""
