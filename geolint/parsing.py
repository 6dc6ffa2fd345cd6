"""CPython's `ast` of any Python 3.10-3.13 module, whichever of those versions runs geolint.

`ast.parse` reads only its own interpreter's grammar: under CPython 3.11 a file with one
`type X = ...` would be a syntax error, and nothing in it would be checked. When `ast.parse`
fails, `parse_module` lowers the newer syntax to what the running parser reads and parses that,
every other token kept at its line and column:

- `type X[T] = value` (3.12) becomes `X = value`, the name moved to where `type` stood;
- type parameters, `class A[T: B](C)` and `def f[T](x)` (3.12), with defaults `[T = int]`
  (3.13), become spaces (type-parameter names used in annotations are then unbound names);
- `except* E` (3.11) becomes `except E`; a star in an index `a[*b]` or in `*args: *Ts` (3.11) a space;
- a PEP 701 f-string (3.12: its own quote, a backslash or a comment inside a replacement
  field) becomes an older f-string: nested strings take the other quote, their backslashes
  and quotes become spaces, comments become spaces, a string nested two levels deep becomes
  `(0)`. A line break inside a replacement field of a one-quote f-string `f'{a +\\n b}'` keeps
  no older f-string on its lines: such an f-string becomes a plain string of the same shape.

Only the tree comes from the lowered text: every reader keeps the original text, and the tree's
positions are the original's (UTF-8 byte columns, as `ast` gives them). What the lowering takes
out is checked first (type parameters must be names with bounds and defaults that parse), so a
file that is wrong in every version still fails: its error is the running parser's on the
lowered text, at the original position, for every supported version (`SUPPORTED_GRAMMARS`).
The common path pays nothing: the lowering runs only after `ast.parse` failed.
"""

from __future__ import annotations

import ast
import bisect
import keyword
import re
import sys
from dataclasses import dataclass
from typing import Final, NamedTuple

OLDEST_SUPPORTED: Final = (3, 10)  # the project's `requires-python`
NEWEST_SUPPORTED: Final = (3, 13)
_RUNNING: Final = sys.version_info[:2]
_NEWEST_READ: Final = max(NEWEST_SUPPORTED, _RUNNING)
# The grammars a syntax error is an error in (what GEO000's message names).
SUPPORTED_GRAMMARS: Final = f"Python {OLDEST_SUPPORTED[0]}.{OLDEST_SUPPORTED[1]}-{_NEWEST_READ[0]}.{_NEWEST_READ[1]}"


def parse_module(source: str) -> ast.Module:
    """`ast.parse(source)`, reading the syntax of Python 3.10-3.13 whatever the running version.

    Raises what `ast.parse` raises: for text that no supported version reads, the running parser's
    SyntaxError (on the lowered text, whose positions are the original's).
    """
    try:
        return ast.parse(source)
    except SyntaxError as error:
        if _RUNNING >= NEWEST_SUPPORTED or not _NEWER_SYNTAX_HINT.search(source) or _is_parser_limit(error):
            raise
        try:
            lowering = _lowering_of(source)
        except (_Unreadable, RecursionError):
            lowering = None
        if lowering is None:
            raise
    try:
        tree = ast.parse(lowering.text)
    except SyntaxError as error:
        error.text = _line_of(source, error.lineno)
        raise error from None
    lowering.restore_positions(tree)
    return tree


# Text that may hold syntax newer than 3.10's (a cheap test before the scan; py2 files seldom pass it).
_NEWER_SYNTAX_HINT: Final = re.compile(
    r"^[ \t]*type[ \t]+\w+[ \t]*[\[=]|\b(?:class|def)[ \t]+\w+[ \t]*\[|\bexcept[ \t]*\*|\b[fF][rR]?['\"]|\b[rR][fF]['\"]"
    r"|\[[ \t]*\*|:[ \t]*\*",
    re.MULTILINE,
)
# What CPython says when one of its parser's limits (not the grammar) stopped it: never lowered.
_PARSER_LIMITS: Final = ("too many nested parentheses", "too many levels of indentation", "too complex", "Exceeds the limit")


def _is_parser_limit(error: SyntaxError) -> bool:
    return any(text in str(error.msg) for text in _PARSER_LIMITS)


def _line_of(source: str, line: int | None) -> str | None:
    lines = _LINE.findall(source)
    return lines[line - 1] if line is not None and 0 < line <= len(lines) else None


_LINE: Final = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+$")


class _Unreadable(Exception):
    """Text the scanner cannot follow: the running parser's error stands."""


