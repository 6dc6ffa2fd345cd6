"""Fixes as libcst transformations: how a rule's replacement becomes a fix's edit, and how edits are applied.

Analysis runs on CPython's `ast`; a rule states its fix as the new source text of the node it reports.
Here that fix becomes a transformation of the module's concrete syntax tree, the job libcst was chosen
for: the finding's node is found in the libcst tree by position (`PositionProvider`), the new text is
parsed into a node of the same kind (an expression, or one statement, or a statement followed by new
ones), and that node takes the old one's place. Everything outside the node is the tree's own: the
parentheses around it, comments, formatting, the line endings. A replacement that is not such a node
(a span that is no node, text that does not parse as one, text libcst would not write back as given)
gives no fix.

An edit (`Edit`: the node's span and its new text) is what that transformation changes, which is what
`--diff`, the language server and SARIF show; `apply_edits` applies edits by the same transformation
and writes the tree back. Only files with a fix to build or apply are parsed with libcst, and only the
top-level statements that hold a fix are located and written again; the tree of the last text is
kept, and the transformed tree is the fixed text's, so fixing a file parses it once.
"""

from __future__ import annotations

import threading
from bisect import bisect_right
from collections.abc import Iterable, Sequence
from typing import Union

import libcst as cst
from libcst.metadata import CodePosition, MetadataWrapper, PositionProvider

from geolint.source_text import split_lines
from geolint.lint_types import Edit

# (line, column, end line, end column): lines from 1, columns from 0, as libcst's positions count them
Span = tuple[int, int, int, int]
Replacement = Union[cst.CSTNode, cst.FlattenSentinel]
# a replacement in place: the top-level statement it is in, the node, what takes the node's place
Change = tuple[int, cst.CSTNode, Replacement]
_REFUSED = (cst.ParserSyntaxError, cst.CSTValidationError, RecursionError, TypeError, ValueError)


class _Tree:
    """A module's libcst tree, its text as libcst writes it, and its nodes by span.

    Positions are resolved one top-level statement at a time, for the statements an edit falls in:
    libcst's `PositionProvider` writes out what it resolves, and most of a module holds no fix."""

    def __init__(self, module: cst.Module, pieces: list[str], joined: bool, lost_tail: str) -> None:
        self.module = module
        # the header, each top-level statement and the footer, as libcst writes them
        self.pieces = pieces
        # `rendered` is the pieces joined, or libcst's `Module.code` where that differs at the end (a
        # file without a last newline); `lost_tail` is what it leaves off the text, if anything
        self.joined = joined
        self.rendered = "".join(pieces) if joined else module.code
        self.lost_tail = lost_tail
        self.statement_starts = []  # where each top-level statement starts in `rendered`
        offset = len(pieces[0])
        for piece in pieces[1:-1]:
            self.statement_starts.append(offset)
            offset += len(piece)
        self.starts = [0]  # where each line of `rendered` starts, and its length last
        for text in split_lines(self.rendered):
            self.starts.append(self.starts[-1] + len(text))
        self.resolved: set[int] = set()
        # an expression node by its span (with how many of its own parentheses the span takes in: `ast`
        # counts a tuple's parentheses as part of it, libcst as the tuple's lpar/rpar), and its statement
        self.expressions: dict[Span, tuple[cst.BaseExpression, int, int]] = {}
        # a small statement by its span (and whether the span runs on to its line's end, over a comment)
        self.statements: dict[Span, tuple[cst.BaseSmallStatement, bool, int]] = {}
        self.lines_of: dict[cst.BaseSmallStatement, cst.SimpleStatementLine] = {}  # the line each small statement is on

    def offset(self, line: int, column: int) -> int:
        return self.starts[line - 1] + column

    def resolve(self, span: Span) -> None:
        """Index the nodes of the top-level statement that holds `span` (once)."""
        where = bisect_right(self.statement_starts, self.offset(span[0], span[1])) - 1
        if where < 0 or where in self.resolved:
            return
        self.resolved.add(where)
        statement = self.module.body[where]
        alone = self.module.with_changes(header=(), body=[statement], footer=())
        positions = MetadataWrapper(alone, unsafe_skip_copy=True).resolve(PositionProvider)
        first_line = bisect_right(self.starts, self.statement_starts[where]) - 1  # 0-based: lines before it

        def span_of(start: CodePosition, end: CodePosition) -> Span:
            return (start.line + first_line, start.column, end.line + first_line, end.column)

        for node, at in positions.items():  # children before their parents: an outer node of one span wins
            if isinstance(node, cst.BaseExpression):
                self.expressions[span_of(at.start, at.end)] = (node, 0, where)
                if len(node.lpar) == len(node.rpar):
                    for inside in range(1, len(node.lpar) + 1):
                        left, right = positions[node.lpar[-inside]], positions[node.rpar[inside - 1]]
                        self.expressions.setdefault(span_of(left.start, right.end), (node, inside, where))
            elif isinstance(node, cst.BaseSmallStatement):
                self.statements[span_of(at.start, at.end)] = (node, False, where)
            elif isinstance(node, cst.SimpleStatementLine):
                for small in node.body:
                    self.lines_of[small] = node
                # the last statement up to its line's end: what an edit that adds statements below it spans
                last_start, line_end = positions[node.body[-1]].start, positions[node.trailing_whitespace.newline].start
                self.statements.setdefault(span_of(last_start, line_end), (node.body[-1], True, where))

    def changed(self, changes: Sequence[Change]) -> _Tree:
        """The tree with the changes made: only the top-level statements they are in are visited and
        written again (the text of the others is kept as it is)."""
        by_statement: dict[int, dict[cst.CSTNode, Replacement]] = {}
        for where, node, new in changes:
            by_statement.setdefault(where, {})[node] = new
        body: list[cst.BaseStatement] = []
        pieces = [self.pieces[0]]
        for where, statement in enumerate(self.module.body):
            replacements = by_statement.get(where)
            if replacements is None:
                body.append(statement)
                pieces.append(self.pieces[where + 1])
                continue
            visited = statement.visit(_Replace(replacements))
            for new_statement in visited.nodes if isinstance(visited, cst.FlattenSentinel) else [visited]:
                body.append(new_statement)  # type: ignore[arg-type]
                pieces.append(self.module.code_for_node(new_statement))  # type: ignore[arg-type]
        pieces.append(self.pieces[-1])
        module = self.module.with_changes(body=body)
        return _Tree(module, pieces, self.joined, self.lost_tail)


