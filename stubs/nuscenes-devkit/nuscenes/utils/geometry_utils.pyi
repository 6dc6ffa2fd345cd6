# nuscenes/utils/geometry_utils.py (1.2.0): `from pyquaternion import Quaternion`, imported from here by dataset code
from pyquaternion import Quaternion as Quaternion
