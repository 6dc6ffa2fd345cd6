"""The language server: lint open documents through `geolint.api` and report over LSP.

- Diagnostics on open, on change (debounced) and on save. They are pushed
  (`textDocument/publishDiagnostics`) to clients that cannot pull, and always answered when
  pulled (`textDocument/diagnostic`), so an editor never shows them twice.
- Code actions: each fixable finding's fix (QuickFix), "ignore GEOxxx for this line", and
  `source.fixAll.geolint` (safe fixes only, through `api.fix_text`).
- Linting runs in worker threads, never on the protocol loop, so a large file does not freeze
  the editor; a result for an outdated version of a document is thrown away.
- Nothing the client sends can stop the server: a bad request gets an error answer, a file that
  does not parse gets geolint's GEO000 finding, an unknown URI gets no diagnostics.

Initialization options (all optional): `{"debounce": seconds}` (default 0.3).
"""

from __future__ import annotations

import asyncio
import functools
import logging
import traceback
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Sequence
from urllib.parse import urlparse

from lsprotocol import types
from pygls.lsp.server import LanguageServer
from pygls.uris import to_fs_path
from pygls.workspace import TextDocument

from geolint import api
from geolint._version import __version__
from geolint.engine import SYNTAX_ERROR
from geolint.lint_types import Config, Edit, Finding
from geolint.lsp.actions import FIX_ALL_KIND, changed_region_edit, ignore_edit
from geolint.lsp.configs import ConfigCache
from geolint.lsp.diagnostics import SOURCE, to_diagnostic
from geolint.lsp.positions import from_lsp_position, split_lines, to_lsp_range
from geolint.lsp.protocol import TolerantLanguageServerProtocol

logger = logging.getLogger(__name__)

DEFAULT_DEBOUNCE_SECONDS = 0.3
CONFIG_FILE = "pyproject.toml"


@dataclass(frozen=True)
class LintResult:
    """What one lint of one document version gave; code actions reuse it."""

    version: int | None
    source: str
    findings: tuple[Finding, ...]


