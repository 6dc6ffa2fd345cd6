"""Every snippet of docs/editors.md, run as far as it can be without the editor itself.

Each editor snippet names a command; the test takes it from the snippet as written (JSON, TOML,
Lua or Emacs Lisp), starts it and completes an LSP handshake with it over stdio. The Neovim
snippets are also checked against the API each one says it needs, and the one the installed Neovim
is new enough for is run headless (Debian 12's 0.7 runs the 0.7 snippet); the VS Code note about
`${workspaceFolder}` is checked against the snippet.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

DOC = Path(__file__).resolve().parents[2] / "docs" / "editors.md"
FENCE = re.compile(r"^```(?P<language>[\w-]*)\n(?P<body>.*?)^```$", re.S | re.M)
HEADING = re.compile(r"^#{1,6} (.+)$", re.M)


def blocks() -> list[tuple[str, str, str, str]]:
    """(heading, language, body, the prose just above) of each fenced block."""
    text = DOC.read_text(encoding="utf-8")
    found = []
    for match in FENCE.finditer(text):
        headings = HEADING.findall(text[: match.start()])
        prose = text[: match.start()].rsplit("```", 1)[-1]
        found.append((headings[-1] if headings else "", match.group("language"), match.group("body"), prose))
    return found


def handshake(command: list[str]) -> dict[str, object]:
    """Start `command` as an editor would and initialize it; the server's capabilities."""
    executable = shutil.which(command[0]) or str(Path(sys.executable).parent / command[0])
    assert Path(executable).exists(), f"{command[0]} is not installed next to this Python"

    def frame(payload: dict[str, object]) -> bytes:
        body = json.dumps(payload).encode()
        return b"Content-Length: %d\r\n\r\n" % len(body) + body

    requests = (
        frame({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}})
        + frame({"jsonrpc": "2.0", "method": "initialized", "params": {}})
        + frame({"jsonrpc": "2.0", "id": 2, "method": "shutdown", "params": None})
        + frame({"jsonrpc": "2.0", "method": "exit", "params": None})
    )
    done = subprocess.run([executable, *command[1:]], input=requests, capture_output=True, timeout=120, check=False)
    assert done.returncode == 0, done.stderr.decode(errors="replace")
    first = done.stdout.split(b"\r\n\r\n", 1)[1]
    length = int(done.stdout.split(b"\r\n", 1)[0].split(b":")[1])
    return json.loads(first[:length])["result"]["capabilities"]  # type: ignore[no-any-return]


def command_of(language: str, body: str) -> list[str] | None:
    if language == "json":
        settings = json.loads(body)
        return [settings["glspc.server.command"], *settings["glspc.server.commandArguments"]]
    if language == "toml":
        server = tomllib.loads(body)["language-server"]["geolint"]
        return [server["command"], *server["args"]]
    if language == "lua":
        match = re.search(r"cmd = \{([^}]*)\}", body)
        return re.findall(r'"([^"]*)"', match.group(1)) if match else None
    if language == "elisp":
        match = re.search(r'\. \(("[^)]*)\)\)', body)
        return re.findall(r'"([^"]*)"', match.group(1)) if match else None
    return None


def test_every_editor_snippet_starts_a_working_server() -> None:
    started = {}
    for heading, language, body, _ in blocks():
        command = command_of(language, body)
        if command is None:
            continue
        assert not any("${" in part for part in command), f"{heading}: a variable the editor does not expand"
        key = tuple(command)
        if key not in started:
            started[key] = handshake(command)
        assert "codeActionProvider" in started[key], heading
    languages = {language for _, language, body, _ in blocks() if command_of(language, body)}
    assert languages >= {"json", "toml", "lua", "elisp"}


