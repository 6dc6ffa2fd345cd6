"""GEO304's second shape: a pyquaternion Quaternion object written into an array slice, which numpy fills
with the object's float() (pyquaternion's is the scalar part w). Which values count as Quaternion objects, which targets
are left alone, and the imports that make `Quaternion` pyquaternion's."""

from __future__ import annotations

import textwrap

from geolint.engine import lint_source
from geolint.rules import rule_by_code

RULES = [rule_by_code("GEO304")]


def findings(source: str) -> list[tuple[int, str]]:
    found = lint_source(textwrap.dedent(source), "dataset.py", rules=RULES)
    return [(finding.line, finding.message) for finding in found]


def lines(source: str) -> list[int]:
    return [line for line, _ in findings(source)]


def test_a_quaternion_through_the_nuscenes_reexport_into_a_feature_slice() -> None:
    source = """
    from nuscenes.eval.common.utils import quaternion_yaw, Quaternion

    def data_info(info):
        rotation = Quaternion(info["ego2global_rotation"])
        features = info["can_bus"]
        features[:3] = info["ego2global_translation"]
        features[3:7] = rotation
        return features, quaternion_yaw(rotation)
    """
    ((line, message),) = findings(source)
    assert line == 8
    assert "`rotation` is a pyquaternion Quaternion written into the slice `features[3:7]`" in message
    assert "every slot holds that number" in message and "`rotation.q` (w, x, y, z)" in message


def test_built_in_place_through_a_module_import_and_a_two_dimensional_slice() -> None:
    source = """
    import pyquaternion

    def fill(table, i, r):
        table[i, 3:7] = pyquaternion.Quaternion(r).conjugate
    """
    assert lines(source) == [5]


def test_components_elements_and_lists_are_silent() -> None:
    source = """
    from pyquaternion import Quaternion

    def fill(state, r):
        q = Quaternion(r)
        state[3:7] = q.q
        state[3:7] = q.elements
        state[3] = q.w
        row = [0.0] * 7
        row[3:] = q
        names = list("abcdefg")
        names[3:7] = q
        return state, row, names
    """
    assert lines(source) == []


def test_another_libraries_quaternion_or_an_unknown_value_is_silent() -> None:
    source = """
    from pyquaternion import Quaternion as PQ
    from geometry_msgs.msg import Quaternion

    def fill(state, msg, maybe):
        state[3:7] = Quaternion(x=0.0, y=0.0, z=0.0, w=1.0)
        state[3:7] = maybe
        state[3:7] = msg.orientation
        q = PQ(maybe) if maybe else None
        state[3:7] = q
    """
    assert lines(source) == []
