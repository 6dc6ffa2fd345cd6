from geolint.typing import QuaternionWXYZ, Radians

class QuaternionBase:
    """Source: pymavlink 2.4.50, pymavlink/quaternion.py, QuaternionBase: the `q` property is "list or array of
    quaternion values [w, x, y, z]" (line 85), `euler` is "[roll, pitch, yaw]" (line 116), computed by
    `_dcm_to_euler` from the matrix, in radians ("euler: array [roll, pitch, yaw] in rad", lines 296 and 387), and
    `dcm` is the 3x3 rotation matrix. Its constructor reads a 4-element list as (w, x, y, z), a 3-element one as
    Euler angles and a 3x3 array as a matrix (lines 43-60), so its argument is left unstated. Checked numerically
    (tests/knowledge/test_stubs_pymavlink.py)."""

    @property
    def q(self) -> QuaternionWXYZ: ...
    @property
    def euler(self) -> Radians: ...

class Quaternion(QuaternionBase):
    """Source: pymavlink 2.4.50, pymavlink/quaternion.py, Quaternion(QuaternionBase) (line 452): the same `q`
    ([w, x, y, z]) and `euler` (radians), with `dcm` a rotmat.Matrix3."""

    @property
    def q(self) -> QuaternionWXYZ: ...
    @property
    def euler(self) -> Radians: ...
