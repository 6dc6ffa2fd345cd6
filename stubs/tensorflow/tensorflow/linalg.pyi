from typing import Annotated

from geolint.knowledge.markers import ArrayOperation

def matmul(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.MATMUL]:
    """Source: https://www.tensorflow.org/api_docs/python/tf/linalg/matmul (2.18): "Multiplies matrix a by matrix b"."""

def inv(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.INVERSE]:
    """Source: https://www.tensorflow.org/api_docs/python/tf/linalg/inv (2.18): "Computes the inverse of one or more square invertible matrices or their adjoints"."""

def matrix_transpose(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.TRANSPOSE]:
    """Source: https://www.tensorflow.org/api_docs/python/tf/linalg/matrix_transpose (2.18): "Transposes last two dimensions of tensor a"."""
