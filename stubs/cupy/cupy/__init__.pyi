from typing import Annotated

from geolint.knowledge.markers import ArrayOperation
from geolint.typing import Degrees, Radians

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

# Angles: cupy's trigonometric functions read radians, its inverse ones return radians.

def sin(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: cupy cupy.sin documentation (numpy's function) (13): the argument is an angle in radians."""

def cos(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: cupy cupy.cos documentation (numpy's function) (13): the argument is an angle in radians."""

def tan(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: cupy cupy.tan documentation (numpy's function) (13): the argument is an angle in radians."""

def arcsin(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: cupy cupy.arcsin documentation (numpy's function) (13): returns an angle in radians."""

def arccos(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: cupy cupy.arccos documentation (numpy's function) (13): returns an angle in radians."""

def arctan(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: cupy cupy.arctan documentation (numpy's function) (13): returns an angle in radians."""

def arctan2(x1: object, x2: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: cupy cupy.arctan2 documentation (numpy's function) (13): returns an angle in radians."""

def degrees(x: Radians, /, *args: object, **kwargs: object) -> Degrees:
    """Source: cupy cupy.degrees documentation (numpy's function) (13): converts angles from radians to degrees."""

def rad2deg(x: Radians, /, *args: object, **kwargs: object) -> Degrees:
    """Source: cupy cupy.rad2deg documentation (numpy's function) (13): converts angles from radians to degrees."""

def radians(x: Degrees, /, *args: object, **kwargs: object) -> Radians:
    """Source: cupy cupy.radians documentation (numpy's function) (13): converts angles from degrees to radians."""

def deg2rad(x: Degrees, /, *args: object, **kwargs: object) -> Radians:
    """Source: cupy cupy.deg2rad documentation (numpy's function) (13): converts angles from degrees to radians."""

pi: Radians
"""Source: cupy cupy.pi documentation (numpy's function) (13): the constant pi, a half turn in radians."""
