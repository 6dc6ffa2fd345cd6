from geolint.typing import Radians

class ORB:
    """Source: skimage/feature/orb.py (0.26.0), ORB: "orientations : (N,) array Corresponding orientations in
    radians" (the attribute detect() and detect_and_extract() set)."""

    @property
    def orientations(self) -> Radians: ...
