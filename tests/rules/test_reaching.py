"""Flow-sensitive reads within a body: a use sees the bindings that can reach it, not every
binding of its name (geolint/factbase/reaching.py), and the rules follow."""

from __future__ import annotations

import ast

import pytest

from geolint import api
from geolint.algebra import Kind
from geolint.factbase.index import ModuleIndex
from geolint.factbase.model import DST_FIRST, FactBase
from geolint.lint_types import Config


def kind_at_marker(source: str) -> Kind | None:
    """The kind the fact base gives the name `x` in the statement `use(x)`."""
    tree = ast.parse(source)
    facts = FactBase(ModuleIndex(tree, source), Config(), "<string>", (DST_FIRST,))
    uses = [
        node.args[0]
        for node in ast.walk(tree)
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "use"
    ]
    assert len(uses) == 1
    return facts.kind_of(uses[0])


@pytest.mark.parametrize(
    ("body", "kind"),
    [
        # the later binding replaces the earlier one
        ("x = mesh.vertices\nx = mesh.face_normals\nuse(x)\n", Kind.DIRECTION),
        ("x = mesh.face_normals\nx = mesh.vertices\nuse(x)\n", Kind.POINT),
        # a use between the two bindings sees the first
        ("x = mesh.vertices\nuse(x)\nx = mesh.face_normals\n", Kind.POINT),
        # a branch may or may not run: both reach, they disagree, nothing is said
        ("x = mesh.vertices\nif flag:\n    x = mesh.face_normals\nuse(x)\n", None),
        # ... unless a later binding always runs
        ("x = mesh.vertices\nif flag:\n    x = mesh.face_normals\nx = mesh.face_normals\nuse(x)\n", Kind.DIRECTION),
        # both branches bind: both reach
        ("if flag:\n    x = mesh.vertices\nelse:\n    x = mesh.face_normals\nuse(x)\n", None),
        # inside the branch, its own binding is what counts
        ("x = mesh.vertices\nif flag:\n    x = mesh.face_normals\n    use(x)\n", Kind.DIRECTION),
        # a loop carries the binding made later in its body back to the next iteration
        ("x = mesh.vertices\nfor i in range(3):\n    use(x)\n    x = mesh.face_normals\n", None),
        # ... unless the body binds it again before the use
        ("x = mesh.vertices\nfor i in range(3):\n    x = mesh.face_normals\n    use(x)\n    x = mesh.vertices\n", Kind.DIRECTION),
        # a try body may stop half-way: its binding does not always run for the code after it
        ("x = mesh.vertices\ntry:\n    x = mesh.face_normals\nexcept OSError:\n    pass\nuse(x)\n", None),
        # the right-hand side reads the binding before the statement's own
        ("x = mesh.face_normals\nx = use(x)\n", Kind.DIRECTION),
        # a loop variable, then rebound after the loop
        ("for x in mesh.vertices:\n    pass\nx = mesh.face_normals\nuse(x)\n", Kind.DIRECTION),
    ],
)
def test_the_bindings_that_reach_a_use(body: str, kind: Kind | None) -> None:
    source = "def f(mesh, flag):\n" + "".join(f"    {line}\n" for line in body.splitlines())
    assert kind_at_marker(source) == kind


def test_a_parameter_rebound_later_is_the_parameter_before() -> None:
    source = "def f(normals, mesh):\n    use(normals)\n    normals = mesh.vertices\n"
    assert kind_at_marker(source) == Kind.DIRECTION


def test_bindings_that_cannot_be_placed_keep_every_binding() -> None:
    # a comprehension variable binds the same name in this scope: order is not attempted
    source = "def f(mesh):\n    x = mesh.vertices\n    y = [x for x in mesh.face_normals]\n    x = mesh.face_normals\n    use(x)\n"
    assert kind_at_marker(source) is None


def test_rules_read_in_order(tmp_path) -> None:
    source = (
        "import numpy as np\n"
        "\n"
        "def move(T_world_cam, points, normals):\n"
        "    ones = np.ones((len(points), 1))\n"
        "    x = points\n"
        "    moved = (T_world_cam @ np.hstack([x, ones]).T).T\n"
        "    x = normals\n"
        "    turned = (T_world_cam @ np.hstack([x, ones]).T).T  # the normals get w = 1\n"
        "    return moved, turned\n"
        "\n"
        "def fine(T_world_cam, points, normals):\n"
        "    x = normals\n"
        "    x = points\n"
        "    return (T_world_cam @ np.hstack([x, np.ones((len(x), 1))]).T).T\n"
    )
    found = [(finding.code, finding.line) for finding in api.lint_text(source, "move.py")]
    assert found == [("GEO101", 8)]
