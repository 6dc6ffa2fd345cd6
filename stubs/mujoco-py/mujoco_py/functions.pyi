from geolint.typing import QuaternionWXYZ, Radians, VectorArray

# mujoco_py/generated/wrappers.pxi (commit 199ee742) is generated from MuJoCo 2.x's mjfunctions.h; `mujoco_py.functions`
# exposes each C function under its own name, called as `functions.mju_quat2Mat(res, quat)`
# (w, x, y, z) quaternions, the result written into the first argument, as in stubs/mujoco.

def mju_quat2Mat(res: object, quat: QuaternionWXYZ) -> None:
    """Source: mujoco_py/generated/wrappers.pxi (199ee742), mju_quat2Mat: the C function (stubs/mujoco)."""

def mju_quat2Vel(res: object, quat: QuaternionWXYZ, dt: float) -> None:
    """Source: mujoco_py/generated/wrappers.pxi (199ee742), mju_quat2Vel: the C function (stubs/mujoco)."""

def mju_quatIntegrate(quat: QuaternionWXYZ, vel: VectorArray, scale: float) -> None:
    """Source: mujoco_py/generated/wrappers.pxi (199ee742), mju_quatIntegrate: the C function (stubs/mujoco)."""

def mju_mulQuat(res: object, quat1: QuaternionWXYZ, quat2: QuaternionWXYZ) -> None:
    """Source: mujoco_py/generated/wrappers.pxi (199ee742), mju_mulQuat: the C function (stubs/mujoco)."""

def mju_negQuat(res: object, quat: QuaternionWXYZ) -> None:
    """Source: mujoco_py/generated/wrappers.pxi (199ee742), mju_negQuat: the C function (stubs/mujoco)."""

def mju_rotVecQuat(res: object, vec: VectorArray, quat: QuaternionWXYZ) -> None:
    """Source: mujoco_py/generated/wrappers.pxi (199ee742), mju_rotVecQuat: the C function (stubs/mujoco)."""

def mju_subQuat(res: object, qa: QuaternionWXYZ, qb: QuaternionWXYZ) -> None:
    """Source: mujoco_py/generated/wrappers.pxi (199ee742), mju_subQuat: the C function (stubs/mujoco)."""

def mju_axisAngle2Quat(res: object, axis: VectorArray, angle: Radians) -> None:
    """Source: mujoco_py/generated/wrappers.pxi (199ee742), mju_axisAngle2Quat: the C function (stubs/mujoco)."""