_last = threading.local()


def build_edits(source: str, requests: Sequence[Edit]) -> list[Edit | None]:
    """For each requested replacement (a node's span and its new text, positions as in `Finding`), the
    edit its libcst transformation makes, or None when it is not a node replacement libcst can make.
    None for all when libcst cannot read the module (or not losslessly)."""
    tree = _tree_of(source)
    if tree is None:
        return [None] * len(requests)
    edits: list[Edit | None] = []
    for request in requests:
        change = _change(tree, request)
        edits.append(None if change is None else _edit_made(tree, request, change))
    return edits


def apply_edits(source: str, edits: Iterable[Edit]) -> str | None:
    """`source` with every edit applied as the replacement of its node in the libcst tree, written back
    by libcst; None when an edit is no node replacement (the caller drops that fix)."""
    tree = _tree_of(source)
    if tree is None:
        return None
    changes: list[Change] = []
    for edit in edits:
        change = _change(tree, edit)
        if change is None or any(change[1] is other for _, other, _ in changes):
            return None
        changes.append(change)
    if not changes:
        return source
    try:
        fixed_tree = tree.changed(changes)
    except _REFUSED:
        return None  # a replacement that does not fit where it goes (libcst refuses to build the tree)
    fixed = fixed_tree.rendered + fixed_tree.lost_tail
    _last.value = (fixed, fixed_tree)  # the next fixes on the fixed text are built on this tree, unparsed
    return fixed


def _tree_of(source: str) -> _Tree | None:
    """The libcst tree of `source`, remembered for the last text asked for in this thread."""
    cached = getattr(_last, "value", None)
    if cached is not None and cached[0] is source:
        return cached[1]
    tree = _parse(source)
    _last.value = (source, tree)
    return tree


def _parse(source: str) -> _Tree | None:
    try:
        module = cst.parse_module(source)
        pieces = [
            "".join(module.code_for_node(line) for line in module.header),
            *(module.code_for_node(statement) for statement in module.body),
            "".join(module.code_for_node(line) for line in module.footer),
        ]
    except _REFUSED:
        return None  # CPython accepts it, libcst does not (or nests it too deeply): no fix, the findings stay
    if "".join(pieces) == source:
        return _Tree(module, pieces, joined=True, lost_tail="")
    rendered = module.code  # the file has no last newline (or is empty)
    if not source.startswith(rendered):
        return None  # libcst would not write this file back as it is
    return _Tree(module, pieces, joined=False, lost_tail=source[len(rendered) :])


