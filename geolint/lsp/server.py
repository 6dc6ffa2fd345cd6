"""The language server: lint open documents through `geolint.api` and report over LSP.

- The server's copy of each document counts lines the LSP way (`document.py`), so incremental
  edits, positions and fixes agree with the editor whatever characters the file holds.
- Diagnostics are pushed (`textDocument/publishDiagnostics`) to clients that cannot pull, and
  answered when pulled (`textDocument/diagnostic`), never both. Either way one schedule decides
  when a document is linted: `debounce` seconds after the last change, but no later than
  `maxDelay` seconds after the first change not yet linted, so diagnostics keep coming while the
  user types without pause. At most one lint per document runs at a time.
- Linting runs in worker processes (`workers.py`), never on the protocol loop. A pull that the
  client cancels (`$/cancelRequest`) stops the lint it was waiting for, if nothing else waits.
  A result for an older version is moved onto the current text (`document.TextChange`):
  what the user has edited since is dropped, the rest is shown where it now is.
- Code actions come from the last lint, so they are answered at once even on large files:
  each fixable finding's fix (QuickFix), "ignore GEOxxx for this line", and
  `source.fixAll.geolint` (safe fixes, through `api.fix_text`), which is computed only when the
  client resolves it (`codeAction/resolve`) or asks for that kind explicitly.
- Config: the pyproject.toml files that could apply are checked (modification time) on every
  request and notification, and every `configPollInterval` seconds while documents are open; a
  client that can watch files is asked to report every `**/pyproject.toml` change
  (`workspace/didChangeWatchedFiles`, registered dynamically). When a config really changed,
  open documents are linted again and their diagnostics published (pushing clients), or the
  client is asked to pull again (`workspace/diagnostic/refresh`), with no edit of a document.
- Nothing the client sends can stop the server: a bad request gets an error answer, a file that
  does not parse gets geolint's GEO000 finding, an unknown URI gets no diagnostics.

Initialization options (all optional): `{"debounce": seconds, "maxDelay": seconds,
"configPollInterval": seconds}` (defaults 0.3, 1.0 and 2.0; a poll interval of 0 turns polling off).
"""

from __future__ import annotations

import asyncio
import json
import logging
import sys
import threading
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, BinaryIO, Sequence
from urllib.parse import urlparse

from lsprotocol import types
from pygls.exceptions import JsonRpcMethodNotFound
from pygls.io_ import StdoutWriter
from pygls.lsp.server import LanguageServer
from pygls.uris import to_fs_path
from pygls.workspace import TextDocument

from geolint._version import __version__
from geolint.engine import SYNTAX_ERROR
from geolint.lint_types import Config, Edit, Finding
from geolint.lsp.actions import FIX_ALL_KIND, changed_region_edit, ignore_edit
from geolint.lsp.configs import CONFIG_FILE, ConfigCache
from geolint.lsp.diagnostics import SOURCE, to_diagnostic
from geolint.lsp.framing import FrameReader, stdin_chunks
from geolint.lsp.document import LspWorkspace, TextChange
from geolint.lsp.positions import from_lsp_position, split_lines, to_lsp_range
from geolint.lsp.protocol import TolerantLanguageServerProtocol
from geolint.lsp.workers import WorkerFailed, WorkerPool

logger = logging.getLogger(__name__)

DEFAULT_DEBOUNCE_SECONDS = 0.3
DEFAULT_MAX_DELAY_SECONDS = 1.0
# How often the configs of open documents are checked without any message from the client: an
# editor that does not watch files then still sees a pyproject.toml edit within this time.
DEFAULT_CONFIG_POLL_SECONDS = 2.0
# A request only tests use, to compare the server's copy of a document with the editor's.
DOCUMENT_TEXT_REQUEST = "geolint/documentText"


@dataclass(frozen=True)
class LintResult:
    """What one lint of one document text gave; diagnostics and code actions reuse it."""

    version: int | None
    source: str
    findings: tuple[Finding, ...]
    config: Config