class _Token(NamedTuple):
    kind: str  # name, number, op, string, comment, newline (ends a logical line), nl, continuation, conversion, spec, other
    start: int
    end: int
    depth: int  # brackets open around it
    string: _String | None = None


@dataclass(frozen=True)
class _String:
    quote: str  # ' " ''' or """
    body_start: int
    body_end: int
    is_f: bool
    fields: tuple[tuple[_Token, ...], ...]  # an f-string's replacement fields (those in format specs too): their tokens


_TOKEN: Final = re.compile(
    r"(?P<space>[ \t\f]+)|(?P<newline>\r\n?|\n)|(?P<comment>#[^\r\n]*)|(?P<continuation>\\(?:\r\n?|\n))"
    r"|(?P<word>\w+)|(?P<quote>'''|\"\"\"|['\"])"
    r"|(?P<op>\*\*=?|//=?|>>=?|<<=?|->|:=|\.\.\.|[-+*/%@&|^~<>=!]=?|[()\[\]{}:;,.])"
)
_STRING_PREFIXES: Final = frozenset({"r", "u", "f", "b", "br", "rb", "fr", "rf"})
# Where a string's body may end or change meaning: a backslash, its quote, a line break (one-quote
# strings), a brace (f-strings).
_BODY_STOPS: Final = {
    (quote, is_f): re.compile("[\\\\" + quote[0] + ("" if len(quote) == 3 else "\r\n") + ("{}" if is_f else "") + "]")
    for quote in ("'", '"', "'''", '"""')
    for is_f in (False, True)
}
_MAX_FIELD_NESTING: Final = 150  # Python 3.12's own limit on f-strings nested in f-strings
_SPEC_STOPS: Final = re.compile(r"[{}\\\r\n'\"]")
_CONVERSION: Final = re.compile(r"![ \t]*\w+[ \t]*")  # 3.12 lets spaces follow it


