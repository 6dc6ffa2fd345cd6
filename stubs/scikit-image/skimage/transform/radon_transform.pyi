from geolint.typing import Degrees

def radon(image: object, theta: Degrees = ..., circle: bool = ..., *, preserve_range: bool = ...) -> object:
    """Source: skimage/transform/radon_transform.py (0.26.0), radon: "theta : array, optional Projection angles (in
    degrees). If `None`, the value is set to np.arange(180)"."""

def iradon(
    radon_image: object, theta: Degrees = ..., output_size: int | None = ..., filter_name: str | None = ...,
    interpolation: str = ..., circle: bool = ..., preserve_range: bool = ...,
) -> object:
    """Source: skimage/transform/radon_transform.py (0.26.0), iradon: "theta : array, optional Reconstruction angles
    (in degrees)"."""

def iradon_sart(
    radon_image: object, theta: Degrees = ..., image: object = ..., projection_shifts: object = ..., clip: object = ...,
    relaxation: float = ..., dtype: object = ...,
) -> object:
    """Source: skimage/transform/radon_transform.py (0.26.0), iradon_sart: "theta : array, shape (N,), optional
    Reconstruction angles (in degrees)"."""
