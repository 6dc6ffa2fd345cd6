"""GEO304 quaternion-component-reused: a quaternion rebuilt from another one uses a component twice, or a
pyquaternion object written into an array slice (its w in every slot)."""

from __future__ import annotations

from typing import Final

import ast
from ast import (
    AST, AnnAssign, Assign, AsyncFunctionDef, Attribute, BinOp, Call, FunctionDef, ListComp, Mult, Name, Slice,
    Starred, Subscript,
)
import re
import string

from geolint.factbase.model import replace_span, subscript_parts
from geolint.factbase.library_calls import library_type
from geolint.factbase.rotations import quaternion_argument, quaternion_order
from geolint.knowledge import knowledge_base
from geolint.rules.fact_rule import FactRule
from geolint.factbase.vocabulary import any_match_at
from geolint.rules.base import Invalid, Valid
from geolint.factbase.quaternion_components import same_base, unwrapped_scalar
from geolint.factbase.quaternion_components import COMPONENTS
from geolint.rules.triggers import AllOf

# Words that make a name a quaternion on their own, and `q`, which needs a second witness
# (in robotics `q` is just as often a joint configuration).
_STRONG: Final = frozenset({"quat", "quats", "quaternion", "quaternions", "qvec", "qvecs", "quatern", "orientation", "orientations", "rotq"})
_WEAK: Final = frozenset({"q", "qs"})
_CYCLES: Final = ((0, 1, 2, 3), (1, 2, 3, 0), (3, 0, 1, 2))


class _NamesQuaternion:
    """Text that can hold a name `_says_quaternion` accepts: one of `_STRONG` in any case, or a word
    `q` / `qs` as `_words` splits names (`q_out`, `coreQ`, `QVec`)."""

    pattern = r"uat|UAT|qvec|Qvec|QVEC|rient|RIENT|otq|OTQ|(?:(?<![A-Za-z])q|Q)s?(?![a-z])"
    # what `_words` makes one of `_STRONG` from (`quat`, `Quat`, `QUAT`...), as plain substrings
    _STRONG_TEXT = ("uat", "UAT", "qvec", "Qvec", "QVEC", "rient", "RIENT", "otq", "OTQ")
    # `(?:(?<![A-Za-z])q|Q)s?(?![a-z])`, the left context checked in Python (the regex engine scans
    # for a leading `q` fast, and for a leading look-behind not at all)
    _WEAK_WORD = re.compile(r"[qQ]s?(?![a-z])")

    def search(self, source: str, /) -> bool:
        return any(text in source for text in self._STRONG_TEXT) or any_match_at(self._WEAK_WORD, source, _starts_a_q_word)


def _starts_a_q_word(source: str, at: int) -> bool:
    before = source[at - 1] if at else " "
    return source[at] == "Q" or before not in _ASCII_LETTERS


_ASCII_LETTERS: Final = frozenset(string.ascii_letters)


