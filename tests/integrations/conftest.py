"""The language-server tests' client: pytest-lsp's, started on `python -m geolint lsp`, that also
records every publishDiagnostics (to count debounced publishes). A test module that needs another
client defines its own `client` fixture, which takes precedence."""

from __future__ import annotations

import sys

import pytest_lsp
from lsprotocol import types
from pygls.protocol import default_converter
from pytest_lsp import ClientServerConfig, LanguageClient
from pytest_lsp.client import DEFAULT_CLIENT_FEATURES, register_lsp_features


class RecordingClient(LanguageClient):
    published: list[types.PublishDiagnosticsParams]


def make_client() -> LanguageClient:
    """pytest-lsp's client, also recording every publishDiagnostics (to count debounced publishes)."""
    client = RecordingClient(converter_factory=default_converter)
    client.published = []

    def publish(client: RecordingClient, params: types.PublishDiagnosticsParams) -> None:
        client.diagnostics[params.uri] = params.diagnostics
        client.published.append(params)

    register_lsp_features(client, {**DEFAULT_CLIENT_FEATURES, types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS: publish})
    return client


@pytest_lsp.fixture(
    config=ClientServerConfig(server_command=[sys.executable, "-m", "geolint", "lsp"], client_factory=make_client)
)
async def client(lsp_client: RecordingClient):  # type: ignore[no-untyped-def]
    yield
    await lsp_client.shutdown_session()
