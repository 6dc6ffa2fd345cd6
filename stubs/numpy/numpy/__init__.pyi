from typing import Annotated

from geolint.knowledge.markers import ArrayOperation

from numpy import linalg as linalg

def transpose(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.TRANSPOSE]:
    """Source: numpy numpy.transpose (2.4.6 documentation): "For a 2-D array, this is the standard matrix transpose"; with `axes`, the permutation given (checked: the last two axes swapped for `axes=(0, 2, 1)`)."""

def swapaxes(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.TRANSPOSE]:
    """Source: numpy numpy.swapaxes (2.4.6 documentation): "Interchange two axes of an array"; `swapaxes(R, -1, -2)` is a batch of transposes."""

def matrix_transpose(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.TRANSPOSE]:
    """Source: numpy numpy.matrix_transpose (2.4.6 documentation): "Transposes a matrix (or a stack of matrices)", the last two axes."""

def dot(a: object, b: object, out: object = ...) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: numpy numpy.dot (2.4.6 documentation): "If both a and b are 2-D arrays, it is matrix multiplication"."""

def matmul(x1: object, x2: object, /, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: numpy numpy.matmul (2.4.6 documentation): "Matrix product of two arrays"; stacks of matrices broadcast."""

def einsum(subscripts: str, *operands: object, **kwargs: object) -> Annotated[object, ArrayOperation.EINSUM]:
    """Source: numpy numpy.einsum (2.4.6 documentation): "Evaluates the Einstein summation convention on the operands"."""

def pad(array: object, pad_width: object, mode: str = ..., **kwargs: object) -> Annotated[object, ArrayOperation.PAD_PER_AXIS]:
    """Source: numpy numpy.pad (2.4.6 documentation): pad_width "((before_1, after_1), ... (before_N, after_N)) unique pad widths for each axis"; `constant_values` defaults to 0 (checked: `np.pad(np.ones((2, 3)), ((0, 0), (0, 1)), constant_values=1)` appends a column of ones)."""