class QuaternionComponentReused(FactRule):
    """A quaternion is rebuilt from another one with a component used twice and another dropped.

    ## What it does
    Flags a 4-vector spelled out from the components of one quaternion
    (`np.array([q[1], q[2], q[2], q[0]])`, `[o.x, o.y, o.y, o.w]`) when one component appears
    twice and another never, and the code says it is a quaternion: the source or target name
    (`quat`, `quaternion`, `qvec`, `orientation`; `q` when both sides or the function say it),
    or the value is passed straight to a quaternion API (scipy `from_quat`, transforms3d
    `quat2mat`, pyquaternion `Quaternion`...).

    It also flags a library quaternion object that numpy reads as one number (its stub defines
    `__float__` and no `__len__`, `__iter__` or `__array__`: pyquaternion's `Quaternion`, built in the
    module, a name bound only to one, or its `.inverse` / `.conjugate` / `.normalised` / `.unit`)
    assigned into a slice of an array (`can_bus[3:7] = rotation`), imported directly or through a
    re-export the stubs know (the nuScenes devkit's `nuscenes.eval.common.utils`).

    ## Why is this bad?
    Converting between the scalar-first and scalar-last conventions moves each of the four
    components exactly once. A repeated index is a typo: the result is not a rotation of the
    original at all (and usually not even unit length), and nothing downstream notices.

    numpy writes an object that is not a sequence it knows into a float slice through `float()`,
    and pyquaternion defines `Quaternion.__float__` as the scalar part: the slice gets w in every
    slot (pyquaternion 0.9.9: `a[3:7] = Quaternion(0.7, 0.1, 0.2, 0.3)` gives
    `[0.7, 0.7, 0.7, 0.7]`), with no error. `rotation.q` (or `.elements`) is the (w, x, y, z) array.

    ## Example
    ```python
    def wxyz_to_xyzw(q_wxyz):
        q_xyzw = np.array([q_wxyz[1], q_wxyz[2], q_wxyz[2], q_wxyz[0]])
        return q_xyzw
    ```

    ## Use instead
    ```python
    def wxyz_to_xyzw(q_wxyz):
        q_xyzw = np.array([q_wxyz[1], q_wxyz[2], q_wxyz[3], q_wxyz[0]])
        return q_xyzw
    ```

    ## Fix safety
    When replacing one of the two repeated indices by the missing one gives a cyclic reorder
    (`[1, 2, 3, 0]`, `[3, 0, 1, 2]` or the identity), that replacement is offered as an unsafe
    fix: the intended order is a guess, however likely.

    ## Known problems
    A 4-vector that is not a quaternion but is named like one, and deliberately repeats a
    component, is flagged. Names with a bare `q` alone (a joint configuration in most robot
    code) are not enough: a second name must say quaternion too.

    A Python list given a slice of Quaternion (`values[3:7] = q`) takes its four components
    (pyquaternion's `__getitem__` makes it iterable): the rule stays silent when the target is bound
    to a list here, and flags it when the list comes from elsewhere (a dict, a parameter). A
    Quaternion reaching the slice through a project helper or an attribute is not followed.
    """

    code = "GEO304"
    name = "quaternion-component-reused"
    # an indexed component followed by another element (`q[2], `), or a `.w` component; and a name
    # `_says_quaternion` can accept (a quaternion API's name says quaternion too, or its import does)
    triggers = AllOf(r"\w\s*\[[^\[\]\n]*\d\s*\]\s*,|\.w\b|pyquaternion|nuscenes", _NamesQuaternion())  # type: ignore[assignment]

    VALID = [
        Valid("import numpy as np\ndef f(q_wxyz):\n    q_xyzw = np.array([q_wxyz[1], q_wxyz[2], q_wxyz[3], q_wxyz[0]])\n    return q_xyzw\n"),
        Valid("import numpy as np\ndef f(q):\n    coupled = np.array([q[0], q[1], q[1], q[2]])\n    return coupled\n"),  # joints
        Valid("import numpy as np\ndef f(box):\n    corners = np.array([box[0], box[1], box[1], box[2]])\n    return corners\n"),
        Valid("def f(o):\n    return [o.x, o.y, o.z, o.w]\n"),
        # the components, and a list (pyquaternion's __getitem__ makes a Quaternion iterable)
        Valid("import numpy as np\nfrom pyquaternion import Quaternion\ndef f(state, r):\n    state[3:7] = Quaternion(r).q\n"),
        Valid("from pyquaternion import Quaternion\ndef f(r):\n    values = [0.0] * 7\n    values[3:7] = Quaternion(r)\n    return values\n"),
    ]
    INVALID = [
        Invalid(
            "import numpy as np\ndef core_to_ros(q_core):\n    q_ros = np.array([q_core[1], q_core[2], q_core[2], q_core[0]])\n    return q_ros\n",
            expected_fix="import numpy as np\ndef core_to_ros(q_core):\n    q_ros = np.array([q_core[1], q_core[2], q_core[3], q_core[0]])\n    return q_ros\n",
            message="`q_core[2]` repeats a component of `q_core` and component 3 is never used: a reorder of a quaternion uses each of its four components once",
            range=(3, 45, 3, 54),
        ),
        Invalid("import numpy as np\ndef f(quat):\n    return np.array([quat[3], quat[0], quat[0], quat[2]])\n"),
        Invalid("from scipy.spatial.transform import Rotation\ndef f(v):\n    return Rotation.from_quat([v[1], v[1], v[3], v[0]])\n"),
        Invalid("def f(pose):\n    orientation = [pose.x, pose.y, pose.y, pose.w]\n    return orientation\n"),
        Invalid("from pyquaternion import Quaternion\ndef f(state, r):\n    rotation = Quaternion(r)\n    state[3:7] = rotation\n"),
    ]

    def run(self) -> None:
        facts = self.facts
        for node in facts.index.nodes(ast.List, ast.Tuple):
            elements = list(node.elts)  # type: ignore[attr-defined]
            if len(elements) != 4 or any(isinstance(element, Starred) for element in elements):
                continue
            self._check(node, elements)  # type: ignore[arg-type]
        if any(_has_float_converted_class(name) for name in facts.index.imports.values()):
            for assign in facts.index.nodes(Assign):
                if isinstance(assign, Assign):
                    self._check_slice_broadcast(assign)

    def _check_slice_broadcast(self, assign: Assign) -> None:
        """`array[3:7] = Quaternion(...)`: numpy fills the slice with the object's `float()`, one number."""
        target = assign.targets[0]
        if len(assign.targets) != 1 or not isinstance(target, Subscript) or not _has_slice(target.slice):
            return
        kb = knowledge_base()
        held = library_type(self.facts, assign.value)
        if held is None or not kb.converted_with_float(held) or self._is_list(target.value):
            return
        components = _components_attribute(held)
        if components is None:
            return
        api = kb.api(held)
        assert api is not None
        value = self.facts.code_of(assign.value)
        attribute, order = components
        self.report(
            assign.value,
            f"`{value}` is a {api.library} {held.rpartition('.')[2]} written into the slice `{self.facts.code_of(target)}`: numpy "
            f"converts it with float(), one number, so every slot holds that number; write `{value}.{attribute}` ({', '.join(order)})",
        )

    def _is_list(self, node: ast.expr) -> bool:
        """A name bound here to a Python list (a literal, `[...] * n`, a comprehension, `list(...)`)."""
        if not isinstance(node, Name):
            return False
        for value in self.facts.bindings(node) or []:
            if isinstance(value, BinOp) and isinstance(value.op, Mult):
                value = value.left if isinstance(value.left, ast.List) else value.right
            if isinstance(value, (ast.List, ListComp)):
                return True
            if isinstance(value, Call) and isinstance(value.func, Name) and value.func.id == "list":
                return True
        return False

    def _check(self, node: ast.expr, elements: list[ast.expr]) -> None:
        facts = self.facts
        by_index = same_base(facts, elements)
        if by_index is not None:
            base, positions = by_index
            components = [str(position) for position in positions]
            universe = ["0", "1", "2", "3"]
        else:
            attributes = [element for element in elements if isinstance(element, Attribute) and element.attr in COMPONENTS]
            if len(attributes) != 4 or len({ast.dump(attribute.value) for attribute in attributes}) != 1:
                return
            base = attributes[0].value
            components = [attribute.attr for attribute in attributes]
            universe = list(COMPONENTS)
            if "w" not in components:
                return  # x, y, z plus one more: a 3-vector written out, not a quaternion
        if len(set(components)) != 3:
            return
        repeated = next(component for component in components if components.count(component) == 2)
        missing = next(component for component in universe if component not in components)
        if not self._says_quaternion(node, base):
            return
        second = [i for i, component in enumerate(components) if component == repeated][1]
        shown = facts.code_of(elements[second])
        fix = self._fix(node, elements, components, repeated, missing) if by_index is not None else None
        self.report(
            elements[second],
            f"`{shown}` repeats a component of `{facts.code_of(base)}` and component {missing} is never used: "
            "a reorder of a quaternion uses each of its four components once",
            replacement=fix,
            applicability="unsafe",
            fix_description=f"use component {missing}",
        )

    def _fix(self, node: ast.expr, elements: list[ast.expr], components: list[str], repeated: str, missing: str) -> str | None:
        """Replace the one occurrence of the repeated index that makes the reorder a cycle."""
        facts = self.facts
        for position, component in enumerate(components):
            if component != repeated:
                continue
            candidate = tuple(int(missing if i == position else c) for i, c in enumerate(components))
            if candidate in _CYCLES:
                element = elements[position]
                text = facts.index.segment(element)
                old = facts.index.segment(subscript_parts(unwrapped_scalar(element))[-1])  # type: ignore[arg-type]
                at = text.rfind(old)
                if not old or at <= 0:
                    return None
                return replace_span(facts.index, element, [(element, text[:at] + missing + text[at + len(old) :])])
        return None

    def _says_quaternion(self, node: ast.expr, base: ast.expr) -> bool:
        """Whether names around the 4-vector, or the API it goes to, make it a quaternion."""
        facts = self.facts
        outer: AST = node
        parent = facts.parent(node)
        if isinstance(parent, Call) and len(parent.args) == 1 and facts.is_array_call(parent.func, "array", "asarray", "tensor"):
            outer, parent = parent, facts.parent(parent)  # np.array([...])
        if isinstance(parent, Call) and quaternion_order(facts, parent) is not None and quaternion_argument(facts, parent) is outer:
            return True
        witnesses = [_name_of(base)]
        if isinstance(parent, (Assign, AnnAssign)):
            targets = parent.targets if isinstance(parent, Assign) else [parent.target]
            witnesses += [_name_of(target) for target in targets]
        function = parent
        while function is not None and not isinstance(function, (FunctionDef, AsyncFunctionDef)):
            function = facts.parent(function)
        if function is not None:
            witnesses.append(function.name)  # type: ignore[attr-defined]
        words = [_words(name) for name in witnesses if name]
        if any(word in _STRONG or word.startswith("quat") for found in words for word in found):
            return True
        return sum(1 for found in words if any(word in _WEAK for word in found)) >= 2


