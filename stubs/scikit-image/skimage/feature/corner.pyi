from geolint.typing import Radians

def corner_orientations(image: object, corners: object, mask: object) -> Radians:
    """Source: skimage/feature/corner.py (0.26.0), corner_orientations: "orientations : (K, 1) array Orientations of
    corners in the range [-pi, pi]"."""
