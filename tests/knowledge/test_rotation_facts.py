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

from geolint.algebra import Kind
from geolint.knowledge import agreed, bind, knowledge_base
from tests.knowledge.facts_helpers import (
    QUARTER_TURN_Z,
    _quarter_turn,
    _quaternion_parts,
    _same_rotation,
    _stated,
)


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


class TestPytransform3d:
    rotations = pytest.importorskip("pytransform3d.rotations")
    transformations = pytest.importorskip("pytransform3d.transformations")
    NAME = "pytransform3d.rotations"

    @pytest.mark.parametrize(("name", "call", "parameter"), [
        ("matrix_from_quaternion", "matrix_from_quaternion(q)", "q"),
        ("quaternion_xyzw_from_wxyz", "quaternion_xyzw_from_wxyz(q)", "q_wxyz"),
        ("quaternion_wxyz_from_xyzw", "quaternion_wxyz_from_xyzw(q)", "q_xyzw"),
    ])  # fmt: skip
    def test_quaternions_are_read_in_the_stated_order(self, name: str, call: str, parameter: str) -> None:
        order = _stated(f"{self.NAME}.{name}", call, parameter)
        produced = getattr(self.rotations, name)(_quarter_turn(order))
        if name == "matrix_from_quaternion":
            assert np.allclose(produced, QUARTER_TURN_Z)
        else:  # a converter: what it returns is in the stub's return order
            returned = _stated(f"{self.NAME}.{name}", call, "return")
            assert returned != order
            assert _same_rotation(_quaternion_parts(produced, returned), _quaternion_parts(_quarter_turn(returned), returned))  # type: ignore[arg-type]

    def test_producers_return_the_stated_order(self) -> None:
        for call, produced in (
            ("quaternion_from_matrix(R)", self.rotations.quaternion_from_matrix(QUARTER_TURN_Z)),
            ("quaternion_from_euler(e, 0, 1, 2, False)", self.rotations.quaternion_from_euler([0.0, 0.0, math.pi / 2], 0, 1, 2, False)),
            ("quaternion_from_angle(2, a)", self.rotations.quaternion_from_angle(2, math.pi / 2)),
        ):
            name = call.partition("(")[0]
            order = _stated(f"{self.NAME}.{name}", call, "return")
            assert _same_rotation(_quaternion_parts(produced, order), _quaternion_parts(_quarter_turn(order), order))  # type: ignore[arg-type]
        batch = pytest.importorskip("pytransform3d.batch_rotations")
        order = _stated("pytransform3d.batch_rotations.matrices_from_quaternions", "matrices_from_quaternions(Q)", "Q")
        assert np.allclose(batch.matrices_from_quaternions([_quarter_turn(order)])[0], QUARTER_TURN_Z)

    def test_angles_are_radians(self) -> None:
        assert _stated(f"{self.NAME}.matrix_from_euler", "matrix_from_euler(e, 0, 1, 2, False)", "e", "angle_unit") == "radians"
        assert np.allclose(self.rotations.matrix_from_euler([0.0, 0.0, math.pi / 2], 0, 1, 2, False), QUARTER_TURN_Z)
        assert _stated(f"{self.NAME}.active_matrix_from_angle", "active_matrix_from_angle(2, a)", "angle", "angle_unit") == "radians"
        assert np.allclose(self.rotations.active_matrix_from_angle(2, math.pi / 2), QUARTER_TURN_Z)
        assert _stated(f"{self.NAME}.euler_from_matrix", "euler_from_matrix(R, 0, 1, 2, False)", "return", "items") == (
            _stated(f"{self.NAME}.euler_from_quaternion", "euler_from_quaternion(q, 0, 1, 2, False)", "return", "items")
        )
        assert np.allclose(self.rotations.euler_from_matrix(QUARTER_TURN_Z, 0, 1, 2, False), [0.0, 0.0, math.pi / 2])

    def test_transform_from_pq_returns_a_transform(self) -> None:
        assert _stated("pytransform3d.transformations.transform_from_pq", "transform_from_pq(pq)", "return", "kind") == "transform"
        half = math.sqrt(0.5)
        pose = self.transformations.transform_from_pq([1.0, 2.0, 3.0, half, 0.0, 0.0, half])  # w first
        assert np.allclose(pose[:3, :3], QUARTER_TURN_Z) and np.allclose(pose[:3, 3], [1.0, 2.0, 3.0])
        assert np.allclose(pose[3], [0.0, 0.0, 0.0, 1.0])

    def test_concat_applies_the_second_transform_after_the_first(self) -> None:
        # concat(A2B, B2C) is A2C = B2C @ A2B, as the stub's frames say (In -> To after From -> In)
        api = knowledge_base().api("pytransform3d.transformations.concat")
        assert api is not None
        a2b = self.transformations.transform_from(QUARTER_TURN_Z, [1.0, 0.0, 0.0])
        b2c = self.transformations.transform_from(np.eye(3), [0.0, 2.0, 0.0])
        assert np.allclose(self.transformations.concat(a2b, b2c), b2c @ a2b)


