"""A pyproject.toml edit reaches every open document without any edit of the document, over stdio
with a real client (pytest-lsp): the server registers a `**/pyproject.toml` watcher with a client
that can watch files and re-publishes on its `workspace/didChangeWatchedFiles`; for a client that
cannot, it notices the edit by polling."""

from __future__ import annotations

import asyncio
import os
import sys
import time
from pathlib import Path
from typing import Callable

import pytest
import pytest_lsp
from lsprotocol import types
from pygls.protocol import default_converter
from pytest_lsp import ClientServerConfig
from pytest_lsp.client import DEFAULT_CLIENT_FEATURES, register_lsp_features

from tests.conftest import DECLARES_DST_FIRST
from tests.integrations.conftest import RecordingClient

# A direction moved by a translation (GEO101), and a transform applied across frames (GEO201).
SOURCE = """\
import numpy as np


def to_world(R_world_cam, t_world_cam, normal_cam, T_world_base, p_cam):
    normal_world = R_world_cam @ normal_cam + t_world_cam
    return normal_world, T_world_base @ p_cam
""" + DECLARES_DST_FIRST

WATCHES_FILES = types.ClientCapabilities(
    workspace=types.WorkspaceClientCapabilities(
        did_change_watched_files=types.DidChangeWatchedFilesClientCapabilities(dynamic_registration=True)
    )
)
CANNOT_WATCH = types.ClientCapabilities()


def make_client() -> RecordingClient:
    """The recording client, which also accepts `client/registerCapability` and keeps what it was asked."""
    client = RecordingClient(converter_factory=default_converter)
    client.published = []
    client.registrations = []

    def publish(client: RecordingClient, params: types.PublishDiagnosticsParams) -> None:
        client.diagnostics[params.uri] = params.diagnostics
        client.published.append(params)

    def register(client: RecordingClient, params: types.RegistrationParams) -> None:
        client.registrations.extend(params.registrations)

    register_lsp_features(
        client,
        {**DEFAULT_CLIENT_FEATURES, types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS: publish, types.CLIENT_REGISTER_CAPABILITY: register},
    )
    return client


@pytest_lsp.fixture(config=ClientServerConfig(server_command=[sys.executable, "-m", "geolint", "lsp"], client_factory=make_client))
async def client(lsp_client: RecordingClient):  # type: ignore[no-untyped-def]
    yield
    await lsp_client.shutdown_session()


async def start(client: RecordingClient, capabilities: types.ClientCapabilities, **options: object) -> None:
    await client.initialize_session(
        types.InitializeParams(capabilities=capabilities, initialization_options={"debounce": 0.1, **options})
    )


def open_doc(client: RecordingClient, path: Path, text: str) -> str:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    uri = path.as_uri()
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(text_document=types.TextDocumentItem(uri=uri, language_id="python", version=1, text=text))
    )
    return uri


def rewrite(path: Path, text: str) -> None:
    path.write_text(text, encoding="utf-8")
    later = time.time() + 2  # a modification time that certainly differs
    os.utime(path, (later, later))


async def eventually(predicate: Callable[[], bool], timeout: float = 60.0) -> None:
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            raise AssertionError("timed out waiting for the server")
        await asyncio.sleep(0.02)


def codes(client: RecordingClient, uri: str) -> list[str]:
    return sorted(str(diagnostic.code) for diagnostic in client.diagnostics.get(uri, []))


@pytest.mark.asyncio
async def test_a_watching_client_is_asked_to_watch_and_every_open_document_is_published_again(
    client: RecordingClient, tmp_path: Path
) -> None:
    pyproject = tmp_path / "pyproject.toml"
    pyproject.write_text("[tool.geolint]\n", encoding="utf-8")
    await start(client, WATCHES_FILES, configPollInterval=0)  # no polling: only the watcher can tell
    await eventually(lambda: bool(client.registrations))
    (registration,) = client.registrations
    assert registration.method == types.WORKSPACE_DID_CHANGE_WATCHED_FILES
    assert [watcher["globPattern"] for watcher in registration.register_options["watchers"]] == ["**/pyproject.toml"]

    first = open_doc(client, tmp_path / "one.py", SOURCE)
    second = open_doc(client, tmp_path / "pkg" / "two.py", SOURCE)
    await eventually(lambda: codes(client, first) == ["GEO101", "GEO201"] and codes(client, second) == ["GEO101", "GEO201"])
    published = len(client.published)

    rewrite(pyproject, '[tool.geolint]\nignore = ["GEO101"]\n')
    client.workspace_did_change_watched_files(
        types.DidChangeWatchedFilesParams(changes=[types.FileEvent(uri=pyproject.as_uri(), type=types.FileChangeType.Changed)])
    )
    await eventually(lambda: codes(client, first) == ["GEO201"] and codes(client, second) == ["GEO201"])
    assert len(client.published) == published + 2  # each document once, and no document was edited

    pyproject.unlink()  # deleted: back to the defaults
    client.workspace_did_change_watched_files(
        types.DidChangeWatchedFilesParams(changes=[types.FileEvent(uri=pyproject.as_uri(), type=types.FileChangeType.Deleted)])
    )
    await eventually(lambda: codes(client, first) == ["GEO101", "GEO201"] and codes(client, second) == ["GEO101", "GEO201"])


@pytest.mark.asyncio
async def test_a_client_that_cannot_watch_files_sees_a_config_edit_without_sending_anything(
    client: RecordingClient, tmp_path: Path
) -> None:
    await start(client, CANNOT_WATCH, configPollInterval=0.2)
    uri = open_doc(client, tmp_path / "mod.py", SOURCE)
    await eventually(lambda: codes(client, uri) == ["GEO101", "GEO201"])
    assert client.registrations == []  # nothing to register with a client that cannot watch

    pyproject = tmp_path / "pyproject.toml"  # created: a config where there was none
    rewrite(pyproject, '[tool.geolint]\nignore = ["GEO2"]\n')
    await eventually(lambda: codes(client, uri) == ["GEO101"])
    rewrite(pyproject, '[tool.geolint]\nselect = ["GEO999"]\n')  # broken: said once, and the defaults apply
    await eventually(lambda: codes(client, uri) == ["GEO101", "GEO201"])
    errors = [message.message for message in client.messages if message.type == types.MessageType.Error]
    assert len(errors) == 1 and "GEO999" in errors[0]
