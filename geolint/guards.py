"""Limits that keep one hostile file from taking a run down: checked before any analysis, and before
libcst's native parser (which crashes the process on deep nesting instead of raising).

- A file longer than `max-file-size` characters is not analysed.
- CPython's parser refuses what it cannot build (absurd nesting, an integer literal past the digit
  limit): it raises, never crashes, so its verdict comes first.
- A syntax tree nested deeper than `max-nesting-depth` levels is not analysed: every analysis walks
  the tree recursively, and libcst's parse time grows with the square of an expression's depth
  (`a + b + c + ...` on one line), so the depth limit is what keeps analysis time linear in the
  file's size.

Each of these gives the file one GEO001 finding naming the limit and the config key that raises it;
the other files of the run are unaffected. There is no per-file time budget: with both limits in
place, analysing a file costs time proportional to its size.
"""

from __future__ import annotations

import ast
import sys
import functools
from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable, Sequence, TypeVar, cast

from geolint.config import enabled_codes
from geolint.lint_types import Config, Finding, Severity
from geolint.source_text import cached_ast

if TYPE_CHECKING:
    from geolint.rules.base import AstRule

# The engine's `lint_source`, whose signature the wrapper keeps for type checkers.
LintSource = TypeVar("LintSource", bound=Callable[..., "list[Finding]"])

TOO_COMPLEX = "GEO001"
TOO_COMPLEX_NAME = "too-complex-to-analyse"

# What CPython's parser says when a limit of the parser (not the grammar) is what stopped it.
_PARSER_LIMIT_MESSAGES = ("Exceeds the limit", "too complex", "maximum recursion depth")
# Fields of `ast` nodes that never hold a child node (saves a getattr per node on the depth walk).
_SCALAR_FIELDS = frozenset(
    {"ctx", "op", "id", "arg", "attr", "name", "level", "module", "kind", "type_comment", "is_async", "conversion", "simple"}
)
_CHILD_FIELDS: dict[type, tuple[str, ...]] = {}
# Python frames the analysis may use per level of the syntax tree (libcst's visitors need about five).
_FRAMES_PER_LEVEL = 10


@dataclass(frozen=True)
class LimitExceeded:
    """Where a file went past a limit and what to say about it."""

    line: int
    column: int
    message: str


def exceeded_limit(source: str, config: Config, measure_depth: bool = True) -> LimitExceeded | None:
    """The first limit `source` exceeds (size, CPython's parser, nesting depth), or None.

    Parses with CPython's `ast` (through the engine's cache), which raises rather than crashes;
    a plain syntax error is not a limit (None: the engine reports it as GEO000). Without
    `measure_depth` the caller measures the depth itself (the engine does it on the fact base's
    walk of the tree, `depth_limit_finding`).
    """
    if len(source) > config.max_file_size:
        return LimitExceeded(
            1,
            1,
            f"file not analysed: {len(source):,} characters is more than the limit of {config.max_file_size:,}; "
            f"raise `max-file-size` in [tool.geolint] to analyse it",
        )
    try:
        tree = cached_ast(source)
    except (RecursionError, MemoryError):
        return _too_deep_for_cpython(source)
    except SyntaxError as error:
        if any(text in str(error.msg) for text in _PARSER_LIMIT_MESSAGES):
            return LimitExceeded(
                error.lineno or 1,
                max(error.offset or 1, 1),
                f"file not analysed: Python's parser refuses it ({error.msg})",
            )
        return None
    except ValueError:  # null bytes: a syntax error, reported by the engine
        return None
    return too_deep(tree, config.max_nesting_depth) if measure_depth else None


def past_depth_limit(at: ast.AST | None, limit: int) -> LimitExceeded:
    """What to say about a tree nested deeper than `limit`, first past it at `at` (see `too_deep`)."""
    return LimitExceeded(
        getattr(at, "lineno", 1),
        getattr(at, "col_offset", 0) + 1,
        f"file not analysed: its syntax tree is nested more than {limit} levels deep here; "
        f"raise `max-nesting-depth` in [tool.geolint] to analyse it",
    )


def make_room_for_recursion(config: Config) -> None:
    """Let the analysis recurse through a tree as deep as the configured limit allows.

    The recursion limit is raised (never lowered) once for the process: Python 3.11+ keeps
    pure-Python calls off the C stack, so the deeper recursion stays safe.
    """
    needed = config.max_nesting_depth * _FRAMES_PER_LEVEL + 1000
    if needed > sys.getrecursionlimit():
        sys.setrecursionlimit(needed)


def limit_finding(path: str, config: Config, limit: LimitExceeded) -> list[Finding]:
    """The one finding of a file past a limit (none when GEO001 is turned off: the file is skipped)."""
    if not enabled_codes(config, path, (TOO_COMPLEX,)):
        return []
    return [
        Finding(
            path=path,
            line=limit.line,
            column=limit.column,
            end_line=limit.line,
            end_column=limit.column + 1,
            code=TOO_COMPLEX,
            name=TOO_COMPLEX_NAME,
            message=limit.message,
            severity=config.severity.get(TOO_COMPLEX, Severity.WARNING),
        )
    ]


def too_deep_becomes_a_finding(lint_source: LintSource) -> LintSource:
    """Wraps the engine's `lint_source`: a RecursionError in the analysis becomes the file's GEO001.

    The depth limit keeps the known shapes out; this catches the ones it measures too low (libcst
    nests what `ast` keeps flat, e.g. thousands of adjacent string literals).
    """

    @functools.wraps(lint_source)
    def guarded(
        source: str, path: str = "<string>", config: Config = Config(), rules: Sequence[type[AstRule]] | None = None
    ) -> list[Finding]:
        try:
            return lint_source(source, path, config, rules)
        except RecursionError:
            return limit_finding(
                path,
                config,
                LimitExceeded(
                    1,
                    1,
                    "file not analysed: an expression in it is nested too deeply for the analysis; "
                    "split long expressions (e.g. thousands of adjacent string literals)",
                ),
            )

    return cast(LintSource, guarded)


def too_deep(tree: ast.AST, limit: int) -> LimitExceeded | None:
    """Walk the tree level by level (no recursion); stop at the first level past `limit`."""
    level: list[ast.AST] = [tree]
    depth = 0
    while level:
        depth += 1
        if depth > limit:
            return past_depth_limit(next((node for node in level if hasattr(node, "lineno")), None), limit)
        children: list[ast.AST] = []
        for node in level:
            names = _CHILD_FIELDS.get(node.__class__)
            if names is None:
                names = _CHILD_FIELDS[node.__class__] = tuple(n for n in node._fields if n not in _SCALAR_FIELDS)
            for name in names:
                value = getattr(node, name, None)
                if value.__class__ is list:
                    children.extend(item for item in value if isinstance(item, ast.AST))
                elif isinstance(value, ast.AST):
                    children.append(value)
        level = children
    return None


def _too_deep_for_cpython(source: str) -> LimitExceeded:
    return LimitExceeded(
        1,
        1,
        "file not analysed: Python's own parser gives up on it (nested too deeply: a very long chain of "
        "operators, calls or attribute accesses, or thousands of `elif` branches); this Python cannot "
        "compile it either",
    )
