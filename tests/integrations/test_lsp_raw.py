"""`geolint lsp` fed raw bytes no well-behaved client would send: broken JSON, wrong parameter
shapes, unknown methods. Every request still gets an answer and the server keeps serving.

(pytest-lsp's client only sends well-typed messages, so this test speaks JSON-RPC by hand.)
"""

from __future__ import annotations

import json
import subprocess
import sys
import threading
from pathlib import Path
from queue import Empty, Queue
from typing import Any

import pytest

TIMEOUT = 20


def frame(body: bytes) -> bytes:
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


def message(payload: dict[str, Any]) -> bytes:
    return frame(json.dumps(payload).encode("utf-8"))


class RawConnection:
    def __init__(self) -> None:
        self.process = subprocess.Popen(
            [sys.executable, "-m", "geolint", "lsp"],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
        )
        self.messages: Queue[dict[str, Any]] = Queue()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self) -> None:
        stdout = self.process.stdout
        assert stdout is not None
        while True:
            length = None
            while True:
                line = stdout.readline()
                if not line:
                    return
                if line in (b"\r\n", b"\n"):
                    break
                name, _, value = line.decode("ascii").partition(":")
                if name.lower() == "content-length":
                    length = int(value)
            if length is not None:
                self.messages.put(json.loads(stdout.read(length)))

    def send(self, data: bytes) -> None:
        assert self.process.stdin is not None
        self.process.stdin.write(data)
        self.process.stdin.flush()

    def response(self, request_id: int) -> dict[str, Any]:
        while True:
            try:
                received = self.messages.get(timeout=TIMEOUT)
            except Empty:
                raise AssertionError(f"no response to request {request_id}") from None
            if received.get("id") == request_id and "method" not in received:
                return received


@pytest.fixture
def raw() -> Any:
    connection = RawConnection()
    yield connection
    connection.process.kill()
    connection.process.wait(timeout=TIMEOUT)