class GeolintLanguageServer(LanguageServer):
    def __init__(self) -> None:
        super().__init__(
            "geolint",
            __version__,
            text_document_sync_kind=types.TextDocumentSyncKind.Incremental,
            protocol_cls=TolerantLanguageServerProtocol,
        )
        self.configs = ConfigCache()
        self.lint_pool = ThreadPoolExecutor(max_workers=2, thread_name_prefix="geolint-lint")
        self.debounce = DEFAULT_DEBOUNCE_SECONDS
        self.pending: dict[str, asyncio.Task[None]] = {}
        self.results: dict[str, LintResult] = {}
        # uri -> (text, fixed text): editors ask for code actions on every cursor move.
        self.fixed: dict[str, tuple[str, str]] = {}
        self.reported_config_errors: set[str] = set()

    def report_server_error(self, error: Exception, source: Any) -> None:
        # pygls pops up "Error in server" for anything unexpected; a person typing should never see
        # that for a message their editor garbled, so it goes to the client's log instead.
        logger.error("server error (%s): %s", getattr(source, "__name__", source), error)
        try:
            self.window_log_message(types.LogMessageParams(type=types.MessageType.Error, message=f"geolint: {error}"))
        except Exception:  # the connection itself is gone
            pass

    # ---- what the client can do -----------------------------------------------------------------

    def client_pulls_diagnostics(self) -> bool:
        text_document = self.client_capabilities.text_document
        return text_document is not None and text_document.diagnostic is not None

    def client_refreshes_diagnostics(self) -> bool:
        workspace = self.client_capabilities.workspace
        return bool(workspace and workspace.diagnostics and workspace.diagnostics.refresh_support)

    # ---- documents, configs, linting ------------------------------------------------------------

    def document_path(self, uri: str) -> Path | None:
        """The file a URI names, or None for URIs that are not files (untitled:, garbage)."""
        if urlparse(uri).scheme != "file":
            return None
        path = to_fs_path(uri)
        return Path(path) if path else None

    def config_for(self, path: Path | None) -> Config:
        folder = path.parent if path is not None else Path(self.workspace.root_path or ".")
        try:
            return self.configs.config_for(folder)
        except Exception as error:  # a broken pyproject.toml: say so once, lint with the defaults
            message = f"geolint: cannot use the configuration near {folder}: {error}"
            if message not in self.reported_config_errors:
                self.reported_config_errors.add(message)
                self.window_show_message(types.ShowMessageParams(type=types.MessageType.Error, message=message))
            return Config()

    def open_document(self, uri: str) -> TextDocument | None:
        """The open document, or the file on disk for a file URI, or None for an unknown URI."""
        document = self.workspace.text_documents.get(uri)
        if document is not None:
            return document
        path = self.document_path(uri)
        if path is None or not path.is_file():
            return None
        return self.workspace.get_text_document(uri)

    async def lint(self, uri: str) -> LintResult | None:
        """Lint the current text of `uri` in a worker thread; None if it cannot be linted."""
        document = self.open_document(uri)
        if document is None:
            return None
        try:
            source = document.source
        except (OSError, ValueError) as error:  # unreadable, or not text (UnicodeDecodeError)
            logger.warning("cannot read %s: %s", uri, error)
            return None
        version = document.version
        cached = self.results.get(uri)
        if cached is not None and cached.version == version and cached.source == source:
            return cached
        path = self.document_path(uri)
        config = self.config_for(path)
        loop = asyncio.get_running_loop()
        try:
            findings = await loop.run_in_executor(
                self.lint_pool, api.lint_text, source, str(path) if path else uri, config
            )
        except Exception:  # the API promises not to raise for bad code; if it does, keep the editor alive
            self.window_log_message(
                types.LogMessageParams(
                    type=types.MessageType.Error, message=f"geolint failed on {uri}:\n{traceback.format_exc()}"
                )
            )
            return None
        result = LintResult(version, source, tuple(findings))
        if uri in self.workspace.text_documents:  # remember open documents only
            self.results[uri] = result
        return result

    def diagnostics_for(self, uri: str, result: LintResult) -> list[types.Diagnostic]:
        document = self.workspace.get_text_document(uri)
        lines = split_lines(result.source)
        return [to_diagnostic(finding, lines, document.position_codec) for finding in result.findings]

    async def lint_and_publish(self, uri: str) -> None:
        result = await self.lint(uri)
        if result is None:
            return
        document = self.workspace.text_documents.get(uri)
        if document is None or document.version != result.version:
            return  # closed, or changed while we linted: the newer lint will publish
        self.text_document_publish_diagnostics(
            types.PublishDiagnosticsParams(uri=uri, version=result.version, diagnostics=self.diagnostics_for(uri, result))
        )

    def schedule(self, uri: str, delay: float) -> None:
        """(Re)start linting `uri` after `delay` seconds, replacing a lint that is still waiting."""
        if self.client_pulls_diagnostics():
            return  # the client asks when it wants them
        waiting = self.pending.pop(uri, None)
        if waiting is not None and not waiting.done():
            waiting.cancel()

        async def later() -> None:
            if delay:
                await asyncio.sleep(delay)
            await self.lint_and_publish(uri)

        task = asyncio.ensure_future(later())
        self.pending[uri] = task
        task.add_done_callback(functools.partial(self._forget, uri))

    def _forget(self, uri: str, task: asyncio.Task[None]) -> None:
        if self.pending.get(uri) is task:
            del self.pending[uri]
        if not task.cancelled() and task.exception() is not None:
            logger.error("linting %s failed: %r", uri, task.exception())

    def config_changed(self) -> None:
        """A pyproject.toml changed: forget configs and results, lint open documents again."""
        self.configs.clear()
        self.results.clear()
        self.fixed.clear()
        self.reported_config_errors.clear()
        if self.client_pulls_diagnostics():
            if self.client_refreshes_diagnostics():
                self.workspace_diagnostic_refresh(None)
            return
        for uri in list(self.workspace.text_documents):
            self.schedule(uri, 0)

    # ---- code actions ---------------------------------------------------------------------------

    def workspace_edit(self, uri: str, source: str, edits: Sequence[Edit]) -> types.WorkspaceEdit:
        document = self.workspace.get_text_document(uri)
        lines = split_lines(source)
        text_edits = [
            types.TextEdit(
                range=to_lsp_range(lines, document.position_codec, e.line, e.column, e.end_line, e.end_column),
                new_text=e.content,
            )
            for e in edits
        ]
        return types.WorkspaceEdit(changes={uri: text_edits})

    def replace_text_edit(self, uri: str, old: str, new: str) -> types.WorkspaceEdit:
        """One edit turning `old` into `new`, covering only the part that changed (the cursor stays put)."""
        return self.workspace_edit(uri, old, [changed_region_edit(old, new)])


