from geolint.typing import Radians, RotationMatrix, TransformMatrix, Translation

def rotx(t: Radians) -> RotationMatrix:
    """Source: pykitti 0.3.1 (PyPI), pykitti/utils.py, rotx(t): "Rotation about the x-axis.", a 3x3 built from
    np.cos(t) and np.sin(t) (radians). Checked numerically (tests/knowledge/test_stubs_pykitti.py)."""

def roty(t: Radians) -> RotationMatrix:
    """Source: pykitti 0.3.1, pykitti/utils.py, roty(t): "Rotation about the y-axis.", from np.cos(t), np.sin(t)."""

def rotz(t: Radians) -> RotationMatrix:
    """Source: pykitti 0.3.1, pykitti/utils.py, rotz(t): "Rotation about the z-axis.", from np.cos(t), np.sin(t)."""

def transform_from_rot_trans(R: RotationMatrix, t: Translation) -> TransformMatrix:
    """Source: pykitti 0.3.1, pykitti/utils.py, transform_from_rot_trans(R, t): "Transforation matrix from rotation
    matrix and translation vector", `np.vstack((np.hstack([R, t]), [0, 0, 0, 1]))` (R reshaped to 3x3, t to 3x1)."""

def pose_from_oxts_packet(packet: object, scale: float) -> tuple[RotationMatrix, Translation]:
    """Source: pykitti 0.3.1, pykitti/utils.py, pose_from_oxts_packet(packet, scale): returns `R, t`, with
    `R = Rz.dot(Ry.dot(Rx))` from the packet's roll, pitch, yaw (radians, through rotx/roty/rotz) and t a Mercator
    position in metres (lon and lat in degrees, `* np.pi / 180.`); load_oxts_packets_and_poses makes
    `T_w_imu = transform_from_rot_trans(R, t - origin)` from them, "in an East-North-Up coordinate system whose
    origin is the first GPS position"."""
