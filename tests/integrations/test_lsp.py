"""`geolint lsp` end to end: a real LSP client (pytest-lsp) talks to `python -m geolint lsp` over stdio.

Expectations come from `geolint.api` run in this process on the same text, so the tests check
that the editor shows exactly what the linter finds, in LSP's terms (0-based lines, UTF-16 columns).
"""

from __future__ import annotations

import asyncio
import time
from pathlib import Path
from typing import Any, Callable

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from geolint import api
from tests.integrations.conftest import RecordingClient
from geolint.engine import apply_edits
from geolint.lint_types import Edit
from geolint.rules import rule_by_code
from tests.conftest import DECLARES_DST_FIRST

# Tests that need real rule findings run once the rules are registered (they are developed in parallel).
needs_rules = pytest.mark.skipif(
    rule_by_code("GEO101") is None or rule_by_code("GEO201") is None, reason="rules GEO101/GEO201 not registered yet"
)

# A surface normal moved by rotation AND translation (GEO101), and a transform applied to a
# point from another frame (GEO201).
BUGGY = """\
import numpy as np


def to_world(R_world_cam, t_world_cam, normal_cam, T_world_base, p_cam):
    normal_world = R_world_cam @ normal_cam + t_world_cam
    p_world = T_world_base @ p_cam
    return normal_world, p_world
""" + DECLARES_DST_FIRST
CLEAN = """\
def to_world(R_world_cam, t_world_cam, normal_cam):
    return R_world_cam @ normal_cam
"""
# The syntax error is after two emoji: 2 code points each count 2 UTF-16 code units.
EMOJI_SYNTAX_ERROR = 'label = "\U0001f916\U0001f916" + (\n'




PUSH_ONLY = types.ClientCapabilities()
PULL = types.ClientCapabilities(
    text_document=types.TextDocumentClientCapabilities(
        diagnostic=types.DiagnosticClientCapabilities(dynamic_registration=False)
    ),
    workspace=types.WorkspaceClientCapabilities(
        diagnostics=types.DiagnosticWorkspaceClientCapabilities(refresh_support=True)
    ),
)


async def start(client: LanguageClient, capabilities: types.ClientCapabilities = PUSH_ONLY, **options: Any) -> types.InitializeResult:
    return await client.initialize_session(
        types.InitializeParams(capabilities=capabilities, initialization_options={"debounce": 0.2, **options})
    )


def open_doc(client: LanguageClient, path: Path, text: str, version: int = 1) -> str:
    uri = path.as_uri()
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(
            text_document=types.TextDocumentItem(uri=uri, language_id="python", version=version, text=text)
        )
    )
    return uri


def change_doc(client: LanguageClient, uri: str, text: str, version: int) -> None:
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
            content_changes=[types.TextDocumentContentChangeWholeDocument(text=text)],
        )
    )


async def eventually(predicate: Callable[[], bool], timeout: float = 15.0) -> None:
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            raise AssertionError("timed out waiting for the server")
        await asyncio.sleep(0.02)


def utf16(text: str) -> int:
    return len(text.encode("utf-16-le")) // 2


def expected_codes(text: str, path: Path) -> list[tuple[str, int]]:
    findings = api.lint_text(text, path, api.find_config(path.parent))
    return [(f.code, f.line - 1) for f in findings]


def diagnostic_codes(diagnostics: Any) -> list[tuple[str, int]]:
    return [(d.code, d.range.start.line) for d in diagnostics]


def apply_text_edits(text: str, edits: list[types.TextEdit]) -> str:
    """Apply LSP edits (UTF-16 columns) to `text` the way an editor does."""
    lines = text.split("\n")

    def column(line: int, units: int) -> int:
        source_line = lines[line] if line < len(lines) else ""
        count = 0
        for index, char in enumerate(source_line):
            if count >= units:
                return index + 1
            count += utf16(char)
        return len(source_line) + 1

    geolint_edits = [
        Edit(
            e.range.start.line + 1,
            column(e.range.start.line, e.range.start.character),
            e.range.end.line + 1,
            column(e.range.end.line, e.range.end.character),
            e.new_text,
        )
        for e in edits
    ]
    return apply_edits(text, geolint_edits)


