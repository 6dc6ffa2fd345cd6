"""The geolint language server (`geolint lsp`): diagnostics and code actions in any LSP editor.

A thin adapter over `geolint.api`, so the editor shows exactly what `geolint check` reports.
`server.py` wires the protocol; `positions.py`, `diagnostics.py`, `actions.py` and `configs.py`
are the plain functions it uses.
"""