server = GeolintLanguageServer()


@server.feature(types.INITIALIZE)
def initialize(ls: GeolintLanguageServer, params: types.InitializeParams) -> None:
    options = params.initialization_options
    if isinstance(options, dict):
        debounce = options.get("debounce")
        if isinstance(debounce, (int, float)) and 0 <= debounce <= 10:
            ls.debounce = float(debounce)


@server.feature(types.INITIALIZED)
async def initialized(ls: GeolintLanguageServer, params: types.InitializedParams) -> None:
    # Ask the client to tell us when any pyproject.toml changes, so the config is re-read.
    workspace = ls.client_capabilities.workspace
    watched = workspace.did_change_watched_files if workspace else None
    if watched is not None and watched.dynamic_registration:
        registration = types.Registration(
            id="geolint-pyproject-watcher",
            method=types.WORKSPACE_DID_CHANGE_WATCHED_FILES,
            register_options=types.DidChangeWatchedFilesRegistrationOptions(
                watchers=[types.FileSystemWatcher(glob_pattern=f"**/{CONFIG_FILE}")]
            ),
        )
        try:
            await ls.client_register_capability_async(types.RegistrationParams(registrations=[registration]))
        except Exception as error:  # the client said no: configs are still re-read by modification time
            logger.info("file watcher registration refused: %s", error)


@server.feature(types.TEXT_DOCUMENT_DID_OPEN)
def did_open(ls: GeolintLanguageServer, params: types.DidOpenTextDocumentParams) -> None:
    ls.schedule(params.text_document.uri, 0)


@server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
def did_change(ls: GeolintLanguageServer, params: types.DidChangeTextDocumentParams) -> None:
    ls.schedule(params.text_document.uri, ls.debounce)


@server.feature(types.TEXT_DOCUMENT_DID_SAVE)
def did_save(ls: GeolintLanguageServer, params: types.DidSaveTextDocumentParams) -> None:
    if Path(params.text_document.uri).name == CONFIG_FILE:
        ls.config_changed()
        return
    ls.schedule(params.text_document.uri, 0)


@server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
def did_close(ls: GeolintLanguageServer, params: types.DidCloseTextDocumentParams) -> None:
    uri = params.text_document.uri
    waiting = ls.pending.pop(uri, None)
    if waiting is not None:
        waiting.cancel()
    ls.results.pop(uri, None)
    ls.fixed.pop(uri, None)
    if not ls.client_pulls_diagnostics():
        ls.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=[]))


@server.feature(types.WORKSPACE_DID_CHANGE_WATCHED_FILES)
def did_change_watched_files(ls: GeolintLanguageServer, params: types.DidChangeWatchedFilesParams) -> None:
    if any(Path(urlparse(change.uri).path).name == CONFIG_FILE for change in params.changes):
        ls.config_changed()


@server.feature(types.WORKSPACE_DID_CHANGE_CONFIGURATION)
def did_change_configuration(ls: GeolintLanguageServer, params: types.DidChangeConfigurationParams) -> None:
    ls.config_changed()