def test_the_install_line_and_help_run() -> None:
    (install,) = [body for heading, language, body, _ in blocks() if language == "sh"][:1]
    assert "[lsp]" in install
    done = subprocess.run([sys.executable, "-m", "geolint", "lsp", "--help"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0 and "--log-file" in done.stdout


# Neovim API by the version that introduced it.
NEOVIM_API = {
    "vim.lsp.config": (0, 11),
    "vim.lsp.enable": (0, 11),
    "vim.fs.root": (0, 10),
    "vim.lsp.start(": (0, 8),
    "vim.fs.find": (0, 8),
    "vim.fs.dirname": (0, 8),
    "nvim_create_autocmd": (0, 7),
}


def test_each_neovim_snippet_uses_only_the_api_of_the_version_it_names() -> None:
    checked = []
    for heading, language, body, prose in blocks():
        if language != "lua" or heading != "Neovim":
            continue
        version = re.search(r"Neovim (\d+)\.(\d+)", prose.strip().split("\n\n")[-1])
        assert version is not None, f"a Neovim snippet without its version: {body[:40]!r}"
        needs = (int(version.group(1)), int(version.group(2)))
        for api, since in NEOVIM_API.items():
            if api in body:
                assert since <= needs, f"the Neovim {needs} snippet uses {api} (new in {since})"
        checked.append(needs)
    assert (0, 7) in checked and (0, 8) in checked and (0, 11) in checked  # Debian 12 ships 0.7


def neovim_snippets() -> list[tuple[tuple[int, int], str]]:
    """(the version a Neovim snippet names, its Lua)."""
    found = []
    for heading, language, body, prose in blocks():
        version = re.search(r"Neovim (\d+)\.(\d+)", prose.strip().split("\n\n")[-1])
        if language == "lua" and heading == "Neovim" and version:
            found.append(((int(version.group(1)), int(version.group(2))), body))
    return found


def installed_neovim() -> tuple[int, int] | None:
    if shutil.which("nvim") is None:
        return None
    done = subprocess.run(["nvim", "--version"], capture_output=True, text=True, timeout=60, check=False)
    match = re.match(r"NVIM v(\d+)\.(\d+)", done.stdout)
    return (int(match.group(1)), int(match.group(2))) if match else None


# Appended to a snippet as the test's own init.lua: wait for geolint's diagnostics, write what Neovim has.
NEOVIM_PROBE = """
function GeolintProbe(out)
  vim.wait(60000, function() return #vim.diagnostic.get(0) > 0 end, 100)
  local lines = {}
  for _, client in pairs((vim.lsp.get_clients or vim.lsp.get_active_clients)({ bufnr = 0 })) do
    table.insert(lines, "client " .. client.name)
  end
  for _, d in ipairs(vim.diagnostic.get(0)) do
    table.insert(lines, string.format("diagnostic %d %s", d.lnum + 1, tostring(d.code)))
  end
  vim.fn.writefile(lines, out)
  vim.cmd("qa!")
end
"""


def test_the_neovim_snippet_for_the_installed_version_attaches_and_shows_findings(tmp_path: Path) -> None:
    """Every snippet the installed Neovim is new enough for, run headless as the user's init.lua."""
    version = installed_neovim()
    if version is None:
        pytest.skip("Neovim is not installed (apt-get install neovim)")
    runnable = [(needs, body) for needs, body in neovim_snippets() if needs <= version]
    assert runnable, f"no snippet for Neovim {version}"
    env = {**os.environ, "PATH": os.pathsep.join([str(Path(sys.executable).parent), os.environ.get("PATH", "")])}
    env["XDG_CONFIG_HOME"] = env["XDG_DATA_HOME"] = env["XDG_STATE_HOME"] = str(tmp_path / "xdg")  # no user config
    for index, (needs, body) in enumerate(runnable):
        project = tmp_path / f"project{index}"
        project.mkdir()
        (project / "pyproject.toml").write_text("[tool.geolint]\n", encoding="utf-8")
        (project / "buggy.py").write_text(
            "def normal_to_world(R_world_cam, t_world_cam, normal_cam):\n    return R_world_cam @ normal_cam + t_world_cam\n",
            encoding="utf-8",
        )
        init = tmp_path / f"init{index}.lua"
        init.write_text(body + NEOVIM_PROBE, encoding="utf-8")
        out = tmp_path / f"out{index}.txt"
        done = subprocess.run(
            ["nvim", "--headless", "-u", str(init), "buggy.py", "-c", f"lua GeolintProbe('{out}')"],
            cwd=project, env=env, capture_output=True, text=True, timeout=120, check=False, stdin=subprocess.DEVNULL,
        )  # fmt: skip
        seen = out.read_text(encoding="utf-8").splitlines() if out.exists() else []
        assert "client geolint" in seen, f"Neovim {needs} snippet: {seen} {done.stderr}"
        assert "diagnostic 2 GEO101" in seen, f"Neovim {needs} snippet: {seen} {done.stderr}"


def test_the_vscode_note_matches_the_snippet() -> None:
    text = DOC.read_text(encoding="utf-8")
    vscode = text[text.index("## VS Code") : text.index("## Neovim")]
    assert "does **not** expand `${workspaceFolder}`" in vscode


@pytest.mark.parametrize("section", ["## Emacs (eglot)", "## Helix", "## VS Code", "## Neovim"])
def test_each_editor_has_a_section(section: str) -> None:
    assert section in DOC.read_text(encoding="utf-8")
