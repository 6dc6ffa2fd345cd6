"""One operand table, four answers: the shared table (`geolint.algebra`), the runtime's operators, the mypy plugin's
revealed types and the linter's fact base (`FactBase.kind_of`, `FactBase.homogenized`) give every operation the
same kind.

Each case is an operator (``+``, ``-``, unary ``-``, ``* 2.0``, ``2.0 *``, ``/ 2.0``, ``@``, ``np.append(x, w)``
with w = 0 or 1) over kinds. A participant may not judge a case: the runtime has no rotation, translation or
homogeneous value; the plugin leaves a 4x4 matrix times a 3-vector to mypy; the linter answers None when a kind is
no evidence (a 4x4 that may be an array). Where it judges, it must agree with the table: the table's kind for a
valid operation; an error (a raised `GeometryTypeError` or `TypeError`, a mypy error, a problem the linter's rules report) for an
invalid one or one the table does not call geometry.
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np
import pytest
from mypy import api

import geolint as gl
from geolint import algebra
from geolint.algebra import Kind, Outcome
from geolint.factbase.index import ModuleIndex
from geolint.factbase.model import FactBase
from geolint.lint_types import Config
from geolint.mypy.geometry import KIND_OF_FULLNAME, VECTOR_WITH_W1

CONFIG = Path(__file__).parent / "mypy.ini"
K = Kind
ERROR = "error"  # the operation is refused or reported
NOT_GEOMETRY = "not geometry"  # the table's None: no participant may give it a kind

LOCATED = (K.POINT, K.VECTOR, K.DIRECTION)
ADDITIVE = (*LOCATED, K.TRANSLATION)
OPERATORS = (K.ROTATION, K.TRANSFORM)


@dataclass(frozen=True)
class Case:
    symbol: str
    left: Kind
    right: Kind | None = None

    def expression(self, names: dict[Kind, str]) -> str | None:
        """The case written with a participant's operand names; None when it has no value of some kind."""
        if self.left not in names or (self.right is not None and self.right not in names):
            return None
        return TEMPLATES[self.symbol].format(a=names[self.left], b=names.get(self.right, ""))  # type: ignore[arg-type]

    def __str__(self) -> str:
        return TEMPLATES[self.symbol].format(a=self.left.name, b=self.right.name if self.right else "")


TEMPLATES = {
    "+": "{a} + {b}",
    "-": "{a} - {b}",
    "neg": "-{a}",
    "*s": "{a} * 2.0",
    "s*": "2.0 * {a}",
    "/s": "{a} / 2.0",
    "@": "{a} @ {b}",
    "w0": "np.append({a}, 0)",
    "w1": "np.append({a}, 1)",
}

CASES = [
    *(Case(symbol, left, right) for symbol in ("+", "-") for left in ADDITIVE for right in ADDITIVE),
    *(Case(symbol, value) for symbol in ("neg", "*s", "s*", "/s") for value in ADDITIVE),
    *(Case("@", operator, value) for operator in OPERATORS for value in (*ADDITIVE, *OPERATORS)),
    *(Case("@", value, operator) for value in LOCATED for operator in OPERATORS),  # rows: `x @ R`
    *(Case(symbol, value) for symbol in ("w0", "w1") for value in LOCATED),
]


def _matmul(left: Kind, right: Kind | None) -> Outcome | None:
    assert right is not None
    return algebra.apply(left, right) if left in OPERATORS else algebra.apply_rows(left, right)


TABLE: dict[str, Callable[[Kind, Kind | None], Outcome | None]] = {
    "+": lambda a, b: algebra.add(a, b),  # type: ignore[arg-type]
    "-": lambda a, b: algebra.sub(a, b),  # type: ignore[arg-type]
    "neg": lambda a, _: algebra.negate(a),
    "*s": lambda a, _: algebra.scale(a),
    "s*": lambda a, _: algebra.scale(a),
    "/s": lambda a, _: algebra.scale(a),
    "@": _matmul,
    "w0": lambda a, _: algebra.homogenize(a, 0),
    "w1": lambda a, _: algebra.homogenize(a, 1),
}

Answer = Kind | str | None


def table_answer(case: Case) -> Answer:
    outcome = TABLE[case.symbol](case.left, case.right)
    if outcome is None:
        return NOT_GEOMETRY
    return ERROR if outcome.problem is not None else outcome.kind


def agrees(answer: Answer, expected: Answer) -> bool:
    if answer is None:
        return True  # this participant does not judge the case
    if answer == ERROR:
        return expected in (ERROR, NOT_GEOMETRY)
    return answer == expected


# --- the runtime ---------------------------------------------------------------------------------------------

