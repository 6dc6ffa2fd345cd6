"""Syntax of a newer Python than the one running geolint: the file is analysed whole, at the original positions.

Each case holds a real GEO101 (a direction rotated and then translated) whose position is written
out: the same line and column under every supported interpreter, lowered (3.10, 3.11, 3.12 for
3.13's type-parameter defaults) or parsed natively (3.12, 3.13). Real syntax errors still give
one GEO000 that names the versions whose grammar rejects them.
"""

from __future__ import annotations

import ast
import sys

import pytest

from geolint.engine import lint_source
from geolint.fixes import fix_source
from geolint.frames_graph import graph_of_source
from geolint.lint_types import Config
from geolint.parsing import SUPPORTED_GRAMMARS, parse_module

BUG = "face_normals @ R_base_mesh.T + t_base_mesh"

CASES = {
    "type alias (3.12)": (
        "import numpy as np\n"
        "\n"
        "type Normals = np.ndarray\n"
        "type Pair[T] = tuple[T, T]\n"
        "\n"
        "def to_base(face_normals: Normals, R_base_mesh, t_base_mesh):\n"
        f"    return {BUG}\n",
        (7, 12),
    ),
    "type alias then a statement on its line (3.12)": (
        "def to_base(face_normals, R_base_mesh, t_base_mesh):\n"
        f"    type Normals = list[float]; world = {BUG}\n"
        "    return world\n",
        (2, 41),
    ),
    "generic function (3.12)": (
        "def to_base[T](mesh: T, R_base_mesh, t_base_mesh):\n"
        "    face_normals = mesh.face_normals\n"
        f"    return {BUG}\n",
        (3, 12),
    ),
    "generic class with bounds (3.12)": (
        "class Mesh[T: (int, float), *Ts, **P](Base):\n"
        "    def to_base[S](self, R_base_mesh, t_base_mesh):\n"
        "        face_normals = self.face_normals\n"
        f"        return {BUG}\n",
        (4, 16),
    ),
    "type parameters over lines, with a comment and defaults (3.13)": (
        "def to_base[\n"
        "    T,  # the mesh type\n"
        "\n"
        "    U = float,\n"
        "    *Ts = *tuple[int, ...],\n"
        "](mesh: T, R_base_mesh, t_base_mesh):\n"
        f"    face_normals = mesh.face_normals; return {BUG}\n",
        (7, 46),
    ),
    "except* (3.11)": (
        "def to_base(face_normals, R_base_mesh, t_base_mesh):\n"
        "    try:\n"
        "        pass\n"
        "    except* ValueError:\n"
        f"        return {BUG}\n",
        (5, 16),
    ),
    "star in an index and in an annotation (3.11)": (
        "def to_base(face_normals, R_base_mesh, t_base_mesh, *shape: *Ts):\n"
        f"    grid = Array[*Ts]; return {BUG}\n",
        (2, 31),
    ),
    "f-string nesting its own quote (3.12)": (
        "def to_base(mesh, face_normals, R_base_mesh, t_base_mesh):\n"
        f'    log(f"{{mesh.names["base"]!r:>{{width}}}}"); normals = {BUG}\n'
        "    return normals\n",
        (2, 56),
    ),
    "f-string with a backslash in a field (3.12)": (
        "def to_base(mesh, face_normals, R_base_mesh, t_base_mesh):\n"
        f"    log(f\"{{'\\n'.join(mesh.names)}}\"); normals = {BUG}\n"
        "    return normals\n",
        (2, 48),
    ),
    "f-string with a comment in a field spanning lines (3.12)": (
        "def to_base(mesh, face_normals, R_base_mesh, t_base_mesh):\n"
        '    log(f"""{\n'
        "        mesh.name  # which mesh\n"
        f'    }}"""); normals = {BUG}\n'
        "    return normals\n",
        (4, 22),
    ),
    "one-quote f-string broken across lines (3.12)": (
        "def to_base(mesh, face_normals, R_base_mesh, t_base_mesh):\n"
        "    log(f'{mesh.name +\n"
        f"           mesh.kind}}'); normals = {BUG}\n"
        "    return normals\n",
        (3, 36),
    ),
    "f-string three levels deep, non-ASCII inside, the bug after it (3.12)": (
        "def to_base(mesh, face_normals, R_base_mesh, t_base_mesh):\n"
        f'    log(f"{{f"{{mesh.names["é"]}}"}}"); normals = {BUG}\n'
        "    return normals\n",
        (2, 47),
    ),
    "the bug inside a PEP 701 f-string (3.12)": (
        "def to_base(mesh, face_normals, R_base_mesh, t_base_mesh):\n"
        f'    log(f"{{mesh.names["base"]}}: {{{BUG}}}")\n',
        (2, 34),
    ),
}


