"""geolint's mypy plugin. Enable it with ``plugins = geolint.mypy`` (mypy.ini / setup.cfg ``[mypy]``, or
``plugins = ["geolint.mypy"]`` in pyproject ``[tool.mypy]``).

It adds what plain generics cannot: string frames (``Point["camera"]``), precise frame messages under the
error codes ``geo-frame``, ``geo-kind`` and ``geo-translation``, and frame inference for plain ndarrays
annotated with `geolint.typing`.

Layout: `plugin` (the dispatch tables, nothing else), `fullnames` and `errorcodes` (defined once), `config`
(settings and the cache key), `geometry` (a mypy type read as kind + frames), `algebra` (the rules),
`messages`; one module per feature: `string_frames` with its `string_frame_prepass`, `operators`,
`numpy_calls`, `markers`, `knowledge_calls` (library calls, from `stubs/`). docs/typing.md is the user guide.
"""

from geolint.mypy.plugin import GeolintPlugin, plugin

__all__ = ["GeolintPlugin", "plugin"]
