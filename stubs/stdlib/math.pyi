from geolint.typing import Degrees, Radians

def sin(x: Radians, /) -> float:
    """Source: https://docs.python.org/3/library/math.html#math.sin (3.13): "Return the sine of x radians"."""

def cos(x: Radians, /) -> float:
    """Source: https://docs.python.org/3/library/math.html#math.cos (3.13): "Return the cosine of x radians"."""

def tan(x: Radians, /) -> float:
    """Source: https://docs.python.org/3/library/math.html#math.tan (3.13): "Return the tangent of x radians"."""

def asin(x: float, /) -> Radians:
    """Source: https://docs.python.org/3/library/math.html#math.asin (3.13): "Return the arc sine of x, in radians"."""

def acos(x: float, /) -> Radians:
    """Source: https://docs.python.org/3/library/math.html#math.acos (3.13): "Return the arc cosine of x, in radians"."""

def atan(x: float, /) -> Radians:
    """Source: https://docs.python.org/3/library/math.html#math.atan (3.13): "Return the arc tangent of x, in radians"."""

def atan2(y: float, x: float, /) -> Radians:
    """Source: https://docs.python.org/3/library/math.html#math.atan2 (3.13): "Return atan(y / x), in radians"."""

def degrees(x: Radians, /) -> Degrees:
    """Source: https://docs.python.org/3/library/math.html#math.degrees (3.13): "Convert angle x from radians to degrees"."""

def radians(x: Degrees, /) -> Radians:
    """Source: https://docs.python.org/3/library/math.html#math.radians (3.13): "Convert angle x from degrees to radians"."""

pi: Radians
"""Source: https://docs.python.org/3/library/math.html#math.pi (3.13): "The mathematical constant pi = 3.141592..."."""
