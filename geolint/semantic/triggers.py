"""Building blocks of the rules' `triggers`: cheap regexes that say a file MAY hold a finding.

The engine skips parsing any file that matches no enabled rule's trigger, so a trigger must
never miss a file the rule could flag (soundness), yet be tight enough that most of a large
non-robotics tree (numpy) is skipped. `all_of` needs every part somewhere in the file.
"""

from __future__ import annotations

import re

from geolint.semantic.names import DIRECTION_WORDS, POINT_WORDS


def word(*words: str) -> str:
    """Any of `words` as a whole `_`-separated token of an identifier (or attribute)."""
    alternatives = "|".join(sorted((re.escape(w) for w in words), key=len, reverse=True))
    return f"(?<![A-Za-z0-9])(?:{alternatives})(?![A-Za-z0-9])"


def any_of(*patterns: str) -> str:
    return "(?:" + "|".join(f"(?:{pattern})" for pattern in patterns) + ")"


def compile_trigger(*conjunctions: str | tuple[str, ...]) -> re.Pattern[str]:
    """A file matches when, for at least one conjunction, EVERY pattern of it occurs in the file.

    Each lookahead is anchored at the start of the file (never nested inside another scan),
    so a search costs a few linear passes, not a quadratic one.
    """
    branches = []
    for conjunction in conjunctions:
        parts = (conjunction,) if isinstance(conjunction, str) else conjunction
        branches.append("".join(f"(?=[\\s\\S]*?(?:{part}))" for part in parts))
    return re.compile("\\A(?:" + "|".join(branches) + ")")


# A matrix product in any spelling (decorators start a line, so `@` must follow an operand).
MATMUL = any_of(r"[\w)\]]\s*@\s*[\w(\[-]", r"\.dot\(", r"\bmatmul\(")
# Something that can carry direction-ness: a direction word, or an operation that makes one.
DIRECTION_SOURCE = any_of(word(*DIRECTION_WORDS, "v", "nrm"), r"\bcross\(", r"\bnorm\(", r"unitize|normalize|unit_vector|norm_vector")
POINT_SOURCE = word(*POINT_WORDS, "p")
# A homogeneous construction: the only ways a constant w column is appended.
HOMOGENEOUS = any_of(
    r"(?<![\w.])(?:np|numpy)\.append\(|(?<![\w.])append\(",
    r"\br_\[",
    r"\bc_\[",
    r"\bones(?:_like)?\(",
    r"\bzeros(?:_like)?\(",
    r"(?:hstack|column_stack|concatenate)\(",
    r"\[\s*2\s*\]\s*,\s*[01](?:\.0*)?\s*\]",
)
TRANSLATION = any_of(word("t", "trans", "translation", "tvec", "tran"), r"\bt_\w", r"\[\s*(?:0\s*)?:\s*3\s*,\s*-?[13]\s*\]")
# A name in one of the frame conventions (an operator name or a value with a frame).
FRAME_OPERATOR = any_of(
    r"\b[TRHX]_[A-Za-z]\w*_[A-Za-z]",  # T_world_cam
    r"\b[TXHR]_[A-Z][0-9]*[A-Z]",  # X_WB
    r"[a-z0-9]_[TRHX]_[A-Za-z]",  # world_T_cam
    r"[A-Za-z0-9]_(?:from|to)_[A-Za-z]",  # world_from_cam, cam_to_world
    r"\b[A-Za-z][A-Za-z0-9]*2[A-Za-z]",  # cam2world
)
# A value name that states a frame: `p_world`, `normals_cam`, `p_BQ`, `point_in_cam`.
VALUE_WITH_FRAME = any_of(
    r"(?<![A-Za-z0-9])(?:" + "|".join(sorted(DIRECTION_WORDS | POINT_WORDS | {"p", "v"}, key=len, reverse=True)) + r")_[A-Za-z]",
    r"_in_[A-Za-z]",
)
