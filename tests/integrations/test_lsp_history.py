"""The editor sees GEO401 too: the language server, driven over stdio by a real client (pytest-lsp),
lints an open copy against the fixes its repository's history holds (`history = true`), from the
same cache `geolint check` keeps."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
import pytest_lsp
from pytest_lsp import ClientServerConfig

from tests.integrations.conftest import RecordingClient
from tests.integrations.test_history import ENVIRONMENT, commit, fix, git
from tests.integrations.test_lsp_config_reload import CANNOT_WATCH, codes, eventually, make_client, open_doc, start


@pytest_lsp.fixture(config=ClientServerConfig(server_command=[sys.executable, "-m", "geolint", "lsp"], client_factory=make_client))
async def client(lsp_client: RecordingClient):  # type: ignore[no-untyped-def]
    yield
    await lsp_client.shutdown_session()


@pytest.mark.asyncio
async def test_an_open_copy_of_a_fixed_statement_gets_geo401(client: RecordingClient, tmp_path: Path) -> None:
    root = tmp_path / "gym"
    (root / "envs").mkdir(parents=True)
    git(root, "init", "-q", "-b", "main")
    git(root, "config", "user.email", "dev@example.com")
    git(root, "config", "user.name", "dev")
    (root / "pyproject.toml").write_text("[tool.geolint]\nhistory = true\n", encoding="utf-8")
    for name in ("mara_v0.py", "mara_v1.py"):
        (root / "envs" / name).write_text(ENVIRONMENT, encoding="utf-8")
    commit(root, "two environments")
    fix(root / "envs/mara_v0.py")
    commit(root, "fixes rew")
    await start(client, CANNOT_WATCH)
    copy = open_doc(client, root / "envs/mara_v1.py", ENVIRONMENT)
    fixed = open_doc(client, root / "envs/mara_v0.py", (root / "envs/mara_v0.py").read_text(encoding="utf-8"))
    await eventually(lambda: codes(client, copy) == ["GEO401"] and fixed in client.diagnostics)
    assert codes(client, fixed) == []
    message = client.diagnostics[copy][0].message
    assert "('fixes rew') fixed in envs/mara_v0.py:5" in message
    assert (root / ".geolint_cache" / "history-1000.json").is_file()  # mined once, kept for the next process