@pytest.mark.asyncio
async def test_initialize_advertises_diagnostics_and_code_actions(client: RecordingClient) -> None:
    result = await start(client)
    capabilities = result.capabilities
    assert capabilities.diagnostic_provider is not None and capabilities.diagnostic_provider.identifier == "geolint"
    assert set(capabilities.code_action_provider.code_action_kinds) == {"quickfix", "source.fixAll.geolint"}
    assert capabilities.position_encoding == types.PositionEncodingKind.Utf16
    assert result.server_info is not None and result.server_info.name == "geolint"


@needs_rules
@pytest.mark.asyncio
async def test_open_pushes_the_linters_findings_with_code_link_and_severity(client: RecordingClient, tmp_path: Path) -> None:
    await start(client)
    path = tmp_path / "robot.py"
    uri = open_doc(client, path, BUGGY)
    expected = expected_codes(BUGGY, path)
    assert {code for code, _ in expected} >= {"GEO101", "GEO201"}  # the linter itself finds the bugs
    await eventually(lambda: uri in client.diagnostics)
    diagnostics = client.diagnostics[uri]
    assert diagnostic_codes(diagnostics) == expected
    for diagnostic in diagnostics:
        assert diagnostic.source == "geolint"
        assert diagnostic.code_description.href == api.rule_url(str(diagnostic.code))
        assert diagnostic.severity == types.DiagnosticSeverity.Error
    geo101 = next(d for d in diagnostics if d.code == "GEO101")
    line = BUGGY.splitlines()[geo101.range.start.line]
    assert "t_world_cam" in line[geo101.range.start.character : geo101.range.end.character + 1] or geo101.range.end.line > geo101.range.start.line


@needs_rules
@pytest.mark.asyncio
async def test_a_diagnostic_carries_its_evidence_as_related_information(client: RecordingClient, tmp_path: Path) -> None:
    await start(client)
    source = (
        "def wrong_source(buffer, stamp, p_camera):\n"
        "    T_lookup = buffer.lookup_transform('map', 'base_link', stamp)\n"
        "    return T_lookup @ p_camera\n"
    )
    uri = open_doc(client, tmp_path / "node.py", source)
    await eventually(lambda: uri in client.diagnostics)
    (diagnostic,) = [d for d in client.diagnostics[uri] if d.code == "GEO201"]
    related = diagnostic.related_information or []
    # the lookup states the frames on line 2 (LSP line 1); the name `p_camera` is evidence at the finding
    stated = [r for r in related if "lookup_transform" in r.message]
    assert stated and stated[0].location.uri == uri and stated[0].location.range.start.line == 1
    assert any("p_camera" in r.message and r.location.range == diagnostic.range for r in related)


@pytest.mark.asyncio
async def test_columns_are_utf16_code_units(client: RecordingClient, tmp_path: Path) -> None:
    await start(client)
    uri = open_doc(client, tmp_path / "emoji.py", EMOJI_SYNTAX_ERROR)
    await eventually(lambda: uri in client.diagnostics)
    (diagnostic,) = client.diagnostics[uri]
    assert diagnostic.code == "GEO000"
    paren = EMOJI_SYNTAX_ERROR.index("(")
    assert diagnostic.range.start.character == utf16(EMOJI_SYNTAX_ERROR[:paren])
    assert diagnostic.range.start.character == paren + 2  # two astral characters, one extra unit each


