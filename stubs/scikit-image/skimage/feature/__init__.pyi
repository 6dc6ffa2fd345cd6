# skimage/feature/__init__.pyi (0.26.0): `from .orb import ORB`, `from .corner import (..., corner_orientations, ...)`
from skimage.feature.corner import corner_orientations as corner_orientations
from skimage.feature.orb import ORB as ORB
