from typing import Annotated

from geolint.knowledge.markers import ArrayOperation

from tensorflow import linalg as linalg
from tensorflow import math as math
# tf.sin is tf.math.sin (the top level re-exports tf.math's trigonometric functions)
from tensorflow.math import acos as acos, asin as asin, atan as atan, atan2 as atan2, cos as cos, sin as sin, tan as tan

def matmul(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: https://www.tensorflow.org/api_docs/python/tf/linalg/matmul (2.18): "Multiplies matrix a by matrix b, producing a * b" (tf.matmul is tf.linalg.matmul)."""

def transpose(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.TRANSPOSE]:
    """Source: https://www.tensorflow.org/api_docs/python/tf/transpose (2.18): "Transposes a ... If perm is not given, it is set to (n-1...0)": a matrix's transpose for 2-D."""

def einsum(equation: str, *inputs: object, **kwargs: object) -> Annotated[object, ArrayOperation.EINSUM]:
    """Source: https://www.tensorflow.org/api_docs/python/tf/einsum (2.18): "Tensor contraction over specified indices and outer product"."""
