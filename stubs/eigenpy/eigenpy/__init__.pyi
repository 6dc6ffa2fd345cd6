from typing import overload

from geolint.typing import QuaternionXYZW

class Quaternion:
    """Source: eigenpy's Quaternion.__init__ docstrings (as pinocchio 4.1.0 shows them): "Initialize from
    coefficients. ... The order of coefficients is *w*, *x*, *y*, *z*"; "vec4 : a 4D vector representing
    quaternion coefficients in the order xyzw"; `coeffs()` is x, y, z, w (checked numerically,
    tests/knowledge/test_simulator_facts.py). Its other constructors (a rotation matrix, an AngleAxis, two
    vectors u and v) take no quaternion and are left out, so that `Quaternion(*q)` can only be four
    coefficients."""

    @overload
    def __init__(self, w: float, x: float, y: float, z: float) -> None: ...
    @overload
    def __init__(self, vec4: QuaternionXYZW) -> None: ...
    def coeffs(self) -> QuaternionXYZW: ...
