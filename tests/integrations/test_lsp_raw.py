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
