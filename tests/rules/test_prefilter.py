"""The gate is sound: wherever a rule finds something, its trigger lets the file through.

Checked on every fixture (annotated, clean, demo) and on ad-hoc flows the triggers must
follow (aliases, helpers, `import ... as`), by linting once with triggers and once without.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from geolint.engine import lint_source
from geolint.lint_types import Config
from geolint.rules import all_rules

ROOT = Path(__file__).resolve().parents[2]
SEMANTIC_RULES = [rule for rule in all_rules() if rule.code[3] in "123"]
SOURCES = sorted((ROOT / "fixtures").glob("GEO*.py")) + sorted((ROOT / "fixtures" / "demo").glob("*.py"))

FLOWS = [
    "from pyquaternion import Quaternion as PQ\nq2 = PQ(q.x, q.y, q.z, q.w)\n",
    "def f(T_world_cam, p):\n    pose = T_world_cam\n    return pose.T @ p\n",
    "import numpy as np\ndef helper(mesh):\n    return mesh.face_normals\nh = np.append(helper(m), 1)\nout = T @ h\n",
    "import numpy as np\nfor n in np.cross(a, b):\n    h = np.r_[n, 1]\n    y = T @ h\n",
    "def f(points, normals, T):\n    moved = (T[:3, :3] @ points.T).T + T[:3, 3]\n    return moved, normals\n",
    # GEO304 without a geometry word: two `q` names, a camelCase `Q`, an API known by its import
    "def f(q):\n    q_out = [q[1], q[2], q[2], q[0]]\n    return q_out\n",
    "def coreQToRosQ(qs):\n    return [qs[3], qs[0], qs[0], qs[2]]\n",
    "from quaternion import from_float_array as ffa\ndef f(v):\n    return ffa([v[1], v[1], v[3], v[0]])\n",
    # GEO304's pyquaternion object in an array slice, through a module alias
    "import pyquaternion as pyq\ndef f(a, r):\n    a[3:7] = pyq.Quaternion(r)\n",
]


def without_triggers(rule, source: str, monkeypatch: pytest.MonkeyPatch) -> list:
    with monkeypatch.context() as patch:
        patch.setattr(rule, "triggers", None)
        return [f for f in lint_source(source, "x.py", rules=[rule]) if f.code == rule.code]


@pytest.mark.parametrize("source", [path.read_text() for path in SOURCES] + FLOWS, ids=[p.name for p in SOURCES] + [f"flow{i}" for i in range(len(FLOWS))])
def test_trigger_never_hides_a_finding(source: str, monkeypatch: pytest.MonkeyPatch) -> None:
    for rule in SEMANTIC_RULES:
        unfiltered = without_triggers(rule, source, monkeypatch)
        filtered = [f for f in lint_source(source, "x.py", rules=[rule]) if f.code == rule.code]
        assert filtered == unfiltered, f"{rule.code}'s trigger hides findings"
        if unfiltered:
            assert rule.triggers.search_with(source, Config())


def test_flows_are_real_findings(monkeypatch: pytest.MonkeyPatch) -> None:
    """The ad-hoc flows above must each be flagged by some rule (else they test nothing)."""
    for source in FLOWS:
        assert any(without_triggers(rule, source, monkeypatch) for rule in SEMANTIC_RULES), source


def test_code_without_geometry_is_skipped() -> None:
    source = (
        "import numpy as np\n"
        "def summarize(table, column=0):\n"
        "    out = np.concatenate([table, np.ones(3)])\n"
        "    return np.sum(out, keepdims=True) + np.random.rand(3)\n"
    )
    assert not any(rule.triggers.search_with(source, Config()) for rule in SEMANTIC_RULES)


def test_gate_is_derived_from_the_vocabulary() -> None:
    from geolint.factbase import vocabulary
    from geolint.semantic import names

    for word in (*names.POINT_WORDS, *vocabulary.POINT_ATTRIBUTES, *vocabulary.EXTRINSICS_TOKENS):
        assert vocabulary.may_hold_geometry(f"x = {word}\n"), word
    for shape in ("T_world_cam", "world_T_cam", "cam2world", "world_from_cam", "p_world", "normal_h", "a @ b"):
        assert vocabulary.may_hold_geometry(f"x = {shape}\n"), shape


def test_decorators_and_conv2d_are_not_geometry() -> None:
    from geolint.factbase import vocabulary

    assert not vocabulary.may_hold_geometry("@property\ndef f(self):\n    return nn.Conv2d(3, 8, 3)(x)\n")


def test_config_words_widen_the_gate() -> None:
    from geolint.factbase.vocabulary import GATE_TRIGGER

    assert not GATE_TRIGGER.search("y = blob + blub\n")
    assert GATE_TRIGGER.search_with("y = blob + blub\n", Config(extra_point_names=("blob",)))


# Pieces the gate's and the pose triggers' regexes are made of, glued at random below: word
# boundaries, underscores, digits, overlapping candidates, non-ASCII word and space characters.
_PIECES = [
    "@", "@=", " ", "\n", "\t", "(", ")", "[", "]", "-", "_", "2", "0", "3", "3:", ":", ",", "=", "s", "T", "R",
    "X", "H", "t", "p", "v", ".", ".dot(", "matmul", ".mT", ".T", "_to_", "_from_", "_in_", "sin(", "cos", "tan(",
    "euler2", "axangle2", "_from_angle(", "_h", "hom", "homog", "x", "é", "٣", "\u00a0", "'", '"', "_R_", "_t_",
    "rotation", "translation", "rot", "trans", "cam", "c", "w", "world", "base", "points", "pts", "quat", "Frame",
    "lookup_transform", "do_transform_", "tf2_ros", "Vector3Stamped", ".linear", "eye(", "2mat(",
    "inv(", "cw", "wc", "[1],", "\u2003", "translate(", "q", "Q", "qs", "uat", "rient", "otq", "@\n", "\n@",  # led by `\b` or `\w\s*`, searched without the lead
    "pos", "ition", "rad", "ians", "deg2", "arc", "a", "vec", "vert", "ices", "rame", "ransform", "bmm(", "set_",  # words grouped in a `WordSet`
]  # fmt: skip


def test_fast_gates_answer_as_their_regexes() -> None:
    """The gate and the pose triggers search several simpler patterns instead of their one regex;
    on random text built from the regexes' own pieces they must answer exactly as the regex does."""
    import random
    import re

    from geolint.factbase.vocabulary import GATE, gate_matches
    from geolint.rules.triggers import POSE_PART_TEXT, AllOf

    triggers = [(POSE_PART_TEXT.search, re.compile(POSE_PART_TEXT.pattern))]
    for rule in all_rules():
        if isinstance(rule.triggers, AllOf):
            triggers += [(test.search, re.compile(test.pattern)) for test in rule.triggers.patterns]
    assert len(triggers) > 5
    rng = random.Random(20261127)
    for _ in range(20_000):
        text = "".join(rng.choice(_PIECES) for _ in range(rng.randint(1, 9)))
        assert gate_matches(text) == (GATE.search(text) is not None), text
        for fast, regex in triggers:
            assert bool(fast(text)) == (regex.search(text) is not None), (text, regex.pattern)


