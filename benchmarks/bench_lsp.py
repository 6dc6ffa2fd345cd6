"""How quickly `geolint lsp` answers: open -> diagnostics for small and large files, and how long a
small file's pull waits while a large file is being linted (it must not wait for it).

Run: `python benchmarks/bench_lsp.py [--repeats 5]`. Prints medians over repeats, in milliseconds.
"""

from __future__ import annotations

import argparse
import asyncio
import statistics
import sys
import tempfile
import time
from pathlib import Path

from lsprotocol import types
from pygls.lsp.client import LanguageClient

FUNCTION = (
    "\n\ndef step_{i}(R_world_cam, normal_cam, t_world_cam, T_world_base, p_cam):\n"
    "    normal_world = R_world_cam @ normal_cam + t_world_cam\n"
    "    return normal_world, T_world_base @ p_cam\n"
)
CLEAN = "def to_world(R_world_cam, normal_cam):\n    return R_world_cam @ normal_cam\n"


def source_with(functions: int) -> str:
    return "import numpy as np\n" + "".join(FUNCTION.format(i=i) for i in range(functions))


async def session() -> LanguageClient:
    client = LanguageClient("bench", "0")
    await client.start_io(sys.executable, "-m", "geolint", "lsp")
    capabilities = types.ClientCapabilities(
        text_document=types.TextDocumentClientCapabilities(diagnostic=types.DiagnosticClientCapabilities())
    )
    await client.initialize_async(types.InitializeParams(capabilities=capabilities))
    client.initialized(types.InitializedParams())
    return client


async def pull(client: LanguageClient, uri: str) -> types.DocumentDiagnosticReport:
    return await client.text_document_diagnostic_async(
        types.DocumentDiagnosticParams(text_document=types.TextDocumentIdentifier(uri=uri))
    )


def open_doc(client: LanguageClient, uri: str, text: str, version: int) -> None:
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(text_document=types.TextDocumentItem(uri, "python", version, text))
    )


async def measure(folder: Path, repeats: int) -> dict[str, list[float]]:
    client = await session()
    timings: dict[str, list[float]] = {}
    try:
        for size in (10, 250, 1000):
            text = source_with(size)
            for repeat in range(repeats):
                uri = (folder / f"f{size}_{repeat}.py").as_uri()
                open_doc(client, uri, text, 1)
                started = time.perf_counter()
                report = await pull(client, uri)
                elapsed = (time.perf_counter() - started) * 1000
                assert len(report.items) >= size
                timings.setdefault(f"open + pull, {len(text.splitlines())} lines", []).append(elapsed)
        big_text = source_with(1000)
        for repeat in range(repeats):
            big, small = (folder / f"big{repeat}.py").as_uri(), (folder / f"small{repeat}.py").as_uri()
            open_doc(client, big, big_text, 1)
            open_doc(client, small, CLEAN, 1)
            started = time.perf_counter()
            big_request = asyncio.ensure_future(pull(client, big))
            await asyncio.sleep(0.01)
            await pull(client, small)
            small_elapsed = (time.perf_counter() - started) * 1000
            await big_request
            big_elapsed = (time.perf_counter() - started) * 1000
            big_lines = len(big_text.splitlines())
            timings.setdefault(f"small file pulled while a {big_lines}-line file lints", []).append(small_elapsed)
            timings.setdefault(f"... the {big_lines}-line file itself", []).append(big_elapsed)
    finally:
        await client.shutdown_async(None)
        client.exit(None)
        await client.stop()
    return timings


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        timings = asyncio.run(measure(Path(folder), args.repeats))
    print(f"{'what':52} {'median ms':>10}  (of {args.repeats})")
    for what, values in timings.items():
        print(f"{what:52} {statistics.median(values):10.1f}")


if __name__ == "__main__":
    main()
