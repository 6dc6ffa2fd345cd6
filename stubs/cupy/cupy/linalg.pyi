from typing import Annotated

from geolint.knowledge.markers import ArrayOperation

def inv(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.INVERSE]:
    """Source: cupy.linalg.inv (https://docs.cupy.dev/en/stable/reference/routines.html): numpy.linalg.inv's API."""

def pinv(a: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.INVERSE]:
    """Source: cupy.linalg.pinv (https://docs.cupy.dev/en/stable/reference/routines.html): numpy.linalg.pinv's API."""
