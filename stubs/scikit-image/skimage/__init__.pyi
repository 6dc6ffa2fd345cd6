# skimage/__init__.py (0.26.0) loads its submodules lazily (`import skimage as ski; ski.transform.rotate(...)`)
from skimage import draw as draw, feature as feature, measure as measure, transform as transform
