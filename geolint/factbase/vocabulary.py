"""The one vocabulary of the fact base: library semantics keyed by qualified names, and the words
the cheap per-file gate looks for (derived from the same tables, never synced by hand).

Names of variables (what `normals` or `T_world_cam` state) live in `geolint.semantic.names`; this
module holds what libraries mean. The gate (`may_hold_geometry`) is a regex built from both.
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import Callable, Final, Iterable

from geolint.knowledge import knowledge_base
from geolint.knowledge.markers import ArrayOperation
from geolint.semantic import names
from geolint.semantic.names import NameFrames

# Packages that are never the project's own modules (no summary is looked for in them): these, and every
# package of the knowledge base (`is_third_party_root`).
_UNSTUBBED_THIRD_PARTY_ROOTS: Final = frozenset(
    {
        "math", "os", "sys", "re", "json", "typing", "collections",
        "matplotlib", "sklearn", "pandas", "yaml", "logging", "pathlib",
        "functools", "itertools",
    }
)  # fmt: skip


def is_third_party_root(top: str) -> bool:
    """Whether an import's first name is a package that is never one of the project's own modules."""
    return top in _UNSTUBBED_THIRD_PARTY_ROOTS or knowledge_base().library_of_module(top) is not None


# Module names that are never geometric values themselves (`np.random.normal` is not a normal): the standard
# library's, and the array namespaces' by their stubs (`knowledge_base().array_module_names()`).
STDLIB_MODULE_LIKE: Final = frozenset({"math", "random", "os", "sys"})


def is_module_name(name: str) -> bool:
    return name in STDLIB_MODULE_LIKE or name in knowledge_base().array_module_names()

DIRECTION_ATTRIBUTES: Final = frozenset({"normals", "vertex_normals", "face_normals", "normal"})
POINT_ATTRIBUTES: Final = frozenset({"vertices", "points", "centroid", "origin", "position"})

# Calls that return their first argument's value, reshaped, copied or moved between devices.
PASSTHROUGH_FUNCTIONS: Final = frozenset(
    {
        "asarray", "array", "copy", "asanyarray", "ascontiguousarray", "atleast_1d", "atleast_2d",
        "squeeze", "float64", "float32", "tensor", "as_tensor", "from_numpy", "clone",
    }
)  # fmt: skip
PASSTHROUGH_METHODS: Final = frozenset(
    {"copy", "astype", "reshape", "squeeze", "flatten", "ravel", "clone", "detach", "cpu", "cuda", "to", "float", "double", "numpy", "contiguous", "view"}
)
# Calls that return a unit vector.
UNIT_FUNCTIONS: Final = frozenset({"unitize", "normalize", "normalized", "unit_vector", "norm_vector", "normalize_vector"})
NORM_FUNCTIONS: Final = frozenset({"norm", "vector_norm"})
INVERSE_FUNCTIONS: Final = frozenset({"inv", "invert_transform", "inverse_transform", "invert", "pinv"})
INVERSE_METHODS: Final = frozenset({"inv", "inverse", "Inverse", "inverted", "inverse_transform"})
# Joins along the last axis that can append a w column (`torch.cat([x, ones], dim=-1)`).
STACKING_FUNCTIONS: Final = frozenset({"hstack", "column_stack", "concatenate", "cat", "concat"})

# Attributes that state a convention in so many words (pycolmap, BOP, nerfstudio-style names).
DECLARING_ATTRIBUTES: Final[dict[str, NameFrames]] = {
    "cam_from_world": NameFrames(dst="camera", src="world", operator="transform"),
    "world_from_cam": NameFrames(dst="world", src="camera", operator="transform"),
    "cam_R_w2c": NameFrames(dst="camera", src="world", operator="rotation"),
    "cam_t_w2c": NameFrames(frame="camera"),
}
# Abbreviations NeRF, SLAM and dataset code uses for camera extrinsics, in names and dict keys
# (`c2w`, `pose_c2w`, `meta["w2c"]`): the direction is in the word itself.
EXTRINSICS_TOKENS: Final[dict[str, NameFrames]] = {
    "c2w": NameFrames(dst="world", src="camera", operator="unknown"),
    "w2c": NameFrames(dst="camera", src="world", operator="unknown"),
    "cam2world": NameFrames(dst="world", src="camera", operator="unknown"),
    "world2cam": NameFrames(dst="camera", src="world", operator="unknown"),
}

DECLARING_ATTRIBUTE_SOURCES: Final = {
    "cam_from_world": "pycolmap: world to camera",
    "world_from_cam": "pycolmap: camera to world",
    "cam_R_w2c": "BOP: world to camera",
    "cam_t_w2c": "BOP: world to camera",
}

# --- the gate ---------------------------------------------------------------------------------

_GATE_WORDS: Final = sorted(
    # point names: GEO103 needs nothing but `+` of two of them, GEO102 a w = 0 pad of one;
    # direction names need a product, a `_h` name or a library call, all gated on their own
    names.POINT_WORDS
    | POINT_ATTRIBUTES
    | set(EXTRINSICS_TOKENS)
    | set(DECLARING_ATTRIBUTES)
    | {"quat", "quaternion", "euler", "rotvec", "axangle", "rpy", "Quaternion", "Rx", "Ry", "Rz", "RPY", "Eul"}
    | {"rotx", "roty", "rotz", "transform_points", "vector_to_point", "vector_to_direction", "do_transform_cloud"}
    | {"matrix_world", "from_frame", "to_frame", "as_frames", "lookup_transform", "lookupTransform", "Frame", "SE3"}
    | {"tform"}  # Boston Dynamics' `odom_tform_body`
)
_FRAME_WORDS: Final = "|".join(sorted(names.KNOWN_FRAMES | {"c", "w", "cam"}))
# Structure every rule needs one of: a matrix product (not a decorator), a transpose, a frame-naming
# shape built from the known frame words (`T_a_b`, `a_T_b`, `X_WB`, `cam2world`, `world_from_cam`,
# `p_world`), a homogeneous name (`p_h`), trig of something, or one of the words above in a name.
GATE: Final = re.compile(
    r"[\w)\]]\s*@=?\s*[\w(\[-]|\.dot\(|matmul|einsum\(|\.m?T\b|\b[TRXH]_[A-Za-z0-9]|_[TRXH]_|"
    rf"\b(?:{_FRAME_WORDS})[0-9]*(?:2|_to_|_from_|_in_)(?:{_FRAME_WORDS})|\b[pv]_(?:{_FRAME_WORDS})\b|"
    r"_h\b|_hom|homog|\b(?:sin|cos|tan)\(|euler2|axangle2|_from_angle\(|QuaternionFromEuler\(|"
    r"(?:\b|_)(?:" + "|".join(re.escape(word) for word in _GATE_WORDS) + r")(?:\b|_|s\b)",
)


# The same test, written so that each part starts with a literal or a small set of characters (which
# the regex engine scans for in C) and checks a leading word boundary in Python at each candidate:
# `GATE.search` tries every alternative at every position and cost as much as half the parse. Each
# `_*_CANDIDATE` is searched again from one past its last start, so overlapping candidates are seen.
# Alternatives that start with different literals are separate regexes: the engine scans for one
# literal fast, and for the first characters of several far slower (3x on gate-failing files).
_AFTER_AT: Final = re.compile(r"@=?\s*[\w(\[-]")
_PRODUCT_TEXTS: Final = (".dot(", "matmul", "einsum(", "_hom", "homog")  # plain text: `in` finds it faster than a regex
_TRANSPOSE_OR_PRODUCT: Final = tuple(re.compile(part) for part in (r"\.m?T\b", "_[TRXH]_", r"_h\b"))
_NAMED_OPERATOR_CANDIDATE: Final = re.compile(r"[TRXH]_[A-Za-z0-9]")
_FRAMES: Final = frozenset(_FRAME_WORDS.split("|"))
_FRAME_PAIR_CANDIDATES: Final = tuple(re.compile(rf"{connector}(?:{_FRAME_WORDS})") for connector in ("2", "_to_", "_from_", "_in_"))
_FRAME_VECTOR_CANDIDATE: Final = re.compile(rf"[pv]_(?:{_FRAME_WORDS})\b")
_TRIG_CANDIDATES: Final = tuple(re.compile(rf"{name}\(") for name in ("sin", "cos", "tan"))
# one regex per word, looked for only where the word occurs at all
_WORD_CANDIDATES: Final = {word: re.compile(re.escape(word) + r"(?:\b|_|s\b)") for word in _GATE_WORDS}


class WordSet:
    """Whether words of a set occur in a text, in fewer scans of it than one `in` per word: a word is
    looked for only where a shorter word of the set within it occurs (`pos`, then `position`), and
    words that share a part of three letters or more, three words or more, only where that part
    occurs (`rot`, then `rotvec`, `rotx`, `roty`). The answer never depends on the grouping, only
    the cost (most texts hold few of the words)."""

    def __init__(self, words: Iterable[str]) -> None:
        self.words = tuple(dict.fromkeys(words))
        self._tree: tuple[_WordNode, ...] | None = None  # built on first use: a run served from the cache never asks

    @property
    def _roots(self) -> tuple[_WordNode, ...]:
        if self._tree is None:
            self._tree = _word_tree(self.words)
        return self._tree

    def any_in(self, source: str, accept: Callable[[str], bool] | None = None) -> bool:
        """Whether a word of the set occurs in `source` (and `accept(word)` holds for it)."""
        roots = self._tree
        if roots is None:
            roots = self._roots
        return _any_found(roots, source, accept)


_WordNode = tuple[str, bool, tuple]  # type: ignore[type-arg]  # (text, a word of the set, nodes within it)


def _word_tree(words: tuple[str, ...]) -> tuple[_WordNode, ...]:
    """The words as a forest: each under the longest other word or shared part it contains."""
    parts = set(words)
    roots = [word for word in words if not any(other != word and other in word for other in words)]
    while True:  # shared parts, the one most root words hold first
        counts: dict[str, int] = {}
        for word in roots:
            for part in {word[i:j] for i in range(len(word)) for j in range(i + _SHARED_PART, len(word) + 1)}:
                counts[part] = counts.get(part, 0) + 1
        shared = [part for part, count in counts.items() if count >= _SHARED_BY and part not in parts]
        if not shared:
            break
        best = max(shared, key=lambda part: (counts[part], len(part), part))
        parts.add(best)
        roots = [word for word in roots if best not in word] + [best]

    def node(text: str) -> _WordNode:
        inner = [other for other in parts if other != text and text in other]
        direct = [other for other in inner if not any(middle != other and middle in other for middle in inner)]
        return (text, text in words, tuple(node(other) for other in sorted(direct, key=words_first)))

    def words_first(text: str) -> tuple[bool, int, str]:
        return (text not in words, len(text), text)

    tops = [part for part in parts if not any(other != part and other in part for other in parts)]
    return tuple(node(part) for part in sorted(tops, key=words_first))


_SHARED_PART: Final = 3  # letters
_SHARED_BY: Final = 3  # words


def _any_found(nodes: tuple[_WordNode, ...], source: str, accept: Callable[[str], bool] | None) -> bool:
    for text, is_word, inner in nodes:
        if text in source:
            if is_word and (accept is None or accept(text)):
                return True
            if inner and _any_found(inner, source, accept):
                return True
    return False


_GATE_WORD_SET: Final = WordSet(_GATE_WORDS)


def is_word_character(character: str) -> bool:
    return character == "_" or character.isalnum()  # exactly `\w` for str patterns


def _starts_a_word(source: str, start: int) -> bool:
    r"""`\b` before a word character at `start`."""
    return start == 0 or not is_word_character(source[start - 1])


def any_match_at(pattern: re.Pattern[str], source: str, accept) -> bool:  # type: ignore[no-untyped-def]
    """Whether `accept(source, start)` holds at the start of a match anywhere (overlapping ones included)."""
    match = pattern.search(source)
    while match is not None:
        if accept(source, match.start()):
            return True
        match = pattern.search(source, match.start() + 1)
    return False


def matrix_product_at(source: str) -> bool:
    r"""`[\w)\]]\s*@=?\s*[\w(\[-]`: an `@` between operands (a decorator follows a line break)."""
    at = source.find("@")
    while at >= 0:
        if _AFTER_AT.match(source, at):
            before = at - 1
            while before >= 0 and source[before].isspace():
                before -= 1
            if before >= 0 and (is_word_character(source[before]) or source[before] in ")]"):
                return True
        at = source.find("@", at + 1)
    return False


def _frame_pair_ends_at(source: str, connector: int) -> bool:
    r"""`\b(?:frame)[0-9]*` right before `connector` (`cam2world`, `base_to_cam`)."""
    start = connector
    while start > 0 and is_word_character(source[start - 1]):
        start -= 1
    digits = connector
    while digits > start and source[digits - 1] in "0123456789":
        digits -= 1
    return any(source[start:end] in _FRAMES for end in range(digits, connector + 1))


def _after_boundary_or_underscore(source: str, start: int) -> bool:
    return _starts_a_word(source, start) or source[start - 1] == "_"


def gate_matches(source: str) -> bool:
    """Exactly `GATE.search(source) is not None`, several times faster."""
    return (
        matrix_product_at(source)
        or any(text in source for text in _PRODUCT_TEXTS)
        or any(part.search(source) is not None for part in _TRANSPOSE_OR_PRODUCT)
        or _GATE_WORD_SET.any_in(source, lambda word: any_match_at(_WORD_CANDIDATES[word], source, _after_boundary_or_underscore))
        or any_match_at(_NAMED_OPERATOR_CANDIDATE, source, _starts_a_word)
        or any(any_match_at(candidate, source, _frame_pair_ends_at) for candidate in _FRAME_PAIR_CANDIDATES)
        or any_match_at(_FRAME_VECTOR_CANDIDATE, source, _starts_a_word)
        or any(any_match_at(candidate, source, _starts_a_word) for candidate in _TRIG_CANDIDATES)
        or "euler2" in source
        or "axangle2" in source
        or "_from_angle(" in source
        or "QuaternionFromEuler(" in source  # pybullet's getQuaternionFromEuler (radians)
    )


@lru_cache(maxsize=1)
def _knowledge_words() -> WordSet:
    """The names of the knowledge base's APIs (`getRotationMatrix2D`, `rpyToMatrix`...): a call to one
    is something the rules reason about (an API that states only the class it returns, `concatenate`, is
    not: what a rule reads is called on its result), and of the functions the stubs mark as matrix products
    (`torch.bmm`, `x.mm`), which the text tests above do not all catch. Built on first use, from stubs/."""
    kb = knowledge_base()
    geometric = {api.qualified_name.rpartition(".")[2] for api in kb.apis() if api.states_geometry}
    return WordSet(sorted(geometric | kb.array_operation_names(ArrayOperation.MATMUL, ArrayOperation.EINSUM)))


def _knowledge_call_named(source: str) -> bool:
    """A call of a knowledge-base API by its name (`name(` after a word boundary or a dot)."""
    return _knowledge_words().any_in(source, lambda word: any_match_at(_call_of(word), source, _starts_a_word))


@lru_cache(maxsize=None)
def _call_of(word: str) -> re.Pattern[str]:
    return re.compile(re.escape(word) + r"\s*\(")


class Gate:
    """The rules' prefilter: a file the gate does not match holds nothing any fact rule reasons about.

    Derived from the vocabulary above, `geolint.semantic.names` and the knowledge base's API names (never
    a second hand-synced list); the config's extra point/direction names and frame aliases widen it.
    """

    description = "mentions geometry: a product, a transpose, a frame-naming shape or a geometry word"

    def __init__(self) -> None:
        self._last: tuple[str, bool] | None = None  # every rule asks about the same text in a row

    def search(self, source: str) -> bool:
        last = self._last
        if last is not None and last[0] is source:
            return last[1]
        found = gate_matches(source) or _knowledge_call_named(source)
        self._last = (source, found)
        return found

    def search_with(self, source: str, config: object) -> bool:
        if self.search(source):
            return True
        extra = [*getattr(config, "extra_direction_names", ()), *getattr(config, "extra_point_names", ())]
        extra += [word for pair in getattr(config, "frame_aliases", {}).items() for word in pair]
        return any(word in source for word in extra)


GATE_TRIGGER: Final = Gate()


def may_hold_geometry(source: str) -> bool:
    """The cheap gate: whether a module's text mentions anything the rules could reason about."""
    return GATE_TRIGGER.search(source)
