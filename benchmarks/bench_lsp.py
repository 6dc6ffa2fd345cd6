"""How quickly `geolint lsp` answers an editor, on a small file and on a 5,000-line one.

Measured over stdio with pygls' client, as an editor would see it:
- open -> diagnostics, pushed (the editor does not pull) and pulled;
- code actions for one line with a finding (the menu an editor asks for on every cursor move),
  for the version that was linted and right after an edit (before the new lint is done);
- the fix-all resolved on demand (`codeAction/resolve`: a whole fix run);
- a small file pulled while the large one is being linted (it must not wait for it).

Run: `python benchmarks/bench_lsp.py [--repeats 3] [--functions 1000]`. Prints medians, in ms.
Each function of the generated module is 5 lines with a fixable GEO101 and a GEO201.
"""

from __future__ import annotations

import argparse
import asyncio
import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from lsprotocol import types
from pygls.lsp.client import LanguageClient

FUNCTION = (
    "\n\ndef step_{i}(R_world_cam, normal_cam, t_world_cam, T_world_base, p_cam):\n"
    "    normal_world = R_world_cam @ normal_cam + t_world_cam\n"
    "    return normal_world, T_world_base @ p_cam\n"
)
CLEAN = "def to_world(R_world_cam, normal_cam):\n    return R_world_cam @ normal_cam\n"
GEO101_LINE = 4  # 0-based line of the first function's GEO101


def source_with(functions: int) -> str:
    return "import numpy as np\n" + "".join(FUNCTION.format(i=i) for i in range(functions))


class Client(LanguageClient):
    def __init__(self) -> None:
        super().__init__("bench", "0")
        self.published: dict[str, asyncio.Event] = {}

        @self.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        def publish(params: types.PublishDiagnosticsParams) -> None:
            self.published.setdefault(params.uri, asyncio.Event()).set()


async def session(pull: bool) -> Client:
    client = Client()
    await client.start_io(sys.executable, "-m", "geolint", "lsp")
    capabilities = types.ClientCapabilities(
        text_document=types.TextDocumentClientCapabilities(
            diagnostic=types.DiagnosticClientCapabilities() if pull else None,
            code_action=types.CodeActionClientCapabilities(
                resolve_support=types.ClientCodeActionResolveOptions(properties=["edit"]), data_support=True
            ),
        )
    )
    await client.initialize_async(types.InitializeParams(capabilities=capabilities))
    client.initialized(types.InitializedParams())
    await asyncio.sleep(1.0)  # the lint workers start
    return client


async def close(client: Client) -> None:
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()


def open_doc(client: LanguageClient, uri: str, text: str) -> None:
    client.text_document_did_open(types.DidOpenTextDocumentParams(text_document=types.TextDocumentItem(uri, "python", 1, text)))


async def pull(client: LanguageClient, uri: str) -> Any:
    return await client.text_document_diagnostic_async(
        types.DocumentDiagnosticParams(text_document=types.TextDocumentIdentifier(uri=uri))
    )


async def actions(client: LanguageClient, uri: str) -> Any:
    return await client.text_document_code_action_async(
        types.CodeActionParams(
            text_document=types.TextDocumentIdentifier(uri=uri),
            range=types.Range(start=types.Position(GEO101_LINE, 0), end=types.Position(GEO101_LINE, 60)),
            context=types.CodeActionContext(diagnostics=[]),
        )
    )


def ms(started: float) -> float:
    return (time.perf_counter() - started) * 1000


async def measure(folder: Path, functions: int, repeats: int, fix_all: bool = True) -> dict[str, list[float]]:
    timings: dict[str, list[float]] = {}
    big_text = source_with(functions)
    lines = len(big_text.splitlines())

    def record(what: str, value: float) -> None:
        timings.setdefault(what, []).append(value)
        print(f"  {what}: {value:.1f} ms", flush=True)  # as it comes: a loaded machine is slow

    pusher, puller = await session(pull=False), await session(pull=True)
    try:
        for repeat in range(repeats):
            small = (folder / f"small{repeat}.py").as_uri()
            started = time.perf_counter()
            open_doc(puller, small, source_with(10))
            await pull(puller, small)
            record("open -> pulled diagnostics, 51 lines", ms(started))

            uri = (folder / f"pushed{repeat}.py").as_uri()
            started = time.perf_counter()
            open_doc(pusher, uri, big_text)
            await pusher.published.setdefault(uri, asyncio.Event()).wait()
            record(f"open -> pushed diagnostics, {lines} lines", ms(started))
            for _ in range(5):
                started = time.perf_counter()
                await actions(pusher, uri)
                record(f"code actions for one line, {lines} lines (linted version)", ms(started))
            here = types.Position(lines - 1, 0)
            pusher.text_document_did_change(
                types.DidChangeTextDocumentParams(
                    text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=2),
                    content_changes=[types.TextDocumentContentChangePartial(range=types.Range(here, here), text="# edit\n")],
                )
            )
            started = time.perf_counter()
            menu = await actions(pusher, uri)
            record(f"code actions for one line, {lines} lines (right after an edit)", ms(started))
            if fix_all:
                lazy = next(a for a in menu if a.kind == "source.fixAll.geolint")
                started = time.perf_counter()
                await pusher.code_action_resolve_async(lazy)
                record(f"fix-all resolved on demand, {lines} lines", ms(started))
            pusher.text_document_did_close(types.DidCloseTextDocumentParams(types.TextDocumentIdentifier(uri)))

            big = (folder / f"pulled{repeat}.py").as_uri()
            other = (folder / f"other{repeat}.py").as_uri()
            started = time.perf_counter()
            open_doc(puller, big, big_text)
            big_request = asyncio.ensure_future(pull(puller, big))
            await asyncio.sleep(0.05)
            open_doc(puller, other, CLEAN)
            small_started = time.perf_counter()
            await pull(puller, other)
            record(f"small file pulled while the {lines}-line file lints", ms(small_started))
            await big_request
            record(f"open -> pulled diagnostics, {lines} lines", ms(started))
    finally:
        await close(pusher)
        await close(puller)
    return timings


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--functions", type=int, default=1000, help="5 lines each (1000: a 5,001-line file)")
    parser.add_argument("--no-fix-all", action="store_true", help="skip resolving the fix-all (a whole fix run)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        timings = asyncio.run(measure(Path(folder), args.functions, args.repeats, fix_all=not args.no_fix_all))
    print(f"{'what':66} {'median ms':>10}  (of)")
    for what, values in timings.items():
        print(f"{what:66} {statistics.median(values):10.1f}  ({len(values)})")


if __name__ == "__main__":
    main()
