# `from pydrake.all import ...`: pydrake.all re-exports the public modules
from pydrake.common.eigen_geometry import Quaternion as Quaternion
from pydrake.math import RigidTransform as RigidTransform, RollPitchYaw as RollPitchYaw, RotationMatrix as RotationMatrix
