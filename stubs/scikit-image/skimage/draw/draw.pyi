from geolint.typing import Radians

def ellipse(r: float, c: float, r_radius: float, c_radius: float, shape: object = ..., rotation: Radians = ...) -> object:
    """Source: skimage/draw/draw.py (0.26.0), ellipse: "rotation : float, optional (default 0.) Set the ellipse rotation
    (rotation) in range (-PI, PI) in contra clock wise direction"; _ellipse_in_shape: "rotation : float, optional
    Rotation of the ellipse defined by the above, in radians". Checked numerically
    (tests/knowledge/test_image_and_scene_facts.py)."""

def ellipse_perimeter(r: int, c: int, r_radius: int, c_radius: int, orientation: Radians = ..., shape: object = ...) -> object:
    """Source: skimage/draw/draw.py (0.26.0), ellipse_perimeter: "orientation : double, optional Major axis orientation
    in clockwise direction as radians"."""
