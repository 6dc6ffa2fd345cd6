"""The component order a function assumes, read from the standard quaternion formulas it computes by index.

`atan2(2 * (q[3] * q[2] + q[0] * q[1]), 1 - 2 * (q[1] ** 2 + q[2] ** 2))` is the yaw of (x, y, z, w)
components: the code says which index plays w as plainly as an API table does. Each formula is
expanded into a polynomial of the components of one base (through local names, `q_w = q[3]` and
`x, y, z, w = q`) and compared, in both standard orders, with the textbook polynomials: yaw, roll
(`atan2`), pitch (`asin`) and the 3x3 rotation matrix (or its transpose).

Some index patterns are two formulas at once (the yaw of x, y, z, w is the roll of w, x, y, z). A
formula then decides only when the component names it reads (`q_w = q[3]`) or the word naming its
result (`yaw = ...`, `def quat_get_yaw`) pick one reading; otherwise it says nothing.
"""

from __future__ import annotations

from typing import Final, TYPE_CHECKING

import ast
from ast import (
    AST,
    Add,
    Assign,
    AsyncFunctionDef,
    Attribute,
    BinOp,
    Call,
    Div,
    FunctionDef,
    Mult,
    Name,
    Pow,
    Return,
    Sub,
    Subscript,
    UAdd,
    UnaryOp,
    USub,
)
from dataclasses import dataclass
from fractions import Fraction

from geolint.factbase.syntax import last_name, number
from geolint.factbase.quaternion_components import component_index
from geolint.factbase.reaching import Unpacked, value_of
from geolint.factbase.rotations import SCALAR_FIRST, SCALAR_LAST

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

Monomial = tuple[int, ...]  # sorted component indices (or letters' positions in "wxyz" for templates)
Polynomial = dict[Monomial, Fraction]

_MAX_DEPTH: Final = 10
_MAX_TERMS: Final = 24
_ATAN2: Final = frozenset({"atan2", "arctan2"})
_ASIN: Final = frozenset({"asin", "arcsin"})
_CLAMPS: Final = frozenset({"clip", "clamp"})
_LETTER_PREFIXES: Final = ("q_", "quat_", "q", "quat", "")
_WORDS: Final = {"yaw": "yaw", "heading": "yaw", "roll": "roll", "pitch": "pitch"}


@dataclass(frozen=True)
class FormulaRead:
    """`node` computes `what` from the components of `base`, read in `order`; `w_index` plays w."""

    node: ast.expr
    base: ast.expr
    order: str
    what: str
    w_index: int
    sliced: bool  # every component was read after a leading `:` / `...` (`q[:, 3]`): a stack's columns

    def evidence(self, facts: FactBase) -> str:
        return (
            f"the {self.what} formula at line {self.node.lineno}, whose w is "
            f"`{facts.code_of(self.base)}[{self.w_index}]`"
        )


# -- polynomials ---------------------------------------------------------------------------------
def _add(a: Polynomial, b: Polynomial, sign: int = 1) -> Polynomial:
    result = dict(a)
    for monomial, coefficient in b.items():
        result[monomial] = result.get(monomial, Fraction(0)) + sign * coefficient
    return {monomial: coefficient for monomial, coefficient in result.items() if coefficient != 0}


def _mul(a: Polynomial, b: Polynomial) -> Polynomial | None:
    result: Polynomial = {}
    for m1, c1 in a.items():
        for m2, c2 in b.items():
            monomial = tuple(sorted(m1 + m2))
            result[monomial] = result.get(monomial, Fraction(0)) + c1 * c2
    result = {monomial: coefficient for monomial, coefficient in result.items() if coefficient != 0}
    return result if len(result) <= _MAX_TERMS else None


def _template(text: str) -> Polynomial:
    """`"2 wz + 2 xy"`-like text as a polynomial over positions in "wxyz" (terms: coefficient, letters)."""
    result: Polynomial = {}
    for term in text.replace("- ", "+ -").split("+"):
        coefficient_text, _, letters = term.strip().partition(" ")
        if not letters:
            coefficient_text, letters = ("1", "") if not coefficient_text.lstrip("-").isdigit() else (coefficient_text, "")
        monomial = tuple(sorted("wxyz".index(letter) for letter in letters))
        result = _add(result, {monomial: Fraction(int(coefficient_text))})
    return result


