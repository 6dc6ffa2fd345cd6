"""A module's text as the linter reads it: its lines as `ast` and libcst count them (`split_lines`),
and its `ast` parsed once for everyone who asks in a row (`cached_ast`). Below the engine and the
fact base alike: the syntax check, the suppression scanner, the rules' prefilter and the fact base's
source spans all read the same lines and tree."""

from __future__ import annotations

import ast
import re
import threading

from geolint.parsing import parse_module

_last_tree = threading.local()


def cached_ast(source: str) -> ast.Module:
    """`parse_module(source)` (CPython's `ast`, Python 3.10-3.13 syntax read under any of them),
    remembered for the last text parsed in this thread.

    The engine's syntax check, the suppression scanner and the rules' prefilter all need the
    `ast` of the same text in a row; parsing it once saves a full parse per file.
    Raises what `ast.parse` raises.
    """
    cached = getattr(_last_tree, "value", None)
    if cached is not None and cached[0] is source:
        return cached[1]
    tree = parse_module(source)
    _last_tree.value = (source, tree)
    return tree


def remember_tree(source: str, tree: ast.Module) -> None:
    """Make `tree` (parsed elsewhere: a shared parse) the one `cached_ast(source)` returns."""
    _last_tree.value = (source, tree)


LINE_BREAK = re.compile(r"(?<=\n)|(?<=\r)(?!\n)")


def split_lines(source: str) -> list[str]:
    """The lines of `source` with their endings, split only at \\n, \\r\\n and \\r (as libcst and
    tokenize count lines; `str.splitlines` also splits at form feeds and would shift positions)."""
    if _OTHER_LINE_BREAKS.search(source) is None:  # the usual text: `str.splitlines` splits it the same, faster
        return source.splitlines(keepends=True)
    return [line for line in LINE_BREAK.split(source) if line]


# What `str.splitlines` splits at besides \n, \r\n and \r.
_OTHER_LINE_BREAKS = re.compile("[\v\f\x1c\x1d\x1e\x85\u2028\u2029]")
