"""The knowledge base's rotation facts, checked against the libraries themselves where they install.

Each check reads the component order or the unit from the stub (through the knowledge base), builds
a quarter turn about z in that order or unit, and compares what the library computes with the matrix
of that turn: a stub that says the wrong order fails here.
"""

from __future__ import annotations

import ast
import math

import numpy as np
import pytest

from geolint.knowledge import agreed, bind, knowledge_base
from tests.knowledge.facts_helpers import QUARTER_TURN_Z, _quarter_turn, _quaternion_parts, _same_rotation, _stated


class TestScipy:
    Rotation = pytest.importorskip("scipy.spatial.transform").Rotation
    NAME = "scipy.spatial.transform.Rotation"

    @pytest.mark.parametrize("call", ["Rotation.from_quat(q)", "Rotation.from_quat(q, scalar_first=True)", "Rotation.from_quat(q, scalar_first=False)"])
    def test_from_quat_reads_the_stated_order(self, call: str) -> None:
        order = _stated(f"{self.NAME}.from_quat", call, "quat")
        keywords = {"scalar_first": True} if "True" in call else {"scalar_first": False} if "False" in call else {}
        matrix = self.Rotation.from_quat(_quarter_turn(order), **keywords).as_matrix()  # type: ignore[arg-type]
        assert np.allclose(matrix, QUARTER_TURN_Z)

    @pytest.mark.parametrize("call", ["r.as_quat()", "r.as_quat(scalar_first=True)"])
    def test_as_quat_returns_the_stated_order(self, call: str) -> None:
        order = _stated(f"{self.NAME}.as_quat", call, "return")
        keywords = {"scalar_first": True} if "True" in call else {}
        produced = self.Rotation.from_matrix(QUARTER_TURN_Z).as_quat(**keywords)
        assert _same_rotation(_quaternion_parts(produced, order), _quaternion_parts(_quarter_turn(order), order))  # type: ignore[arg-type]

    @pytest.mark.parametrize(("call", "angle"), [("Rotation.from_euler('z', a)", math.pi / 2), ("Rotation.from_euler('z', a, degrees=True)", 90.0)])
    def test_from_euler_reads_the_stated_unit(self, call: str, angle: float) -> None:
        unit = _stated(f"{self.NAME}.from_euler", call, "angles", "angle_unit")
        assert unit == ("degrees" if "degrees=True" in call else "radians")
        keywords = {"degrees": True} if unit == "degrees" else {}
        assert np.allclose(self.Rotation.from_euler("z", angle, **keywords).as_matrix(), QUARTER_TURN_Z)


class TestTransforms3d:
    quaternions = pytest.importorskip("transforms3d.quaternions")
    euler = pytest.importorskip("transforms3d.euler")

    def test_quat2mat_reads_the_stated_order(self) -> None:
        order = _stated("transforms3d.quaternions.quat2mat", "quat2mat(q)", "q")
        assert np.allclose(self.quaternions.quat2mat(_quarter_turn(order)), QUARTER_TURN_Z)  # type: ignore[arg-type]

    def test_mat2quat_and_euler2quat_return_the_stated_order(self) -> None:
        for qualified, call, produced in (
            ("transforms3d.quaternions.mat2quat", "mat2quat(M)", self.quaternions.mat2quat(QUARTER_TURN_Z)),
            ("transforms3d.euler.euler2quat", "euler2quat(0, 0, a)", self.euler.euler2quat(0.0, 0.0, math.pi / 2)),
        ):
            order = _stated(qualified, call, "return")
            assert _same_rotation(_quaternion_parts(produced, order), _quaternion_parts(_quarter_turn(order), order))  # type: ignore[arg-type]

    def test_taitbryan_reads_and_returns_the_stated_units(self) -> None:
        taitbryan = pytest.importorskip("transforms3d.taitbryan")
        assert _stated("transforms3d.taitbryan.euler2mat", "euler2mat(z, y, x)", "z", "angle_unit") == "radians"
        assert np.allclose(taitbryan.euler2mat(math.pi / 2, 0.0, 0.0), QUARTER_TURN_Z)
        order = _stated("transforms3d.taitbryan.euler2quat", "euler2quat(z, y, x)", "return")
        assert _same_rotation(_quaternion_parts(taitbryan.euler2quat(math.pi / 2, 0.0, 0.0), order), _quaternion_parts(_quarter_turn(order), order))  # type: ignore[arg-type]
        assert np.allclose(taitbryan.mat2euler(QUARTER_TURN_Z), (math.pi / 2, 0.0, 0.0))  # radians, z first

    def test_euler2mat_reads_the_stated_unit(self) -> None:
        assert _stated("transforms3d.euler.euler2mat", "euler2mat(a, b, c)", "ak", "angle_unit") == "radians"
        assert np.allclose(self.euler.euler2mat(0.0, 0.0, math.pi / 2), QUARTER_TURN_Z)