class _Scanner:
    """Python's tokens as Python 3.12 reads them (f-strings nest), only as far as the lowering needs."""

    def __init__(self, text: str) -> None:
        self.text = text
        self.pos = 0
        self.fields_open = 0  # replacement fields around `pos`: each is a level of recursion

    def code(self, in_field: bool) -> list[_Token]:
        """The tokens from `pos` to the end of the text, or (`in_field`) to the end of a replacement field's expression."""
        text = self.text
        tokens: list[_Token] = []
        depth = 0
        while self.pos < len(text):
            start = self.pos
            char = text[start]
            if in_field and depth == 0 and (char in "}:" or (char == "!" and not text.startswith("!=", start))):
                return tokens
            match = _TOKEN.match(text, start)
            if match is None:  # a character no token starts with: the parser will say so
                tokens.append(_Token("other", start, start + 1, depth))
                self.pos = start + 1
                continue
            kind, end = match.lastgroup or "other", match.end()
            if kind == "space":
                self.pos = end
                continue
            if kind == "word":
                if text[end : end + 1] in ("'", '"') and text[start:end].lower() in _STRING_PREFIXES:
                    tokens.append(self.string(start, end, depth))
                    continue
                kind = "number" if char.isdigit() else "name"
            elif kind == "quote":
                tokens.append(self.string(start, start, depth))
                continue
            elif kind == "newline" and (depth > 0 or in_field):
                kind = "nl"
            elif kind == "op" and char in "([{":
                tokens.append(_Token(kind, start, end, depth))
                depth += 1
                self.pos = end
                continue
            elif kind == "op" and char in ")]}":
                if depth == 0 and in_field:
                    raise _Unreadable
                depth = max(depth - 1, 0)
            tokens.append(_Token(kind, start, end, depth))
            self.pos = end
        if in_field:
            raise _Unreadable
        return tokens

    def string(self, start: int, quote_start: int, depth: int) -> _Token:
        """The string literal whose prefix starts at `start` and whose quote starts at `quote_start`."""
        text = self.text
        prefix = text[start:quote_start].lower()
        quote = text[quote_start] * (3 if text.startswith(text[quote_start] * 3, quote_start) else 1)
        is_f, raw = "f" in prefix, "r" in prefix
        body_start = self.pos = quote_start + len(quote)
        stops = _BODY_STOPS[quote, is_f]
        fields: list[tuple[_Token, ...]] = []
        while True:
            match = stops.search(text, self.pos)
            if match is None:
                raise _Unreadable
            at = match.start()
            char = text[at]
            if text.startswith(quote, at):
                self.pos = at + len(quote)
                return _Token("string", start, self.pos, depth, _String(quote, body_start, at, is_f, tuple(fields)))
            if char == "\\":
                following = text[at + 1 : at + 2]
                if is_f and not raw and following == "N" and text.startswith("{", at + 2):  # \N{DEGREE SIGN}
                    close = text.find("}", at + 3)
                    if close < 0:
                        raise _Unreadable
                    self.pos = close + 1
                elif is_f and following in ("{", "}"):  # the brace still opens (or closes) a field
                    self.pos = at + 1
                else:
                    self.pos = at + (3 if text.startswith("\r\n", at + 1) else 2)
            elif char in "\r\n":  # a line break in a one-quote string
                raise _Unreadable
            elif char == "{":
                if text.startswith("{{", at):
                    self.pos = at + 2
                else:
                    self.pos = at
                    fields.extend(self.field(quote))
            elif char == "}":
                self.pos = at + (2 if text.startswith("}}", at) else 1)
            else:  # the quote character alone inside a three-quote string
                self.pos = at + 1

    def field(self, quote: str, in_spec: bool = False) -> list[tuple[_Token, ...]]:
        """The replacement field at `pos` (its opening brace) and those nested in its format spec
        (`in_spec`: this field is itself in a format spec)."""
        text = self.text
        self.pos += 1
        self.fields_open += 1
        if self.fields_open > _MAX_FIELD_NESTING:
            raise _Unreadable
        expression = self.code(in_field=True)
        if text.startswith("!", self.pos):
            conversion = _CONVERSION.match(text, self.pos)
            if conversion is None:
                raise _Unreadable
            expression.append(_Token("conversion", self.pos, conversion.end(), 0))
            self.pos = conversion.end()
        fields = [tuple(expression)]
        if text.startswith(":", self.pos):
            spec_start, too_deep = self.pos, False
            self.pos += 1
            while True:
                match = _SPEC_STOPS.search(text, self.pos)
                if match is None:
                    raise _Unreadable
                at = match.start()
                char = text[at]
                if char == "{":
                    self.pos = at
                    nested = self.field(quote, in_spec=True)
                    if in_spec:  # a field in the spec of a field in a spec: 3.12's depth, not 3.11's
                        too_deep = True
                    else:
                        fields.extend(nested)
                elif char == "}":
                    self.pos = at
                    break
                elif char == "\\":
                    self.pos = at + 2
                elif text.startswith(quote, at) or (char in "\r\n" and len(quote) == 1):
                    raise _Unreadable
                else:
                    self.pos = at + 1
            if too_deep:
                fields[0] += (_Token("spec", spec_start, self.pos, 0),)
        if not text.startswith("}", self.pos):
            raise _Unreadable
        self.pos += 1
        self.fields_open -= 1
        return fields


@dataclass(frozen=True)
class _Lowering:
    """The lowered text, and what `restore_positions` needs to give its tree the original's positions."""

    source: str
    text: str
    moved_names: tuple[tuple[int, int], ...]  # (where `type` starts, where its alias's name starts)

    def restore_positions(self, tree: ast.AST) -> None:
        """Give back the byte columns of lines where a non-ASCII character became a space, and the
        columns of type aliases' names (moved to where `type` stood)."""
        original, lowered = _LINE.findall(self.source), _LINE.findall(self.text)
        moved = {
            row: (old, new)
            for row, (old, new) in enumerate(zip(original, lowered), start=1)
            if old != new and not (old.isascii() and new.isascii())
        }
        names = dict(self._name_columns(original))
        if not moved and not names:
            return

        def column(row: int, offset: int) -> int:
            old, new = moved[row]
            return len(old[: len(new.encode("utf-8")[:offset].decode("utf-8", "replace"))].encode("utf-8"))

        for node in ast.walk(tree):
            row = getattr(node, "lineno", None)
            if row in moved:
                node.col_offset = column(row, node.col_offset)  # type: ignore[attr-defined]
            end_row = getattr(node, "end_lineno", None)
            if end_row in moved and getattr(node, "end_col_offset", None) is not None:
                node.end_col_offset = column(end_row, node.end_col_offset)  # type: ignore[attr-defined]
            if isinstance(node, ast.Name) and (node.lineno, node.col_offset) in names:
                node.col_offset, node.end_col_offset = names[node.lineno, node.col_offset]

    def _name_columns(self, lines: list[str]) -> list[tuple[tuple[int, int], tuple[int, int]]]:
        """(row, byte column of `type`) -> (byte columns of the alias's name) for each lowered type alias."""
        if not self.moved_names:
            return []
        starts = [0]
        for line in lines:
            starts.append(starts[-1] + len(line))

        def byte_column(offset: int) -> tuple[int, int]:
            row = bisect.bisect_right(starts, offset) - 1
            return row + 1, len(lines[row][: offset - starts[row]].encode("utf-8"))

        found = []
        for keyword_start, name_start in self.moved_names:
            name_end = _TOKEN.match(self.source, name_start).end()  # type: ignore[union-attr]
            found.append((byte_column(keyword_start), (byte_column(name_start)[1], byte_column(name_end)[1])))
        return found


