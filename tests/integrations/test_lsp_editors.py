"""`geolint lsp` under the traffic real editors send, over stdio with a real client (pytest-lsp).

Each test is one trap an editor hit on a large file: code actions that waited for a whole fix run,
pulls that were not debounced and could not be cancelled, diagnostics that waited for the user to
stop typing, settings notifications that re-linted everything, and config edits that never reached
an editor that does not watch files.
"""

from __future__ import annotations

import asyncio
import os
import time
from pathlib import Path
from typing import Any, Callable

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from geolint import api
from tests.integrations.conftest import RecordingClient
from tests.conftest import DECLARES_DST_FIRST

FIX_ALL = "source.fixAll.geolint"
FUNCTION = (
    "\n\ndef step_{i}(R_world_cam, normal_cam, t_world_cam, T_world_base, p_cam):\n"
    "    normal_world = R_world_cam @ normal_cam + t_world_cam\n"
    "    return normal_world, T_world_base @ p_cam\n"
)


def source_with(functions: int) -> str:
    """A module of `functions` functions, each with a fixable GEO101 and a GEO201 (5 lines each)."""
    return "import numpy as np\n" + "".join(FUNCTION.format(i=i) for i in range(functions)) + DECLARES_DST_FIRST




PUSH = types.ClientCapabilities()
PULL = types.ClientCapabilities(
    text_document=types.TextDocumentClientCapabilities(diagnostic=types.DiagnosticClientCapabilities()),
    workspace=types.WorkspaceClientCapabilities(
        diagnostics=types.DiagnosticWorkspaceClientCapabilities(refresh_support=True)
    ),
)
RESOLVES = types.ClientCapabilities(
    text_document=types.TextDocumentClientCapabilities(
        code_action=types.CodeActionClientCapabilities(
            resolve_support=types.ClientCodeActionResolveOptions(properties=["edit"]), data_support=True
        )
    )
)


async def start(client: LanguageClient, capabilities: types.ClientCapabilities, **options: Any) -> None:
    await client.initialize_session(types.InitializeParams(capabilities=capabilities, initialization_options=options))


def open_doc(client: LanguageClient, path: Path, text: str) -> str:
    uri = path.as_uri()
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(text_document=types.TextDocumentItem(uri=uri, language_id="python", version=1, text=text))
    )
    return uri


def type_at(client: LanguageClient, uri: str, version: int, line: int, character: int, text: str) -> None:
    here = types.Position(line=line, character=character)
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
            content_changes=[types.TextDocumentContentChangePartial(range=types.Range(start=here, end=here), text=text)],
        )
    )


async def eventually(predicate: Callable[[], bool], timeout: float = 120.0) -> None:
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            raise AssertionError("timed out waiting for the server")
        await asyncio.sleep(0.02)


def pull_params(uri: str) -> types.DocumentDiagnosticParams:
    return types.DocumentDiagnosticParams(text_document=types.TextDocumentIdentifier(uri=uri))


def actions_params(uri: str, line: int, only: list[str] | None = None) -> types.CodeActionParams:
    return types.CodeActionParams(
        text_document=types.TextDocumentIdentifier(uri=uri),
        range=types.Range(start=types.Position(line=line, character=0), end=types.Position(line=line, character=60)),
        context=types.CodeActionContext(diagnostics=[], only=only),
    )


# ---- code actions ---------------------------------------------------------------------------------


async def check_quick_fixes_come_from_the_last_lint(client: RecordingClient, tmp_path: Path, functions: int) -> None:
    """Quick fixes are read from the last lint and moved onto the current text after an edit.

    How fast they come back is a benchmark's question (benchmarks/bench_lsp.py), not a test's:
    this checks what they are, so it holds on a loaded CI machine too.
    """
    text = source_with(functions)
    uri = open_doc(client, tmp_path / "large.py", text)
    await eventually(lambda: any(p.uri == uri for p in client.published))
    geo101_line = 4  # the first function's `normal_world = ...` (0-based)
    actions = await client.text_document_code_action_async(actions_params(uri, geo101_line))
    assert any(a.title.startswith("Fix GEO101") for a in actions)
    # Right after an edit above the finding (before the new version is linted): the fix from the
    # last lint, moved one line down with the text.
    type_at(client, uri, 2, 0, 0, "# typed\n")
    actions = await client.text_document_code_action_async(actions_params(uri, geo101_line + 1))
    fix = next(a for a in actions if a.title.startswith("Fix GEO101"))
    assert fix.edit.changes[uri][0].range.start.line == geo101_line + 1


