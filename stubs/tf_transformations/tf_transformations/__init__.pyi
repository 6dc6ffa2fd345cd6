"""ROS 2 tf_transformations: tf.transformations' API reimplemented on transforms3d, quaternions
(x, y, z, w): `_reorder_input_quaternion` unpacks `x, y, z, w = quaternion` before calling
transforms3d, `_reorder_output_quaternion` returns `x, y, z, w`.
"""

from geolint.typing import PointArray, QuaternionXYZW, Radians, TransformMatrix, Translation, VectorArray

def identity_matrix() -> TransformMatrix:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), identity_matrix: the 4x4 identity."""

def translation_matrix(direction: Translation) -> TransformMatrix:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), translation_matrix: `transforms3d.affines.compose(direction, ROTATION_IDENTITY, ZOOM_IDENTITY)`."""

def translation_from_matrix(matrix: TransformMatrix) -> Translation:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), translation_from_matrix: `transforms3d.affines.decompose(matrix)[0]`."""

def rotation_matrix(angle: Radians, direction: VectorArray, point: PointArray | None = ...) -> TransformMatrix:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), rotation_matrix: `transforms3d.axangles.axangle2aff(direction, angle, point=point)`
    (transforms3d reads the angle in radians)."""

def rotation_from_matrix(matrix: TransformMatrix) -> tuple[Radians, VectorArray, PointArray]:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), rotation_from_matrix: `transforms3d.axangles.aff2axangle(matrix)`, returned as angle,
    direction, point."""

def euler_matrix(ai: Radians, aj: Radians, ak: Radians, axes: str = ...) -> TransformMatrix:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), euler_matrix: `transforms3d.euler.euler2mat(ai, aj, ak, axes=axes)` (radians) in a
    4x4 homogeneous matrix."""

def euler_from_matrix(matrix: object, axes: str = ...) -> tuple[Radians, Radians, Radians]:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), euler_from_matrix: `transforms3d.euler.mat2euler(matrix, axes=axes)` (radians)."""

def euler_from_quaternion(quaternion: QuaternionXYZW, axes: str = ...) -> tuple[Radians, Radians, Radians]:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), euler_from_quaternion: `euler_from_matrix(quaternion_matrix(quaternion), axes)`."""

def quaternion_from_euler(ai: Radians, aj: Radians, ak: Radians, axes: str = ...) -> QuaternionXYZW:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), quaternion_from_euler: `_reorder_output_quaternion(transforms3d.euler.euler2quat(ai,
    aj, ak, axes=axes))`: radians in, (x, y, z, w) out."""

def quaternion_about_axis(angle: Radians, axis: VectorArray) -> QuaternionXYZW:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), quaternion_about_axis: `_reorder_output_quaternion(transforms3d.quaternions.axangle2quat(axis,
    angle))`: (x, y, z, w)."""

def quaternion_matrix(quaternion: QuaternionXYZW) -> TransformMatrix:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), quaternion_matrix: `transforms3d.quaternions.quat2mat(_reorder_input_quaternion(quaternion))`
    (`x, y, z, w = quaternion`) in a 4x4 homogeneous matrix."""

def quaternion_from_matrix(matrix: object) -> QuaternionXYZW:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), quaternion_from_matrix: `_reorder_output_quaternion(transforms3d.quaternions.mat2quat(...))`:
    (x, y, z, w)."""

def quaternion_multiply(quaternion1: QuaternionXYZW, quaternion0: QuaternionXYZW) -> QuaternionXYZW:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), quaternion_multiply(quaternion1, quaternion0): unpacks each as
    (x, y, z, w)."""

def quaternion_conjugate(quaternion: QuaternionXYZW) -> QuaternionXYZW:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), quaternion_conjugate: `(-quaternion[0], -quaternion[1], -quaternion[2], quaternion[3])`."""

def quaternion_inverse(quaternion: QuaternionXYZW) -> QuaternionXYZW:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), quaternion_inverse: the conjugate over the squared norm."""

def quaternion_slerp(quat0: QuaternionXYZW, quat1: QuaternionXYZW, fraction: float, spin: int = ..., shortestpath: bool = ...) -> QuaternionXYZW:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), quaternion_slerp(quat0, quat1, fraction, spin=0, shortestpath=True):
    interpolates the four components as given, so the result is in their order."""

def random_quaternion(rand: object = ...) -> QuaternionXYZW:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), random_quaternion(rand=None): (x, y, z, w)."""

def random_rotation_matrix(rand: object = ...) -> TransformMatrix:
    """Source: DLu/tf_transformations tf_transformations/__init__.py (commit c755a481c451cba59c2e1844bf86db088b8f10cf), random_rotation_matrix: `quaternion_matrix(random_quaternion(rand))`."""