def _change(tree: _Tree, edit: Edit) -> Change | None:
    """The node at the edit's span and what takes its place: the edit's text as a node of the same kind."""
    span = (edit.line, edit.column - 1, edit.end_line, edit.end_column - 1)
    try:
        tree.resolve(span)
    except _REFUSED:
        return None
    found = tree.expressions.get(span)
    if found is not None:
        node, inside, where = found
        new = _expression(tree.module, edit.content)
        if new is not None:  # the parentheses outside the span stay the old node's
            outer = len(node.lpar) - inside
            return where, node, new.with_changes(lpar=[*node.lpar[:outer], *new.lpar], rpar=[*new.rpar, *node.rpar[inside:]])
    statement = tree.statements.get(span)
    if statement is not None:
        old, to_line_end, where = statement
        replaced = _statements(tree, old, to_line_end, edit)
        return None if replaced is None else (where, *replaced)
    return None


def _expression(module: cst.Module, text: str) -> cst.BaseExpression | None:
    """`text` as an expression node that writes back as `text` (parsed inside parentheses, so that an
    expression spanning lines reads as it does where it stands)."""
    try:
        wrapped = cst.parse_expression(f"({text})", config=module.config_for_parsing)
    except _REFUSED:
        return None
    if not wrapped.lpar or not wrapped.rpar:
        return None
    new = wrapped.with_changes(lpar=wrapped.lpar[1:], rpar=wrapped.rpar[:-1])
    return new if module.code_for_node(new) == text else None


def _statements(tree: _Tree, old: cst.BaseSmallStatement, to_line_end: bool, edit: Edit) -> tuple[cst.CSTNode, Replacement] | None:
    """`old` replaced by the statement the edit's text starts with, and the statements after it (written
    on the lines below, at the same indentation) put after old's line. The comment at the line's end
    stays the line's, unless the edit's span takes it in (`to_line_end`; then the text has the line's
    new end)."""
    line = tree.lines_of.get(old)
    lines = split_lines(edit.content)
    first_line = tree.rendered[tree.starts[edit.line - 1] : tree.starts[edit.line]]
    indent = first_line[: len(first_line) - len(first_line.lstrip(" \t"))]
    text = lines[0] + "".join(line[len(indent) :] if line.startswith(indent) else line for line in lines[1:])
    try:
        parsed = cst.parse_module(text, config=tree.module.config_for_parsing)
    except _REFUSED:
        return None
    if not parsed.body or parsed.header or parsed.footer or not isinstance(parsed.body[0], cst.SimpleStatementLine):
        return None
    first = parsed.body[0]
    if len(first.body) != 1 or first.leading_lines:
        return None
    new, below = first.body[0].with_changes(semicolon=old.semicolon), parsed.body[1:]
    if first.trailing_whitespace.comment and not to_line_end:
        return None  # the text brings a comment the line keeps its own
    if not below and not to_line_end:
        return (old, new) if tree.module.code_for_node(first.body[0]) == edit.content else None
    if line is None or line.body[-1] is not old:
        return None  # new statements go on the lines after old's, so old must end its line
    body = [new if small is old else small for small in line.body]
    ending = first.trailing_whitespace if to_line_end else line.trailing_whitespace
    changed = line.with_changes(body=body, trailing_whitespace=ending)
    return line, cst.FlattenSentinel([changed, *below]) if below else changed


def _edit_made(tree: _Tree, request: Edit, change: Change) -> Edit | None:
    """The edit that turns the module's text into the transformed tree's: over the request's span, or
    on to the end of its last line when statements are added below a line that ends in a comment."""
    if not isinstance(change[1], cst.SimpleStatementLine):
        # one node for another, which writes back as the request's text (checked when it was parsed),
        # and a node writes the same text wherever it stands: the edit is the request
        return request
    try:
        changed = tree.changed([change]).rendered
    except _REFUSED:
        return None
    old, starts = tree.rendered, tree.starts
    start = tree.offset(request.line, request.column - 1)
    if changed[:start] != old[:start]:
        return None
    last_line = old[starts[request.end_line - 1] : starts[request.end_line]]
    line_end = starts[request.end_line - 1] + len(last_line.rstrip("\r\n"))
    for end in (tree.offset(request.end_line, request.end_column - 1), line_end):
        kept = len(old) - end
        if len(changed) - kept >= start and changed[len(changed) - kept :] == old[end:]:
            column = end - starts[request.end_line - 1] + 1
            return Edit(request.line, request.column, request.end_line, column, changed[start : len(changed) - kept])
    return None  # the transformation changed text beyond the node's line: not this edit


class _Replace(cst.CSTTransformer):
    """Puts each replacement in its node's place (nodes are matched by identity)."""

    def __init__(self, replacements: dict[cst.CSTNode, Replacement]) -> None:
        super().__init__()
        self.replacements = replacements

    def on_leave(self, original_node: cst.CSTNode, updated_node: cst.CSTNode) -> Replacement:  # type: ignore[override]
        return self.replacements.get(original_node, updated_node)
