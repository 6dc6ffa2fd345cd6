"""Reading LSP frames (`Content-Length: N\\r\\n\\r\\n` + N bytes of JSON) so that a bad one costs only itself.

pygls reads a header line only when it is exactly `Content-Length: N\\r\\n` and then trusts N:
after a frame whose length is missing, not a number, too small or too large, the rest of that
body and the next header run together on one "line" and are dropped, and so is every message
after them; a length of a terabyte makes it try to allocate a terabyte. Here:

- a frame starts wherever a `Content-Length: N` header block is found, so bytes that belong to
  no frame (a body cut short, a frame without a length) are skipped up to the next header;
- a body that turns out to contain the next header block was shorter than its length said (a
  JSON body cannot contain a raw CRLF CRLF after a `Content-Length` outside its strings), so it
  ends there and the next frame is read normally, without waiting for bytes that never come;
- a declared length above `max_body` is refused, and its bytes are skipped like any others.

The body of a bad frame is still handed on (it fails to parse and is logged); what matters is
that the messages after it are answered.
"""

from __future__ import annotations

import asyncio
import logging
import os
import re
import threading
from typing import Any, Callable

logger = logging.getLogger(__name__)

MAX_BODY_BYTES = 256 * 1024 * 1024
_HEADER_BLOCK = re.compile(rb"Content-Length[ \t]*:[ \t]*(\d{1,20})[ \t]*\r\n(?:[^\r\n]+\r\n)*\r\n")
_CHUNK = 1024 * 1024
_OVERLAP = 256  # bytes re-scanned at the seam between reads, for a header split across them


class FrameReader:
    """Frames from a stream of byte chunks; `next_body()` is None at the end of the stream."""

    def __init__(self, read_chunk: Callable[[], Any], max_body: int = MAX_BODY_BYTES) -> None:
        self._read_chunk = read_chunk  # an awaitable factory: the next chunk, b"" at the end
        self._buffer = bytearray()
        self._ended = False
        self.max_body = max_body
        self.skipped_bytes = 0  # bytes that belonged to no frame (for the log and tests)

    async def _fill(self) -> bool:
        if self._ended:
            return False
        chunk = await self._read_chunk()
        if not chunk:
            self._ended = True
            return False
        self._buffer += chunk
        return True

    def _skip(self, count: int) -> None:
        if count:
            self.skipped_bytes += count
            logger.warning("skipped %d bytes that belong to no LSP frame", count)
            del self._buffer[:count]

    async def next_body(self) -> bytes | None:
        while True:
            header = _HEADER_BLOCK.search(self._buffer)
            if header is None:
                # Keep only what could still be the start of a header.
                keep = self._buffer.rfind(b"Content-Length")
                self._skip(len(self._buffer) - _OVERLAP if keep < 0 and len(self._buffer) > _OVERLAP else max(keep, 0))
                if not await self._fill():
                    return None
                continue
            length, start, end = int(header.group(1)), header.start(), header.end()
            self._skip(start)  # (the match reads the buffer itself: take what it found first)
            del self._buffer[: end - start]
            if length > self.max_body:
                logger.warning("refused a frame of %d bytes (the limit is %d)", length, self.max_body)
                continue
            scanned = 0
            while len(self._buffer) < length:
                early = _HEADER_BLOCK.search(self._buffer, max(scanned - _OVERLAP, 0))
                if early is not None:  # the next frame began before this one's length was reached
                    logger.warning("a frame said %d bytes but the next one began after %d", length, early.start())
                    body = bytes(self._buffer[: early.start()])
                    del self._buffer[: early.start()]
                    return body
                scanned = len(self._buffer)
                if not await self._fill():
                    return None
            body = bytes(self._buffer[:length])
            del self._buffer[:length]
            return body


def stdin_chunks(stream_fd: int) -> Callable[[], "asyncio.Future[bytes]"]:
    """Chunks of a file descriptor, read by a daemon thread (it never holds up the exit)."""
    loop = asyncio.get_running_loop()
    queue: asyncio.Queue[bytes] = asyncio.Queue(maxsize=64)

    def pump() -> None:
        while True:
            try:
                chunk = os.read(stream_fd, _CHUNK)
            except OSError:
                chunk = b""
            asyncio.run_coroutine_threadsafe(queue.put(chunk), loop).result()
            if not chunk:
                return

    threading.Thread(target=pump, name="geolint-lsp-stdin", daemon=True).start()
    return lambda: asyncio.ensure_future(queue.get())
