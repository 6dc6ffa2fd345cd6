"""The answers the fact base gives, as types: a frame fact with its evidence, a matrix product's
operands, a homogeneous construction; and the constants its questions are asked with (the naming
orders `T_a_b` is read in, the kinds of geometric values and of operators)."""

from __future__ import annotations

import ast
from dataclasses import dataclass
from typing import Final

from geolint.algebra import Kind
from geolint.semantic.names import NameFrames

DST_FIRST: Final = "dst-first"
SRC_FIRST: Final = "src-first"
GEOMETRIC: Final = frozenset({Kind.POINT, Kind.VECTOR, Kind.DIRECTION})
OPERATORS: Final = frozenset({Kind.TRANSFORM, Kind.ROTATION})


@dataclass(frozen=True)
class Homogeneous:
    """A homogeneous 4-vector (or N x 4 array) built from `inner` with the constant `w`.

    `construction` is the expression that builds it; `fixed` the source text of that expression
    with the other w (0 <-> 1), ready to be a fix's replacement.
    """

    inner: ast.expr
    w: int
    construction: ast.expr
    fixed: str | None  # None when the w is set elsewhere (inside a helper): no fix here
    # False when only the use can tell a homogeneous w from a padded coordinate
    # (`np.column_stack((xy, np.zeros(n)))` lifts 2D points to z = 0).
    explicit: bool = True


@dataclass(frozen=True)
class MatMul:
    """`left @ right` in any spelling (`@`, `.dot`, `np.dot`, `np.matmul`, `torch.matmul`)."""

    node: ast.expr
    left: ast.expr
    right: ast.expr


@dataclass(frozen=True)
class FrameFact:
    """Frames and the evidence they rest on (strongest source first)."""

    frames: NameFrames
    evidence: tuple[str, ...] = ()
    declared: bool = False  # an explicit declaration, not a name
