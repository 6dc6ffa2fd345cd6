from geolint.typing import Degrees

class Image:
    """Source: src/PIL/Image.py (13.0.0), Image.rotate(angle, resample=Resampling.NEAREST, expand=False, center=None,
    translate=None, fillcolor=None): "Returns a rotated copy of this image. This method returns a copy of this image,
    rotated the given number of degrees counter clockwise around its centre." and ":param angle: In degrees
    counterclockwise."; its body starts `angle = angle % 360.0`. docs/reference/Image.rst: "This rotates the input
    image by ``theta`` degrees counter clockwise". The other methods listed return a new Image (their `-> Image`
    annotations in Image.py), so that a rotate later in a chain is recognised. Checked numerically
    (tests/knowledge/test_image_and_scene_facts.py)."""

    def rotate(
        self, angle: Degrees, resample: object = ..., expand: int | bool = ..., center: object = ..., translate: object = ...,
        fillcolor: object = ...,
    ) -> Image: ...
    def convert(self, mode: str | None = ..., matrix: object = ..., dither: object = ..., palette: object = ..., colors: int = ...) -> Image: ...
    def copy(self) -> Image: ...
    def crop(self, box: object = ...) -> Image: ...
    def resize(self, size: object, resample: object = ..., box: object = ..., reducing_gap: float | None = ...) -> Image: ...
    def transpose(self, method: object) -> Image: ...
    def transform(
        self, size: object, method: object, data: object = ..., resample: int = ..., fill: int = ..., fillcolor: object = ...,
    ) -> Image: ...

def open(fp: object, mode: str = ..., formats: object = ...) -> Image:
    """Source: src/PIL/Image.py (13.0.0), open(fp, mode="r", formats=None) -> ImageFile.ImageFile, a subclass of Image."""

def new(mode: str, size: object, color: object = ...) -> Image:
    """Source: src/PIL/Image.py (13.0.0), new(mode, size, color=0) -> Image."""

def fromarray(obj: object, mode: str | None = ...) -> Image:
    """Source: src/PIL/Image.py (13.0.0), fromarray(obj, mode=None) -> Image."""