def _has_slice(index: ast.expr) -> bool:
    """`a[3:7]`, `a[i, 3:7]`: an index that selects several slots."""
    return isinstance(index, Slice) or isinstance(index, ast.Tuple) and any(isinstance(part, Slice) for part in index.elts)


def _name_of(node: AST) -> str | None:
    if isinstance(node, Name):
        return node.id
    if isinstance(node, Attribute):
        return node.attr
    return None


def _words(name: str) -> list[str]:
    """`q_core` -> [q, core]; `coreQToRosQ` -> [core, q, to, ros, q]; `quat2mat` -> [quat, 2, mat]."""
    return [word.lower() for word in re.findall(r"[A-Z]?[a-z]+|[A-Z]+(?![a-z])|\d+", name)]


def _has_float_converted_class(module: str) -> bool:
    """Whether an imported name is, or is a module of a library that has, a class numpy reads as one number."""
    kb = knowledge_base()
    if kb.converted_with_float(module):
        return True
    library = kb.library_of_module(module)
    return library is not None and any(kb.library_of_module(name) is library for name in kb.classes_converted_with_float())


def _components_attribute(class_name: str) -> tuple[str, str] | None:
    """The first attribute of the class that holds its four components in a stated order (`q`: w, x, y, z)."""
    for api in knowledge_base().apis():
        if api.is_attribute and api.qualified_name.rpartition(".")[0] == class_name:
            orders = {signature.returns.quaternion_order for signature in api.signatures if signature.returns is not None}
            if len(orders) == 1 and None not in orders:
                return api.qualified_name.rpartition(".")[2], orders.pop()  # type: ignore[return-value]
    return None
