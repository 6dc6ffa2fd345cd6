# tf_conversions/__init__.py: `from .posemath import *`, which exports posemath's `from tf import transformations`
from tf import transformations as transformations
