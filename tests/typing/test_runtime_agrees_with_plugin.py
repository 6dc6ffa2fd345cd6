"""The runtime and the mypy plugin give every operation the same kind and frame: each expression below is
evaluated on real values and revealed by real mypy with the plugin, and the two answers are compared."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from mypy import api

import geolint as gl

CONFIG = Path(__file__).parent / "mypy.ini"

SETUP = '''
from geolint import Direction, Point, Transform, Vector

p = Point["world"]([1.0, 2.0, 3.0])
q = Point["world"]([0.0, 1.0, 0.0])
v = Vector["world"]([0.0, 0.0, 2.0])
d = Direction["world"]([0.0, 0.0, 1.0])
e = Direction["world"]([1.0, 0.0, 0.0])
T = Transform["camera", "world"](translation=[0.0, 0.0, 1.0])
batch = Point["world"]([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]])
'''

EXPRESSIONS = [
    "-d",
    "-v",
    "d + e",
    "d - e",
    "2.0 * d",
    "d * 2.0",
    "d / 2.0",
    "p - q",
    "p + v",
    "p - v",
    "v + p",
    "v + d",
    "T @ p",
    "T @ v",
    "T @ d",
    "batch[0]",
    "batch[0:1]",
]

REVEALED = re.compile(r'^\S+:(?P<line>\d+): note: Revealed type is "geolint\.runtime\.\w+\.(?P<kind>\w+)\[(?P<frame>.*)\]"$')


@pytest.fixture(scope="module")
def revealed(tmp_path_factory: pytest.TempPathFactory) -> dict[str, tuple[str, str]]:
    folder = tmp_path_factory.mktemp("agreement")
    lines = SETUP.splitlines()
    first = len(lines) + 1
    source = "\n".join([*lines, *(f"reveal_type({expression})" for expression in EXPRESSIONS)]) + "\n"
    (folder / "agreement.py").write_text(source)
    stdout, stderr, _ = api.run(
        ["--config-file", str(CONFIG), "--cache-dir", str(folder / "cache"), str(folder / "agreement.py")]
    )
    found: dict[str, tuple[str, str]] = {}
    for text in stdout.splitlines():
        match = REVEALED.match(text)
        if match:
            frame = match["frame"].replace("Literal['", "").replace("']", "")
            found[EXPRESSIONS[int(match["line"]) - first]] = (match["kind"], frame)
    assert len(found) == len(EXPRESSIONS), stdout + stderr
    return found


@pytest.mark.parametrize("expression", EXPRESSIONS)
def test_same_kind_and_frame(expression: str, revealed: dict[str, tuple[str, str]]) -> None:
    namespace: dict[str, object] = {}
    exec(SETUP, namespace)  # noqa: S102  (our own fixed snippet)
    value = eval(expression, namespace)  # noqa: S307
    runtime_answer = (type(value).__name__.split("[", 1)[0], value.frame)
    assert runtime_answer == revealed[expression]


def test_every_runtime_kind_is_covered() -> None:
    kinds = {type(eval(e, _namespace())).__name__.split("[", 1)[0] for e in EXPRESSIONS}  # noqa: S307
    assert kinds == {gl.Point.__name__, gl.Vector.__name__, gl.Direction.__name__}


def _namespace() -> dict[str, object]:
    namespace: dict[str, object] = {}
    exec(SETUP, namespace)  # noqa: S102
    return namespace
