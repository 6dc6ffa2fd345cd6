from mujoco_py import functions as functions

from typing import Annotated

from geolint.knowledge.markers import STACKED, any_receiver
from geolint.typing import QuaternionWXYZ

# `sim.data` and `sim.model`: MuJoCo 2.x's mjData and mjModel arrays, (w, x, y, z) rows, under their C
# names and mujoco-py's `body_` aliases. Recognised by name on any object in a module that imports mujoco_py.

@any_receiver(when_imported=("mujoco_py",))
class PyMjData:
    """Source: mujoco_py/generated/wrappers.pxi (199ee742), PyMjData: the `xquat` array (nbody x 4), its alias
    `body_xquat`, and `get_body_xquat(name)`, which returns `self.xquat[self._model.body_name2id(name)]`."""

    xquat: Annotated[QuaternionWXYZ, STACKED]
    body_xquat: Annotated[QuaternionWXYZ, STACKED]
    def get_body_xquat(self, name: str) -> QuaternionWXYZ: ...

@any_receiver(when_imported=("mujoco_py",))
class PyMjModel:
    """Source: mujoco_py/generated/wrappers.pxi (199ee742), PyMjModel: body_quat, body_iquat, geom_quat,
    site_quat, cam_quat (n x 4), MuJoCo 2.x's mjModel fields."""

    body_quat: Annotated[QuaternionWXYZ, STACKED]
    body_iquat: Annotated[QuaternionWXYZ, STACKED]
    geom_quat: Annotated[QuaternionWXYZ, STACKED]
    site_quat: Annotated[QuaternionWXYZ, STACKED]
    cam_quat: Annotated[QuaternionWXYZ, STACKED]
