from geolint.typing import Radians

def hough_line(image: object, theta: Radians = ...) -> tuple[object, Radians, object]:
    """Source: skimage/transform/hough_transform.py (0.26.0), hough_line: "theta : ndarray of double, shape (K,),
    optional Angles at which to compute the transform, in radians"; returns "hspace", "angles : ndarray Angles at which
    the transform is computed, in radians" and "distances". Checked numerically
    (tests/knowledge/test_image_and_scene_facts.py)."""

def hough_line_peaks(
    hspace: object, angles: Radians, dists: object, min_distance: int = ..., min_angle: int = ..., threshold: float | None = ...,
    num_peaks: float = ...,
) -> tuple[object, Radians, object]:
    """Source: skimage/transform/hough_transform.py (0.26.0), hough_line_peaks: "angles : array, shape (N,) Angles
    returned by the `hough_line` function. Assumed to be continuous. (`angles[-1] - angles[0] == PI`)"; returns
    "accum, angles, dists : tuple of array Peak values in Hough space, angles and distances" (a selection of the
    angles given)."""

def probabilistic_hough_line(
    image: object, threshold: int = ..., line_length: int = ..., line_gap: int = ..., theta: Radians = ..., rng: object = ...,
) -> object:
    """Source: skimage/transform/hough_transform.py (0.26.0), probabilistic_hough_line: "theta : ndarray of dtype,
    shape (K,), optional Angles at which to compute the transform, in radians"."""
