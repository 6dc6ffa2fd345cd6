from geolint.knowledge.markers import STACKED
from geolint.typing import PointArray, QuaternionWXYZ
from typing_extensions import Annotated

class PosePath3D:
    """Source: evo 1.38.1, evo/core/trajectory.py, PosePath3D.__init__: ":param orientations_quat_wxyz: nx4 list
    of quaternions (w,x,y,z format)"; the property of the same name returns that order. Checked numerically
    (tests/knowledge/test_evo_autolab_facts.py)."""

    def __init__(self, positions_xyz: PointArray = ..., orientations_quat_wxyz: Annotated[QuaternionWXYZ, STACKED] = ..., poses_se3: object = ..., meta: object = ..., name: object = ...) -> None: ...
    @property
    def orientations_quat_wxyz(self) -> Annotated[QuaternionWXYZ, STACKED]: ...

class PoseTrajectory3D:
    """Source: evo 1.38.1, evo/core/trajectory.py, PoseTrajectory3D.__init__(positions_xyz,
    orientations_quat_wxyz, timestamps, poses_se3, meta, name): as PosePath3D, with timestamps."""

    def __init__(self, positions_xyz: PointArray = ..., orientations_quat_wxyz: Annotated[QuaternionWXYZ, STACKED] = ..., timestamps: object = ..., poses_se3: object = ..., meta: object = ..., name: object = ...) -> None: ...
    @property
    def orientations_quat_wxyz(self) -> Annotated[QuaternionWXYZ, STACKED]: ...
