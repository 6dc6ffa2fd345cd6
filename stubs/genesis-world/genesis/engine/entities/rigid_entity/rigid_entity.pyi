from geolint.knowledge.markers import any_receiver
from geolint.typing import PointArray, QuaternionWXYZ

# Recognised on any receiver in a module that imports genesis: an entity comes from `scene.add_entity(...)`.
@any_receiver(when_imported=("genesis",))
class RigidEntity:
    """Source: genesis/engine/entities/rigid_entity/rigid_entity.py (0.4.5, 7bf5f6a): RigidEntity.set_quat (line 3281) and
    the inherited KinematicEntity.get_quat (1349), the base link's quaternion in the morphs' "w-x-y-z convention"
    (genesis/options/morphs.py:81-82; the solver unpacks `w, x, y, z = quat`, genesis/utils/geom.py:146)."""

    def set_quat(self, quat: QuaternionWXYZ, envs_idx: object = ..., *, zero_velocity: bool = ..., relative: bool = ..., skip_forward: bool = ...) -> None: ...
    def get_quat(self, envs_idx: object = ...) -> QuaternionWXYZ: ...
    def set_pos(self, pos: PointArray, envs_idx: object = ..., *, zero_velocity: bool = ..., relative: bool = ..., skip_forward: bool = ...) -> None: ...
    def get_pos(self, envs_idx: object = ...) -> PointArray: ...
