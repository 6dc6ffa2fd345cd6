"""Jupyter notebooks through the real CLI: code cells linted as one module, findings by cell
(`lab.ipynb:cell 3:2:5`, as ruff prints them), IPython magics tolerated, and fixes written back
into the cells they change without touching the rest of the notebook."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from geolint.notebook import NotebookError, read_notebook, write_back


def notebook(*cells: tuple[str, str], indent: int = 1) -> str:
    """A notebook's JSON text: cells of (type, source), outputs and metadata as Jupyter writes them."""
    entries = []
    for number, (kind, source) in enumerate(cells):
        entry = {"cell_type": kind, "id": f"cell-{number}", "metadata": {"tags": ["kept"]}, "source": source.splitlines(keepends=True)}
        if kind == "code":
            entry = {**entry, "execution_count": number, "outputs": [{"output_type": "stream", "name": "stdout", "text": ["é\n"]}]}
        entries.append(entry)
    document = {
        "cells": entries,
        "metadata": {"kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"}},
        "nbformat": 4,
        "nbformat_minor": 5,
    }
    return json.dumps(document, indent=indent, ensure_ascii=False) + "\n"


LAB = notebook(
    ("markdown", "# Grasping\n"),
    ("code", "%matplotlib inline\nimport numpy as np\nfiles = !ls\n"),
    ("code", "def step():\n    return bad_thing\n"),
    ("code", "risky_thing = 1\nnp.zeros?"),
)


def test_findings_are_reported_by_cell(cli):
    cli.write("lab.ipynb", LAB)
    result = cli("check", "lab.ipynb")
    assert result.returncode == 1, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0] == "lab.ipynb:cell 3:2:12: GEO190 `bad_thing` is bad"
    assert lines[1] == "  | return bad_thing"  # the cell's line, not the JSON's
    assert "lab.ipynb:cell 4:1:1: GEO191 `risky_thing` is risky" in lines
    as_json = json.loads(cli("check", "lab.ipynb", "--output-format", "json").stdout)
    assert [(f["cell"], f["line"], f["column"], f["code"]) for f in as_json] == [(3, 2, 12, "GEO190"), (4, 1, 1, "GEO191")]
    assert as_json[0]["fix"]["edits"][0]["line"] == 2  # the fix's lines count within the cell too
    full = cli("check", "lab.ipynb", "--output-format", "full", "--select", "GEO190").stdout.splitlines()
    assert full[1:5] == [" --> lab.ipynb:cell 3:2:12", "  |", "1 | def step():", "2 |     return bad_thing"]
    assert "--> lab.ipynb:cell 3:" not in "\n".join(full[5:9])  # the context stops at the cell's edge
    github = cli("check", "lab.ipynb", "--output-format", "github", "--select", "GEO190").stdout
    assert "line=2," in github and "cell 3: `bad_thing` is bad" in github
    # found when walking a folder, as ruff finds notebooks
    assert {f["path"] for f in json.loads(cli("check", "--output-format", "json").stdout)} == {"lab.ipynb"}


def test_a_cell_that_does_not_parse_costs_only_itself(cli):
    """IPython compiles each cell alone: a pasted table or a doctest in a code cell is one GEO000,
    and the other cells are still linted."""
    cli.write("lab.ipynb", notebook(
        ("code", "| joint | angle |\n|---|---|\n"),
        ("code", "def step():\n    return bad_thing\n"),
        ("code", ">>> step()\n"),
    ))  # fmt: skip
    as_json = json.loads(cli("check", "lab.ipynb", "--output-format", "json").stdout)
    assert [(f["cell"], f["line"], f["code"]) for f in as_json] == [(1, 1, "GEO000"), (2, 2, "GEO190"), (3, 1, "GEO000")]
    assert as_json[0]["message"] == "syntax error for Python 3.10-3.13: invalid syntax"


def test_real_rules_read_a_notebook(cli_real):
    cli_real.write(
        "lab.ipynb",
        notebook(("markdown", "Move the normal into the world frame.\n"), ("code", "import numpy as np\n"),
                 ("code", "def to_world(R, t, normal):\n    return R @ normal + t\n")),
    )  # fmt: skip
    result = cli_real("check", "--no-cache", "--output-format", "concise", "lab.ipynb")
    assert result.returncode == 1, result.stdout + result.stderr
    assert result.stdout.startswith("lab.ipynb:cell 3:2:12: GEO101 [*] ")


