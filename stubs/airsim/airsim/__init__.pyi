# PythonClient/airsim/__init__.py (1.8.1): `from .client import *`, `from .utils import *`, `from .types import *`
from airsim.client import MultirotorClient as MultirotorClient
from airsim.types import Quaternionr as Quaternionr, YawMode as YawMode
from airsim.utils import to_eularian_angles as to_eularian_angles, to_quaternion as to_quaternion