def _lowering_of(source: str) -> _Lowering | None:
    """The text with the newer syntax the running parser lacks lowered; None when there is none."""
    tokens = _Scanner(source).code(in_field=False)
    edits = _Edits(source)
    significant = [token for token in tokens if token.kind not in ("comment", "nl", "continuation")]
    _lower_statements(source, significant, edits)
    if _RUNNING < (3, 12):
        blanked = sorted((start, end) for start, end, _ in edits.spans)  # f-strings in them go with them
        for token in significant:
            if token.string is not None and token.string.is_f and not _inside(blanked, token.start):
                edits.extend(_lowered_f_string(source, token))
    if not edits:
        return None
    return _Lowering(source, edits.applied(), tuple(edits.moved_names))


class _Edits:
    """Replacements of spans of the text, each as long as what it replaces, with the line breaks where they were."""

    def __init__(self, source: str) -> None:
        self.source = source
        self.spans: list[tuple[int, int, str]] = []
        self.moved_names: list[tuple[int, int]] = []  # (where `type` starts, where its alias's name starts)

    def __bool__(self) -> bool:
        return bool(self.spans)

    def add(self, start: int, end: int, replacement: str) -> None:
        if replacement != self.source[start:end]:
            self.spans.append((start, end, replacement))

    def extend(self, spans: list[tuple[int, int, str]]) -> None:
        for span in spans:
            self.add(*span)

    def blank(self, start: int, end: int) -> None:
        """Spaces for the span, a backslash ending each line of it but the last (the statement goes on)."""
        self.add(start, end, _blank(self.source[start:end], continue_lines=True))

    def applied(self) -> str:
        pieces, at = [], 0
        for start, end, replacement in sorted(self.spans):
            if start < at:  # inside a span already replaced (an f-string in blanked type parameters)
                continue
            pieces += [self.source[at:start], replacement]
            at = end
        pieces.append(self.source[at:])
        return "".join(pieces)


def _inside(spans: list[tuple[int, int]], offset: int) -> bool:
    """Whether `offset` lies in one of the sorted, disjoint `spans`."""
    at = bisect.bisect_right(spans, (offset, sys.maxsize)) - 1
    return at >= 0 and spans[at][0] <= offset < spans[at][1]


_LINE_BREAK: Final = re.compile(r"\r\n|\r|\n")


def _blank(text: str, continue_lines: bool) -> str:
    """`text` as spaces with its line breaks kept; `continue_lines` ends each broken line with a backslash."""
    lines = _LINE_BREAK.split(text)
    breaks = _LINE_BREAK.findall(text)
    if not continue_lines:
        return "".join(" " * len(line) + brk for line, brk in zip(lines, [*breaks, ""]))
    # an empty line gets a backslash it did not have: nothing else is on it, so no position moves
    return "".join(
        (" " * (len(line) - 1) + "\\" if line else "\\") + brk for line, brk in zip(lines, breaks)
    ) + " " * len(lines[-1])


def _placeholder(text: str) -> str:
    """A parenthesized `0` as long as `text` (a string literal nested too deep to requote), its lines kept."""
    chars = list(_blank(text, continue_lines=False))
    chars[0], chars[-1] = "(", ")"
    if len(chars) > 2 and chars[1] == " ":
        chars[1] = "0"
    return "".join(chars)


def _plain_string_of_shape(text: str) -> str:
    """A plain string literal of spaces spanning the lines `text` spans (backslash-continued)."""
    chars = list(_blank(text, continue_lines=True))
    chars[0], chars[-1] = "'", "'"
    return "".join(chars)


_COMPOUND_KEYWORDS: Final = frozenset(
    {"if", "elif", "else", "for", "while", "with", "try", "except", "finally", "def", "class", "async", "match", "case"}
)
_SUBSCRIPTABLE_KEYWORDS: Final = frozenset({"None", "True", "False"})


