# skimage/draw/__init__.pyi (0.26.0): `from .draw import (ellipse, ..., ellipse_perimeter, ...)`
from skimage.draw.draw import ellipse as ellipse, ellipse_perimeter as ellipse_perimeter
