"""The plugin's error codes, defined once.

They are real mypy `ErrorCode`s, so users can select and silence them like mypy's own:
``# type: ignore[geo-frame]``, ``--disable-error-code geo-translation``, ``enable_error_code``.
"""

from __future__ import annotations

from mypy.errorcodes import ErrorCode

GEO_FRAME = ErrorCode(
    "geo-frame",
    "A transform applied to, or composed with, a value in another frame",
    "geolint",
)
GEO_KIND = ErrorCode(
    "geo-kind",
    "Algebra that has no geometric meaning (point + point) or a kind where another is required",
    "geolint",
)
GEO_TRANSLATION = ErrorCode(
    "geo-translation",
    "A translation reaches a vector or direction (through the raw matrix, R @ v + t, or w=1)",
    "geolint",
)

GEO_QUATERNION_ORDER = ErrorCode(
    "geo-quaternion-order",
    "A quaternion in one component order passed where a library reads the other (the knowledge base's stubs)",
    "geolint",
)

ALL = (GEO_FRAME, GEO_KIND, GEO_TRANSLATION, GEO_QUATERNION_ORDER)
