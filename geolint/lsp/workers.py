"""Lint in worker processes that can be stopped.

A lint of a large file takes seconds. A thread cannot be interrupted, so a request the editor has
cancelled (or a lint of a version the user has already typed past) would keep a core busy to the
end. Each worker here is a `python -m geolint.lsp.worker` process; stopping its job kills it and
starts a fresh one. A worker that dies on its own (a crash in a native parser) takes only that
lint with it.
"""

from __future__ import annotations

import asyncio
import logging
import pickle
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from typing import IO, Any

logger = logging.getLogger(__name__)


class WorkerFailed(Exception):
    """The job raised in the worker, or the worker died; the message says which."""


class _Worker:
    def __init__(self) -> None:
        self.process = subprocess.Popen(
            [sys.executable, "-m", "geolint.lsp.worker"],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=None,  # the server's stderr: the editor's log
        )

    def call(self, request: tuple[str, tuple[Any, ...], dict[str, Any]]) -> tuple[str, Any]:
        """Send one job and wait for its answer (in a thread; EOFError when the worker is killed)."""
        stdin: IO[bytes] = self.process.stdin  # type: ignore[assignment]
        stdout: IO[bytes] = self.process.stdout  # type: ignore[assignment]
        try:
            pickle.dump(request, stdin, protocol=pickle.HIGHEST_PROTOCOL)
            stdin.flush()
        except (BrokenPipeError, OSError) as error:
            raise EOFError(str(error)) from error
        return pickle.load(stdout)  # type: ignore[no-any-return]

    def kill(self) -> None:
        if self.process.poll() is None:
            self.process.kill()
        self.process.wait()
        for stream in (self.process.stdin, self.process.stdout):
            if stream is not None:
                try:
                    stream.close()
                except OSError:
                    pass


def _retrieve(job: "asyncio.Future[Any]") -> None:
    if not job.cancelled():
        job.exception()


class WorkerPool:
    """`size` worker processes; `run` waits for a free one. Cancelling `run` stops the job."""

    def __init__(self, size: int = 2) -> None:
        self.size = size
        self._idle: list[_Worker] = []
        self._all: set[_Worker] = set()  # idle and busy: all are killed on close
        self._free = asyncio.Semaphore(size)
        self._threads = ThreadPoolExecutor(max_workers=size, thread_name_prefix="geolint-worker-io")
        self.killed = 0  # jobs stopped before they finished (for tests and logs)

    def warm_up(self) -> None:
        """Start the workers now, so the first lint does not wait for Python to start."""
        while len(self._idle) < self.size:
            self._idle.append(self._new())

    def _new(self) -> _Worker:
        worker = _Worker()
        self._all.add(worker)
        return worker

    def _discard(self, worker: _Worker) -> None:
        worker.kill()
        self._all.discard(worker)

    async def run(self, function: str, *args: Any, **kwargs: Any) -> Any:
        async with self._free:
            worker = self._idle.pop() if self._idle else self._new()
            loop = asyncio.get_running_loop()
            job = loop.run_in_executor(self._threads, worker.call, (function, args, kwargs))
            job.add_done_callback(_retrieve)  # a killed job ends in EOFError that nobody awaits
            try:
                status, value = await asyncio.shield(job)
            except asyncio.CancelledError:
                self.killed += 1
                self._discard(worker)  # unblocks the thread waiting on the worker (EOFError)
                self._idle.append(self._new())
                raise
            except (EOFError, pickle.UnpicklingError, OSError) as error:
                code = worker.process.poll()
                self._discard(worker)
                self._idle.append(self._new())
                raise WorkerFailed(f"the lint worker died (exit code {code}): {error!r}") from error
            self._idle.append(worker)
        if status != "ok":
            raise WorkerFailed(value)
        return value

    def close(self) -> None:
        for worker in list(self._all):
            self._discard(worker)
        self._idle.clear()
        self._threads.shutdown(wait=False)