@pytest.mark.parametrize("source, position", CASES.values(), ids=CASES.keys())
def test_a_finding_in_newer_syntax_is_found_where_it_is(source, position):
    findings = [(f.code, f.line, f.column) for f in lint_source(source, "newer.py")]
    assert findings == [("GEO101", *position)]
    assert source.splitlines()[position[0] - 1][position[1] - 1 :].startswith(BUG)


@pytest.mark.parametrize("source", [source for source, _ in CASES.values()], ids=CASES.keys())
def test_every_name_in_the_tree_is_at_its_place_in_the_original_text(source):
    tree = parse_module(source)
    names = [node for node in ast.walk(tree) if isinstance(node, ast.Name)]
    assert names
    for node in names:
        assert ast.get_source_segment(source, node) == node.id, (node.id, node.lineno, node.col_offset)


def test_a_text_the_running_python_reads_gets_its_own_tree():
    source = "x = f'{a!r}'\ndef f(x):\n    return [*x]\n"
    assert ast.dump(parse_module(source), include_attributes=True) == ast.dump(ast.parse(source), include_attributes=True)


SYNTAX_ERRORS = {
    "unclosed parameters": ("def to_base(R, normals:\n    return normals @ R.T\n", 1),
    "empty type parameters": ("def to_base[](x):\n    return x\n", 1),
    "a number as a type parameter": ("class Mesh[1]:\n    pass\n", 1),
    "a type alias inside a call": ("def f():\n    register(type Vec = list)\n", 2),
    "except* without a type": ("try:\n    pass\nexcept*:\n    pass\n", 3),
    "an f-string field left empty": ("x = 1\nlabel = f'{x +\n }'\n", 2),
    "python 2": ('print "hello"\n', 1),
}


@pytest.mark.parametrize("source, line", SYNTAX_ERRORS.values(), ids=SYNTAX_ERRORS.keys())
def test_a_real_syntax_error_is_one_geo000_naming_the_grammars(source, line):
    [finding] = lint_source(source, "broken.py")
    assert (finding.code, finding.line) == ("GEO000", line)
    assert finding.message.startswith(f"syntax error for {SUPPORTED_GRAMMARS}: ")
    newest = max((3, 13), sys.version_info[:2])
    assert SUPPORTED_GRAMMARS == f"Python 3.10-{newest[0]}.{newest[1]}"


def test_a_fix_applies_in_a_file_of_newer_syntax():
    source, _ = CASES["generic function (3.12)"]
    outcome = fix_source(source, "newer.py", Config())
    assert outcome.fixed == 1
    assert "return face_normals @ R_base_mesh.T\n" in outcome.source
    assert outcome.source.startswith("def to_base[T](mesh: T, R_base_mesh, t_base_mesh):\n")


def test_the_frame_graph_reads_a_file_of_newer_syntax():
    source = "type Pose = object\n\ndef camera_in_world[T](T_world_base, T_base_cam):\n    return T_world_base @ T_base_cam\n"
    graph = graph_of_source(source, "newer.py")
    assert [(edge.parent, edge.child, edge.location) for edge in graph.edges] == [
        ("world", "base", "newer.py:3"),
        ("base", "cam", "newer.py:3"),
    ]


def test_a_suppression_comment_on_a_line_of_newer_syntax_is_read():
    source = (
        "def to_base[T](mesh: T, face_normals, R_base_mesh, t_base_mesh):\n"
        f'    log(f"{{mesh.names["base"]}}"); normals = {BUG}  # geolint: ignore[GEO101]\n'
        "    return normals\n"
    )
    assert lint_source(source, "newer.py") == []
    unused = source.replace("ignore[GEO101]", "ignore[GEO102]")
    assert [(f.code, f.line) for f in lint_source(unused, "newer.py")] == [("GEO101", 2), ("GEO900", 2)]
