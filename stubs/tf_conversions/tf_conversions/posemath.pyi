# tf_conversions/posemath.py (ros/geometry, commit 8b45c5d7): `from tf import transformations`
from tf import transformations as transformations
