from geolint.typing import QuaternionWXYZ, RotationMatrix

from autolab_core import transformations as transformations

class RigidTransform:
    """Source: autolab_core 1.1.1, autolab_core/rigid_transformations.py: `quaternion` is "A quaternion vector
    in wxyz layout" (computed as `np.roll(q_xyzw, 1)` from its tf-style transformations module), and
    `rotation_from_quaternion(q_wxyz)` reads "A quaternion in wxyz order". Checked numerically
    (tests/knowledge/test_evo_autolab_facts.py)."""

    @property
    def quaternion(self) -> QuaternionWXYZ: ...
    @staticmethod
    def rotation_from_quaternion(q_wxyz: QuaternionWXYZ) -> RotationMatrix: ...
