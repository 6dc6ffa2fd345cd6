"""The server's copy of a document under thousands of random incremental edits, against a reference.

A real client (pytest-lsp) drives `python -m geolint lsp` over stdio. Every edit is made with LSP
positions computed on a reference string by this file's own code (lines broken at \\n, \\r\\n and
\\r only; columns in UTF-16 code units), then applied to the reference. The edits carry the
characters that `str.splitlines` mistakes for line breaks (\\f, \\v, \\x1c-\\x1e, \\x85, U+2028,
U+2029), CR-only and CRLF line endings, emoji and other astral characters, and span lines.
After each batch the server's text must equal the reference; every few batches its diagnostics
must be the linter's findings for the reference, and every code action it offers, applied to the
reference, must leave a module that parses.
"""

from __future__ import annotations

import ast
import asyncio
import random
import re
import sys
import time
from pathlib import Path
from typing import Any

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import ClientServerConfig, LanguageClient

from geolint import api

LINE_BREAK = re.compile(r"\r\n|\r|\n")
# Not line breaks for LSP (nor for Python's tokenizer), but line breaks for str.splitlines.
NOT_BREAKS = "\f\v\x1c\x1d\x1e\x85\u2028\u2029"
ASTRAL = "\U0001f916\U0001f600\U00010348\U0001d11e"
ALPHABET = "abc xyz_09()=+" + NOT_BREAKS + ASTRAL + "é中"
BREAKS = ("\n", "\r\n", "\r")
FIX_ALL = "source.fixAll.geolint"

# Top-level blocks; {nl} is a line break, {text} random text without breaks or quotes.
BLOCKS = (
    "def step_{i}(R_world_cam, normal_cam, t_world_cam):  # {text}{nl}    return R_world_cam @ normal_cam + t_world_cam{nl}",
    "def apply_{i}(T_world_base, p_cam):{nl}    return T_world_base @ p_cam{nl}",
    'label_{i} = "{text}"{nl}',
    "# {text}{nl}",
    "x_{i} = (1 +{nl}       2)  # {text}{nl}",
)
BLOCK_HEADS = ("def ", "label_", "x_", "# ")
MAX_BLOCKS = 7


# ---- the reference: LSP positions computed independently of the server's code ----------------------


def utf16(text: str) -> int:
    return len(text.encode("utf-16-le")) // 2


def line_starts(text: str) -> list[int]:
    return [0, *(m.end() for m in LINE_BREAK.finditer(text))]


def position(text: str, offset: int) -> types.Position:
    starts = line_starts(text)
    line = max(i for i, start in enumerate(starts) if start <= offset)
    return types.Position(line=line, character=utf16(text[starts[line] : offset]))


def offset_of(text: str, pos: types.Position) -> int:
    """The LSP spec's reading of a position: past the last line is the end, past a line's end is its end."""
    starts = line_starts(text)
    if pos.line >= len(starts):
        return len(text)
    start = starts[pos.line]
    end = starts[pos.line + 1] if pos.line + 1 < len(starts) else len(text)
    content = LINE_BREAK.sub("", text[start:end])
    units, index = 0, 0
    while index < len(content) and units < pos.character:
        units += utf16(content[index])
        index += 1
    return start + index


def apply(text: str, edits: list[tuple[types.Range, str]]) -> str:
    """Apply non-overlapping LSP edits (all positions refer to `text`), last first."""
    spans = sorted(((offset_of(text, r.start), offset_of(text, r.end), new) for r, new in edits), reverse=True)
    for start, end, new in spans:
        text = text[:start] + new + text[end:]
    return text


def parses(text: str) -> bool:
    try:
        ast.parse(text)
    except (SyntaxError, ValueError):
        return False
    return True


# ---- random edits ---------------------------------------------------------------------------------


def random_text(rng: random.Random, longest: int = 6) -> str:
    return "".join(rng.choice(ALPHABET) for _ in range(rng.randint(1, longest)))


def new_block(rng: random.Random) -> str:
    template = rng.choice(BLOCKS)
    return template.format(i=rng.randint(0, 999), text=random_text(rng), nl=rng.choice(BREAKS))


def new_document(rng: random.Random) -> str:
    return "".join(new_block(rng) for _ in range(rng.randint(2, MAX_BLOCKS)))


def comment_spans(text: str) -> list[tuple[int, int]]:
    """(start, end) offsets of the text of each comment: after '#' up to the line break."""
    spans = []
    for start, end in zip(line_starts(text), [*line_starts(text)[1:], len(text)]):
        line = LINE_BREAK.sub("", text[start:end])
        hash_at = line.find("#")
        if hash_at >= 0 and '"' not in line[:hash_at]:
            spans.append((start + hash_at + 1, start + len(line)))
    return spans