@dataclass
class _Track:
    """The lint schedule and last result of one open document."""

    result: LintResult | None = None
    first_pending: float | None = None  # loop time of the first change no lint has started on
    ready_at: float = 0.0  # loop time the last change has settled (its debounce is over)
    timer: asyncio.TimerHandle | None = None
    running: asyncio.Task[LintResult | None] | None = None
    waiters: int = 0  # pull requests waiting for a lint
    finished: asyncio.Event = field(default_factory=asyncio.Event)
    moved: tuple[int | None, LintResult, LintResult] | None = None  # (version, result, moved result)


class GeolintLanguageServer(LanguageServer):
    def __init__(self) -> None:
        super().__init__(
            "geolint",
            __version__,
            text_document_sync_kind=types.TextDocumentSyncKind.Incremental,
            protocol_cls=TolerantLanguageServerProtocol,
        )
        self.configs = ConfigCache()
        self.acted_on_generation = 0
        self.workers = WorkerPool(2)
        self.debounce = DEFAULT_DEBOUNCE_SECONDS
        self.max_delay = DEFAULT_MAX_DELAY_SECONDS
        self.config_poll_interval = DEFAULT_CONFIG_POLL_SECONDS
        self.config_poller: asyncio.Task[None] | None = None
        self.expose_document_text = False
        self.tracks: dict[str, _Track] = {}
        # uri -> (text, fixed text): computing fix-all is a full fix run.
        self.fixed: dict[str, tuple[str, str]] = {}
        self.reported_config_errors: set[str] = set()

    def _start_io_async(self, stdin: BinaryIO | None = None, stdout: BinaryIO | None = None) -> None:
        """pygls' stdio loop, with frames read by `framing.FrameReader` (a bad frame costs only itself)."""
        stop = self._stop_event = threading.Event()
        self.protocol.set_writer(StdoutWriter(stdout or sys.stdout.buffer))
        stdin_fd = (stdin or sys.stdin.buffer).fileno()

        async def serve() -> None:
            frames = FrameReader(stdin_chunks(stdin_fd))
            while not stop.is_set():
                body = await frames.next_body()
                if body is None:
                    break
                try:
                    message = json.loads(body, object_hook=self.protocol.structure_message)
                    self.protocol.handle_message(message)
                except Exception as error:
                    logger.warning("ignored an unreadable message (%d bytes): %r", len(body), error)

        try:
            asyncio.run(serve())
        except BrokenPipeError:
            logger.error("the connection to the client is lost; shutting down")
        except (KeyboardInterrupt, SystemExit):
            pass
        finally:
            self.close()
            self.shutdown()

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

    def client_resolves_code_action_edits(self) -> bool:
        text_document = self.client_capabilities.text_document
        code_action = text_document.code_action if text_document else None
        resolve = code_action.resolve_support if code_action else None
        return resolve is not None and "edit" in resolve.properties

    # ---- documents and configs ------------------------------------------------------------------

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

    def open_text(self, uri: str) -> TextDocument | None:
        return self.workspace.text_documents.get(uri)

    def check_configs(self, force: bool = False) -> None:
        """Act on config files that really changed: lint again, or ask a pulling client to pull."""
        if force:
            self.configs.reload()
        else:
            self.configs.check()
        if self.configs.generation == self.acted_on_generation:
            return
        self.acted_on_generation = self.configs.generation
        self.reported_config_errors.clear()
        self.fixed.clear()
        if self.client_pulls_diagnostics():
            if self.client_refreshes_diagnostics():
                self.workspace_diagnostic_refresh(None)
            return
        for uri, track in self.tracks.items():
            if track.result is not None and track.result.config != self.config_for(self.document_path(uri)):
                self.changed(uri, delay=0)

    # ---- linting --------------------------------------------------------------------------------

    async def lint_text(self, uri: str, version: int | None, source: str) -> LintResult | None:
        path = self.document_path(uri)
        config = self.config_for(path)
        try:
            findings = await self.workers.run("lint_text", source, str(path) if path else uri, config)
        except WorkerFailed as error:  # the API promises not to raise for bad code; keep the editor alive
            self.window_log_message(
                types.LogMessageParams(type=types.MessageType.Error, message=f"geolint failed on {uri}:\n{error}")
            )
            return LintResult(version, source, (), config)
        return LintResult(version, source, tuple(findings), config)

    async def lint_file(self, uri: str) -> LintResult | None:
        """A file that is not open (a pull for a file on disk): lint what is on disk, uncached."""
        path = self.document_path(uri)
        if path is None or not path.is_file():
            return None
        try:
            source = self.workspace.get_text_document(uri).source
        except (OSError, ValueError) as error:  # unreadable, or not text (UnicodeDecodeError)
            logger.warning("cannot read %s: %s", uri, error)
            return None
        return await self.lint_text(uri, None, source)

    def is_fresh(self, uri: str, result: LintResult | None, version: int | None) -> bool:
        """Whether `result` covers `version` (or later) of the document, with the config in force now."""
        if result is None or result.version is None or version is None or result.version < version:
            return False
        return result.config == self.config_for(self.document_path(uri))

    def changed(self, uri: str, delay: float | None = None) -> None:
        """`uri` needs a lint: after `delay` (default: the debounce) unless it changes again."""
        track = self.tracks.setdefault(uri, _Track())
        now = asyncio.get_running_loop().time()
        track.ready_at = now + (self.debounce if delay is None else delay)
        if track.first_pending is None:
            track.first_pending = now
        if not self.client_pulls_diagnostics() or track.waiters:
            self.plan(uri)

    def plan(self, uri: str) -> None:
        """Start a lint of `uri` when it is due: when the last change has settled, but at most
        `max_delay` after the first unlinted one. A running lint finishes first (it plans the next)."""
        track = self.tracks.get(uri)
        if track is None or track.running is not None:
            return
        loop = asyncio.get_running_loop()
        if track.first_pending is None:
            due = loop.time()
        else:
            due = min(track.ready_at, track.first_pending + self.max_delay)
        if track.timer is not None:
            track.timer.cancel()
        track.timer = loop.call_at(due, self.start_lint, uri)

    def start_lint(self, uri: str) -> None:
        track = self.tracks.get(uri)
        document = self.open_text(uri)
        if track is None or document is None:
            return
        track.timer = None
        track.first_pending = None
        running = asyncio.ensure_future(self.lint_text(uri, document.version, document.source))
        track.running = running
        running.add_done_callback(lambda task: self.lint_finished(uri, task))

    def lint_finished(self, uri: str, task: asyncio.Task[LintResult | None]) -> None:
        track = self.tracks.get(uri)
        if track is None or track.running is not task:
            return
        track.running = None
        if task.cancelled():  # stopped: what it would have covered is pending again
            if track.first_pending is None:
                track.first_pending = asyncio.get_running_loop().time()
        elif task.exception() is not None:
            logger.error("linting %s failed: %r", uri, task.exception())
        elif task.result() is not None:
            track.result = task.result()
            if not self.client_pulls_diagnostics():
                self.publish(uri)
        finished, track.finished = track.finished, asyncio.Event()
        finished.set()
        if track.first_pending is not None and (not self.client_pulls_diagnostics() or track.waiters):
            self.plan(uri)

    def stop(self, uri: str) -> None:
        """Stop the waiting or running lint of `uri` (no one wants it any more)."""
        track = self.tracks.get(uri)
        if track is None:
            return
        if track.timer is not None:
            track.timer.cancel()
            track.timer = None
        if track.running is not None:
            track.running.cancel()

    def current_result(self, uri: str) -> LintResult | None:
        """The last result of an open document, moved onto its current text if it is older."""
        track = self.tracks.get(uri)
        document = self.open_text(uri)
        if track is None or track.result is None or document is None:
            return None
        result = track.result
        if result.version == document.version:
            return result
        if track.moved is not None and track.moved[0] == document.version and track.moved[1] is result:
            return track.moved[2]
        source = document.source
        change = TextChange(result.source, source)
        findings = tuple(moved for f in result.findings if (moved := change.move_finding(f)) is not None)
        moved_result = LintResult(document.version, source, findings, result.config)
        track.moved = (document.version, result, moved_result)
        return moved_result

    async def wait_for_result(self, uri: str) -> LintResult | None:
        """A result covering the version of `uri` open now (debounced like pushes); cancellable."""
        track = self.tracks.setdefault(uri, _Track())
        document = self.open_text(uri)
        target = document.version if document is not None else None
        track.waiters += 1
        try:
            while not self.is_fresh(uri, track.result, target):
                if self.open_text(uri) is None or self.tracks.get(uri) is not track:
                    return None
                finished = track.finished
                if track.running is None and track.timer is None:
                    if track.first_pending is None:  # nothing changed, yet not fresh (the config changed)
                        self.changed(uri, delay=0)
                    self.plan(uri)
                await finished.wait()
            return self.current_result(uri)
        finally:
            track.waiters -= 1
            if track.waiters == 0 and self.client_pulls_diagnostics():
                self.stop(uri)

    def diagnostics_for(self, uri: str, result: LintResult) -> list[types.Diagnostic]:
        codec = self.workspace.position_codec
        lines = split_lines(result.source)
        return [to_diagnostic(finding, lines, codec, uri) for finding in result.findings]

    def publish(self, uri: str) -> None:
        result = self.current_result(uri)
        if result is None:
            return
        self.text_document_publish_diagnostics(
            types.PublishDiagnosticsParams(uri=uri, version=result.version, diagnostics=self.diagnostics_for(uri, result))
        )

    # ---- code actions ---------------------------------------------------------------------------

    def workspace_edit(self, uri: str, source: str, edits: Sequence[Edit]) -> types.WorkspaceEdit:
        codec = self.workspace.position_codec
        lines = split_lines(source)
        text_edits = [
            types.TextEdit(
                range=to_lsp_range(lines, codec, e.line, e.column, e.end_line, e.end_column),
                new_text=e.content,
            )
            for e in edits
        ]
        return types.WorkspaceEdit(changes={uri: text_edits})

    def replace_text_edit(self, uri: str, old: str, new: str) -> types.WorkspaceEdit:
        """One edit turning `old` into `new`, covering only the part that changed (the cursor stays put)."""
        return self.workspace_edit(uri, old, [changed_region_edit(old, new)])

    async def fix_all(self, uri: str, source: str) -> str | None:
        cached = self.fixed.get(uri)
        if cached is not None and cached[0] == source:
            return cached[1]
        path = self.document_path(uri)
        config = self.config_for(path)
        try:
            fixed, _remaining = await self.workers.run("fix_text", source, str(path) if path else uri, config, unsafe=False)
        except WorkerFailed as error:
            self.window_log_message(types.LogMessageParams(type=types.MessageType.Error, message=f"geolint fix failed:\n{error}"))
            return None
        if uri in self.workspace.text_documents:
            self.fixed[uri] = (source, fixed)
        return fixed  # type: ignore[no-any-return]

    def start_config_polling(self) -> None:
        """Check the open documents' configs every `config_poll_interval` seconds (0: never)."""
        if self.config_poll_interval <= 0 or self.config_poller is not None:
            return

        async def poll() -> None:
            while True:
                await asyncio.sleep(self.config_poll_interval)
                if not self.tracks:
                    continue
                try:
                    self.check_configs()
                except Exception as error:  # a config that cannot be read is reported when used
                    logger.warning("config check failed: %r", error)

        self.config_poller = asyncio.ensure_future(poll())

    def close(self) -> None:
        if self.config_poller is not None:
            self.config_poller.cancel()
            self.config_poller = None
        for uri in list(self.tracks):
            self.stop(uri)
        self.workers.close()


