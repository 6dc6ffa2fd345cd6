"""GEO303's read side: the bottom row of a column-convention 4x4 stored where a translation goes.

Only a destination that wants a translation (a `location` / `translation` key, keyword or name, a
translating call) counts, and only when the same function uses the matrix's translation column
`[:3, 3]`; a bare read of the bottom row, or a row-vector matrix, stays silent."""

from __future__ import annotations

import pytest

from geolint.engine import lint_source
from geolint.lint_types import Config
from geolint.rules.rotation.geo303_misplaced_translation import MisplacedTranslation

PREFIX = (
    "import numpy as np\n"
    "def f(R, t, loader, pts_h):\n"
    "    T = np.eye(4)\n"
    "    T[:3, :3] = R\n"
    "    T[:3, 3] = t\n"
)


def findings(body: str, prefix: str = PREFIX) -> list[str]:
    source = prefix + "".join(f"    {line}\n" for line in body.splitlines())
    found = lint_source(source, "example.py", Config(), rules=[MisplacedTranslation])
    return [f"{finding.line}:{finding.column}" for finding in found if finding.code == "GEO303"]


@pytest.mark.parametrize(
    "body",
    [
        "config = {'location': list(T[3, :])}",  # the BOP loader shape
        "loader.add_camera({'translation': T[3, :3].tolist()})",
        "loader.add_camera(location=T[-1, :3])",
        "loader.camera.location = tuple(T[3, 0:3])",
        "t_cam = T[3, :3]",
        "row = T[3, :]\nreturn {'position': row}",  # through a local name
        "loader.translate(T[3, :3])",
    ],
)
def test_bottom_row_stored_as_a_translation(body: str) -> None:
    assert len(findings(body)) == 1


@pytest.mark.parametrize(
    "body",
    [
        "assert np.allclose(T[3, :], [0, 0, 0, 1])",  # a bare read
        "config = {'location': list(T[:3, 3]), 'last_row': list(T[3, :])}",
        "config = {'location': list(T[3, 3:])}",  # not the row's first three entries
        "config = {'location': list(T[2, :3])}",  # not the bottom row
        "config = {'rotation': list(T[3, :])}",  # not a translation's destination
    ],
)
def test_silent_without_a_translation_destination(body: str) -> None:
    assert findings(body) == []


def test_silent_without_the_translation_column() -> None:
    """Nothing in the function says the 4x4 keeps its translation in column 3."""
    prefix = "import numpy as np\ndef f(R, t):\n    T = np.eye(4)\n    T[:3, :3] = R\n"
    assert findings("return {'location': list(T[3, :3])}", prefix) == []


def test_silent_for_a_row_vector_matrix() -> None:
    """`pts_h @ M`: the translation lives in the bottom row on purpose."""
    prefix = "import numpy as np\ndef f(R, t, pts_h):\n    M = np.eye(4)\n    M[:3, :3] = R\n    M[3, :3] = t\n"
    assert findings("return {'translation': M[3, :3], 'points': pts_h @ M}", prefix) == []


def test_an_inverse_keeps_the_column_layout() -> None:
    """`np.linalg.inv(T)` is not a transpose: the matrix is still laid out for column vectors."""
    assert len(findings("T_inv = np.linalg.inv(T)\nreturn {'location': list(T[3, :]), 'inverse': T_inv}")) == 1
