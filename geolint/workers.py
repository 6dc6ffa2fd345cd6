"""Worker processes for linting many files: a file that kills its worker is reported, not the run.

Each worker takes one file at a time. When a worker dies (a segfault in a native extension, the
out-of-memory killer), the file it held gets an error result naming the signal, a fresh worker
takes its place, and every other file is still checked. Workers exit with their parent: on Linux
the kernel sends them SIGTERM when the parent dies (`PR_SET_PDEATHSIG`), elsewhere a watchdog
thread notices the parent is gone; an interrupted parent terminates them on its way out.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
import sys
import threading
import time
from collections import deque
from multiprocessing.connection import Connection, wait
from typing import Any, Callable, Hashable, Sequence, TypeVar

Item = TypeVar("Item")
Result = TypeVar("Result")

_PR_SET_PDEATHSIG = 1
_WATCHDOG_SECONDS = 1.0


def run_in_workers(
    items: Sequence[Item],
    work: Callable[[Item], Result],
    crashed: Callable[[Item, str], Result],
    jobs: int,
    done: Callable[[int], None] | None = None,
    group: Callable[[Item], Hashable] | None = None,
) -> list[Result]:
    """``work(item)`` for every item across ``jobs`` processes, results in the items' order.

    ``crashed(item, why)`` makes the result of an item whose worker died; ``done(index)`` is called
    as each item finishes. ``work`` and the items must be picklable when processes are spawned.
    Items are handed out in the given order, except that a worker keeps to the ``group`` of its last
    item while that group has items left (what a worker parsed for one file, its neighbours reuse).
    """
    methods = multiprocessing.get_all_start_methods()
    context = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
    results: dict[int, Result] = {}
    pending = _Pending([group(item) for item in items] if group is not None else [None] * len(items))
    workers: list[_Worker] = []
    try:
        for _ in range(min(jobs, len(items))):
            workers.append(_Worker(context, work, items))
        for worker in workers:
            worker.give(pending, items)
        while any(worker.busy is not None for worker in workers):
            ready = wait([worker.connection for worker in workers if worker.busy is not None]
                         + [worker.process.sentinel for worker in workers if worker.busy is not None])
            for index, worker in enumerate(workers):
                if worker.busy is None:
                    continue
                if worker.connection in ready or worker.process.sentinel in ready:
                    finished = worker.busy
                    try:
                        results[finished] = worker.connection.recv()
                    except Exception:  # EOF: the worker died holding this item
                        results[finished] = crashed(items[finished], worker.death())
                        worker.close()
                        worker = workers[index] = _Worker(context, work, items)
                    worker.busy = None
                    if done is not None:
                        done(finished)
                    worker.give(pending, items)
    finally:
        for worker in workers:
            worker.close()
    return [results[index] for index in range(len(items))]


NO_GROUP = object()  # a worker that holds no group yet (or any more)


class _Pending:
    """The items not handed out yet, by group, each group in the given order; groups in the order of
    their first item."""

    def __init__(self, groups: list[Hashable]) -> None:
        self._queues: dict[Hashable, deque[int]] = {}
        for index, key in enumerate(groups):
            self._queues.setdefault(key, deque()).append(index)
        self._held: dict[Hashable, int] = {}  # group -> how many workers are on it

    def take(self, previous: Hashable) -> tuple[int, Hashable] | None:
        """The next item for a worker whose last item was of group `previous` (`NO_GROUP`: it had none)."""
        if previous is not NO_GROUP:
            self._held[previous] -= 1
            queue = self._queues.get(previous)
            if queue:
                return self._hand_out(previous, queue)
        key = next((key for key in self._queues if not self._held.get(key)), NO_GROUP)  # one nobody holds
        if key is NO_GROUP:
            key = next(iter(self._queues), NO_GROUP)  # else help with a held one
        if key is NO_GROUP:
            return None
        return self._hand_out(key, self._queues[key])

    def _hand_out(self, key: Hashable, queue: deque[int]) -> tuple[int, Hashable]:
        index = queue.popleft()
        if not queue:
            del self._queues[key]
        self._held[key] = self._held.get(key, 0) + 1
        return index, key


class _Worker:
    """One worker process and the pipe to it; ``busy`` is the index of the item it holds.

    A forked worker starts with a copy of ``items`` and is sent only indices: a file's bytes and the
    config are not pickled through the pipe once per file.
    """

    def __init__(self, context: Any, work: Callable[[Any], Any], items: Sequence[Any]) -> None:
        self.connection, child_end = context.Pipe()
        self.forked = context.get_start_method() == "fork"
        known = items if self.forked else None
        self.process = context.Process(target=_serve, args=(child_end, work, os.getpid(), known), daemon=True)
        self.process.start()
        child_end.close()
        self.busy: int | None = None
        self.group: Hashable = NO_GROUP

    def give(self, pending: _Pending, items: Sequence[Any]) -> None:
        taken = pending.take(self.group)
        self.busy, self.group = taken if taken is not None else (None, NO_GROUP)
        if self.busy is not None:
            self.connection.send(self.busy if self.forked else items[self.busy])

    def death(self) -> str:
        """Why the process ended, in words (it has ended, or is about to)."""
        self.process.join(5)
        code = self.process.exitcode
        if code is not None and code < 0:
            try:
                name = signal.Signals(-code).name
            except ValueError:
                name = f"signal {-code}"
            return f"the worker process checking this file was killed by {name}"
        return f"the worker process checking this file exited unexpectedly (exit code {code})"

    def close(self) -> None:
        try:
            self.connection.close()
        except OSError:
            pass
        if self.process.is_alive():
            self.process.terminate()
            self.process.join(2)
            if self.process.is_alive():
                self.process.kill()
                self.process.join()


def _serve(connection: Connection, work: Callable[[Any], Any], parent: int, items: Sequence[Any] | None) -> None:
    """A worker's loop: take an item (or, forked with the items, its index), send its result, until the
    pipe closes or the parent is gone."""
    _exit_with_parent(parent)
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C reaches the parent, which ends us
    while True:
        try:
            received = connection.recv()
        except (EOFError, OSError):
            return
        connection.send(work(items[received] if items is not None else received))


def _exit_with_parent(parent: int) -> None:
    if sys.platform.startswith("linux"):
        try:
            import ctypes

            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(_PR_SET_PDEATHSIG, signal.SIGTERM, 0, 0, 0)
        except (OSError, AttributeError):
            pass
    if os.getppid() != parent:  # the parent died before the kernel was told to watch it
        os._exit(1)
    threading.Thread(target=_watch_parent, args=(parent,), daemon=True).start()


def _watch_parent(parent: int) -> None:
    while os.getppid() == parent:
        time.sleep(_WATCHDOG_SECONDS)
    os._exit(1)