def test_a_word_set_finds_what_in_finds() -> None:
    """A `WordSet` looks for a word only where a shorter word or a shared part it holds occurs; it
    must answer as one `in` per word does, with and without a test on the word found."""
    import random

    from geolint.factbase.vocabulary import WordSet

    words = ["pos", "position", "positions", "rotx", "roty", "rotvec", "arccos", "arcsin", "arctan", "acos", "w2c", "cam_R_w2c", "c2w"]
    word_set = WordSet(words)
    assert sum(1 for _, is_word, _ in word_set._roots if not is_word) == 2  # `rot` and `arc`: parts, not words
    pieces = [*words, "po", "s", "ition", "rot", "x", "y", "arc", "cos", "sin", "2", "c", "w", "_", "R", " "]
    rng = random.Random(20261128)
    for _ in range(5_000):
        text = "".join(rng.choice(pieces) for _ in range(rng.randint(1, 6)))
        assert word_set.any_in(text) == any(word in text for word in words), text
        starts_r = lambda word: word.startswith("r")  # noqa: E731
        assert word_set.any_in(text, starts_r) == any(word in text and starts_r(word) for word in words), text


def test_a_regex_is_split_only_at_top_level_bars() -> None:
    from geolint.rules.triggers import _top_level_alternatives

    assert _top_level_alternatives(r"a|b(c|d)|[|]|\||[]|]x|[^]|]") == ["a", "b(c|d)", "[|]", r"\|", "[]|]x", "[^]|]"]


def test_geo304_trigger_lets_through_every_name_the_rule_accepts() -> None:
    """GEO304's text test is a superset of `_says_quaternion`'s names: any name whose words hold a
    quaternion word or a bare `q` / `qs` (generated from the letters that make them, in every case)."""
    import itertools
    import random

    from geolint.rules.rotation import geo304_quaternion_component_reused as geo304

    test = geo304._NamesQuaternion()
    generator = random.Random(304)
    letters = "qQsSuatUATvecVECrientRIENToO_1x"
    names = {"".join(generator.choice(letters) for _ in range(generator.randint(1, 8))) for _ in range(50_000)}
    names |= {"".join(parts) for parts in itertools.product(["", "a", "A", "_"], ["q", "Q", "qs", "Qs", "QS"], ["", "s", "x", "X", "_", "1"])}
    accepted = [name for name in names if any(word in geo304._STRONG or word.startswith("quat") or word in geo304._WEAK for word in geo304._words(name))]
    assert len(accepted) > 1000  # the generator does reach the words
    assert [name for name in accepted if not test.search(f" {name} ")] == []
    assert not test.search("def summarize(table):\n    return request.equal(unique)\n")
