from pybullet_utils.bullet_client import BulletClient as _Client

# the module's functions, which a BulletClient forwards to (stubs/pybullet/pybullet_utils/bullet_client.pyi)
getQuaternionFromEuler = _Client.getQuaternionFromEuler
getEulerFromQuaternion = _Client.getEulerFromQuaternion
getMatrixFromQuaternion = _Client.getMatrixFromQuaternion
getQuaternionFromAxisAngle = _Client.getQuaternionFromAxisAngle
getAxisAngleFromQuaternion = _Client.getAxisAngleFromQuaternion
getDifferenceQuaternion = _Client.getDifferenceQuaternion