@needs_rules
@pytest.mark.asyncio
async def test_changes_are_debounced_into_one_publish_for_the_last_version(client: RecordingClient, tmp_path: Path) -> None:
    await start(client)
    uri = open_doc(client, tmp_path / "typing.py", BUGGY)
    await eventually(lambda: len(client.published) == 1)
    half_typed = [BUGGY[:n] for n in range(len(CLEAN) // 2, len(CLEAN), 7)]
    for version, text in enumerate([*half_typed, CLEAN], start=2):  # a person typing fast
        change_doc(client, uri, text, version)
    await eventually(lambda: len(client.published) >= 2)
    await asyncio.sleep(0.6)  # longer than the debounce: nothing else may arrive
    assert len(client.published) == 2
    last = client.published[-1]
    assert last.version == len(half_typed) + 2
    assert list(last.diagnostics) == []


@needs_rules
@pytest.mark.asyncio
async def test_half_typed_code_gets_a_syntax_finding_and_the_server_carries_on(client: RecordingClient, tmp_path: Path) -> None:
    await start(client)
    uri = open_doc(client, tmp_path / "half.py", CLEAN)
    await eventually(lambda: uri in client.diagnostics)
    change_doc(client, uri, "def to_world(R_world_cam, \n", 2)
    await eventually(lambda: [d.code for d in client.diagnostics[uri]] == ["GEO000"])
    change_doc(client, uri, BUGGY, 3)
    await eventually(lambda: "GEO101" in [d.code for d in client.diagnostics[uri]])


@pytest.mark.asyncio
async def test_save_lints_again(client: RecordingClient, tmp_path: Path) -> None:
    await start(client)
    uri = open_doc(client, tmp_path / "saved.py", CLEAN)
    await eventually(lambda: len(client.published) == 1)
    client.text_document_did_save(types.DidSaveTextDocumentParams(text_document=types.TextDocumentIdentifier(uri=uri)))
    await eventually(lambda: len(client.published) == 2)


@needs_rules
@pytest.mark.asyncio
async def test_pull_diagnostics_and_no_duplicate_push(client: RecordingClient, tmp_path: Path) -> None:
    await start(client, PULL)
    path = tmp_path / "pulled.py"
    uri = open_doc(client, path, BUGGY)
    report = await client.text_document_diagnostic_async(
        types.DocumentDiagnosticParams(text_document=types.TextDocumentIdentifier(uri=uri))
    )
    assert report.kind == "full"
    assert diagnostic_codes(report.items) == expected_codes(BUGGY, path)
    await asyncio.sleep(0.5)
    assert client.published == []  # a client that pulls is not also pushed to


@needs_rules
@pytest.mark.asyncio
async def test_quick_fix_and_fix_all_remove_the_fixable_finding(client: RecordingClient, tmp_path: Path) -> None:
    await start(client)
    path = tmp_path / "fixme.py"
    uri = open_doc(client, path, BUGGY)
    await eventually(lambda: uri in client.diagnostics)
    geo101 = next(d for d in client.diagnostics[uri] if d.code == "GEO101")
    actions = await client.text_document_code_action_async(
        types.CodeActionParams(
            text_document=types.TextDocumentIdentifier(uri=uri),
            range=geo101.range,
            context=types.CodeActionContext(diagnostics=[geo101]),
        )
    )
    titles = [action.title for action in actions]
    fix = next(a for a in actions if a.title.startswith("Fix GEO101"))
    assert fix.kind == types.CodeActionKind.QuickFix and fix.is_preferred
    fixed = apply_text_edits(BUGGY, list(fix.edit.changes[uri]))
    assert "GEO101" not in [code for code, _ in expected_codes(fixed, path)]
    assert "GEO201" in [code for code, _ in expected_codes(fixed, path)]  # only that finding was touched
    assert "Ignore GEO101 for this line" in titles

    (fix_all,) = await client.text_document_code_action_async(
        types.CodeActionParams(
            text_document=types.TextDocumentIdentifier(uri=uri),
            range=types.Range(start=types.Position(0, 0), end=types.Position(0, 0)),
            context=types.CodeActionContext(diagnostics=[], only=["source.fixAll.geolint"]),
        )
    )
    assert fix_all.kind == "source.fixAll.geolint"
    all_fixed = apply_text_edits(BUGGY, list(fix_all.edit.changes[uri]))
    assert all_fixed == api.fix_text(BUGGY, path, api.find_config(path.parent))[0]


@needs_rules
@pytest.mark.asyncio
async def test_ignore_for_this_line_adds_then_extends_the_suppression(client: RecordingClient, tmp_path: Path) -> None:
    await start(client)
    path = tmp_path / "ignore.py"
    uri = open_doc(client, path, BUGGY)
    await eventually(lambda: uri in client.diagnostics)

    async def ignore(code: str, text: str, version: int) -> str:
        await eventually(lambda: client.published[-1].version == version)
        diagnostic = next(d for d in client.diagnostics[uri] if d.code == code)
        actions = await client.text_document_code_action_async(
            types.CodeActionParams(
                text_document=types.TextDocumentIdentifier(uri=uri),
                range=diagnostic.range,
                context=types.CodeActionContext(diagnostics=[diagnostic], only=[types.CodeActionKind.QuickFix]),
            )
        )
        action = next(a for a in actions if a.title == f"Ignore {code} for this line")
        return apply_text_edits(text, list(action.edit.changes[uri]))

    once = await ignore("GEO101", BUGGY, 1)
    assert "normal_world = R_world_cam @ normal_cam + t_world_cam  # geolint: ignore[GEO101]" in once
    assert "GEO101" not in [code for code, _ in expected_codes(once, path)]
    # Put both findings on one line, then ignore the second code: the comment is extended.
    joined = once.replace("\n    p_world = T_world_base @ p_cam\n", "\n").replace(
        "  # geolint: ignore[GEO101]", "; p_world = T_world_base @ p_cam  # geolint: ignore[GEO101]"
    )
    assert "GEO201" in [code for code, _ in expected_codes(joined, path)]
    change_doc(client, uri, joined, 2)
    twice = await ignore("GEO201", joined, 2)
    assert "# geolint: ignore[GEO101, GEO201]" in twice
    assert expected_codes(twice, path) == []


@needs_rules
@pytest.mark.asyncio
async def test_config_is_read_and_reread_when_pyproject_changes(client: RecordingClient, tmp_path: Path) -> None:
    pyproject = tmp_path / "pyproject.toml"
    pyproject.write_text('[tool.geolint]\nignore = ["GEO101"]\n', encoding="utf-8")
    await start(client)
    uri = open_doc(client, tmp_path / "configured.py", BUGGY)
    await eventually(lambda: uri in client.diagnostics)
    assert "GEO101" not in [d.code for d in client.diagnostics[uri]]
    assert "GEO201" in [d.code for d in client.diagnostics[uri]]

    pyproject.write_text('[tool.geolint]\nignore = ["GEO2"]\n\n[tool.geolint.severity]\nGEO101 = "warning"\n', encoding="utf-8")
    client.workspace_did_change_watched_files(
        types.DidChangeWatchedFilesParams(
            changes=[types.FileEvent(uri=pyproject.as_uri(), type=types.FileChangeType.Changed)]
        )
    )
    await eventually(lambda: [d.code for d in client.diagnostics[uri]] == ["GEO101"])
    assert client.diagnostics[uri][0].severity == types.DiagnosticSeverity.Warning


@pytest.mark.asyncio
async def test_survives_unknown_uris_and_garbage(client: RecordingClient, tmp_path: Path) -> None:
    await start(client)
    # A pull for a file that was never opened and does not exist, and for a non-file URI.
    for uri in ((tmp_path / "missing.py").as_uri(), "untitled:Untitled-1", "not a uri at all"):
        report = await client.text_document_diagnostic_async(
            types.DocumentDiagnosticParams(text_document=types.TextDocumentIdentifier(uri=uri))
        )
        assert list(report.items) == []
    # A change and a code action for a document that was never opened.
    change_doc(client, (tmp_path / "ghost.py").as_uri(), "x = 1\n", 5)
    ghost = await client.text_document_code_action_async(
        types.CodeActionParams(
            text_document=types.TextDocumentIdentifier(uri=(tmp_path / "ghost.py").as_uri()),
            range=types.Range(start=types.Position(0, 0), end=types.Position(0, 0)),
            context=types.CodeActionContext(diagnostics=[]),
        )
    )
    assert not ghost
    # A code action range far outside the document.
    uri = open_doc(client, tmp_path / "after.py", BUGGY)
    await eventually(lambda: uri in client.diagnostics)
    actions = await client.text_document_code_action_async(
        types.CodeActionParams(
            text_document=types.TextDocumentIdentifier(uri=uri),
            range=types.Range(start=types.Position(999, 999), end=types.Position(1000, 0)),
            context=types.CodeActionContext(diagnostics=[]),
        )
    )
    assert actions is not None
    assert diagnostic_codes(client.diagnostics[uri]) == expected_codes(BUGGY, tmp_path / "after.py")


@pytest.mark.slow  # a 5,000-line module linted while the server answers
@needs_rules
@pytest.mark.asyncio
async def test_a_large_file_is_linted_off_the_main_loop(client: RecordingClient, tmp_path: Path) -> None:
    await start(client, PULL)
    big_text = BUGGY + "".join(
        f"\n\ndef step_{i}(R_world_cam, normal_cam, t_world_cam):\n    return R_world_cam @ normal_cam + t_world_cam\n"
        for i in range(6000)
    )
    small = open_doc(client, tmp_path / "small.py", CLEAN)
    big = open_doc(client, tmp_path / "big.py", big_text)
    big_request = asyncio.ensure_future(
        client.text_document_diagnostic_async(
            types.DocumentDiagnosticParams(text_document=types.TextDocumentIdentifier(uri=big))
        )
    )
    await asyncio.sleep(0.05)
    small_report = await client.text_document_diagnostic_async(
        types.DocumentDiagnosticParams(text_document=types.TextDocumentIdentifier(uri=small))
    )
    # The behaviour under test is the order of the answers: the small file's comes back
    # while the big one is still being linted. No wall-clock ratio, which a loaded CI
    # machine makes flaky.
    assert not big_request.done(), "the big file linted too fast to tell anything; make it bigger"
    big_report = await big_request
    assert list(small_report.items) == []
    assert len([d for d in big_report.items if d.code == "GEO101"]) >= 6000


@needs_rules
@pytest.mark.asyncio
async def test_a_pulling_client_is_asked_to_refresh_when_the_config_changes(client: RecordingClient, tmp_path: Path) -> None:
    await start(client, PULL)
    pyproject = tmp_path / "pyproject.toml"
    pyproject.write_text("[tool.geolint]\n", encoding="utf-8")
    uri = open_doc(client, tmp_path / "pulled.py", BUGGY)
    params = types.DocumentDiagnosticParams(text_document=types.TextDocumentIdentifier(uri=uri))
    before = await client.text_document_diagnostic_async(params)
    assert "GEO101" in [d.code for d in before.items]
    pyproject.write_text('[tool.geolint]\nignore = ["GEO101"]\n', encoding="utf-8")
    client.workspace_did_change_watched_files(
        types.DidChangeWatchedFilesParams(changes=[types.FileEvent(uri=pyproject.as_uri(), type=types.FileChangeType.Changed)])
    )
    await eventually(lambda: client.diagnostic_refresh_count == 1)
    after = await client.text_document_diagnostic_async(params)
    assert "GEO101" not in [d.code for d in after.items] and "GEO201" in [d.code for d in after.items]


@needs_rules
@pytest.mark.asyncio
async def test_a_broken_config_is_reported_once_and_linting_goes_on(client: RecordingClient, tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text('[tool.geolint]\nselectt = ["GEO1"]\n', encoding="utf-8")
    await start(client)
    first = open_doc(client, tmp_path / "one.py", BUGGY)
    second = open_doc(client, tmp_path / "two.py", BUGGY)
    await eventually(lambda: first in client.diagnostics and second in client.diagnostics)
    assert "GEO101" in [d.code for d in client.diagnostics[first]]
    errors = [m for m in client.messages if m.type == types.MessageType.Error]
    assert len(errors) == 1 and "pyproject.toml" in errors[0].message and "selectt" in errors[0].message


@pytest.mark.asyncio
async def test_columns_follow_a_negotiated_utf8_encoding(client: RecordingClient, tmp_path: Path) -> None:
    utf8_only = types.ClientCapabilities(general=types.GeneralClientCapabilities(position_encodings=["utf-8"]))
    result = await start(client, utf8_only)
    assert result.capabilities.position_encoding == types.PositionEncodingKind.Utf8
    uri = open_doc(client, tmp_path / "emoji8.py", EMOJI_SYNTAX_ERROR)
    await eventually(lambda: uri in client.diagnostics)
    (diagnostic,) = client.diagnostics[uri]
    paren = EMOJI_SYNTAX_ERROR.index("(")
    assert diagnostic.range.start.character == len(EMOJI_SYNTAX_ERROR[:paren].encode("utf-8"))
