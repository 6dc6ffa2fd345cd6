from scipy.spatial.transform._rigid_transform import RigidTransform as RigidTransform
from scipy.spatial.transform._rotation import Rotation as Rotation, Slerp as Slerp
