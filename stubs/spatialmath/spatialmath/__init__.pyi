from spatialmath import base as base
from spatialmath.pose3d import SE3 as SE3, SO3 as SO3
from spatialmath.quaternion import Quaternion as Quaternion, UnitQuaternion as UnitQuaternion
