from typing import Annotated

from geolint.knowledge.markers import ArrayOperation
from geolint.typing import Degrees, Radians

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

# Angles: jax.numpy's trigonometric functions read radians, its inverse ones return radians.

def sin(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: jax jax.numpy.sin documentation (numpy's function) (0.4): the argument is an angle in radians."""

def cos(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: jax jax.numpy.cos documentation (numpy's function) (0.4): the argument is an angle in radians."""

def tan(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: jax jax.numpy.tan documentation (numpy's function) (0.4): the argument is an angle in radians."""

def arcsin(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: jax jax.numpy.arcsin documentation (numpy's function) (0.4): returns an angle in radians."""

def arccos(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: jax jax.numpy.arccos documentation (numpy's function) (0.4): returns an angle in radians."""

def arctan(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: jax jax.numpy.arctan documentation (numpy's function) (0.4): returns an angle in radians."""

def arctan2(x1: object, x2: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: jax jax.numpy.arctan2 documentation (numpy's function) (0.4): returns an angle in radians."""

def degrees(x: Radians, /, *args: object, **kwargs: object) -> Degrees:
    """Source: jax jax.numpy.degrees documentation (numpy's function) (0.4): converts angles from radians to degrees."""

def rad2deg(x: Radians, /, *args: object, **kwargs: object) -> Degrees:
    """Source: jax jax.numpy.rad2deg documentation (numpy's function) (0.4): converts angles from radians to degrees."""

def radians(x: Degrees, /, *args: object, **kwargs: object) -> Radians:
    """Source: jax jax.numpy.radians documentation (numpy's function) (0.4): converts angles from degrees to radians."""

def deg2rad(x: Degrees, /, *args: object, **kwargs: object) -> Radians:
    """Source: jax jax.numpy.deg2rad documentation (numpy's function) (0.4): converts angles from degrees to radians."""

pi: Radians
"""Source: jax jax.numpy.pi documentation (numpy's function) (0.4): the constant pi, a half turn in radians."""