# The textbook formulas (Hamilton quaternions, w the scalar): each entry is a list of equivalent
# spellings (a unit quaternion's 1 - 2(y^2 + z^2) is also w^2 + x^2 - y^2 - z^2).
_YAW: Final = ([_template("2 wz + 2 xy")], [_template("1 - 2 yy - 2 zz"), _template("1 ww + 1 xx - 1 yy - 1 zz")])
_ROLL: Final = ([_template("2 wx + 2 yz")], [_template("1 - 2 xx - 2 yy"), _template("1 ww - 1 xx - 1 yy + 1 zz")])
_PITCH: Final = [_template("2 wy - 2 xz")]
_DIAGONAL: Final = [
    [_template("1 - 2 yy - 2 zz"), _template("1 ww + 1 xx - 1 yy - 1 zz")],
    [_template("1 - 2 xx - 2 zz"), _template("1 ww - 1 xx + 1 yy - 1 zz")],
    [_template("1 - 2 xx - 2 yy"), _template("1 ww - 1 xx - 1 yy + 1 zz")],
]
_OFF_DIAGONAL: Final = {
    (0, 1): _template("2 xy - 2 wz"), (0, 2): _template("2 xz + 2 wy"),
    (1, 0): _template("2 xy + 2 wz"), (1, 2): _template("2 yz - 2 wx"),
    (2, 0): _template("2 xz - 2 wy"), (2, 1): _template("2 yz + 2 wx"),
}


def _relabelled(template: Polynomial, order: str) -> Polynomial:
    """The template over component indices when the components are stored in `order`."""
    return {tuple(sorted(order.index("wxyz"[letter]) for letter in monomial)): c for monomial, c in template.items()}


def _scale(observed: Polynomial, template: Polynomial) -> Fraction | None:
    """k > 0 with observed == k * template, else None."""
    if set(observed) != set(template):
        return None
    ratios = {observed[monomial] / template[monomial] for monomial in template}
    if len(ratios) != 1:
        return None
    ratio = ratios.pop()
    return ratio if ratio > 0 else None


# -- reading expressions as polynomials of one base's components -----------------------------------
class _Expansion:
    """The polynomial of one expression, the base whose components it reads, and the names read."""

    def __init__(self, facts: FactBase) -> None:
        self.facts = facts
        self.base: ast.expr | None = None
        self.base_key: str | None = None
        self.hints: dict[int, str] = {}  # component index -> the letter a name gave it (`q_w = q[3]`)
        self.conflict = False
        self.sliced = True

    def expand(self, node: ast.expr, depth: int = 0) -> Polynomial | None:
        if depth > _MAX_DEPTH:
            return None
        value = number(node)
        if value is not None:
            return {(): Fraction(value).limit_denominator(10**6)} if value else {}
        if isinstance(node, UnaryOp) and isinstance(node.op, (USub, UAdd)):
            inner = self.expand(node.operand, depth + 1)
            return None if inner is None else {m: -c for m, c in inner.items()} if isinstance(node.op, USub) else inner
        if isinstance(node, BinOp):
            return self._binop(node, depth)
        found = component_index(node)
        if found is not None:
            return self._component(found[0], found[1], node)
        if isinstance(node, Name):
            return self._name(node, depth)
        return None

    def _binop(self, node: BinOp, depth: int) -> Polynomial | None:
        left = self.expand(node.left, depth + 1)
        if left is None:
            return None
        if isinstance(node.op, Pow):
            exponent = number(node.right)
            if exponent not in (2, 3, 4) or isinstance(exponent, float):
                return None
            result: Polynomial | None = left
            for _ in range(int(exponent) - 1):  # type: ignore[arg-type]
                result = _mul(result, left) if result is not None else None
            return result
        if isinstance(node.op, Div):
            divisor = number(node.right)
            if not divisor:
                return None
            return {m: c / Fraction(divisor).limit_denominator(10**6) for m, c in left.items()}
        right = self.expand(node.right, depth + 1)
        if right is None:
            return None
        if isinstance(node.op, Add):
            return _add(left, right)
        if isinstance(node.op, Sub):
            return _add(left, right, -1)
        if isinstance(node.op, Mult):
            return _mul(left, right)
        return None

    def _component(self, base: ast.expr, index: int, read: ast.expr) -> Polynomial | None:
        key = ast.dump(base)
        if self.base_key is None:
            self.base, self.base_key = base, key
        elif key != self.base_key:
            return None  # components of two values: not one quaternion's formula
        if not (isinstance(read, Subscript) and isinstance(read.slice, ast.Tuple)):
            self.sliced = False
        return {(index,): Fraction(1)}

    def _name(self, node: Name, depth: int) -> Polynomial | None:
        value = value_of(self.facts.index, node)
        if value is None:
            return None
        if isinstance(value, Unpacked):
            # `x, y, z, w = q`: the position is the component, the name its stated letter
            if len(value.names) != 4 or isinstance(value.value, (ast.Tuple, ast.List)):
                return None
            result = self._component(value.value, value.index, value.value)
            if result is not None:
                self.sliced = False
                self._hint(node.id, value.index)
            return result
        result = self.expand(value, depth + 1)
        if result is not None and len(result) == 1:
            ((monomial, coefficient),) = result.items()
            if len(monomial) == 1 and coefficient == 1:
                self._hint(node.id, monomial[0])  # `q_w = q[3]`: the name says which component index 3 is
        return result

    def _hint(self, name: str, index: int) -> None:
        lowered = name.lower()
        for prefix in _LETTER_PREFIXES:
            rest = lowered[len(prefix) :]
            if lowered.startswith(prefix) and len(rest) == 1 and rest in "wxyz":
                if self.hints.get(index, rest) != rest or rest in {l for i, l in self.hints.items() if i != index}:
                    self.conflict = True
                self.hints[index] = rest
                return


