from typing import Annotated

from geolint.knowledge.markers import ArrayOperation
from geolint.typing import Degrees, Radians

from torch import linalg as linalg

def transpose(input: object, dim0: int, dim1: int) -> Annotated[object, ArrayOperation.TRANSPOSE]:
    """Source: torch torch.transpose (PyTorch 2.x documentation): "Returns a tensor that is a transposed version of input. The given dimensions dim0 and dim1 are swapped"."""

def swapaxes(input: object, axis0: int, axis1: int) -> Annotated[object, ArrayOperation.TRANSPOSE]:
    """Source: torch torch.swapaxes (PyTorch 2.x documentation): "Alias for torch.transpose()"."""

def inverse(input: object, *, out: object = ...) -> Annotated[object, ArrayOperation.INVERSE]:
    """Source: torch torch.inverse (PyTorch 2.x documentation): "Alias for torch.linalg.inv()"."""

def matmul(input: object, other: object, *, out: object = ...) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: torch torch.matmul (PyTorch 2.x documentation): "Matrix product of two tensors"; batched for more than two dimensions."""

def bmm(input: object, mat2: object, *, out: object = ...) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: torch torch.bmm (PyTorch 2.x documentation): "Performs a batch matrix-matrix product of matrices stored in input and mat2"."""

def mm(input: object, mat2: object, *, out: object = ...) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: torch torch.mm (PyTorch 2.x documentation): "Performs a matrix multiplication of the matrices input and mat2"."""

def einsum(equation: str, *operands: object) -> Annotated[object, ArrayOperation.EINSUM]:
    """Source: torch torch.einsum (PyTorch 2.x documentation): "Sums the product of the elements of the input operands along dimensions specified using a notation based on the Einstein summation convention"."""

# Array makers: the shape may be given as separate sizes (`torch.zeros(4, 4)`), unlike numpy's one shape argument.

def zeros(*size: int, **kwargs: object) -> object:
    """Source: torch torch.zeros (PyTorch 2.x documentation): "size (int...) – a sequence of integers defining the shape of the output tensor. Can be a variable number of arguments or a collection like a list or tuple"."""

def ones(*size: int, **kwargs: object) -> object:
    """Source: torch torch.ones (PyTorch 2.x documentation): "size (int...) – a sequence of integers defining the shape of the output tensor. Can be a variable number of arguments or a collection like a list or tuple"."""

def empty(*size: int, **kwargs: object) -> object:
    """Source: torch torch.empty (PyTorch 2.x documentation): "size (int...) – a sequence of integers defining the shape of the output tensor. Can be a variable number of arguments or a collection like a list or tuple"."""

# Angles: torch's trigonometric functions read radians, its inverse ones return radians.

def sin(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: torch torch.sin (PyTorch 2.x documentation) (2.5): the argument is an angle in radians."""

def cos(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: torch torch.cos (PyTorch 2.x documentation) (2.5): the argument is an angle in radians."""

def tan(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: torch torch.tan (PyTorch 2.x documentation) (2.5): the argument is an angle in radians."""

def asin(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: torch torch.asin (PyTorch 2.x documentation) (2.5): returns an angle in radians."""

def acos(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: torch torch.acos (PyTorch 2.x documentation) (2.5): returns an angle in radians."""

def atan(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: torch torch.atan (PyTorch 2.x documentation) (2.5): returns an angle in radians."""

def atan2(x1: object, x2: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: torch torch.atan2 (PyTorch 2.x documentation) (2.5): returns an angle in radians."""

# torch's numpy-style names for the same functions (PyTorch 2.x documentation: "torch.arcsin: Alias for torch.asin()")
arcsin = asin
arccos = acos
arctan = atan
arctan2 = atan2

def rad2deg(x: Radians, /, *args: object, **kwargs: object) -> Degrees:
    """Source: torch torch.rad2deg (PyTorch 2.x documentation) (2.5): converts angles from radians to degrees."""

def deg2rad(x: Degrees, /, *args: object, **kwargs: object) -> Radians:
    """Source: torch torch.deg2rad (PyTorch 2.x documentation) (2.5): converts angles from degrees to radians."""

pi: Radians
"""Source: torch torch.pi (PyTorch 2.x documentation) (2.5): the constant pi, a half turn in radians."""
