from typing import Annotated

from geolint.knowledge.markers import ArrayOperation
from geolint.typing import Radians

from tensorflow import linalg as linalg
from tensorflow import math as math

def matmul(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: https://www.tensorflow.org/api_docs/python/tf/linalg/matmul (2.18): "Multiplies matrix a by matrix b, producing a * b" (tf.matmul is tf.linalg.matmul)."""

def transpose(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.TRANSPOSE]:
    """Source: https://www.tensorflow.org/api_docs/python/tf/transpose (2.18): "Transposes a ... If perm is not given, it is set to (n-1...0)": a matrix's transpose for 2-D."""

def einsum(equation: str, *inputs: object, **kwargs: object) -> Annotated[object, ArrayOperation.EINSUM]:
    """Source: https://www.tensorflow.org/api_docs/python/tf/einsum (2.18): "Tensor contraction over specified indices and outer product"."""

# Angles: tensorflow's trigonometric functions read radians, its inverse ones return radians.

def sin(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/sin (2.18): the argument is an angle in radians."""

def cos(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/cos (2.18): the argument is an angle in radians."""

def tan(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/tan (2.18): the argument is an angle in radians."""

def asin(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/asin (2.18): returns an angle in radians."""

def acos(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/acos (2.18): returns an angle in radians."""

def atan(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/atan (2.18): returns an angle in radians."""

def atan2(x1: object, x2: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/atan2 (2.18): returns an angle in radians."""
