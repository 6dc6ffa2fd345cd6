from geolint.typing import Degrees

def rotate(input: object, angle: Degrees, axes: object = ..., reshape: bool = ..., output: object = ..., order: int = ..., mode: str = ..., cval: float = ..., prefilter: bool = ...) -> object:
    """Source: scipy/ndimage/_interpolation.py (1.17.1), rotate: "angle : float The rotation angle in degrees"."""
