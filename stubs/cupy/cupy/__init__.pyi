from typing import Annotated

from geolint.knowledge.markers import ArrayOperation

from cupy import linalg as linalg

def transpose(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.TRANSPOSE]:
    """Source: cupy.transpose (https://docs.cupy.dev/en/stable/reference/routines.html): numpy.transpose's API."""

def swapaxes(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.TRANSPOSE]:
    """Source: cupy.swapaxes (https://docs.cupy.dev/en/stable/reference/routines.html): numpy.swapaxes's API."""

def dot(a: object, b: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: cupy.dot (https://docs.cupy.dev/en/stable/reference/routines.html): numpy.dot's API."""

def matmul(a: object, b: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: cupy.matmul (https://docs.cupy.dev/en/stable/reference/routines.html): numpy.matmul's API."""

def einsum(subscripts: str, *operands: object, **kwargs: object) -> Annotated[object, ArrayOperation.EINSUM]:
    """Source: cupy.einsum (https://docs.cupy.dev/en/stable/reference/routines.html): numpy.einsum's API."""

def pad(array: object, pad_width: object, mode: str = ..., **kwargs: object) -> Annotated[object, ArrayOperation.PAD_PER_AXIS]:
    """Source: cupy cupy.pad (13 documentation): "Pads an array with specified widths and values", pad_width "((before_1, after_1), ... (before_N, after_N))" per axis, as numpy.pad."""
