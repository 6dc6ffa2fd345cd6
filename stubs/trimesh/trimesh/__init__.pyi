# trimesh/__init__.py (5.2.0): `from .transformations import transform_points`
from trimesh.transformations import transform_points as transform_points
