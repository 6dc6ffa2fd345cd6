"""Flow-sensitive reads within a body: a use sees the bindings that can reach it, not every
binding of its name (geolint/factbase/reaching.py), and the rules follow."""

from __future__ import annotations

import ast

import pytest

from geolint import api
from geolint.algebra import Kind
from geolint.factbase import reaching
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


@pytest.mark.parametrize(
    ("body", "kind"),
    [
        # `:=` in an `if`'s test binds before its blocks and before the statements after it
        ("x = mesh.vertices\nif (x := mesh.face_normals) is not None:\n    use(x)\n", Kind.DIRECTION),
        ("x = mesh.face_normals\nif (x := mesh.vertices) is not None:\n    pass\nuse(x)\n", Kind.POINT),
        ("x = mesh.vertices\nif (x := mesh.face_normals) is not None:\n    pass\nx = mesh.vertices\nuse(x)\n", Kind.POINT),
        ("x = mesh.vertices\nwhile (x := mesh.face_normals) is not None:\n    use(x)\n", Kind.DIRECTION),
        # the test of a conditional expression always runs; an operand after `or` may not
        ("x = mesh.vertices\ny = 1 if (x := mesh.face_normals) is not None else 0\nuse(x)\n", Kind.DIRECTION),
        ("x = mesh.vertices\nok = flag or (x := mesh.face_normals) is not None\nuse(x)\n", None),
        # in a comprehension `:=` binds the function's name (PEP 572), on iterations that may not happen
        ("x = mesh.vertices\nys = [(x := n) for n in mesh.face_normals]\nuse(x)\n", None),
        # a `for`'s iterable runs once: a binding later in the body is carried to the next iteration
        ("for v in (x := mesh.vertices):\n    use(x)\n    x = mesh.face_normals\n", None),
        # source order is not evaluation order inside one statement: the body of a conditional
        # expression runs after its test, a comprehension's element after its conditions
        ("x = mesh.vertices\ny = use(x) if (x := mesh.face_normals) is not None else 0\n", None),
        ("x = mesh.vertices\nys = [use(x) for n in mesh.face_normals if (x := n) is not None]\n", None),
    ],
)
def test_an_assignment_expression_binds_in_evaluation_order(body: str, kind: Kind | None) -> None:
    source = "def f(mesh, flag):\n" + "".join(f"    {line}\n" for line in body.splitlines())
    assert kind_at_marker(source) == kind


@pytest.mark.parametrize(
    ("body", "kind"),
    [
        # after the comprehension, its target is gone: the function's own binding reaches
        ("x = mesh.face_normals\ny = [x for x in mesh.vertices]\nuse(x)\n", Kind.DIRECTION),
        ("x = mesh.vertices\ny = [x for x in mesh.face_normals]\nx = mesh.face_normals\nuse(x)\n", Kind.DIRECTION),
        # inside it, the target is what is read (the first iterable is read outside)
        ("x = mesh.vertices\ny = [use(x) for x in x]\n", Kind.POINT),
    ],
)
def test_a_comprehension_target_reaches_only_its_comprehension(body: str, kind: Kind | None) -> None:
    source = "def f(mesh):\n" + "".join(f"    {line}\n" for line in body.splitlines())
    assert kind_at_marker(source) == kind


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


def test_rules_read_an_assignment_expression_where_it_binds() -> None:
    source = (
        "import numpy as np\n"
        "\n"
        "def move(T_world_cam, mesh):\n"
        "    x = mesh.vertices\n"
        "    moved = (T_world_cam @ np.hstack([x, np.ones((len(x), 1))]).T).T\n"
        "    if (x := mesh.vertex_normals) is not None:\n"
        "        turned = (T_world_cam @ np.hstack([x, np.ones((len(x), 1))]).T).T  # the normals get w = 1\n"
        "        return moved, turned\n"
        "    return moved, None\n"
        "\n"
        "def fine(T_world_cam, mesh):\n"
        "    x = mesh.vertex_normals\n"
        "    if (x := mesh.vertices) is not None:\n"
        "        return (T_world_cam @ np.hstack([x, np.ones((len(x), 1))]).T).T\n"
        "    return None\n"
    )
    found = [(finding.code, finding.line) for finding in api.lint_text(source, "move.py")]
    assert found == [("GEO101", 7)]


