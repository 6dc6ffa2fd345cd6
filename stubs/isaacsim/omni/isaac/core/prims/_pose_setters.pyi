from typing import Annotated

from geolint.knowledge.markers import STACKED, any_receiver
from geolint.typing import QuaternionWXYZ

_WXYZ = Annotated[QuaternionWXYZ, STACKED]

@any_receiver(when_imported=("omni.isaac.core.", "isaacsim.core."), unless_imported=("omnigibson",))
class _PoseSetters:
    """Source: omni/isaac/core/prims/xform_prim.py and xform_prim_view.py (Isaac Sim 4.1) and the isaacsim.core.prims API
    reference (4.5): `set_world_pose(position, orientation)`, `set_local_pose(translation, orientation)`,
    `set_default_state(position, orientation)` and their view forms take "quaternion is scalar-first (w, x, y, z)".
    Every prim, object, robot and view class has them, so they are recognised by name in a module that imports
    Isaac Sim's core; OmniGibson wraps the same core with prims that take x, y, z, w, so not where it is imported."""

    def set_world_pose(self, position: object = ..., orientation: _WXYZ = ..., **options: object) -> None: ...
    def set_local_pose(self, translation: object = ..., orientation: _WXYZ = ..., **options: object) -> None: ...
    def set_default_state(self, position: object = ..., orientation: _WXYZ = ..., **options: object) -> None: ...
    def set_world_poses(self, positions: object = ..., orientations: _WXYZ = ..., **options: object) -> None: ...
    def set_local_poses(self, translations: object = ..., orientations: _WXYZ = ..., **options: object) -> None: ...
