"""geolint's mypy plugin. Enable it with ``plugins = geolint.mypy`` (mypy.ini / setup.cfg ``[mypy]``, or
``plugins = ["geolint.mypy"]`` in pyproject ``[tool.mypy]``).

It adds what plain generics cannot: string frames (``Point["camera"]``), precise frame messages under the
error codes ``geo-frame``, ``geo-kind`` and ``geo-translation``, and frame inference for plain ndarrays
annotated with `geolint.typing`. Layout: `plugin` (dispatch tables), `fullnames`, `errorcodes`, `geometry`
(types as kinds + frames), `algebra` (the rules), and one module per feature.
"""

from geolint.mypy.plugin import GeolintPlugin, plugin

__all__ = ["GeolintPlugin", "plugin"]
