from geolint.typing import Radians

class RegionProperties:
    """Source: skimage/measure/_regionprops.py (0.26.0), regionprops: "**orientation** : float Angle between the 0th
    axis (rows) and the major axis of the ellipse that has the same second moments as the region, ranging from
    -pi/2 to pi/2 counter-clockwise"; RegionProperties.orientation returns `0.5 * atan2(-2 * b, c - a)` (or
    `PI / 4.0`)."""

    @property
    def orientation(self) -> Radians: ...