server = GeolintLanguageServer()


@server.feature(types.INITIALIZE)
def initialize(ls: GeolintLanguageServer, params: types.InitializeParams) -> None:
    # pygls made its Workspace before this handler runs; ours splits lines the LSP way.
    ls.protocol._workspace = LspWorkspace.like(ls.workspace)
    options = params.initialization_options
    if isinstance(options, dict):
        debounce = options.get("debounce")
        if isinstance(debounce, (int, float)) and 0 <= debounce <= 10:
            ls.debounce = float(debounce)
        max_delay = options.get("maxDelay")
        if isinstance(max_delay, (int, float)) and 0 <= max_delay <= 60:
            ls.max_delay = float(max_delay)
        ls.expose_document_text = options.get("exposeDocumentText") is True
        poll = options.get("configPollInterval")
        if isinstance(poll, (int, float)) and 0 <= poll <= 600:
            ls.config_poll_interval = float(poll)
    ls.workers.warm_up()


@server.feature(types.INITIALIZED)
async def initialized(ls: GeolintLanguageServer, params: types.InitializedParams) -> None:
    # Ask the client to tell us when any pyproject.toml changes (configs are also checked by mtime,
    # on every message and by the poller, for clients that cannot watch files or files outside the workspace).
    ls.start_config_polling()
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
        except Exception as error:  # the client said no: configs are still checked by modification time
            logger.info("file watcher registration refused: %s", error)


