"""Rule triggers: cheap text tests the engine's prefilter runs on a module's source before any tree
is walked (`AllOf`), and the texts the pose rules look for (`POSE_PART_TEXT`, `MATMUL_TEXT`)."""

from __future__ import annotations

import re
from typing import Final, Protocol

from geolint.factbase.vocabulary import WordSet, any_match_at, is_word_character, matrix_product_at


class AllOf:
    """A rule trigger: the source matches every pattern (a cheap gate before any tree is walked).

    A pattern is a regex, or an object with `search(text)` (`POSE_PART_TEXT`). A regex is searched
    one top-level alternative at a time, a plain word with `in`: the regex engine scans quickly
    for a pattern's first characters, and an alternation of many has no first character to scan for.
    """

    def __init__(self, *patterns: str | TextTest) -> None:
        self.patterns = tuple(_text_test(pattern) for pattern in patterns)
        self._last: tuple[str, bool] | None = None  # rules sharing a trigger ask about the same text in a row

    def search(self, source: str, /) -> bool:
        last = self._last
        if last is not None and last[0] is source:
            return last[1]
        found = all(pattern.search(source) for pattern in self.patterns)
        self._last = (source, found)
        return found

    def search_with(self, source: str, config: object, /) -> bool:
        """The engine's prefilter entry point (no configuration read)."""
        return self.search(source)


class AnyOf:
    """A text test that passes when one of its tests does (regexes, or objects with `search`)."""

    def __init__(self, *tests: str | TextTest) -> None:
        self.tests = tuple(_text_test(test) for test in tests)

    @property
    def pattern(self) -> str:  # on demand: a test's pattern may be read from the knowledge base
        return "|".join(f"(?:{test.pattern})" for test in self.tests)

    def search(self, source: str, /) -> bool:
        return any(test.search(source) for test in self.tests)


class _MatrixProductText:
    """An `@` between two operands (`a @ b`, `x @= T`), never a decorator's."""

    pattern = r"[\w)\]]\s*@=?\s*[\w(\[-]"

    def search(self, source: str, /) -> bool:
        return matrix_product_at(source)


class TextTest(Protocol):
    @property
    def pattern(self) -> str: ...

    def search(self, source: str, /) -> object: ...


class _AnyAlternative:
    """A regex as its top-level alternatives, each searched on its own (plain words with `in`)."""

    def __init__(self, pattern: str) -> None:
        self.pattern = pattern
        alternatives = _top_level_alternatives(pattern)
        literals = [_literal(part) for part in alternatives]
        self.words = WordSet(literal for literal in literals if literal)
        self.regexes = tuple(_regex_test(part) for part, literal in zip(alternatives, literals) if not literal)

    def search(self, source: str, /) -> bool:
        return self.words.any_in(source) or any(regex.search(source) for regex in self.regexes)


def _literal(pattern: str) -> str | None:
    r"""The text a regex matches when it is plain text (`matmul\(` -> `matmul(`), else None: searched
    with `in`, as part of a `WordSet`, about twice as fast as the regex engine finds a literal."""
    text = _ESCAPED_PUNCTUATION.sub(r"\1", pattern)
    return text if text and re.escape(text) == pattern else None


_ESCAPED_PUNCTUATION: Final = re.compile(r"\\([^\w\s])")


def _regex_test(pattern: str) -> re.Pattern[str] | _LeftContext:
    r"""The regex, or for one led by `\b` or `\w\s*` the rest of it with that lead checked in Python:
    the regex engine scans quickly for the rest's first characters (`inv(`, `[`), and not at all for
    a lead that can start anywhere."""
    for lead, check in ((r"\b", _at_word_boundary), (r"\w\s*", _after_word_and_spaces)):
        rest = pattern[len(lead) :]
        if pattern.startswith(lead) and rest and rest[0] not in "*+?{|" and not rest.startswith(r"\s"):
            return _LeftContext(re.compile(rest), check)
    return re.compile(pattern)


class _LeftContext:
    """`lead + rest` searched as `rest`, each match kept when `accept(source, start)` holds for its lead."""

    def __init__(self, rest: re.Pattern[str], accept) -> None:  # type: ignore[no-untyped-def]
        self.rest = rest
        self.accept = accept

    def search(self, source: str) -> bool:
        return any_match_at(self.rest, source, self.accept)


def _at_word_boundary(source: str, at: int) -> bool:
    r"""`\b` at `at`: a word character on exactly one side."""
    before = at > 0 and is_word_character(source[at - 1])
    return before != (at < len(source) and is_word_character(source[at]))


