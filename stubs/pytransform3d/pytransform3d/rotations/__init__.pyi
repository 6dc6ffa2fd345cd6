from geolint.typing import QuaternionWXYZ, QuaternionXYZW, Radians, RotationMatrix, RotationVector, VectorArray

# Every quaternion of pytransform3d.rotations is "Unit quaternion to represent rotation: (w, x, y, z)"
# (pytransform3d/rotations/_quaternion.py docstrings, 3.17.0); every angle is "in radians".

def check_quaternion(q: QuaternionWXYZ, unit: bool = ...) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), check_quaternion: "q : array-like,
    shape (4,) Quaternion to represent rotation: (w, x, y, z)"."""

def matrix_from_quaternion(q: QuaternionWXYZ) -> RotationMatrix:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), matrix_from_quaternion: "Unit quaternion
    to represent rotation: (w, x, y, z)"."""

def axis_angle_from_quaternion(q: QuaternionWXYZ) -> object:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), axis_angle_from_quaternion: (w, x, y, z)
    in; (x, y, z, angle) out."""

def compact_axis_angle_from_quaternion(q: QuaternionWXYZ) -> RotationVector:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), compact_axis_angle_from_quaternion:
    "Axis of rotation and rotation angle: angle * (x, y, z)"."""

def mrp_from_quaternion(q: QuaternionWXYZ) -> object:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), mrp_from_quaternion: (w, x, y, z) in."""

def euler_from_quaternion(q: QuaternionWXYZ, i: int, j: int, k: int, extrinsic: bool) -> tuple[Radians, Radians, Radians]:
    """Source: pytransform3d/rotations/_euler.py (3.17.0), euler_from_quaternion: "q : array-like,
    shape (4,) Unit quaternion to represent rotation: (w, x, y, z)"; returns "Extracted rotation angles in
    radians about the axes i, j, k in this order" (an array of shape (3,))."""

def euler_from_matrix(R: RotationMatrix, i: int, j: int, k: int, extrinsic: bool, strict_check: bool = ...) -> tuple[Radians, Radians, Radians]:
    """Source: pytransform3d/rotations/_euler.py (3.17.0), euler_from_matrix: "Extracted rotation angles
    in radians about the axes i, j, k in this order" (an array of shape (3,))."""

def matrix_from_euler(e: Radians, i: int, j: int, k: int, extrinsic: bool) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler.py (3.17.0), matrix_from_euler: "e : array-like, shape (3,)
    Rotation angles in radians about the axes i, j, k in this order"."""

def quaternion_from_euler(e: Radians, i: int, j: int, k: int, extrinsic: bool) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), quaternion_from_euler: "e : array-like,
    shape (3,) Rotation angles in radians about the axes i, j, k in this order"; returns "(w, x, y, z)"."""

def quaternion_from_extrinsic_euler_xyz(e: Radians) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0), quaternion_from_extrinsic_euler_xyz."""

def quaternion_from_matrix(R: RotationMatrix, strict_check: bool = ...) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_matrix.py (3.17.0), quaternion_from_matrix: returns "Unit
    quaternion to represent rotation: (w, x, y, z)"."""

def quaternion_from_axis_angle(a: object) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_axis_angle.py (3.17.0), quaternion_from_axis_angle: (x, y, z,
    angle) in, (w, x, y, z) out."""

def quaternion_from_compact_axis_angle(a: RotationVector) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_axis_angle.py (3.17.0), quaternion_from_compact_axis_angle."""

def quaternion_from_mrp(mrp: object) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_mrp.py (3.17.0), quaternion_from_mrp."""

def quaternion_from_angle(basis: int, angle: Radians) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_angle.py (3.17.0), quaternion_from_angle: "angle : float
    Rotation angle"; returns "(w, x, y, z)"."""

def active_matrix_from_angle(basis: int, angle: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_angle.py (3.17.0), active_matrix_from_angle (`np.cos(angle)`)."""

def passive_matrix_from_angle(basis: int, angle: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_angle.py (3.17.0), passive_matrix_from_angle (`np.cos(angle)`)."""

def random_quaternion(rng: object = ...) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_random.py (3.17.0), random_quaternion."""

def concatenate_quaternions(q1: QuaternionWXYZ, q2: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), concatenate_quaternions: both "(w, x, y, z)"."""

def q_prod_vector(q: QuaternionWXYZ, v: VectorArray) -> VectorArray:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), q_prod_vector: "Apply rotation
    represented by a quaternion to a vector" (a rotation only)."""

def q_conj(q: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), q_conj."""

def quaternion_slerp(start: QuaternionWXYZ, end: QuaternionWXYZ, t: float, shortest_path: bool = ...) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_slerp.py (3.17.0), quaternion_slerp."""

def quaternion_dist(q1: QuaternionWXYZ, q2: QuaternionWXYZ) -> Radians:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), quaternion_dist: "Rotational distance"
    (an angle)."""

def quaternion_diff(q1: QuaternionWXYZ, q2: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), quaternion_diff."""

def quaternion_double(q: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), quaternion_double."""

def pick_closest_quaternion(quaternion: QuaternionWXYZ, target_quaternion: QuaternionWXYZ) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), pick_closest_quaternion: "Quaternion
    (w, x, y, z) of which we are unsure..."."""

def quaternion_wxyz_from_xyzw(q_xyzw: QuaternionXYZW) -> QuaternionWXYZ:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), quaternion_wxyz_from_xyzw: "Converts from
    x, y, z, w to w, x, y, z convention"."""

def quaternion_xyzw_from_wxyz(q_wxyz: QuaternionWXYZ) -> QuaternionXYZW:
    """Source: pytransform3d/rotations/_quaternion.py (3.17.0), quaternion_xyzw_from_wxyz: "Converts from
    w, x, y, z to x, y, z, w convention"."""

def active_matrix_from_intrinsic_euler_xzx(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (intrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_intrinsic_euler_xyx(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (intrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_intrinsic_euler_yxy(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (intrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_intrinsic_euler_yzy(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (intrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_intrinsic_euler_zyz(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (intrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_intrinsic_euler_zxz(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (intrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_intrinsic_euler_xzy(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (intrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_intrinsic_euler_xyz(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (intrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_intrinsic_euler_yxz(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (intrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_intrinsic_euler_yzx(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (intrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_intrinsic_euler_zyx(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (intrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_intrinsic_euler_zxy(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (intrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_extrinsic_euler_xzx(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (extrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_extrinsic_euler_xyx(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (extrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_extrinsic_euler_yxy(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (extrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_extrinsic_euler_yzy(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (extrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_extrinsic_euler_zyz(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (extrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_extrinsic_euler_zxz(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (extrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_extrinsic_euler_xzy(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (extrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_extrinsic_euler_xyz(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (extrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_extrinsic_euler_yxz(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (extrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_extrinsic_euler_yzx(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (extrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_extrinsic_euler_zyx(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (extrinsic rotations), through `active_matrix_from_angle` (radians)."""

def active_matrix_from_extrinsic_euler_zxy(e: Radians) -> RotationMatrix:
    """Source: pytransform3d/rotations/_euler_deprecated.py (3.17.0): "e : array-like, shape (3,) Angles
    for rotation around" the three axes (extrinsic rotations), through `active_matrix_from_angle` (radians)."""
