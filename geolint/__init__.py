"""geolint: catch geometric type errors (points vs vectors, frames, quaternion order) in Python.

`import geolint` gives the typed geometry runtime (numpy only). The linter lives in
`geolint.api` / `geolint check`, the mypy plugin in `geolint.mypy`.
"""

from geolint._version import __version__

__all__ = ["__version__"]