class TestSpatialmath:
    base = pytest.importorskip("spatialmath.base")
    spatialmath = pytest.importorskip("spatialmath")

    @pytest.mark.parametrize("call", ["q2r(q)", "q2r(q, order='xyzs')", "q2r(q, 'sxyz')"])
    def test_q2r_reads_the_stated_order(self, call: str) -> None:
        order = _stated("spatialmath.base.q2r", call, "q")
        keywords = {"order": "xyzs"} if "xyzs" in call else {}
        assert np.allclose(self.base.q2r(_quarter_turn(order), **keywords), QUARTER_TURN_Z)

    @pytest.mark.parametrize("call", ["r2q(R)", "r2q(R, order='xyzs')"])
    def test_r2q_returns_the_stated_order(self, call: str) -> None:
        order = _stated("spatialmath.base.r2q", call, "return")
        keywords = {"order": "xyzs"} if "xyzs" in call else {}
        produced = self.base.r2q(QUARTER_TURN_Z, **keywords)
        assert _same_rotation(_quaternion_parts(produced, order), _quaternion_parts(_quarter_turn(order), order))  # type: ignore[arg-type]

    def test_unit_quaternion_reads_one_vector_in_the_stated_order(self) -> None:
        order = _stated("spatialmath.UnitQuaternion", "UnitQuaternion(q)", "s")
        assert np.allclose(self.spatialmath.UnitQuaternion(_quarter_turn(order)).R, QUARTER_TURN_Z)
        # a scalar and a vector: no whole quaternion to read
        api = knowledge_base().api("spatialmath.UnitQuaternion")
        assert api is not None
        node = ast.parse("UnitQuaternion(s, v)", mode="eval").body
        assert isinstance(node, ast.Call)
        assert agreed(bind(api, node), lambda bound: bound.signature.parameter("s").geometry) is None  # type: ignore[union-attr]

    @pytest.mark.parametrize(("call", "angle"), [("rotz(a)", math.pi / 2), ("rotz(a, 'deg')", 90.0), ("rotz(a, unit='deg')", 90.0)])
    def test_rotz_reads_the_stated_unit(self, call: str, angle: float) -> None:
        unit = _stated("spatialmath.base.rotz", call, "theta", "angle_unit")
        assert unit == ("degrees" if "deg" in call else "radians")
        assert np.allclose(self.base.rotz(angle, unit="deg" if unit == "degrees" else "rad"), QUARTER_TURN_Z)

    @pytest.mark.parametrize("call", ["SE3.RPY(r, p, y)", "SE3.RPY(r, p, y, unit='deg')", "SE3.Rz(a)", "SE3.Rz(a, 'deg')"])
    def test_pose_constructors_read_the_stated_unit(self, call: str) -> None:
        method = call.partition("(")[0].rpartition(".")[2]
        first = "roll" if method == "RPY" else "theta"
        unit = _stated(f"spatialmath.SE3.{method}", call, first, "angle_unit")
        assert unit == ("degrees" if "deg" in call else "radians")
        quarter = 90.0 if unit == "degrees" else math.pi / 2
        words = {"unit": "deg" if unit == "degrees" else "rad"}
        pose = self.spatialmath.SE3.RPY(0.0, 0.0, quarter, **words) if method == "RPY" else self.spatialmath.SE3.Rz(quarter, **words)
        assert np.allclose(pose.R, QUARTER_TURN_Z)

    def test_a_pose_times_an_array_moves_it_as_the_stub_says(self) -> None:
        # the stub: `SE3 * PointArray` takes points, so the translation is applied (R p + t)
        api = knowledge_base().api("spatialmath.SE3.__mul__")
        assert api is not None
        taken = {parameter.geometry.kind for signature in api.signatures for parameter in signature.parameters if parameter.geometry is not None}
        assert Kind.POINT in taken
        pose = self.spatialmath.SE3.Trans(1.0, 0.0, 0.0) * self.spatialmath.SE3.Rz(math.pi / 2)
        assert np.allclose(np.ravel(pose * np.array([1.0, 0.0, 0.0])), [1.0, 1.0, 0.0])
        assert type(pose * pose).__name__ == "SE3"

    @pytest.mark.parametrize("call", ["T.rpy()", "T.rpy(unit='deg')", "T.rpy('deg')"])
    def test_rpy_returns_the_stated_unit(self, call: str) -> None:
        items = _stated("spatialmath.SE3.rpy", call, "return", "items")
        units = {item.angle_unit for item in items}  # type: ignore[attr-defined]
        assert units == ({"degrees"} if "deg" in call else {"radians"})
        returned = self.spatialmath.SE3.Rz(math.pi / 2).rpy(unit="deg" if "deg" in call else "rad")
        assert np.allclose(returned[2], 90.0 if "deg" in call else math.pi / 2)