RUNTIME_NAMES = {K.POINT: "p", K.VECTOR: "v", K.DIRECTION: "d", K.TRANSFORM: "T"}
RUNTIME_KINDS = [(gl.Direction, K.DIRECTION), (gl.Point, K.POINT), (gl.Vector, K.VECTOR), (gl.Transform, K.TRANSFORM)]


def runtime_answer(case: Case) -> Answer:
    expression = case.expression(RUNTIME_NAMES)
    if expression is None or case.symbol in ("w0", "w1"):
        return None  # no runtime value of that kind, no homogeneous one
    namespace = {
        "p": gl.Point["world"]([0.3, 0.4, 0.5]),
        "v": gl.Vector["world"]([0.3, 0.4, 0.5]),
        "d": gl.Direction["world"]([0.3, 0.4, 0.5]),
        "T": gl.Transform["world", "world"](np.eye(3), [1.0, 2.0, 3.0]),
    }
    try:
        value = eval(expression, namespace)  # noqa: S307  (our own fixed expressions)
    except (gl.GeometryTypeError, TypeError):  # refused, or no such operator (`point / 2.0`)
        return ERROR
    return next(kind for runtime_type, kind in RUNTIME_KINDS if isinstance(value, runtime_type))  # Direction first


# --- the mypy plugin -----------------------------------------------------------------------------------------

ARRAY_NAMES = {K.POINT: "p", K.VECTOR: "v", K.DIRECTION: "d", K.ROTATION: "R", K.TRANSFORM: "T", K.TRANSLATION: "t"}
PLUGIN_HEADER = """\
import numpy as np
from geolint import Direction, Point, Transform, Vector
from geolint.typing import DirectionArray, PointArray, RotationMatrix, TransformMatrix, Translation, VectorArray
"""
FAMILIES = {
    "runtime": ('p: Point["world"], v: Vector["world"], d: Direction["world"], T: Transform["world", "world"]', RUNTIME_NAMES),
    "arrays": (
        'p: PointArray["world"], v: VectorArray["world"], d: DirectionArray["world"], R: RotationMatrix["world", "world"], '
        'T: TransformMatrix["world", "world"], t: Translation["world", "cam"]',
        ARRAY_NAMES,
    ),
}
MYPY_LINE = re.compile(r"^[^:]+:(?P<line>\d+): (?P<severity>error|note): (?P<message>.*)$")
REVEALED = re.compile(r'Revealed type is "(?P<fullname>[\w.]+)\[')


@pytest.fixture(scope="module")
def plugin_answers(tmp_path_factory: pytest.TempPathFactory) -> dict[tuple[str, Case], Answer]:
    """(family, case) -> what mypy with the plugin says of the case, from one run over one file."""
    lines = PLUGIN_HEADER.splitlines()
    at_line: dict[int, tuple[str, Case]] = {}
    for family, (parameters, names) in FAMILIES.items():
        lines.append(f"def {family}({parameters}) -> None:")
        for case in CASES:
            expression = case.expression(names)
            if expression is not None and not (family == "runtime" and case.symbol in ("w0", "w1")):  # not arrays
                lines.append(f"    reveal_type({expression})")
                at_line[len(lines)] = (family, case)
    folder = tmp_path_factory.mktemp("algebra_agreement")
    (folder / "agreement.py").write_text("\n".join(lines) + "\n")
    stdout, stderr, _ = api.run(["--config-file", str(CONFIG), "--cache-dir", str(folder / "cache"), str(folder / "agreement.py")])
    errors: set[int] = set()
    revealed: dict[int, str] = {}
    for text in stdout.splitlines():
        match = MYPY_LINE.match(text)
        if match is None:
            continue
        line = int(match["line"])
        if match["severity"] == "error":
            errors.add(line)
        elif (shown := REVEALED.search(match["message"])) is not None:
            revealed[line] = shown["fullname"]
    assert set(revealed) | errors >= set(at_line), stdout + stderr  # every case was checked
    return {key: None if key in PLUGIN_DEFERS else _plugin_answer(line in errors, revealed.get(line)) for line, key in at_line.items()}


# Cases the plugin leaves to mypy on purpose, whose revealed type is therefore numpy's stubs', not the plugin's.
PLUGIN_DEFERS = {
    ("arrays", Case("neg", K.POINT)): "a reflected point array is left alone; numpy types `-a` as a's own class",
}


def _plugin_answer(error: bool, fullname: str | None) -> Answer:
    if error:
        return ERROR
    family_kind = KIND_OF_FULLNAME.get(fullname or "")
    if family_kind is None:
        return None  # a plain ndarray, a float: mypy's own answer, not the plugin's
    kind = family_kind[1]
    if kind == VECTOR_WITH_W1:
        return ERROR  # a vector carrying w = 1: reported where a 4x4 meets it
    return Kind(kind) if kind in Kind._value2member_map_ else None  # an origin offset: a carrier of its own


