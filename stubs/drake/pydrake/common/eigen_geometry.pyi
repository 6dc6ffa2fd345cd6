from typing import overload

from geolint.typing import QuaternionWXYZ

class Quaternion:
    """Source: drake 1.51.1, pydrake.common.eigen_geometry.Quaternion.__init__.__doc__: "__init__(self, wxyz:
    numpy.ndarray[numpy.float64[4, 1]])", "__init__(self, w: float, x: float, y: float, z: float)"; `wxyz()`
    returns the same order. Its constructor from a rotation matrix is left out, so that one array is read
    as `wxyz`. Checked numerically (tests/knowledge/test_drake_facts.py)."""

    @overload
    def __init__(self, wxyz: QuaternionWXYZ) -> None: ...
    @overload
    def __init__(self, w: float, x: float, y: float, z: float) -> None: ...
    def wxyz(self) -> QuaternionWXYZ: ...