def random_edit(rng: random.Random, text: str) -> tuple[types.Range, str]:
    """One edit that keeps a parsing module parsing (mostly), or now and then any edit at all."""
    end_position = position(text, len(text))
    block_starts = [start for start in line_starts(text) if text.startswith(BLOCK_HEADS, start)]
    kind = rng.random()
    if kind < 0.05:  # anything, anywhere, positions past line ends and past the end included
        line = rng.randint(0, end_position.line + 1)
        start = types.Position(line=line, character=rng.randint(0, 12))
        end = types.Position(line=line + rng.randint(0, 2), character=rng.randint(0, 12))
        if (end.line, end.character) < (start.line, start.character):
            start, end = end, start
        return types.Range(start=start, end=end), random_text(rng) + rng.choice(("", *BREAKS))
    if kind < 0.2 and len(block_starts) < MAX_BLOCKS:  # a new block (multi-line text)
        at = rng.choice([*block_starts, len(text)]) if text.endswith(BREAKS) or not text else rng.choice(block_starts or [0])
        here = position(text, at)
        return types.Range(start=here, end=here), new_block(rng)
    if kind < 0.3 and len(block_starts) > 1:  # delete a block (a range over lines)
        index = rng.randrange(len(block_starts))
        start = block_starts[index]
        end = block_starts[index + 1] if index + 1 < len(block_starts) else len(text)
        return types.Range(start=position(text, start), end=position(text, end)), ""
    spans = comment_spans(text)
    if spans:
        start, end = rng.choice(spans)
        first = rng.randint(start, end)
        last = rng.randint(first, end)
        new = "" if kind < 0.55 else random_text(rng)
        return types.Range(start=position(text, first), end=position(text, max(first, last))), new
    here = position(text, len(text))
    return types.Range(start=here, end=here), new_block(rng)


# ---- the session ----------------------------------------------------------------------------------


@pytest_lsp.fixture(config=ClientServerConfig(server_command=[sys.executable, "-m", "geolint", "lsp"]))
async def client(lsp_client: LanguageClient):  # type: ignore[no-untyped-def]
    yield
    await lsp_client.shutdown_session()


PULL = types.ClientCapabilities(
    text_document=types.TextDocumentClientCapabilities(
        diagnostic=types.DiagnosticClientCapabilities(dynamic_registration=False)
    )
)


async def server_text(client: LanguageClient, uri: str) -> Any:
    return await client.protocol.send_request_async("geolint/documentText", {"textDocument": {"uri": uri}})


def expected_diagnostics(text: str, path: Path) -> list[tuple[str, tuple[int, int], tuple[int, int]]]:
    """The linter's findings for `text` as LSP ranges; a column past a line's end means its end."""
    lines = LINE_BREAK.split(text)

    def lsp(line: int, column: int) -> tuple[int, int]:
        if line - 1 >= len(lines):
            return len(lines) - 1, utf16(lines[-1])
        return line - 1, utf16(lines[line - 1][: column - 1])

    return [
        (f.code, lsp(f.line, f.column), lsp(f.end_line, f.end_column))
        for f in api.lint_text(text, path, api.find_config(path.parent))
    ]


def got_diagnostics(items: Any) -> list[tuple[str, tuple[int, int], tuple[int, int]]]:
    return [(d.code, (d.range.start.line, d.range.start.character), (d.range.end.line, d.range.end.character)) for d in items]


EDITS = 3000
CHECK_EVERY = 4  # batches between linter comparisons (each costs a lint here and one in the server)