@pytest.mark.asyncio
async def test_quick_fixes_come_from_the_last_lint_not_a_fix_run(client: RecordingClient, tmp_path: Path) -> None:
    await start(client, PUSH)
    await check_quick_fixes_come_from_the_last_lint(client, tmp_path, 100)


@pytest.mark.asyncio
async def test_fix_all_is_computed_only_when_resolved(client: RecordingClient, tmp_path: Path) -> None:
    await start(client, RESOLVES)
    path = tmp_path / "resolve.py"
    text = source_with(3)
    uri = open_doc(client, path, text)
    await eventually(lambda: uri in client.diagnostics)
    actions = await client.text_document_code_action_async(actions_params(uri, 4))
    (lazy,) = [a for a in actions if a.kind == FIX_ALL]
    assert lazy.edit is None and lazy.data is not None  # offered, not computed
    resolved = await client.code_action_resolve_async(lazy)
    (edit,) = resolved.edit.changes[uri]
    lines = text.split("\n")
    first = sum(len(line) + 1 for line in lines[: edit.range.start.line]) + edit.range.start.character
    last = sum(len(line) + 1 for line in lines[: edit.range.end.line]) + edit.range.end.character
    assert text[:first] + edit.new_text + text[last:] == api.fix_text(text, path, api.find_config(path.parent))[0]


# ---- pulls: debounced, cancellable ------------------------------------------------------------------


@pytest.mark.asyncio
async def test_a_pull_after_a_change_waits_for_the_debounce(client: RecordingClient, tmp_path: Path) -> None:
    await start(client, PULL, debounce=0.6, maxDelay=5)
    uri = open_doc(client, tmp_path / "pulled.py", source_with(1))
    await client.text_document_diagnostic_async(pull_params(uri))
    type_at(client, uri, 2, 0, 0, "# one\n")
    pending = asyncio.ensure_future(client.text_document_diagnostic_async(pull_params(uri)))
    for version, key in enumerate("abc", start=3):  # still typing: each key restarts the wait
        await asyncio.sleep(0.2)
        assert not pending.done()
        type_at(client, uri, version, 0, 0, key)
    started = time.monotonic()
    report = await pending
    assert time.monotonic() - started > 0.4
    # It answers for the text after the last key: the findings sit one line lower.
    assert sorted({d.range.start.line for d in report.items if d.code == "GEO101"}) == [5]


def cpu_seconds(pid: int) -> float:
    """CPU time of a process and its children (the lint workers), from /proc."""
    ticks = os.sysconf("SC_CLK_TCK")
    total = 0.0
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if entry.name == str(pid) or fields[1] == str(pid):  # fields[1] is the parent's pid
            total += (int(fields[11]) + int(fields[12])) / ticks
    return total


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads CPU time from /proc")
@pytest.mark.asyncio
async def test_a_cancelled_pull_stops_its_lint(client: RecordingClient, tmp_path: Path) -> None:
    await start(client, PULL, debounce=0)
    # About 900,000 characters (under the default max-file-size): a lint of a couple of seconds on
    # an idle machine, so it is still running when the cancel arrives.
    uri = open_doc(client, tmp_path / "big.py", source_with(5000))
    request = asyncio.ensure_future(
        client.protocol.send_request_async(types.TEXT_DOCUMENT_DIAGNOSTIC, pull_params(uri), msg_id="big-pull")
    )
    await asyncio.sleep(0.5)  # the lint is running
    assert not request.done(), "the file linted too fast to tell; make it bigger"
    client.protocol.notify(types.CANCEL_REQUEST, types.CancelParams(id="big-pull"))
    with pytest.raises(Exception, match="cancel"):
        await request
    await asyncio.sleep(1.5)  # a replacement worker starts (that costs CPU) and settles
    server = client._server.pid  # type: ignore[union-attr]
    before = cpu_seconds(server)
    await asyncio.sleep(2.0)
    burned = cpu_seconds(server) - before
    assert burned < 0.3, f"the server and its workers used {burned:.2f} s of CPU after the cancel"


