from geolint.typing import QuaternionXYZW

class Rotation3d:
    """Source: pycolmap 4.2.1, Rotation3d.__init__.__doc__: "__init__(self, xyzw: ...[4, 1]) ... Quaternion
    in [x,y,z,w] format" (0.5.0: "__init__(self, xyzw: numpy.ndarray[numpy.float64[4, 1]])"); `quat` is
    the same order. Its constructors from a 3x3 matrix and from an axis-angle vector are left out, so that
    one array is read as `xyzw`. Checked numerically (tests/knowledge/test_colmap_facts.py)."""

    def __init__(self, xyzw: QuaternionXYZW) -> None: ...
    @property
    def quat(self) -> QuaternionXYZW: ...