# -- the formulas --------------------------------------------------------------------------------
def formula_reads(facts: FactBase) -> list[FormulaRead]:
    """Every formula of the module whose component order is decided (memoised per module)."""
    return facts.module_fact("quaternion formulas", lambda: _find(facts))


def formula_reads_within(facts: FactBase, function: AST) -> list[FormulaRead]:
    """The formulas in one function's own body (not in functions nested in it)."""
    scope_of = facts.index.scope_of
    return [read for read in formula_reads(facts) if scope_of(read.node).node is function]


def _find(facts: FactBase) -> list[FormulaRead]:
    found: list[FormulaRead | None] = []
    index = facts.index
    # the angle formulas only where the text calls one of their functions (most modules call none)
    if any(name in index.source for name in (*_ATAN2, *_ASIN)):
        for node in index.nodes(Call):
            name = last_name(node.func)  # type: ignore[attr-defined]
            if name in _ATAN2 and len(node.args) == 2 and not node.keywords:  # type: ignore[attr-defined]
                found.append(_angle(facts, node, node.args, (("yaw", _YAW), ("roll", _ROLL))))  # type: ignore[arg-type, attr-defined]
            elif name in _ASIN and len(node.args) == 1 and not node.keywords:  # type: ignore[attr-defined]
                found.append(_angle(facts, node, [_unclamped(node.args[0])], (("pitch", (_PITCH,)),)))  # type: ignore[arg-type, attr-defined]
    for kind in (ast.List, ast.Tuple):
        found.extend(_matrix(facts, node) for node in index.nodes(kind) if len(node.elts) == 3)  # type: ignore[attr-defined, arg-type]
    # in source order, as one walk would give them
    return sorted((read for read in found if read is not None), key=lambda read: (read.node.lineno, read.node.col_offset))


def _unclamped(node: ast.expr) -> ast.expr:
    """`np.clip(t, -1, 1)`, `torch.clamp(t, -1, 1)`, `t.clamp(-1, 1)`: t (clamping keeps the formula)."""
    if isinstance(node, Call) and last_name(node.func) in _CLAMPS:
        if isinstance(node.func, Attribute) and len(node.args) == 3 and isinstance(node.func.value, Name):
            return node.args[0]  # np.clip(t, lo, hi)
        if isinstance(node.func, Attribute) and len(node.args) == 2:
            return node.func.value  # t.clamp(lo, hi)
    return node