def _components(qualified: str, call: str) -> str:
    api = knowledge_base().api(qualified)
    assert api is not None, f"{qualified} is not in the knowledge base"
    node = ast.parse(call, mode="eval").body
    assert isinstance(node, ast.Call)
    stated = agreed(bind(api, node), lambda bound: bound.signature.components)
    assert stated is not None, f"the stub of {qualified} names no component order for {call}"
    return stated


class TestPyquaternion:
    Quaternion = pytest.importorskip("pyquaternion").Quaternion
    NAME = "pyquaternion.Quaternion"

    def test_four_components_and_one_array_are_read_in_the_stated_order(self) -> None:
        components = _components(self.NAME, "Quaternion(*q)")
        assert np.allclose(self.Quaternion(*_quarter_turn(components)).rotation_matrix, QUARTER_TURN_Z)
        order = _stated(self.NAME, "Quaternion(q)", "array")
        assert np.allclose(self.Quaternion(_quarter_turn(order)).rotation_matrix, QUARTER_TURN_Z)  # type: ignore[arg-type]
        order = _stated(self.NAME, "Quaternion(array=q)", "array")
        assert np.allclose(self.Quaternion(array=_quarter_turn(order)).rotation_matrix, QUARTER_TURN_Z)  # type: ignore[arg-type]

    def test_elements_and_angles(self) -> None:
        order = _stated(f"{self.NAME}.elements", "q.elements()", "return")
        quarter = self.Quaternion(matrix=QUARTER_TURN_Z)
        assert _same_rotation(_quaternion_parts(quarter.elements, order), _quaternion_parts(_quarter_turn(order), order))  # type: ignore[arg-type]
        assert _stated(self.NAME, "Quaternion(axis=a, angle=t)", "angle", "angle_unit") == "radians"
        assert np.allclose(self.Quaternion(axis=[0, 0, 1], angle=math.pi / 2).rotation_matrix, QUARTER_TURN_Z)
        assert _stated(self.NAME, "Quaternion(axis=a, degrees=t)", "degrees", "angle_unit") == "degrees"
        assert np.allclose(self.Quaternion(axis=[0, 0, 1], degrees=90.0).rotation_matrix, QUARTER_TURN_Z)


class TestNumpyQuaternion:
    quaternion = pytest.importorskip("quaternion")

    def test_constructor_and_float_arrays_use_the_stated_order(self) -> None:
        components = _components("quaternion.quaternion", "quaternion(*q)")
        turn = self.quaternion.quaternion(*_quarter_turn(components))
        assert np.allclose(self.quaternion.as_rotation_matrix(turn), QUARTER_TURN_Z)
        order = _stated("quaternion.from_float_array", "from_float_array(a)", "a")
        assert np.allclose(self.quaternion.as_rotation_matrix(self.quaternion.from_float_array(_quarter_turn(order))), QUARTER_TURN_Z)
        order = _stated("quaternion.as_float_array", "as_float_array(q)", "return")
        produced = self.quaternion.as_float_array(self.quaternion.from_rotation_matrix(QUARTER_TURN_Z))
        assert _same_rotation(_quaternion_parts(produced, order), _quaternion_parts(_quarter_turn(order), order))  # type: ignore[arg-type]

    def test_numpy_gains_the_dtype_on_import(self) -> None:
        assert np.quaternion is self.quaternion.quaternion  # what METADATA.toml's [extends] states
        assert knowledge_base().extension("numpy.quaternion", ["quaternion"]) is knowledge_base().api("quaternion.quaternion")
        assert knowledge_base().extension("numpy.quaternion", ["numpy"]) is None