# --- the linter ----------------------------------------------------------------------------------------------

LINTER_NAMES = ARRAY_NAMES
# Each operand's kind comes from what the fact base reads as evidence: ROS message fields, a mesh attribute,
# library calls whose result kind is known.
LINTER_HEADER = """\
import numpy as np
from geometry_msgs.msg import PointStamped, Transform, Vector3Stamped
from pytransform3d.transformations import transform_from
from transforms3d.euler import euler2mat
p = PointStamped().point
v = Vector3Stamped().vector
d = mesh.vertex_normals
R = euler2mat(0.0, 0.0, 1.0)
T = transform_from(R, np.zeros(3))
t = Transform().translation
"""


@pytest.fixture(scope="module")
def linter_answers() -> dict[Case, Answer]:
    written = [(case, case.expression(LINTER_NAMES)) for case in CASES]
    source = LINTER_HEADER + "".join(f"{expression}\n" for _, expression in written)
    tree = ast.parse(source)
    facts = FactBase(ModuleIndex(tree, source), Config())
    declarations = tree.body[: len(LINTER_HEADER.splitlines())]
    for statement, kind in zip(declarations[-6:], (K.POINT, K.VECTOR, K.DIRECTION, K.ROTATION, K.TRANSFORM, K.TRANSLATION)):
        assert facts.kind_of(statement.targets[0]) == kind, ast.unparse(statement)  # type: ignore[attr-defined]
    expressions = [statement.value for statement in tree.body[len(declarations) :]]  # type: ignore[attr-defined]
    return {case: _linter_answer(facts, case, node) for (case, _), node in zip(written, expressions)}


def _linter_answer(facts: FactBase, case: Case, node: ast.expr) -> Answer:
    if case.symbol in ("w0", "w1"):
        homogeneous = facts.homogeneous(node)
        outcome = None if homogeneous is None else facts.homogenized(homogeneous)
        if outcome is None:
            return None
        return ERROR if outcome.problem is not None else outcome.kind  # GEO101 / GEO102 report the problem
    return facts.kind_of(node)


# --- the agreement -------------------------------------------------------------------------------------------


@pytest.mark.parametrize("case", CASES, ids=str)
def test_every_participant_agrees_with_the_table(
    case: Case, plugin_answers: dict[tuple[str, Case], Answer], linter_answers: dict[Case, Answer]
) -> None:
    expected = table_answer(case)
    answers = {
        "runtime": runtime_answer(case),
        "plugin on runtime values": plugin_answers.get(("runtime", case)),
        "plugin on arrays": plugin_answers.get(("arrays", case)),
        "linter": linter_answers[case],
    }
    disagreeing = {who: answer for who, answer in answers.items() if not agrees(answer, expected)}
    assert not disagreeing, f"{case}: the table says {expected}, {disagreeing}"


# The decision made once: a direction added to, subtracted from or scaled by anything is a plain vector (no longer
# unit); negated it is still a direction. Every participant answers these.
DECIDED = [
    (Case("-", K.DIRECTION, K.DIRECTION), K.VECTOR),
    (Case("+", K.DIRECTION, K.DIRECTION), K.VECTOR),
    (Case("*s", K.DIRECTION), K.VECTOR),
    (Case("s*", K.DIRECTION), K.VECTOR),
    (Case("/s", K.DIRECTION), K.VECTOR),
    (Case("neg", K.DIRECTION), K.DIRECTION),
    (Case("-", K.POINT, K.POINT), K.VECTOR),
]


@pytest.mark.parametrize(("case", "kind"), DECIDED, ids=[str(case) for case, _ in DECIDED])
def test_the_direction_decision_is_everyone_s(
    case: Case, kind: Kind, plugin_answers: dict[tuple[str, Case], Answer], linter_answers: dict[Case, Answer]
) -> None:
    assert table_answer(case) == kind
    assert runtime_answer(case) == kind
    assert plugin_answers[("runtime", case)] == kind
    assert plugin_answers[("arrays", case)] == kind
    assert linter_answers[case] == kind


# Where the table gives a kind and the linter says nothing, and why. Anything else the table answers, the linter
# answers too: a change that silences it (or makes it speak here) is seen.
LINTER_SILENT = {
    **{Case("@", K.TRANSFORM, value): "a 4x4 reaches homogeneous 4-vectors only" for value in LOCATED},
}


def test_the_linter_answers_what_the_table_answers(linter_answers: dict[Case, Answer]) -> None:
    silent = {case for case in CASES if isinstance(table_answer(case), Kind) and linter_answers[case] is None}
    assert {str(case) for case in silent} == {str(case) for case in LINTER_SILENT}