def _angle(facts: FactBase, node: Call, arguments: list[ast.expr], candidates: tuple) -> FormulaRead | None:  # type: ignore[type-arg]
    expansion = _Expansion(facts)
    polynomials = [expansion.expand(argument) for argument in arguments]
    if any(polynomial is None for polynomial in polynomials) or expansion.base is None or expansion.conflict:
        return None
    matches: set[tuple[str, str]] = set()
    for order in (SCALAR_FIRST, SCALAR_LAST):
        for what, spellings in candidates:
            scales = [
                {_scale(polynomial, _relabelled(template, order)) for template in spelled}  # type: ignore[arg-type]
                for polynomial, spelled in zip(polynomials, spellings)
            ]
            common = set.intersection(*scales) - {None} if len(scales) > 1 else scales[0] - {None}
            if what == "pitch":
                common &= {Fraction(1)}  # asin's argument is the sine itself: no free scale
            if common:
                matches.add((order, what))
    return _decided(facts, node, expansion, matches)


def _matrix(facts: FactBase, node: ast.List | ast.Tuple) -> FormulaRead | None:
    rows = node.elts
    if len(rows) != 3 or not all(isinstance(row, (ast.List, ast.Tuple)) and len(row.elts) == 3 for row in rows):
        return None
    if isinstance(facts.parent(node), (ast.List, ast.Tuple)):
        return None
    expansion = _Expansion(facts)
    entries = [[expansion.expand(entry) for entry in row.elts] for row in rows]  # type: ignore[attr-defined]
    if any(entry is None for row in entries for entry in row) or expansion.base is None or expansion.conflict:
        return None
    matches: set[tuple[str, str]] = set()
    for order in (SCALAR_FIRST, SCALAR_LAST):
        for transposed in (False, True):
            if _is_rotation_matrix(entries, order, transposed):  # type: ignore[arg-type]
                matches.add((order, "rotation-matrix"))
    matrix: ast.expr = node
    parent = facts.parent(node)
    if isinstance(parent, Call) and len(parent.args) == 1 and parent.args[0] is node:
        matrix = parent  # `np.array([[...], ...])`: the matrix is the call
    return _decided(facts, matrix, expansion, matches)


def _is_rotation_matrix(entries: list[list[Polynomial]], order: str, transposed: bool) -> bool:
    for row in range(3):
        for column in range(3):
            entry = entries[row][column]
            if row == column:
                if not any(entry == _relabelled(spelling, order) for spelling in _DIAGONAL[row]):
                    return False
            elif entry != _relabelled(_OFF_DIAGONAL[(column, row) if transposed else (row, column)], order):
                return False
    return True


def _decided(facts: FactBase, node: ast.expr, expansion: _Expansion, matches: set[tuple[str, str]]) -> FormulaRead | None:
    """One reading among the matches: the component names, then the result's name, must pick it."""
    if expansion.hints:
        matches = {(order, what) for order, what in matches if all(order[i] == letter for i, letter in expansion.hints.items())}
    if len({order for order, _ in matches}) > 1:
        word = _result_word(facts, node)
        matches = {(order, what) for order, what in matches if what == word}
    if len({order for order, _ in matches}) != 1:
        return None  # no textbook formula, or two readings the code does not choose between
    (order, what), *_ = sorted(matches)
    assert expansion.base is not None
    return FormulaRead(node, expansion.base, order, what, order.index("w"), expansion.sliced)


def _result_word(facts: FactBase, node: ast.expr) -> str | None:
    """`yaw = atan2(...)`, `return atan2(...)` in `def quat_get_yaw`: the angle the code names."""
    parent = facts.parent(node)
    names: list[str] = []
    if isinstance(parent, Assign) and len(parent.targets) == 1 and isinstance(parent.targets[0], Name):
        names.append(parent.targets[0].id)
    elif isinstance(parent, Return):
        function: AST | None = parent
        while function is not None and not isinstance(function, (FunctionDef, AsyncFunctionDef)):
            function = facts.parent(function)
        if function is not None:
            names.append(function.name)
    words = {_WORDS[word] for name in names for word in _WORDS if word in name.lower()}
    return words.pop() if len(words) == 1 else None
