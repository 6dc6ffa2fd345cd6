"""Plain mypy and plain basedpyright (no plugin) infer and reject frame algebra through the generics alone.

One generated module holds every case; ONE mypy run and ONE basedpyright run check it. Each case line is
either ``reveal_type(expr)`` with the expected type, a line that must be an error, or a line that must be
clean. Both checkers must report errors on exactly the expected lines (no misses, no false alarms).
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

import geolint

REPO_ROOT = Path(geolint.__file__).resolve().parent.parent
BASEDPYRIGHT = Path(sys.executable).with_name("basedpyright")

HEADER = textwrap.dedent(
    """\
    from __future__ import annotations

    from typing import TypeVar, reveal_type

    import numpy as np

    from geolint import Direction, Frame, FrameTree, Point, PointCloud, Transform, Twist, Vector, Wrench


    class World(Frame): ...
    class Cam(Frame): ...
    class Base(Frame): ...


    A = TypeVar("A")
    B = TypeVar("B")


    def move(T: Transform[A, B], p: Point[B]) -> Point[A]:
        return T @ p


    T_wc = Transform[World, Cam](translation=[0.0, 0.0, 1.0])
    T_cb = Transform[Cam, Base]()
    p_c, p_b = Point[Cam]([1.0, 2.0, 3.0]), Point[Base]([1.0, 2.0, 3.0])
    v_c, v_b = Vector[Cam]([1.0, 0.0, 0.0]), Vector[Base]([1.0, 0.0, 0.0])
    d_c, d_b = Direction[Cam]([1.0, 0.0, 0.0]), Direction[Base]([1.0, 0.0, 0.0])
    cloud_c = PointCloud[Cam](points=[[0.0, 0.0, 0.0]])
    twist_c = Twist[Cam](linear=[0.0, 0.0, 0.0], angular=[0.0, 0.0, 1.0])
    wrench_c = Wrench[Cam](force=[0.0, 0.0, -9.81], torque=[0.0, 0.0, 0.0])
    tree = FrameTree()
    """
)

REVEAL = [
    ("T_wc @ p_c", "Point[World]"),
    ("T_wc @ v_c", "Vector[World]"),
    ("T_wc @ d_c", "Direction[World]"),
    ("T_wc @ T_cb", "Transform[World, Base]"),
    ("T_wc.inverse()", "Transform[Cam, World]"),
    ("T_wc @ T_cb @ p_b", "Point[World]"),
    ("p_c - p_c", "Vector[Cam]"),
    ("p_c + v_c", "Point[Cam]"),
    ("p_c - v_c", "Point[Cam]"),
    ("p_c + d_c", "Point[Cam]"),
    ("v_c + v_c", "Vector[Cam]"),
    ("v_c + p_c", "Point[Cam]"),
    ("2.0 * v_c", "Vector[Cam]"),
    ("v_c / 2.0", "Vector[Cam]"),
    ("-v_c", "Vector[Cam]"),
    ("d_c + d_c", "Vector[Cam]"),
    ("Transform.identity(World)", "Transform[World, World]"),
    ("Transform[World, Cam].from_matrix(np.eye(4))", "Transform[World, Cam]"),
    ('Transform[World, Cam].from_quat([0.0, 0.0, 0.0, 1.0], order="xyzw")', "Transform[World, Cam]"),
    ("T_wc @ cloud_c", "PointCloud[World]"),
    ("T_wc @ twist_c", "Twist[World]"),
    ("T_wc @ wrench_c", "Wrench[World]"),
    ("tree.lookup(World, Cam)", "Transform[World, Cam]"),
    ("tree.transform(p_c, to=World)", "Point[World]"),
    ("move(T_wc, p_c)", "Point[World]"),
]

MUST_FAIL = [
    "T_wc @ p_b",  # Transform[World, Cam] applied to Point[Base]
    "T_wc @ v_b",
    "T_wc @ d_b",
    "T_cb @ T_wc",  # T_ab @ T_cd with b != c
    "T_wc @ T_wc",
    "p_c + p_c",  # point + point
    "p_c + v_b",
    "p_c - p_b",
    "v_c + v_b",
    "v_c - p_c",
    "2.0 * p_c",
    "-p_c",
    "T_wc @ np.zeros(3)",  # a raw array is neither a point nor a vector
    "np.eye(3) @ p_c",  # a raw matrix on a wrapped value
    "Transform.identity(World) @ p_c",
    "move(T_wc, p_b)",
    "wrong_frame: Point[World] = p_c",  # assigning a Point[Cam] to a Point[World]
    "wrong_direction: Transform[World, Cam] = T_wc.inverse()",
    "wrong_kind: Point[Cam] = v_c",
    "T_wc @ tree.lookup(Base, Cam)",
]

MUST_PASS = [
    "as_vector: Vector[Cam] = d_c",  # a Direction is a Vector
    "chained: Point[World] = T_wc @ (T_cb @ p_b)",
    "np_coords = np.asarray(p_c)",
]


def _build_module() -> tuple[str, dict[int, str], set[int], set[int]]:
    lines = HEADER.splitlines()
    reveals: dict[int, str] = {}
    failing: set[int] = set()
    passing: set[int] = set()
    for expression, expected in REVEAL:
        lines.append(f"reveal_type({expression})")
        reveals[len(lines)] = expected
    for statement in MUST_FAIL:
        lines.append(statement)
        failing.add(len(lines))
    for statement in MUST_PASS:
        lines.append(statement)
        passing.add(len(lines))
    return "\n".join(lines) + "\n", reveals, failing, passing


def _short_type(text: str) -> str:
    """``geolint.runtime.primitives.Point[static_cases.World]`` -> ``Point[World]``."""
    return re.sub(r"\b(?:[A-Za-z_]\w*\.)+([A-Za-z_]\w*)", r"\1", text)


@pytest.fixture(scope="module")
def cases(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, dict[int, str], set[int], set[int]]:
    folder = tmp_path_factory.mktemp("static")
    source, reveals, failing, passing = _build_module()
    path = folder / "static_cases.py"
    path.write_text(source)
    return path, reveals, failing, passing


@pytest.mark.skipif(sys.version_info < (3, 11), reason="the generated module imports typing.reveal_type (Python 3.11+)")
def test_the_generated_module_runs(cases) -> None:  # type: ignore[no-untyped-def]
    """The clean part of the module is real, working runtime code (the failing lines are checked statically)."""
    path, reveals, failing, _ = cases
    lines = path.read_text().splitlines()
    runnable = [line if i + 1 not in failing else "pass" for i, line in enumerate(lines)]
    namespace: dict[str, object] = {"__name__": "static_cases"}
    tree_setup = "tree.add(T_wc)\ntree.add(T_cb)\n"
    source = "\n".join(runnable).replace("tree = FrameTree()", "tree = FrameTree()\n" + tree_setup, 1)
    exec(compile(source.replace("reveal_type(", "(lambda value: value)("), "static_cases", "exec"), namespace)


@pytest.mark.skipif(sys.version_info < (3, 11), reason="the generated module imports typing.reveal_type (Python 3.11+)")
def test_plain_mypy_infers_and_rejects(cases) -> None:  # type: ignore[no-untyped-def]
    from mypy import api

    path, reveals, failing, passing = cases
    config = path.parent / "mypy.ini"
    config.write_text(f"[mypy]\nmypy_path = {REPO_ROOT}\nfollow_imports = silent\nwarn_unused_ignores = False\n")
    stdout, stderr, _ = api.run(
        ["--config-file", str(config), "--no-incremental", "--show-error-codes", "--no-error-summary", str(path)]
    )
    assert not stderr, stderr
    revealed: dict[int, str] = {}
    errors: dict[int, str] = {}
    for line in stdout.splitlines():
        match = re.match(rf"{re.escape(str(path))}:(\d+): (error|note): (.*)", line)
        if not match:
            continue
        number, kind, message = int(match.group(1)), match.group(2), match.group(3)
        if kind == "note" and message.startswith("Revealed type is"):
            revealed[number] = _short_type(message.split('"')[1])
        elif kind == "error":
            errors[number] = message
    assert revealed == reveals, stdout
    assert set(errors) == failing, stdout
    assert not passing & set(errors)


def test_plain_basedpyright_infers_and_rejects(cases) -> None:  # type: ignore[no-untyped-def]
    if not BASEDPYRIGHT.exists():
        pytest.skip("basedpyright is not installed next to this Python")
    path, reveals, failing, passing = cases
    (path.parent / "pyrightconfig.json").write_text(
        json.dumps({"extraPaths": [str(REPO_ROOT)], "typeCheckingMode": "standard", "pythonVersion": "3.11"})
    )
    result = subprocess.run(
        [str(BASEDPYRIGHT), "--outputjson", "--pythonpath", sys.executable, str(path)],
        cwd=path.parent,
        capture_output=True,
        text=True,
        timeout=300,
    )
    report = json.loads(result.stdout)
    revealed: dict[int, str] = {}
    errors: dict[int, str] = {}
    for diagnostic in report["generalDiagnostics"]:
        number = diagnostic["range"]["start"]["line"] + 1
        if diagnostic["severity"] == "information" and diagnostic["message"].startswith("Type of"):
            revealed[number] = _short_type(diagnostic["message"].rsplit('"', 2)[1])
        elif diagnostic["severity"] == "error":
            errors[number] = diagnostic["message"]
    assert revealed == reveals, result.stdout
    assert set(errors) == failing, json.dumps(errors, indent=1)
    assert not passing & set(errors)
