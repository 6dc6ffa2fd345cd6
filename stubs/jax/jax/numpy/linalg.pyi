from typing import Annotated

from geolint.knowledge.markers import ArrayOperation

def inv(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.INVERSE]:
    """Source: jax.numpy.linalg.inv (https://jax.readthedocs.io/en/latest/jax.numpy.html): numpy.linalg.inv's API."""

def pinv(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.INVERSE]:
    """Source: jax.numpy.linalg.pinv (https://jax.readthedocs.io/en/latest/jax.numpy.html): numpy.linalg.pinv's API."""
