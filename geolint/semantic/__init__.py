"""Name-level vocabulary shared by the linter, the frames graph, the mypy plugin and the editor server.

`names` reads what a single name states (kind, frames); `prefilter` is the per-rule `ast` gate.
The fact base that reasons about whole modules lives in `geolint.factbase`.
"""
