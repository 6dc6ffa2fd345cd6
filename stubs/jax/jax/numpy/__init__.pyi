from typing import Annotated

from geolint.knowledge.markers import ArrayOperation

from jax.numpy import linalg as linalg

def transpose(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.TRANSPOSE]:
    """Source: jax.numpy.transpose (https://jax.readthedocs.io/en/latest/jax.numpy.html): numpy.transpose's API."""

def swapaxes(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.TRANSPOSE]:
    """Source: jax.numpy.swapaxes (https://jax.readthedocs.io/en/latest/jax.numpy.html): numpy.swapaxes's API."""

def dot(a: object, b: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: jax.numpy.dot (https://jax.readthedocs.io/en/latest/jax.numpy.html): numpy.dot's API."""

def matmul(a: object, b: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: jax.numpy.matmul (https://jax.readthedocs.io/en/latest/jax.numpy.html): numpy.matmul's API."""

def einsum(subscripts: str, *operands: object, **kwargs: object) -> Annotated[object, ArrayOperation.EINSUM]:
    """Source: jax.numpy.einsum (https://jax.readthedocs.io/en/latest/jax.numpy.html): numpy.einsum's API."""

def pad(array: object, pad_width: object, mode: str = ..., **kwargs: object) -> Annotated[object, ArrayOperation.PAD_PER_AXIS]:
    """Source: jax jax.numpy.pad (0.4 documentation): "Add padding to an array", numpy.pad's signature: pad_width is "((before_1, after_1), ... (before_N, after_N))" per axis."""