@server.feature(types.SHUTDOWN)
def shutdown(ls: GeolintLanguageServer, params: None) -> None:
    ls.close()


@server.feature(types.TEXT_DOCUMENT_DID_OPEN)
def did_open(ls: GeolintLanguageServer, params: types.DidOpenTextDocumentParams) -> None:
    uri = params.text_document.uri
    ls.stop(uri)
    ls.tracks[uri] = _Track()
    ls.check_configs()
    ls.changed(uri, delay=0)


@server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
def did_change(ls: GeolintLanguageServer, params: types.DidChangeTextDocumentParams) -> None:
    if params.text_document.uri in ls.workspace.text_documents:
        ls.changed(params.text_document.uri)


@server.feature(types.TEXT_DOCUMENT_DID_SAVE)
def did_save(ls: GeolintLanguageServer, params: types.DidSaveTextDocumentParams) -> None:
    uri = params.text_document.uri
    if Path(urlparse(uri).path).name == CONFIG_FILE:
        ls.check_configs(force=True)
        return
    ls.check_configs()
    if uri in ls.tracks:
        ls.changed(uri, delay=0)


@server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
def did_close(ls: GeolintLanguageServer, params: types.DidCloseTextDocumentParams) -> None:
    uri = params.text_document.uri
    ls.stop(uri)
    track = ls.tracks.pop(uri, None)
    if track is not None:
        track.finished.set()  # waiting pulls see the document is gone
    ls.fixed.pop(uri, None)
    if not ls.client_pulls_diagnostics():
        ls.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=[]))


