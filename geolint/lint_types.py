"""Value types shared by the linter's engine, rules, API, CLI and language server.

Everything here is a frozen dataclass so a finding or a config can be cached, hashed,
sent to a worker process and compared in tests without surprises.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum
from pathlib import Path
from typing import Literal, Mapping


# A file that does not parse (or decode, or is no notebook): the code every layer reports it under.
SYNTAX_ERROR = "GEO000"
SYNTAX_ERROR_NAME = "syntax-error"


class Severity(str, Enum):
    """How loudly a finding is reported (the LSP severities, in the same order)."""

    ERROR = "error"
    WARNING = "warning"
    INFO = "info"
    HINT = "hint"


Applicability = Literal["safe", "unsafe"]


@dataclass(frozen=True)
class Edit:
    """Replace the text between two 1-based (line, column) positions; end is exclusive."""

    line: int
    column: int
    end_line: int
    end_column: int
    content: str


@dataclass(frozen=True)
class Fix:
    """A rewrite that removes a finding. `safe` fixes never change intended behaviour."""

    applicability: Applicability
    edits: tuple[Edit, ...]
    description: str = ""


@dataclass(frozen=True)
class Finding:
    """One reported problem. Lines and columns are 1-based; end_column is exclusive."""

    path: str
    line: int
    column: int
    end_line: int
    end_column: int
    code: str
    name: str
    message: str
    severity: Severity
    fix: Fix | None = None
    # why the rule believes it, strongest evidence first ("from_frame='obj', to_frame='world' at line 12")
    evidence: tuple[str, ...] = ()
    # a frame mismatch's two frames, (expected, found): the frame the operation needs and the one it got
    frames: tuple[str, str] | None = None


@dataclass(frozen=True)
class NamingConventions:
    """Which naming conventions may assign frames to names (all on by default).

    Each switch is one key of `[tool.geolint.naming]`.
    """

    dst_first: bool = True  # T_world_cam, R_world_cam: maps cam into world
    prefix_t: bool = True  # world_T_cam
    # Drake: X_WB, R_WB, p_BQ. None (the default): only in projects that import pydrake, since
    # elsewhere `X_EQ`, `X_GOAL` are state vectors (X is control theory's state)
    monogram: bool | None = None
    from_style: bool = True  # world_from_cam, point_in_cam
    to_style: bool = True  # cam_to_world, cam2world (src first)
    suffix: bool = True  # p_world, v_cam
    # How `T_a_b` reads: "dst-first" (maps b into a), "src-first" (maps a into b), or "auto" (learned
    # from the project's own declarations and compositions; see geolint.factbase.conventions)
    order: str = "auto"


@dataclass(frozen=True)
class Config:
    """The linter's settings, read from `[tool.geolint]` of the nearest pyproject.toml.

    `source` names the file the settings came from (None for defaults), so every
    config error and every cache key can point at it.
    """

    select: tuple[str, ...] = ("GEO",)
    ignore: tuple[str, ...] = ()
    per_file_ignores: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    exclude: tuple[str, ...] = ()
    extend_exclude: tuple[str, ...] = ()
    naming: NamingConventions = NamingConventions()
    frame_aliases: Mapping[str, str] = field(default_factory=dict)
    extra_direction_names: tuple[str, ...] = ()
    extra_point_names: tuple[str, ...] = ()
    severity: Mapping[str, Severity] = field(default_factory=dict)
    # Analysis limits (geolint.guards): a file past one gets a single GEO001 finding instead.
    max_file_size: int = 1_000_000  # characters
    max_nesting_depth: int = 150  # levels of the syntax tree
    # The project's own fixes (geolint.history): shapes its git history fixed, and shapes it names
    history: bool = False
    history_limit: int = 1000  # commits read, newest first
    known_fixes: tuple[tuple[str, str, str], ...] = ()  # (before, after, reason)
    source: Path | None = None

    def __hash__(self) -> int:  # mappings are not hashable; the repr is stable
        return hash(repr(self))
