"""Worker processes (issue 13): a worker that dies costs one file, not the run, and no worker outlives
the `geolint` process that started it (a CI timeout, Ctrl-C, SIGTERM from pre-commit, SIGKILL).

The real CLI runs in a subprocess; the tests look for its children in /proc.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests.conftest import DECLARES_DST_FIRST

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")

# Fault injection for the crash test: the CLI with engine.lint_bytes made to segfault on a marker,
# the way a native extension would (workers are forked, so they inherit the patch).
CRASHING_LAUNCHER = """
import os, signal, sys
import geolint.engine as engine
original = engine.lint_bytes
def lint_bytes(data, *args, **kwargs):
    if b"CRASH_WORKER_HERE" in data:
        os.kill(os.getpid(), signal.SIGSEGV)
    return original(data, *args, **kwargs)
engine.lint_bytes = lint_bytes
from geolint.cli import main
sys.exit(main(sys.argv[1:]))
"""


def test_a_worker_that_dies_costs_its_file_only(cli_real):
    for index in range(12):
        cli_real.write(f"f{index:02}.py", "p_world = T_world_cam @ p_base\n" + DECLARES_DST_FIRST)
    cli_real.write("crash.py", "CRASH_WORKER_HERE = 1\n")
    result = subprocess.run(
        [sys.executable, "-c", CRASHING_LAUNCHER, "check", "--no-cache", "--jobs", "2", "--format", "json"],
        cwd=cli_real.project,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert result.returncode == 2, result.stderr
    assert "crash.py" in result.stderr and "SIGSEGV" in result.stderr
    paths = sorted({finding["path"] for finding in json.loads(result.stdout)})
    assert paths == [f"f{index:02}.py" for index in range(12)]  # every other file was checked


def children_of(pid: int) -> set[int]:
    found = set()
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:
            continue
        # "pid (comm) state ppid ...": comm may hold spaces, so split after the last ')'
        fields = stat.rsplit(")", 1)[1].split()
        if int(fields[1]) == pid and fields[0] != "Z":
            found.add(int(entry.name))
    return found


def alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


@pytest.mark.parametrize("how", [signal.SIGTERM, signal.SIGINT, signal.SIGKILL], ids=lambda s: s.name)
def test_workers_exit_with_their_parent(cli_real, how):
    body = "".join(f"p{i}_world = T_world_cam @ p{i}_cam\nn{i} = R @ normal + t\n" for i in range(150))
    for index in range(120):
        cli_real.write(f"m{index:03}.py", body)
    process = subprocess.Popen(
        [sys.executable, "-m", "geolint", "check", "--no-cache", "--jobs", "2", "-q"],
        cwd=cli_real.project,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        deadline = time.monotonic() + 60
        workers: set[int] = set()
        while len(workers) < 2 and time.monotonic() < deadline and process.poll() is None:
            workers |= children_of(process.pid)
            time.sleep(0.05)
        assert len(workers) >= 2, "the run never started two workers"
        time.sleep(0.5)  # let them get busy
        assert process.poll() is None, "the run ended before it could be interrupted; give it more work"
        process.send_signal(how)
        process.wait(timeout=30)
        deadline = time.monotonic() + 15
        while any(alive(pid) for pid in workers) and time.monotonic() < deadline:
            time.sleep(0.1)
        orphans = [pid for pid in workers if alive(pid)]
        for pid in orphans:  # clean up before failing
            os.kill(pid, signal.SIGKILL)
        assert not orphans, f"workers {orphans} outlived their parent ({how.name})"
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()


def test_a_worker_keeps_to_its_project_while_it_has_files_left():
    from geolint.workers import NO_GROUP, _Pending

    pending = _Pending(["big", "small", "big", "small", "big"])  # the order api gives: largest project first
    first = pending.take(NO_GROUP)
    second = pending.take(NO_GROUP)
    assert (first, second) == ((0, "big"), (1, "small"))  # the second worker starts on a project nobody holds
    assert pending.take("big") == (2, "big")
    assert pending.take("big") == (4, "big")  # not 3: that one is the other worker's project's
    assert pending.take("big") == (3, "small")  # its project done, it helps with the other
    assert pending.take("small") is None


def test_results_come_back_in_the_given_order_whatever_the_groups():
    from geolint.workers import run_in_workers

    items = list(range(40))
    results = run_in_workers(items, _square, _crashed_item, 2, group=lambda item: item % 3)
    assert results == [item * item for item in items]


def _square(item: int) -> int:
    return item * item


def _crashed_item(item: int, why: str) -> int:
    return -1