def _read(source: str, line: int, name: str) -> tuple[ModuleIndex, ast.Name]:
    """The module's index and the read of `name` on `line`."""
    tree = ast.parse(source)
    reads = [n for n in ast.walk(tree) if isinstance(n, ast.Name) and n.id == name and isinstance(n.ctx, ast.Load) and n.lineno == line]
    assert len(reads) == 1
    return ModuleIndex(tree, source), reads[0]


@pytest.mark.parametrize(
    ("body", "line", "value"),
    [
        ("x = a\nuse(x)\n", 3, "a"),
        ("x = a\nif flag:\n    x = b\nuse(x)\n", 5, None),  # two definitions reach
        ("if flag:\n    x = a\nuse(x)\n", 4, "a"),  # the only one that can reach
        ("use(x)\nx = a\n", 2, None),  # nothing placed before the read
        ("x = a\nx -= t\nuse(x)\n", 4, "x - t"),  # an augmented assignment is x = x - t
        ("x, y = a, b\nuse(y)\n", 3, "b"),  # a literal's element
        ("for x in xs:\n    pass\nuse(x)\n", 4, None),  # a loop target holds no one value
        ("if (x := a) is not None:\n    use(x)\n", 3, "a"),  # `:=` in the test, before the block
        ("x = a\nif (x := b) is not None:\n    pass\nuse(x)\n", 5, "b"),
        ("x = a\nif flag and (x := b):\n    pass\nuse(x)\n", 5, None),  # `:=` may not run
        ("x = a\nys = [(x := y) for y in xs]\nuse(x)\n", 4, None),
        ("x = a\nuse(x) if (x := b) else None\n", 3, None),  # the test runs first
        ("x = a\nassert flag, (x := b)\nuse(x)\n", 4, None),  # a message runs only on failure
        ("x = b\nmatch flag:\n    case 1 if (x := a):\n        pass\nuse(x)\n", 6, None),  # nor a case's guard
        ("match (x := a):\n    case 1:\n        use(x)\n", 4, "a"),
        ("with open((x := a)) as fh:\n    use(x)\n", 3, "a"),
    ],
)
def test_the_single_definition_reaching_a_read(body: str, line: int, value: str | None) -> None:
    source = "def f(xs, flag):\n" + "".join(f"    {text}\n" for text in body.splitlines())
    index, read = _read(source, line, "x" if "use(x)" in body else "y")
    found = reaching.value_of(index, read)
    assert (ast.unparse(found) if isinstance(found, ast.expr) else found) == value


def test_an_augmented_value_reads_the_value_before_it() -> None:
    index, read = _read("def f(T, p):\n    x = p\n    x -= T[:3, 3]\n    return x\n", 4, "x")
    augmented = reaching.value_of(index, read)
    assert isinstance(augmented, ast.BinOp) and isinstance(augmented.left, ast.Name)
    assert ast.unparse(reaching.value_of(index, augmented.left)) == "p"  # type: ignore[arg-type]
    assert reaching.statement_of(index, augmented.left) is reaching.statement_of(index, augmented)


def test_unpacking_a_call_gives_each_name_its_element() -> None:
    index, read = _read("def f(T):\n    R, t = split_pose(T)\n    return t\n", 3, "t")
    unpacked = reaching.value_of(index, read)
    assert isinstance(unpacked, reaching.Unpacked) and (unpacked.index, unpacked.names) == (1, ("R", "t"))


def test_a_parameter_and_the_binding_a_read_sees() -> None:
    source = "def f(T, S):\n    use(T)\n    T = S\n    use(T)\n    use(S)\n"
    index, first = _read(source, 2, "T")
    _, second = _read(source, 4, "T")
    assert reaching.parameter_of(index, first) is not None and reaching.parameter_of(index, second) is None
    assert reaching.binding_of(index, first) != reaching.binding_of(index, second)
    _, free = _read("def f():\n    use(np)\n", 2, "np")
    assert reaching.binding_of(ModuleIndex(ast.parse(""), ""), free) == ("free", "np")
