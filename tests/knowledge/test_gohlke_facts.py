"""The knowledge base's facts about Christoph Gohlke's transformations module, checked against the
copies that install here: the PyPI `transformations` (its C functions and the `_py` Python ones) and
`trimesh.transformations`. (ROS 1 `tf.transformations` and ROS 2 `tf_transformations` do not install
from PyPI; their stubs cite their source.)

Each check reads the component order or the unit from the stub (through the knowledge base), never
from a copy in this file: a stub that states the wrong order fails here.
"""

from __future__ import annotations

import math
from types import ModuleType

import numpy as np
import pytest

from geolint.knowledge import SCALAR_FIRST, SCALAR_LAST
from tests.knowledge.facts_helpers import (
    QUARTER_TURN_Z,
    _quarter_turn,
    _quaternion_parts,
    _same_rotation,
    _stated,
)

_HALF = math.sqrt(0.5)
# A quarter turn about x: (w, x) = (sqrt(1/2), sqrt(1/2)), y = z = 0, so w and z are told apart as well.
_QUARTER_TURN_X = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
_OTHER = {SCALAR_FIRST: SCALAR_LAST, SCALAR_LAST: SCALAR_FIRST}


def _modules() -> list[tuple[str, ModuleType, str]]:
    """(the name the stub is looked up by, the module, the suffix of the function names to test)."""
    found: list[tuple[str, ModuleType, str]] = []
    for name, suffixes in (("transformations", ("", "_py")), ("trimesh.transformations", ("",))):
        try:
            module = __import__(name, fromlist=["quaternion_matrix"])
        except ImportError:
            continue
        found.extend((name, module, suffix) for suffix in suffixes)
    return found


_CASES = _modules()
_IDS = [f"{name}{'(_py)' if suffix else ''}" for name, _, suffix in _CASES]
pytestmark = pytest.mark.skipif(not _CASES, reason="neither transformations nor trimesh installs here")