@server.feature(
    types.TEXT_DOCUMENT_DIAGNOSTIC,
    types.DiagnosticOptions(identifier=SOURCE, inter_file_dependencies=False, workspace_diagnostics=False),
)
async def pull_diagnostics(
    ls: GeolintLanguageServer, params: types.DocumentDiagnosticParams
) -> types.RelatedFullDocumentDiagnosticReport:
    uri = params.text_document.uri
    result = await ls.lint(uri)
    items = ls.diagnostics_for(uri, result) if result is not None else []
    return types.RelatedFullDocumentDiagnosticReport(items=items)


def _overlaps(finding: Finding, first: tuple[int, int], last: tuple[int, int]) -> bool:
    return (finding.line, finding.column) <= last and first <= (finding.end_line, finding.end_column)


def _wants(only: Sequence[str] | None, kind: str) -> bool:
    # `only` lists kinds or their parents: "source" asks for "source.fixAll.geolint" too.
    return only is None or any(kind == k or kind.startswith(f"{k}.") for k in only)


@server.feature(
    types.TEXT_DOCUMENT_CODE_ACTION,
    types.CodeActionOptions(
        code_action_kinds=[types.CodeActionKind.QuickFix, FIX_ALL_KIND], resolve_provider=False
    ),
)
async def code_actions(ls: GeolintLanguageServer, params: types.CodeActionParams) -> list[types.CodeAction] | None:
    uri = params.text_document.uri
    if uri not in ls.workspace.text_documents:
        return None
    result = await ls.lint(uri)
    if result is None:
        return None
    document = ls.workspace.get_text_document(uri)
    lines = split_lines(result.source)
    first = from_lsp_position(lines, document.position_codec, params.range.start)
    last = from_lsp_position(lines, document.position_codec, params.range.end)
    only = params.context.only
    actions: list[types.CodeAction] = []
    if _wants(only, types.CodeActionKind.QuickFix):
        for finding in result.findings:
            if not _overlaps(finding, first, last):
                continue
            diagnostic = to_diagnostic(finding, lines, document.position_codec)
            if finding.fix is not None:
                unsafe = " (unsafe)" if finding.fix.applicability == "unsafe" else ""
                title = finding.fix.description or "apply the fix"
                actions.append(
                    types.CodeAction(
                        title=f"Fix {finding.code}: {title}{unsafe}",
                        kind=types.CodeActionKind.QuickFix,
                        diagnostics=[diagnostic],
                        is_preferred=finding.fix.applicability == "safe",
                        edit=ls.workspace_edit(uri, result.source, finding.fix.edits),
                    )
                )
            # A syntax error is fixed, not silenced.
            suppress = None if finding.code == SYNTAX_ERROR else ignore_edit(result.source, finding.line, finding.code)
            if suppress is not None:
                actions.append(
                    types.CodeAction(
                        title=f"Ignore {finding.code} for this line",
                        kind=types.CodeActionKind.QuickFix,
                        diagnostics=[diagnostic],
                        edit=ls.workspace_edit(uri, result.source, [suppress]),
                    )
                )
    if _wants(only, FIX_ALL_KIND) and (only is not None or any(f.fix for f in result.findings)):
        fixed = await _fix_all(ls, uri, result)
        if fixed is not None and fixed != result.source:
            actions.append(
                types.CodeAction(
                    title="geolint: fix all safe fixes",
                    kind=FIX_ALL_KIND,
                    edit=ls.replace_text_edit(uri, result.source, fixed),
                )
            )
    return actions


async def _fix_all(ls: GeolintLanguageServer, uri: str, result: LintResult) -> str | None:
    cached = ls.fixed.get(uri)
    if cached is not None and cached[0] == result.source:
        return cached[1]
    path = ls.document_path(uri)
    config = ls.config_for(path)
    loop = asyncio.get_running_loop()
    try:
        fixed, _remaining = await loop.run_in_executor(
            ls.lint_pool, lambda: api.fix_text(result.source, str(path) if path else uri, config, unsafe=False)
        )
    except Exception:
        ls.window_log_message(
            types.LogMessageParams(type=types.MessageType.Error, message=f"geolint fix failed:\n{traceback.format_exc()}")
        )
        return None
    if uri in ls.workspace.text_documents:
        ls.fixed[uri] = (result.source, fixed)
    return fixed
