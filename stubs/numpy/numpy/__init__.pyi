from typing import Annotated

from geolint.knowledge.markers import ArrayOperation
from geolint.typing import Degrees, Radians

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

def asarray(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.AS_ARRAY]:
    """Source: numpy numpy.asarray (2.4.6 documentation): "Convert the input to an array"; "No copy is performed if the input is already an ndarray" (checked: `np.asarray(p) is p`)."""

def append(arr: object, values: object, axis: object = ...) -> Annotated[object, ArrayOperation.APPEND_FLAT]:
    """Source: numpy numpy.append (2.4.6 documentation): "Append values to the end of an array"; "If axis is not specified, values can be any shape and will be flattened before use" (checked: `np.append([1.0, 2.0, 3.0], 1.0)` is `[1, 2, 3, 1]`)."""

# Angles: numpy's trigonometric functions read radians, its inverse ones return radians.

def sin(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: numpy numpy.sin documentation (2.4.6): the argument is an angle in radians."""

def cos(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: numpy numpy.cos documentation (2.4.6): the argument is an angle in radians."""

def tan(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: numpy numpy.tan documentation (2.4.6): the argument is an angle in radians."""

def arcsin(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: numpy numpy.arcsin documentation (2.4.6): returns an angle in radians."""

def arccos(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: numpy numpy.arccos documentation (2.4.6): returns an angle in radians."""

def arctan(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: numpy numpy.arctan documentation (2.4.6): returns an angle in radians."""

def arctan2(x1: object, x2: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: numpy numpy.arctan2 documentation (2.4.6): returns an angle in radians."""

# numpy 2's array-API names for the same functions (numpy 2.4.6 documentation: "numpy.asin ... alias of arcsin")
asin = arcsin
acos = arccos
atan = arctan
atan2 = arctan2

def degrees(x: Radians, /, *args: object, **kwargs: object) -> Degrees:
    """Source: numpy numpy.degrees documentation (2.4.6): converts angles from radians to degrees."""

def rad2deg(x: Radians, /, *args: object, **kwargs: object) -> Degrees:
    """Source: numpy numpy.rad2deg documentation (2.4.6): converts angles from radians to degrees."""

def radians(x: Degrees, /, *args: object, **kwargs: object) -> Radians:
    """Source: numpy numpy.radians documentation (2.4.6): converts angles from degrees to radians."""

def deg2rad(x: Degrees, /, *args: object, **kwargs: object) -> Radians:
    """Source: numpy numpy.deg2rad documentation (2.4.6): converts angles from degrees to radians."""

pi: Radians
"""Source: numpy numpy.pi documentation (2.4.6): the constant pi, a half turn in radians."""
