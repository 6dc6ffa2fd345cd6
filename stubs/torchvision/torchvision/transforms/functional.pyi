from geolint.typing import Degrees

def rotate(img: object, angle: Degrees, interpolation: object = ..., expand: bool = ..., center: object = ..., fill: object = ...) -> object:
    """Source: torchvision.transforms.functional.rotate (0.29 documentation): "angle (number): rotation angle
    value in degrees, counter-clockwise"."""