def _lower_statements(source: str, tokens: list[_Token], edits: _Edits) -> None:
    """Type aliases and type parameters; on 3.10, `except*` and stars in an index or annotation."""

    def text(index: int) -> str:
        return source[tokens[index].start : tokens[index].end] if 0 <= index < len(tokens) else ""

    def is_name(index: int) -> bool:
        return 0 <= index < len(tokens) and tokens[index].kind == "name" and not keyword.iskeyword(text(index))

    closer: dict[int, int] = {}
    opener_of: list[int | None] = []
    open_brackets: list[int] = []
    for index, token in enumerate(tokens):
        opener_of.append(open_brackets[-1] if open_brackets else None)
        if token.kind == "op" and text(index) in ("(", "[", "{"):
            open_brackets.append(index)
        elif token.kind == "op" and text(index) in (")", "]", "}") and open_brackets:
            closer[open_brackets.pop()] = index

    line_first = 0
    for index, token in enumerate(tokens):
        word = text(index)
        if index > 0 and tokens[index - 1].kind == "newline":
            line_first = index
        if token.kind == "name" and word in ("class", "def") and is_name(index + 1) and text(index + 2) == "[":
            _lower_type_parameters(source, tokens, index + 2, closer.get(index + 2), edits)
        elif token.kind == "name" and word == "type" and is_name(index + 1) and text(index + 2) in ("[", "="):
            starts_statement = index == 0 or tokens[index - 1].kind == "newline" or text(index - 1) == ";" or (
                text(index - 1) == ":" and tokens[index - 1].depth == 0 and text(line_first) in _COMPOUND_KEYWORDS
            )
            brackets = closer.get(index + 2) if text(index + 2) == "[" else None
            equals = index + 2 if brackets is None else brackets + 1
            if not starts_statement or text(equals) != "=" or (text(index + 2) == "[" and brackets is None):
                continue
            if brackets is not None and not _lower_type_parameters(source, tokens, index + 2, brackets, edits):
                continue
            name = tokens[index + 1]
            head = source[token.start : name.end]
            if _RUNNING < (3, 12) and "\n" not in head and "\r" not in head:
                edits.add(token.start, name.end, source[name.start : name.end].ljust(len(head)))
                edits.moved_names.append((token.start, name.start))
        elif _RUNNING < (3, 11) and token.kind == "op" and word == "*":
            after_except = text(index - 1) == "except" and text(index + 1) != ":"
            star_annotation = text(index - 1) == ":" and is_name(index - 2) and text(index - 3) == "*"
            opener = opener_of[index]
            in_index = (
                opener is not None
                and text(opener) == "["
                and text(index - 1) in ("[", ",")
                and opener > 0
                and (
                    is_name(opener - 1)
                    or text(opener - 1) in _SUBSCRIPTABLE_KEYWORDS
                    or text(opener - 1) in (")", "]", "}")
                    or tokens[opener - 1].kind == "string"
                )
            )
            if after_except or star_annotation or in_index:
                edits.add(token.start, token.end, " ")


def _lower_type_parameters(source: str, tokens: list[_Token], opener: int, closer: int | None, edits: _Edits) -> bool:
    """Blank the type parameters between `tokens[opener]` (`[`) and `tokens[closer]` when the running
    parser lacks them (3.12 lacks only defaults) and they are well formed; whether they were."""
    if closer is None or not _valid_type_parameters(source, tokens[opener + 1 : closer], tokens[opener].depth + 1):
        return False
    inside = tokens[opener + 1 : closer]
    has_default = any(t.kind == "op" and t.depth == tokens[opener].depth + 1 and source[t.start : t.end] == "=" for t in inside)
    if _RUNNING < (3, 12) or has_default:
        edits.blank(tokens[opener].start, tokens[closer].end)
    return True