def _after_word_and_spaces(source: str, at: int) -> bool:
    r"""`\w\s*` ends at `at`: past any whitespace before it, a word character."""
    at -= 1
    while at >= 0 and source[at].isspace():
        at -= 1
    return at >= 0 and is_word_character(source[at])


def _text_test(pattern: str | TextTest) -> TextTest:
    return _AnyAlternative(pattern) if isinstance(pattern, str) else pattern


def _top_level_alternatives(pattern: str) -> list[str]:
    """`a|b(c|d)|[|]` -> ["a", "b(c|d)", "[|]"]: split at `|` outside groups and character classes."""
    parts, current, depth, position = [], [], 0, 0
    in_class = False
    while position < len(pattern):
        character = pattern[position]
        if character == "\\":
            current.append(pattern[position : position + 2])
            position += 2
            continue
        if in_class:
            if character == "]" and not _opens_class_at(pattern, position):
                in_class = False
        elif character == "[":
            in_class = True
        elif character == "(":
            depth += 1
        elif character == ")":
            depth -= 1
        elif character == "|" and depth == 0:
            parts.append("".join(current))
            current = []
            position += 1
            continue
        current.append(character)
        position += 1
    parts.append("".join(current))
    return parts


def _opens_class_at(pattern: str, position: int) -> bool:
    """A `]` right after `[` or `[^` is a literal member of the class, not its end."""
    return pattern[position - 1] == "[" or (pattern[position - 2 : position] == "[^")


class _PosePartText:
    """Source text that can hold a pose's rotation or translation: a `[:3, 3]`-style slice, a part
    attribute or key, or `R, t` unpacked together. `search` answers as `pattern` would, faster
    (the unpacking alternative starts at every word and backtracks through it, and a top-level
    alternation of regexes with different first characters is searched about ten times slower than
    each of them on its own)."""

    pattern = (
        r"\[[^\]\n]*:\s*3\s*,\s*(?:3|-1|3:)|\.(?:rotation|translation|R|t|rot|trans|tvec)\b"
        r"|['\"]\w*(?:_R_|_t_|rotation|translation)\w*['\"]|['\"](?:R|t)['\"]"
        r"|\b\w*(?:R|rot|rotation)\w*\s*,\s*\w*(?:t|trans|translation)\w*\s*="
    )
    _SLICE = re.compile(r"\[[^\]\n]*:\s*3\s*,\s*(?:3|-1|3:)")
    _ATTRIBUTE = re.compile(r"\.(?:rotation|translation|R|t|rot|trans|tvec)\b")
    _QUOTED_LETTER = tuple(f"{a}{letter}{b}" for letter in "Rt" for a in "'\"" for b in "'\"")
    _KEY_WORDS = tuple(re.compile(word) for word in ("_R_", "_t_", "rotation", "translation"))
    # `\b\w*(?:R|rot|rotation)\w*\s*,...`: the `\b\w*` lead always holds (a word starts at a boundary),
    # so the rest, led by `R` or `rot`, which the regex engine scans for quickly (`t` and `translation`
    # hold a `t`)
    _UNPACKED = tuple(re.compile(rf"{lead}\w*\s*,\s*\w*t\w*\s*=") for lead in ("R", "rot"))

    def search(self, source: str, /) -> bool:
        # cheapest first; the quoted letters, eight scans of the text, rarely decide
        return (
            self._SLICE.search(source) is not None
            or self._ATTRIBUTE.search(source) is not None
            or any(unpacked.search(source) is not None for unpacked in self._UNPACKED)
            or any(any_match_at(word, source, _inside_quoted_word) for word in self._KEY_WORDS)
            or any(text in source for text in self._QUOTED_LETTER)
        )


def _inside_quoted_word(source: str, start: int) -> bool:
    r"""`['"]\w*<word>\w*['"]` for a word of word characters at `start`: the word around it is quoted on both sides."""
    end = start
    while start > 0 and is_word_character(source[start - 1]):
        start -= 1
    while end < len(source) and is_word_character(source[end]):
        end += 1
    return start > 0 and source[start - 1] in "'\"" and end < len(source) and source[end] in "'\""


POSE_PART_TEXT: Final = _PosePartText()
MATMUL_TEXT: Final = AnyOf(_MatrixProductText(), r"\.dot\(|matmul\(|bmm\(|einsum\(")