# ---- pushes during continuous typing ---------------------------------------------------------------


@pytest.mark.asyncio
async def test_diagnostics_refresh_while_the_user_keeps_typing(client: RecordingClient, tmp_path: Path) -> None:
    await start(client, PUSH, debounce=0.3, maxDelay=1.0)
    uri = open_doc(client, tmp_path / "typing.py", source_with(2) + "# ")
    await eventually(lambda: len(client.published) == 1)
    last_line = len(source_with(2).splitlines())
    typing_started = time.monotonic()
    for version in range(2, 42):  # 4 s of typing, a key every 0.1 s (never a 0.3 s pause)
        type_at(client, uri, version, last_line, version, "x")
        await asyncio.sleep(0.1)
    during = [p for p in client.published[1:]]
    assert time.monotonic() - typing_started >= 4
    assert len(during) >= 2, "no diagnostics while typing"
    await eventually(lambda: client.published[-1].version == 41, timeout=30)


# ---- settings and config files -----------------------------------------------------------------------


@pytest.mark.asyncio
async def test_a_settings_notification_that_changes_nothing_does_not_relint(client: RecordingClient, tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text("[tool.geolint]\n", encoding="utf-8")
    await start(client, PUSH)
    uri = open_doc(client, tmp_path / "settled.py", source_with(2))
    await eventually(lambda: len(client.published) == 1)
    client.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings={"geolint": {}}))
    os.utime(tmp_path / "pyproject.toml")  # touched, not changed
    client.workspace_did_change_watched_files(
        types.DidChangeWatchedFilesParams(
            changes=[types.FileEvent(uri=(tmp_path / "pyproject.toml").as_uri(), type=types.FileChangeType.Changed)]
        )
    )
    await asyncio.sleep(1.5)
    assert len(client.published) == 1 and uri in client.diagnostics


def rewrite(path: Path, text: str) -> None:
    path.write_text(text, encoding="utf-8")
    later = time.time() + 2  # a modification time that certainly differs
    os.utime(path, (later, later))


@pytest.mark.asyncio
async def test_a_config_edit_reaches_a_pulling_editor_that_does_not_watch_files(client: RecordingClient, tmp_path: Path) -> None:
    pyproject = tmp_path / "pyproject.toml"
    pyproject.write_text("[tool.geolint]\n", encoding="utf-8")
    await start(client, PULL)
    uri = open_doc(client, tmp_path / "pulled.py", source_with(1))
    before = await client.text_document_diagnostic_async(pull_params(uri))
    assert "GEO101" in [d.code for d in before.items]
    rewrite(pyproject, '[tool.geolint]\nignore = ["GEO101"]\n')
    await client.text_document_code_action_async(actions_params(uri, 4))  # any request
    await eventually(lambda: client.diagnostic_refresh_count == 1, timeout=10)
    after = await client.text_document_diagnostic_async(pull_params(uri))
    assert "GEO101" not in [d.code for d in after.items] and "GEO201" in [d.code for d in after.items]


@pytest.mark.asyncio
async def test_a_config_edit_reaches_a_pushed_to_editor_on_its_next_request(client: RecordingClient, tmp_path: Path) -> None:
    pyproject = tmp_path / "pyproject.toml"
    pyproject.write_text("[tool.geolint]\n", encoding="utf-8")
    await start(client, PUSH)
    uri = open_doc(client, tmp_path / "pushed.py", source_with(1))
    await eventually(lambda: uri in client.diagnostics)
    assert "GEO101" in [d.code for d in client.diagnostics[uri]]
    rewrite(pyproject, '[tool.geolint]\nignore = ["GEO101"]\n')
    await client.text_document_code_action_async(actions_params(uri, 4))
    await eventually(lambda: "GEO101" not in [d.code for d in client.diagnostics[uri]], timeout=10)
    assert "GEO201" in [d.code for d in client.diagnostics[uri]]