@server.feature(types.WORKSPACE_DID_CHANGE_WATCHED_FILES)
def did_change_watched_files(ls: GeolintLanguageServer, params: types.DidChangeWatchedFilesParams) -> None:
    if any(Path(urlparse(change.uri).path).name == CONFIG_FILE for change in params.changes):
        ls.check_configs(force=True)


@server.feature(types.WORKSPACE_DID_CHANGE_CONFIGURATION)
def did_change_configuration(ls: GeolintLanguageServer, params: types.DidChangeConfigurationParams) -> None:
    # geolint reads no editor settings; this only re-checks the config files (usually: no change).
    ls.check_configs()


@server.feature(
    types.TEXT_DOCUMENT_DIAGNOSTIC,
    types.DiagnosticOptions(identifier=SOURCE, inter_file_dependencies=False, workspace_diagnostics=False),
)
async def pull_diagnostics(
    ls: GeolintLanguageServer, params: types.DocumentDiagnosticParams
) -> types.RelatedFullDocumentDiagnosticReport:
    uri = params.text_document.uri
    ls.check_configs()
    if uri in ls.workspace.text_documents:
        result = await ls.wait_for_result(uri)
    else:
        result = await ls.lint_file(uri)
    items = ls.diagnostics_for(uri, result) if result is not None else []
    return types.RelatedFullDocumentDiagnosticReport(items=items)


