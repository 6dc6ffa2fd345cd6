from geolint.typing import Radians

# tf.math's trigonometric functions (also at the top level: tf.sin is tf.math.sin) read radians; its
# inverse ones return radians. TensorFlow has no degree conversions.

def sin(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/sin (2.18): "Computes sine of x element-wise", x in radians."""

def cos(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/cos (2.18): "Computes cos of x element-wise", x in radians."""

def tan(x: Radians, /, *args: object, **kwargs: object) -> object:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/tan (2.18): "Computes tan of x element-wise", x in radians."""

def asin(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/asin (2.18): "Computes the trignometric inverse sine of x element-wise", in radians."""

def acos(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/acos (2.18): "Computes acos of x element-wise", in radians."""

def atan(x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/atan (2.18): "Computes the trignometric inverse tangent of x element-wise", in radians."""

def atan2(y: object, x: object, /, *args: object, **kwargs: object) -> Radians:
    """Source: https://www.tensorflow.org/api_docs/python/tf/math/atan2 (2.18): "Computes arctangent of y/x element-wise, respecting signs of the arguments", in radians."""