def test_garbage_gets_errors_and_the_server_keeps_serving(raw: RawConnection, tmp_path: Path) -> None:
    document = tmp_path / "robot.py"
    document.write_text("x = (\n", encoding="utf-8")
    raw.send(message({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}}))
    assert "capabilities" in raw.response(1)["result"]
    raw.send(message({"jsonrpc": "2.0", "method": "initialized", "params": {}}))

    raw.send(frame(b"{this is not json"))  # a broken body
    raw.send(message({"jsonrpc": "2.0", "id": 2, "method": "textDocument/diagnostic", "params": {"textDocument": 42}}))
    raw.send(message({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": 7}}}))
    raw.send(message({"jsonrpc": "2.0", "id": 3, "method": "geolint/noSuchMethod", "params": {}}))
    raw.send(message({"jsonrpc": "2.0", "method": "textDocument/didChange", "params": None}))
    raw.send(
        message(
            {
                "jsonrpc": "2.0",
                "id": 4,
                "method": "textDocument/codeAction",
                "params": {"textDocument": {"uri": document.as_uri()}, "range": "everything", "context": {}},
            }
        )
    )

    assert "error" in raw.response(2)
    assert raw.response(3)["error"]["code"] == -32601  # method not found
    assert "error" in raw.response(4)

    # After all that, a well-formed pull is answered with the linter's finding.
    raw.send(
        message(
            {
                "jsonrpc": "2.0",
                "id": 5,
                "method": "textDocument/diagnostic",
                "params": {"textDocument": {"uri": document.as_uri()}},
            }
        )
    )
    items = raw.response(5)["result"]["items"]
    assert [item["code"] for item in items] == ["GEO000"]

    raw.send(message({"jsonrpc": "2.0", "id": 6, "method": "shutdown", "params": None}))
    assert raw.response(6)["result"] is None
    raw.send(message({"jsonrpc": "2.0", "method": "exit", "params": None}))
    assert raw.process.wait(timeout=TIMEOUT) == 0


def initialize(raw: RawConnection, capabilities: dict[str, Any] | None = None, **options: Any) -> None:
    raw.send(
        message(
            {
                "jsonrpc": "2.0",
                "id": 0,
                "method": "initialize",
                "params": {"capabilities": capabilities or {}, "initializationOptions": options},
            }
        )
    )
    assert "capabilities" in raw.response(0)["result"]
    raw.send(message({"jsonrpc": "2.0", "method": "initialized", "params": {}}))


def pull(request_id: int, uri: str) -> bytes:
    return message(
        {"jsonrpc": "2.0", "id": request_id, "method": "textDocument/diagnostic", "params": {"textDocument": {"uri": uri}}}
    )


def malformed_frames(uri: str) -> list[tuple[str, bytes]]:
    """Bad frames, each with a description. A pull follows each one in the test."""
    body = json.dumps({"jsonrpc": "2.0", "id": 999, "method": "textDocument/diagnostic", "params": {"textDocument": {"uri": uri}}}).encode()
    return [
        ("length not a number", b"Content-Length: abc\r\n\r\n" + body),
        ("negative length", b"Content-Length: -5\r\n\r\n" + body),
        ("no length header", b"Content-Type: application/vscode-jsonrpc; charset=utf-8\r\n\r\n" + body),
        ("length too small", b"Content-Length: %d\r\n\r\n" % (len(body) - 9) + body),
        ("length too large", b"Content-Length: %d\r\n\r\n" % (len(body) + 500) + body),
        ("length of a terabyte", b"Content-Length: 1000000000000\r\n\r\n" + body),
        ("zero length", b"Content-Length: 0\r\n\r\n"),
        ("invalid JSON", frame(b'{"jsonrpc": "2.0", "id": 998, "method": ')),
        ("invalid UTF-8", frame(b'{"jsonrpc": "2.0", "method": "\xff\xfe"}')),
        ("JSON that is not an object", frame(b"[1, 2, 3]")),
        ("a bare JSON string", frame(b'"textDocument/diagnostic"')),
        ("JSON null", frame(b"null")),
        ("a huge notification", message({"jsonrpc": "2.0", "method": "geolint/junk", "params": {"blob": "x" * 20_000_000}})),
        ("a huge body that is not JSON", frame(b"\x00" * 5_000_000)),
        ("bytes outside any frame", b"\r\n\r\ngarbage\r\n\r\n"),
    ]


def test_every_malformed_frame_costs_only_itself(raw: RawConnection, tmp_path: Path) -> None:
    document = tmp_path / "robot.py"
    document.write_text("x = (\n", encoding="utf-8")
    uri = document.as_uri()
    initialize(raw)
    for number, (what, bad) in enumerate(malformed_frames(uri), start=1):
        raw.send(bad + pull(number, uri))
        answer = raw.response(number)
        assert [item["code"] for item in answer["result"]["items"]] == ["GEO000"], what
    # A huge request that is well formed is answered too.
    raw.send(message({"jsonrpc": "2.0", "id": 100, "method": "geolint/noSuchMethod", "params": {"blob": "y" * 20_000_000}}))
    assert raw.response(100)["error"]["code"] == -32601


def rss_kib(pid: int) -> int:
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    raise AssertionError("no VmRSS")


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="reads the server's RSS from /proc")
def test_memory_stays_flat_over_5000_edits_of_one_document(raw: RawConnection, tmp_path: Path) -> None:
    """The server process's resident memory after 1,000 edits and after 5,000 (lints run meanwhile)."""
    initialize(raw, debounce=0.05, maxDelay=0.2)
    uri = (tmp_path / "typed.py").as_uri()
    text = "def step(R_world_cam, normal_cam, t_world_cam):\n    return R_world_cam @ normal_cam + t_world_cam\n# \n"
    raw.send(
        message(
            {
                "jsonrpc": "2.0",
                "method": "textDocument/didOpen",
                "params": {"textDocument": {"uri": uri, "languageId": "python", "version": 1, "text": text}},
            }
        )
    )
    column = 2
    samples = {}
    for version in range(2, 5002):
        # Type into the last comment; every 50th keystroke deletes what was typed (the text stays small).
        if version % 50:
            change = {"range": {"start": {"line": 2, "character": column}, "end": {"line": 2, "character": column}}, "text": "\u00e9\U0001f916\f"[version % 3]}
            column += 2 if version % 3 == 1 else 1
        else:
            change = {"range": {"start": {"line": 2, "character": 2}, "end": {"line": 2, "character": column}}, "text": ""}
            column = 2
        raw.send(
            message(
                {
                    "jsonrpc": "2.0",
                    "method": "textDocument/didChange",
                    "params": {"textDocument": {"uri": uri, "version": version}, "contentChanges": [change]},
                }
            )
        )
        if version in (1001, 5001):
            raw.send(message({"jsonrpc": "2.0", "id": version, "method": "geolint/noSuchMethod", "params": {}}))
            raw.response(version)  # every edit before it has been handled
            samples[version] = rss_kib(raw.process.pid)
    growth = samples[5001] - samples[1001]
    print(f"server RSS after 1,000 edits {samples[1001]} KiB, after 5,000 {samples[5001]} KiB")
    assert growth < 1024, f"the server grew by {growth} KiB over 4,000 edits"
