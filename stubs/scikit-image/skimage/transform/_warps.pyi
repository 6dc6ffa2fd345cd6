from geolint.typing import Degrees, Radians

def rotate(
    image: object, angle: Degrees, resize: bool = ..., center: object = ..., order: int | None = ..., mode: str = ...,
    cval: float = ..., clip: bool = ..., preserve_range: bool = ...,
) -> object:
    """Source: skimage/transform/_warps.py (0.26.0), rotate: "angle : float Rotation angle in degrees in
    counter-clockwise direction". Checked numerically (tests/knowledge/test_image_and_scene_facts.py)."""

def swirl(
    image: object, center: object = ..., strength: float = ..., radius: float = ..., rotation: Radians = ...,
    output_shape: object = ..., order: int | None = ..., mode: str = ..., cval: float = ..., clip: bool = ...,
    preserve_range: bool = ...,
) -> object:
    """Source: skimage/transform/_warps.py (0.26.0), swirl: "rotation : float, optional Additional rotation applied to
    the image"; _swirl_mapping adds it to an angle: `theta = rotation + strength * np.exp(-rho / radius) +
    np.arctan2(y - y0, x - x0)`, then `np.cos(theta)`, so it is radians."""