def test_fix_changes_only_the_cells_it_fixes(cli):
    path = cli.write("lab.ipynb", LAB)
    result = cli("check", "--fix", "--unsafe-fixes", "lab.ipynb")
    assert result.returncode == 0, result.stdout + result.stderr
    before, after = json.loads(LAB), json.loads(path.read_text(encoding="utf-8"))
    assert after["cells"][2]["source"] == ["def step():\n", "    return good_thing\n"]
    # the magics, the help line without a final newline, outputs, metadata: all as they were
    assert after["cells"][1]["source"] == before["cells"][1]["source"]
    assert after["cells"][3]["source"] == ["safe_thing = 1\n", "np.zeros?"]
    for index in (0, 1):
        assert after["cells"][index] == before["cells"][index]
    assert [cell["outputs"] for cell in after["cells"][1:]] == [cell["outputs"] for cell in before["cells"][1:]]
    assert after["metadata"] == before["metadata"] and list(after) == list(before)
    # written as Jupyter wrote it: one-space indentation, UTF-8 characters as they are
    expected = LAB.replace("return bad_thing", "return good_thing").replace('"risky_thing = 1', '"safe_thing = 1')
    assert path.read_text(encoding="utf-8") == expected
    again = cli("check", "--fix", "--unsafe-fixes", "lab.ipynb")
    assert again.returncode == 0 and path.read_text(encoding="utf-8") == expected


def test_fix_rewrites_only_the_fixed_line_of_a_hand_formatted_notebook(cli):
    # the layout json.dumps would not give back: mixed indentation, escaped non-ASCII, no final newline
    text = (
        '{\n    "cells": [\n  {"cell_type": "code", "metadata": {}, "outputs": [], "execution_count": null,\n'
        '   "source": ["# caf\\u00e9\\n", "x = bad_thing\\n",\n      "y = 2"]}],\n'
        ' "metadata": {}, "nbformat": 4, "nbformat_minor": 2}'
    )
    path = cli.write("hand.ipynb", text)
    assert cli("check", "--fix", "hand.ipynb").returncode == 0
    assert path.read_text(encoding="utf-8") == text.replace('"x = bad_thing', '"x = good_thing')


def test_stdin_notebook_and_a_broken_one(cli):
    fixed = cli("check", "-", "--stdin-filename", "lab.ipynb", "--fix", input=LAB)
    assert fixed.returncode == 1  # the unsafe fix stays
    assert json.loads(fixed.stdout)["cells"][2]["source"] == ["def step():\n", "    return good_thing\n"]
    assert "lab.ipynb:cell 4:1:1: GEO191" in fixed.stderr
    # not a notebook (broken JSON, a Git LFS pointer): one GEO000 finding, as ruff's invalid-syntax, and the run goes on
    cli.write("broken.ipynb", '{"cells": [')
    cli.write("pointer.ipynb", "version https://git-lfs.github.com/spec/v1\noid sha256:0\n")
    cli.write("mod.py", "x = bad_thing\n")
    broken = cli("check", "--output-format", "concise")
    assert broken.returncode == 1, broken.stderr
    assert broken.stdout.splitlines()[:3] == [
        "broken.ipynb:1:1: GEO000 not a Jupyter notebook: Expecting value: line 1 column 12 (char 11)",
        "mod.py:1:5: GEO190 [*] `bad_thing` is bad",
        "pointer.ipynb:1:1: GEO000 not a Jupyter notebook: Expecting value: line 1 column 1 (char 0)",
    ]


def test_add_noqa_writes_into_the_cell(cli):
    path = cli.write("lab.ipynb", LAB)
    assert cli("check", "--add-noqa", "lab.ipynb").returncode == 0
    after = json.loads(path.read_text(encoding="utf-8"))
    assert after["cells"][2]["source"][1] == "    return bad_thing  # geolint: ignore[GEO190]\n"
    assert cli("check", "lab.ipynb").returncode == 0


# ---- the notebook module itself -------------------------------------------------------------------


def test_magics_become_python_line_for_line() -> None:
    read = read_notebook(
        notebook(
            ("code", "%%bash\nls -l\n"),
            ("code", "%%time\nx = 1\n"),
            ("code", "if x:\n    !echo yes\n    y = (x\n         % 2)\nz = %env HOME\n"),
            ("code", "!colmap feature_extractor \\\n--use_gpu 0 \\\n--image_path \"{x}\"\nw = 2 \\\n  + 1\n"),
        ).encode()
    )
    assert [cell.python for cell in read.cells] == [
        ("\n", "\n"),
        ("\n", "x = 1\n"),
        ("if x:\n", "    pass\n", "    y = (x\n", "         % 2)\n", "z = None\n"),  # `% 2` is Python's modulo
        ("\n", "\n", "\n", "w = 2 \\\n", "  + 1\n"),  # a shell line continued with `\`; then Python's own `\`
    ]
    compile(read.python, "lab.ipynb", "exec")


def test_write_back_refuses_what_it_cannot_put_back() -> None:
    data = LAB.encode()
    python = read_notebook(data).python
    with pytest.raises(NotebookError, match="IPython lines"):
        write_back(data, python.replace("files = None\n", "files = None\nextra = 1\n"))
    with pytest.raises(NotebookError, match="cell boundary"):
        write_back(data, python.replace("# ---- notebook cell (geolint) ----\n", "", 1))
    assert write_back(data, python) == data  # nothing changed: the same bytes
