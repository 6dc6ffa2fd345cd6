"""The language server's lint worker (`python -m geolint.lsp.worker`), a long-lived process, driven over
its pipes as the server drives it."""

from __future__ import annotations

import pickle
import subprocess
import sys
from pathlib import Path

from geolint.lint_types import Config

NAMES_ONLY = "def f(T_world_cam, p_base):\n    return T_world_cam @ p_base\n"


def test_a_declaration_edited_in_another_file_reaches_the_next_lint(tmp_path: Path) -> None:
    """Names are frame evidence while poses.py states the convention; the same worker must see it stop."""
    (tmp_path / "setup.py").write_text("")
    poses = tmp_path / "poses.py"
    poses.write_text('T_world_base = RigidTransform(R, t, from_frame="base", to_frame="world")\n')
    planner = str(tmp_path / "planner.py")
    Path(planner).write_text(NAMES_ONLY)  # an open document is a file of its project
    worker = subprocess.Popen(
        [sys.executable, "-m", "geolint.lsp.worker"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, cwd=tmp_path
    )
    assert worker.stdin is not None and worker.stdout is not None

    def codes() -> list[str]:
        pickle.dump(("lint_text", (NAMES_ONLY, planner, Config()), {}), worker.stdin)
        worker.stdin.flush()
        status, findings = pickle.load(worker.stdout)
        assert status == "ok", findings
        return [finding.code for finding in findings]

    try:
        assert codes() == ["GEO201"]
        poses.write_text("T_world_base = load()\n")
        assert codes() == []
    finally:
        worker.stdin.close()
        worker.wait(timeout=30)
