from typing import Annotated

from geolint.knowledge.markers import STACKED, any_receiver
from geolint.typing import QuaternionWXYZ, Radians, VectorArray

# MuJoCo (4.0.0): "MuJoCo uses quaternions in (w, x, y, z) order" (documentation, "Quaternions" in the
# modeling and programming chapters); its own tests expect the identity {1, 0, 0, 0}. Output buffers (`res`)
# state nothing: what a function writes into them is not a value the linter follows.

def mju_quat2Mat(res: object, quat: QuaternionWXYZ) -> None:
    """Source: mujoco 4.0.0, mju_quat2Mat.__doc__: "Convert quaternion to 3D rotation matrix"; checked
    numerically (tests/knowledge/test_simulator_facts.py)."""

def mju_quat2Vel(res: object, quat: QuaternionWXYZ, dt: float) -> None:
    """Source: mujoco 4.0.0, mju_quat2Vel.__doc__: "Convert quaternion (corresponding to orientation
    difference) to 3D velocity"."""

def mju_quatIntegrate(quat: QuaternionWXYZ, vel: VectorArray, scale: float) -> None:
    """Source: mujoco 4.0.0, mju_quatIntegrate.__doc__: "Integrate quaternion given 3D angular velocity"
    (in place)."""

def mju_mulQuat(res: object, quat1: QuaternionWXYZ, quat2: QuaternionWXYZ) -> None:
    """Source: mujoco 4.0.0, mju_mulQuat.__doc__: "Multiply quaternions"."""

def mju_negQuat(res: object, quat: QuaternionWXYZ) -> None:
    """Source: mujoco 4.0.0, mju_negQuat.__doc__: "Conjugate quaternion, corresponding to opposite rotation"."""

def mju_rotVecQuat(res: object, vec: VectorArray, quat: QuaternionWXYZ) -> None:
    """Source: mujoco 4.0.0, mju_rotVecQuat.__doc__: "Rotate vector by quaternion"."""

def mju_subQuat(res: object, qa: QuaternionWXYZ, qb: QuaternionWXYZ) -> None:
    """Source: mujoco 4.0.0, mju_subQuat.__doc__: "Subtract quaternions, express as 3D velocity:
    qb*quat(res) = qa"."""

def mju_axisAngle2Quat(res: object, axis: VectorArray, angle: Radians) -> None:
    """Source: mujoco 4.0.0, mju_axisAngle2Quat.__doc__: "Convert axisAngle to quaternion" (the angle in
    radians; checked numerically)."""

def mju_euler2Quat(quat: object, euler: Radians, seq: str) -> None:
    """Source: mujoco 4.0.0, mju_euler2Quat.__doc__: "Convert sequence of Euler angles (radians) to
    quaternion"."""

# The state and model arrays, one (w, x, y, z) row per body, geom, site or camera. Recognised by name on
# any object in a module that imports MuJoCo or dm_control (whose `physics.data` wraps the same MjData):
# a model and its data are seldom built where they are read.

@any_receiver(when_imported=("mujoco", "dm_control"))
class MjData:
    """Source: mujoco 4.0.0, the MjData reference (documentation, "mjData": `xquat` "Cartesian orientation of
    body frame", nbody x 4); checked numerically (a body with quat="0.7071068 0 0 0.7071068" has the
    quarter-turn about z as its xmat, tests/knowledge/test_simulator_facts.py)."""

    xquat: Annotated[QuaternionWXYZ, STACKED]

@any_receiver(when_imported=("mujoco", "dm_control"))
class MjModel:
    """Source: mujoco 4.0.0, the MjModel reference ("mjModel": body_quat, body_iquat, geom_quat, site_quat,
    cam_quat, each n x 4, "orientation ... relative to parent"); checked numerically as MjData."""

    body_quat: Annotated[QuaternionWXYZ, STACKED]
    body_iquat: Annotated[QuaternionWXYZ, STACKED]
    geom_quat: Annotated[QuaternionWXYZ, STACKED]
    site_quat: Annotated[QuaternionWXYZ, STACKED]
    cam_quat: Annotated[QuaternionWXYZ, STACKED]