def _overlaps(finding: Finding, first: tuple[int, int], last: tuple[int, int]) -> bool:
    return (finding.line, finding.column) <= last and first <= (finding.end_line, finding.end_column)


def _wants(only: Sequence[str] | None, kind: str) -> bool:
    # `only` lists kinds or their parents: "source" asks for "source.fixAll.geolint" too.
    return only is None or any(kind == k or kind.startswith(f"{k}.") for k in only)


FIX_ALL_TITLE = "geolint: fix all safe fixes"


@server.feature(
    types.TEXT_DOCUMENT_CODE_ACTION,
    types.CodeActionOptions(code_action_kinds=[types.CodeActionKind.QuickFix, FIX_ALL_KIND], resolve_provider=True),
)
async def code_actions(ls: GeolintLanguageServer, params: types.CodeActionParams) -> list[types.CodeAction] | None:
    uri = params.text_document.uri
    if uri not in ls.workspace.text_documents:
        return None
    ls.check_configs()
    result = ls.current_result(uri)
    if result is None:  # never linted yet: wait for the first lint
        result = await ls.wait_for_result(uri)
        if result is None:
            return None
    codec = ls.workspace.position_codec
    lines = split_lines(result.source)
    first = from_lsp_position(lines, codec, params.range.start)
    last = from_lsp_position(lines, codec, params.range.end)
    only = params.context.only
    actions: list[types.CodeAction] = []
    if _wants(only, types.CodeActionKind.QuickFix):
        for finding in result.findings:
            if not _overlaps(finding, first, last):
                continue
            diagnostic = to_diagnostic(finding, lines, codec, params.text_document.uri)
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
    explicit = only is not None and _wants(only, FIX_ALL_KIND)
    fixable = any(f.fix is not None and f.fix.applicability == "safe" for f in result.findings)
    if _wants(only, FIX_ALL_KIND) and (explicit or fixable):
        if ls.client_resolves_code_action_edits():
            # The fix-all is a whole fix run: computed only if the user picks it (codeAction/resolve).
            actions.append(types.CodeAction(title=FIX_ALL_TITLE, kind=FIX_ALL_KIND, data={"uri": uri}))
        elif explicit:  # asked for by name (a key binding, on save): worth the wait
            action = await _resolved_fix_all(ls, uri)
            if action is not None:
                actions.append(action)
        # else: a menu on a client that cannot resolve: not offered rather than computed every time
    return actions


async def _resolved_fix_all(ls: GeolintLanguageServer, uri: str) -> types.CodeAction | None:
    document = ls.open_text(uri)
    if document is None:
        return None
    source = document.source
    fixed = await ls.fix_all(uri, source)
    if fixed is None or fixed == source:
        return None
    return types.CodeAction(title=FIX_ALL_TITLE, kind=FIX_ALL_KIND, edit=ls.replace_text_edit(uri, source, fixed))


@server.feature(types.CODE_ACTION_RESOLVE)
async def resolve_code_action(ls: GeolintLanguageServer, action: types.CodeAction) -> types.CodeAction:
    data = action.data
    uri = data.get("uri") if isinstance(data, dict) else None
    if action.kind != FIX_ALL_KIND or not isinstance(uri, str) or action.edit is not None:
        return action
    resolved = await _resolved_fix_all(ls, uri)
    action.edit = resolved.edit if resolved is not None else types.WorkspaceEdit(changes={uri: []})
    return action


@server.feature(DOCUMENT_TEXT_REQUEST)
def document_text(ls: GeolintLanguageServer, params: Any) -> str | None:
    """The server's copy of an open document (only with the `exposeDocumentText` option: for tests)."""
    if not ls.expose_document_text:
        raise JsonRpcMethodNotFound.of(DOCUMENT_TEXT_REQUEST)
    text_document = getattr(params, "text_document", None) or getattr(params, "textDocument", None)
    uri = getattr(text_document, "uri", None)
    document = ls.open_text(uri) if isinstance(uri, str) else None
    return document.source if document is not None else None