@pytest.mark.asyncio
async def test_random_incremental_edits_keep_the_server_text_and_its_fixes_sound(client: LanguageClient, tmp_path: Path) -> None:
    await client.initialize_session(
        types.InitializeParams(capabilities=PULL, initialization_options={"debounce": 0, "exposeDocumentText": True})
    )
    rng = random.Random(20261127)
    path = tmp_path / "edited.py"
    reference = new_document(rng)
    uri = path.as_uri()
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(text_document=types.TextDocumentItem(uri=uri, language_id="python", version=1, text=reference))
    )
    version, edits_sent, batches, checked, actions_applied = 1, 0, 0, 0, 0
    started = time.monotonic()
    while edits_sent < EDITS:
        if not parses(reference) and rng.random() < 0.5:  # start over, by an edit over the whole text
            changes = [(types.Range(start=types.Position(0, 0), end=position(reference, len(reference))), new_document(rng))]
        else:
            changes = [random_edit(rng, reference) for _ in range(rng.randint(1, 30))]
        # One didChange may carry several changes, each against the text the previous one left.
        grouped = rng.random() < 0.5
        events = []
        for edit_range, new_text in changes:
            reference = apply(reference, [(edit_range, new_text)])
            event = types.TextDocumentContentChangePartial(range=edit_range, text=new_text)
            if grouped:
                events.append(event)
            else:
                version += 1
                client.text_document_did_change(
                    types.DidChangeTextDocumentParams(
                        text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version), content_changes=[event]
                    )
                )
        if grouped:
            version += 1
            client.text_document_did_change(
                types.DidChangeTextDocumentParams(
                    text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version), content_changes=events
                )
            )
        edits_sent += len(changes)
        batches += 1
        assert await server_text(client, uri) == reference, f"text diverged after {edits_sent} edits"
        if batches % CHECK_EVERY:
            continue
        checked += 1
        report = await client.text_document_diagnostic_async(
            types.DocumentDiagnosticParams(text_document=types.TextDocumentIdentifier(uri=uri))
        )
        assert got_diagnostics(report.items) == expected_diagnostics(reference, path), f"after {edits_sent} edits"
        if not parses(reference):
            continue
        everything = types.Range(start=types.Position(0, 0), end=position(reference, len(reference)))
        only = None if checked % 3 else [types.CodeActionKind.QuickFix, FIX_ALL]
        actions = await client.text_document_code_action_async(
            types.CodeActionParams(
                text_document=types.TextDocumentIdentifier(uri=uri), range=everything, context=types.CodeActionContext(diagnostics=[], only=only)
            )
        )
        for action in actions or []:
            assert action.edit is not None
            fixed = apply(reference, [(e.range, e.new_text) for e in action.edit.changes[uri]])
            assert parses(fixed), f"{action.title!r} breaks the module after {edits_sent} edits:\n{fixed!r}"
            if action.kind == FIX_ALL:
                assert fixed == api.fix_text(reference, path, api.find_config(path.parent))[0]
            actions_applied += 1
    elapsed = time.monotonic() - started
    print(f"{edits_sent} edits in {batches} batches, {checked} linter comparisons, {actions_applied} code actions applied, {elapsed:.1f} s")
    assert checked >= 30 and actions_applied >= 30  # the comparisons really ran
    await asyncio.sleep(0)


@pytest.mark.asyncio
async def test_a_keystroke_after_a_form_feed_lands_where_the_editor_put_it(client: LanguageClient, tmp_path: Path) -> None:
    """The issue's reproducer: such a character in a comment, then one edit on a later line."""
    await client.initialize_session(types.InitializeParams(capabilities=PULL, initialization_options={"debounce": 0}))
    for number, separator in enumerate(NOT_BREAKS):
        await check_keystroke_after(client, tmp_path / f"paged{number}.py", separator)


async def check_keystroke_after(client: LanguageClient, path: Path, separator: str) -> None:
    text = (
        f"# section one{separator} section two\n"
        "def step(R_world_cam, normal_cam, t_world_cam):\n"
        "    return R_world_cam @ normal_cam\n"
    )
    uri = path.as_uri()
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(text_document=types.TextDocumentItem(uri=uri, language_id="python", version=1, text=text))
    )
    end_of_return = types.Position(line=2, character=len("    return R_world_cam @ normal_cam"))
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=2),
            content_changes=[types.TextDocumentContentChangePartial(range=types.Range(start=end_of_return, end=end_of_return), text=" + t_world_cam")],
        )
    )
    edited = text.replace("normal_cam\n", "normal_cam + t_world_cam\n")
    report = await client.text_document_diagnostic_async(
        types.DocumentDiagnosticParams(text_document=types.TextDocumentIdentifier(uri=uri))
    )
    assert got_diagnostics(report.items) == expected_diagnostics(edited, path)
    assert [d.code for d in report.items] == ["GEO101"]
    (diagnostic,) = report.items
    actions = await client.text_document_code_action_async(
        types.CodeActionParams(
            text_document=types.TextDocumentIdentifier(uri=uri),
            range=diagnostic.range,
            context=types.CodeActionContext(diagnostics=[diagnostic], only=[types.CodeActionKind.QuickFix]),
        )
    )
    fix = next(a for a in actions if a.title.startswith("Fix GEO101"))
    assert apply(edited, [(e.range, e.new_text) for e in fix.edit.changes[uri]]) == text