def _valid_type_parameters(source: str, tokens: list[_Token], depth: int) -> bool:
    """Whether `tokens` are a type-parameter list: `T`, `T: bound`, `*Ts`, `**P`, each with an optional
    `= default`, comma-separated, at least one; bounds and defaults must parse as expressions."""
    items: list[list[_Token]] = [[]]
    for token in tokens:
        if token.kind == "op" and token.depth == depth and source[token.start : token.end] == ",":
            items.append([])
        else:
            items[-1].append(token)
    if items[-1] == [] and len(items) > 1:
        items.pop()  # a trailing comma
    for item in items:
        texts = [source[t.start : t.end] for t in item]
        star = texts[0] in ("*", "**") if texts else False
        name = 1 if star else 0
        if len(item) <= name or item[name].kind != "name" or keyword.iskeyword(texts[name]):
            return False
        rest = item[name + 1 :]
        equals = next((k for k, t in enumerate(rest) if t.depth == depth and source[t.start : t.end] == "="), len(rest))
        bound, default = rest[:equals], rest[equals + 1 :]
        if bound and (star or source[bound[0].start : bound[0].end] != ":" or not _is_expression(source, bound[1:])):
            return False
        if equals < len(rest):
            if default and texts[0] == "*" and source[default[0].start : default[0].end] == "*":
                default = default[1:]  # `*Ts = *tuple[int, ...]`
            if not _is_expression(source, default):
                return False
    return True


def _is_expression(source: str, tokens: list[_Token]) -> bool:
    if not tokens:
        return False
    if any(t.string is not None and t.string.is_f for t in tokens):
        return True  # an f-string in a bound: not checked (the running parser may not read it)
    try:
        ast.parse("(" + source[tokens[0].start : tokens[-1].end] + "\n)", mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return False
    return True


def _lowered_f_string(source: str, token: _Token) -> list[tuple[int, int, str]]:
    """Edits that make a PEP 701 f-string one the running (3.10/3.11) parser reads; [] when it needs none
    or must stay as it is (its replacement fields do not parse: the parser's error stands)."""
    string = token.string
    assert string is not None
    edits = _f_string_edits(source, string, one_quote=len(string.quote) == 1)
    if edits is not None:
        return edits
    # A line break inside a replacement field of a one-quote f-string: checked as if it had three
    # quotes, then replaced by a plain string on the same lines.
    body = list(source[string.body_start : string.body_end])
    for start, end, replacement in _f_string_edits(source, string, one_quote=False) or ():
        body[start - string.body_start : end - string.body_start] = [replacement] + [""] * (end - start - 1)
    prefix, quote = source[token.start : string.body_start - 1], string.quote * 3
    try:
        ast.parse("(" + prefix + quote + "".join(body) + quote + "\n)", mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return []
    return [(token.start, token.end, _plain_string_of_shape(source[token.start : token.end]))]


def _f_string_edits(source: str, string: _String, one_quote: bool) -> list[tuple[int, int, str]] | None:
    """Edits inside the replacement fields of a top-level f-string (quote `string.quote`, or three of it when
    not `one_quote`); None when a field spans lines in a one-quote f-string."""
    quote = string.quote[0]
    other = "'" if quote == '"' else '"'
    edits: list[tuple[int, int, str]] = []
    for field in string.fields:
        for token in field:
            spans_lines = "\n" in source[token.start : token.end] or "\r" in source[token.start : token.end]
            if one_quote and (token.kind in ("nl", "continuation") or spans_lines):
                return None
            if token.kind in ("comment", "spec"):
                edits.append((token.start, token.end, _blank(source[token.start : token.end], continue_lines=False)))
            elif token.kind == "continuation":
                edits.append((token.start, token.start + 1, " "))
            elif token.kind == "conversion":  # `!r ` -> ` !r`: the older grammar has no space after it
                conversion = source[token.start : token.end]
                edits.append((token.start, token.end, "".join(conversion.split()).rjust(len(conversion))))
            elif token.string is not None:
                edits.append(_nested_string(source, token, quote, other, one_quote))
    return edits


def _nested_string(source: str, token: _Token, quote: str, other: str, one_quote: bool) -> tuple[int, int, str]:
    """A string literal inside a replacement field, as the older grammar reads it there: in the other
    quote, without backslashes or either quote in its body; `(0)` when that cannot be (an f-string with
    strings of its own, a line break the field may not hold)."""
    string = token.string
    assert string is not None
    text = source[token.start : token.end]
    body = source[string.body_start : string.body_end]
    prefix = source[token.start : string.body_start - len(string.quote)]
    if string.is_f:
        requotable = not any(char in body for char in (quote, other, "\\", "#"))
        new_body = body
    else:
        requotable = True
        new_body = "".join(" " if char in (quote, other, "\\") else char for char in body)
    line_break = "\n" in new_body or "\r" in new_body
    if not requotable or (line_break and (one_quote or len(string.quote) == 1)):
        return token.start, token.end, _placeholder(text)
    new_quote = other * len(string.quote)
    return token.start, token.end, prefix + new_quote + new_body + new_quote