@pytest.mark.parametrize(("name", "module", "suffix"), _CASES, ids=_IDS)
class TestGohlkeTransformations:
    def test_quaternion_matrix_reads_the_stated_order(self, name: str, module: ModuleType, suffix: str) -> None:
        order = _stated(f"{name}.quaternion_matrix{suffix}", f"quaternion_matrix{suffix}(q)", "quaternion")
        matrix = getattr(module, f"quaternion_matrix{suffix}")
        assert np.allclose(np.asarray(matrix(_quarter_turn(order)))[:3, :3], QUARTER_TURN_Z)
        # the same four numbers in the other order are another rotation
        assert not np.allclose(np.asarray(matrix(_quarter_turn(_OTHER[order])))[:3, :3], QUARTER_TURN_Z)

    def test_euler_from_quaternion_reads_the_stated_order_and_returns_radians(self, name: str, module: ModuleType, suffix: str) -> None:
        del suffix  # defined once, in Python
        order = _stated(f"{name}.euler_from_quaternion", "euler_from_quaternion(q)", "quaternion")
        assert order == _stated(f"{name}.quaternion_matrix", "quaternion_matrix(q)", "quaternion")
        units = _stated(f"{name}.euler_from_quaternion", "euler_from_quaternion(q)", "return", "items")
        assert {item.angle_unit for item in units} == {"radians"}  # type: ignore[attr-defined]
        assert np.allclose(module.euler_from_quaternion(_quarter_turn(order)), [0.0, 0.0, math.pi / 2])

    def test_quaternion_from_euler_returns_the_stated_order(self, name: str, module: ModuleType, suffix: str) -> None:
        qualified, call = f"{name}.quaternion_from_euler{suffix}", f"quaternion_from_euler{suffix}(0, 0, a)"
        order = _stated(qualified, call, "return")
        assert _stated(qualified, call, "ak", "angle_unit") == "radians"
        produce = getattr(module, f"quaternion_from_euler{suffix}")
        produced = produce(0.0, 0.0, math.pi / 2)  # radians: a quarter turn about z
        assert _same_rotation(_quaternion_parts(produced, order), _quaternion_parts(_quarter_turn(order), order))
        about_x = np.asarray(produce(math.pi / 2, 0.0, 0.0), dtype=float)  # about x: the scalar at the stated w position only
        assert abs(about_x[order.index("w")] - _HALF) < 1e-9
        assert abs(about_x[_OTHER[order].index("w")]) < 1e-9

    def test_quaternion_from_matrix_and_about_axis_return_the_stated_order(self, name: str, module: ModuleType, suffix: str) -> None:
        matrix = np.identity(4)
        matrix[:3, :3] = _QUARTER_TURN_X
        expected = {"w": _HALF, "x": _HALF, "y": 0.0, "z": 0.0}
        for function, call, produced in (
            ("quaternion_from_matrix", "quaternion_from_matrix{}(M)", lambda f: f(matrix)),
            ("quaternion_about_axis", "quaternion_about_axis{}(a, axis)", lambda f: f(math.pi / 2, [1.0, 0.0, 0.0])),
        ):
            order = _stated(f"{name}.{function}{suffix}", call.format(suffix), "return")
            value = produced(getattr(module, f"{function}{suffix}"))
            assert _same_rotation(_quaternion_parts(value, order), expected)
        assert _stated(f"{name}.quaternion_about_axis{suffix}", f"quaternion_about_axis{suffix}(a, axis)", "angle", "angle_unit") == "radians"

    def test_multiply_conjugate_and_slerp_keep_the_stated_order(self, name: str, module: ModuleType, suffix: str) -> None:
        call = f"quaternion_multiply{suffix}(q1, q0)"
        order = _stated(f"{name}.quaternion_multiply{suffix}", call, "quaternion1")
        assert order == _stated(f"{name}.quaternion_multiply{suffix}", call, "quaternion0") == _stated(f"{name}.quaternion_multiply{suffix}", call, "return")
        quarter = _quarter_turn(order)
        half_turn = np.asarray(getattr(module, f"quaternion_multiply{suffix}")(quarter, quarter), dtype=float)
        assert _same_rotation(_quaternion_parts(half_turn, order), {"w": 0.0, "x": 0.0, "y": 0.0, "z": 1.0})
        conjugate = np.asarray(getattr(module, f"quaternion_conjugate{suffix}")(quarter), dtype=float)
        assert _stated(f"{name}.quaternion_conjugate{suffix}", f"quaternion_conjugate{suffix}(q)", "return") == order
        assert _same_rotation(_quaternion_parts(conjugate, order), {"w": _HALF, "x": 0.0, "y": 0.0, "z": -_HALF})
        slerp_order = _stated(f"{name}.quaternion_slerp{suffix}", f"quaternion_slerp{suffix}(q0, q1, t)", "return")
        unit = [{"w": 1.0, "x": 0.0, "y": 0.0, "z": 0.0}[letter] for letter in slerp_order]
        halfway = getattr(module, f"quaternion_slerp{suffix}")(unit, _quarter_turn(slerp_order), 0.5)
        eighth = {"w": math.cos(math.pi / 8), "x": 0.0, "y": 0.0, "z": math.sin(math.pi / 8)}
        assert _same_rotation(_quaternion_parts(halfway, slerp_order), eighth)

    def test_euler_matrix_and_rotation_matrix_read_radians(self, name: str, module: ModuleType, suffix: str) -> None:
        assert _stated(f"{name}.euler_matrix{suffix}", f"euler_matrix{suffix}(a, b, c)", "ak", "angle_unit") == "radians"
        assert np.allclose(np.asarray(getattr(module, f"euler_matrix{suffix}")(0.0, 0.0, math.pi / 2))[:3, :3], QUARTER_TURN_Z)
        assert _stated(f"{name}.rotation_matrix{suffix}", f"rotation_matrix{suffix}(a, d)", "angle", "angle_unit") == "radians"
        assert np.allclose(np.asarray(getattr(module, f"rotation_matrix{suffix}")(math.pi / 2, [0.0, 0.0, 1.0]))[:3, :3], QUARTER_TURN_Z)
