from geolint.typing import Degrees
from PIL.Image import Image

class ImageDraw:
    """Source: docs/reference/ImageDraw.rst (Pillow 13.0.0.dev0, commit 4e5f09f), ImageDraw.arc(xy, start, end, fill=None,
    width=0): ":param start: Starting angle, in degrees. Angles are measured from 3 o'clock, increasing clockwise.",
    ":param end: Ending angle, in degrees."; chord: "Same as arc, but connects the end points with a straight line";
    pieslice: the same start and end; regular_polygon(bounding_circle, n_sides, rotation=0, ...): "rotation of
    ``rotation`` degrees", ":param rotation: Apply an arbitrary rotation to the polygon (e.g. ``rotation=90``, applies
    a 90 degree rotation)" (src/PIL/ImageDraw.py 13.0.0: `math.radians(360 - degrees)`). Checked numerically
    (tests/knowledge/test_image_and_scene_facts.py)."""

    def __init__(self, im: Image, mode: str | None = ...) -> None: ...
    def arc(self, xy: object, start: Degrees, end: Degrees, fill: object = ..., width: int = ...) -> None: ...
    def chord(self, xy: object, start: Degrees, end: Degrees, fill: object = ..., outline: object = ..., width: int = ...) -> None: ...
    def pieslice(self, xy: object, start: Degrees, end: Degrees, fill: object = ..., outline: object = ..., width: int = ...) -> None: ...
    def regular_polygon(
        self, bounding_circle: object, n_sides: int, rotation: Degrees = ..., fill: object = ..., outline: object = ..., width: int = ...,
    ) -> None: ...

def Draw(im: Image, mode: str | None = ...) -> ImageDraw:
    """Source: src/PIL/ImageDraw.py (13.0.0), Draw(im, mode=None) -> ImageDraw: "A simple 2D drawing interface for PIL
    images."."""
