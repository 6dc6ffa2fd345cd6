"""pymavlink's facts in stubs/pymavlink, checked against pymavlink where it installs (skipped where it does not:
the dev extra does not install it). The orders and units are read from the stubs, not restated here."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from geolint.knowledge import RADIANS, SCALAR_FIRST, knowledge_base
from tests.knowledge.facts_helpers import QUARTER_TURN_Z, _quarter_turn, _stated

pytest.importorskip("pymavlink")
from pymavlink import quaternion, rotmat
from pymavlink.dialects.v20 import common


def test_quaternion_base_holds_the_stated_order() -> None:
    order = _stated("pymavlink.quaternion.QuaternionBase.q", "q.q()", "return")
    assert order == SCALAR_FIRST
    held = quaternion.QuaternionBase(_quarter_turn(order))  # type: ignore[arg-type]
    assert np.allclose(held.dcm, QUARTER_TURN_Z)
    assert np.allclose(held.q, _quarter_turn(order))  # type: ignore[arg-type]


def test_quaternion_base_euler_is_in_the_stated_unit() -> None:
    unit = _stated(
        "pymavlink.quaternion.QuaternionBase.euler",
        "q.euler()",
        "return",
        field="angle_unit",
    )
    assert unit == RADIANS
    roll, pitch, yaw = quaternion.QuaternionBase(_quarter_turn(SCALAR_FIRST)).euler
    assert np.allclose([roll, pitch, yaw], [0.0, 0.0, math.pi / 2])


def test_matrix3_reads_and_returns_the_stated_unit() -> None:
    assert (
        _stated(
            "pymavlink.rotmat.Matrix3.from_euler",
            "m.from_euler(r, p, y)",
            "yaw",
            field="angle_unit",
        )
        == RADIANS
    )
    returned = _stated(
        "pymavlink.rotmat.Matrix3.to_euler", "m.to_euler()", "return", field="items"
    )
    assert [part.angle_unit for part in returned] == [RADIANS] * 3  # type: ignore[attr-defined]
    matrix = rotmat.Matrix3()
    matrix.from_euler(0.0, 0.0, math.pi / 2)
    rows = [[row.x, row.y, row.z] for row in (matrix.a, matrix.b, matrix.c)]
    assert np.allclose(rows, QUARTER_TURN_Z)
    assert np.allclose(matrix.to_euler(), [0.0, 0.0, math.pi / 2])
    rotated = rotmat.Matrix3()
    rotated.from_euler(0.0, 0.0, 0.0)
    rotated.rotate_yaw(math.pi / 2)
    assert np.allclose(
        [[row.x, row.y, row.z] for row in (rotated.a, rotated.b, rotated.c)],
        QUARTER_TURN_Z,
    )


def test_set_attitude_target_carries_the_stated_order_through_the_wire() -> None:
    order = _stated(
        "pymavlink.dialects.v20.common.MAVLink.set_attitude_target_send",
        "m.set_attitude_target_send(0, 1, 1, 0, q, 0, 0, 0, 0.5)",
        "q",
    )
    mav = common.MAVLink(None)
    message = mav.set_attitude_target_encode(
        0, 1, 1, 0, _quarter_turn(order), 0, 0, 0, 0.5
    )  # type: ignore[arg-type]
    decoded = mav.decode(bytearray(message.pack(mav)))
    # the autopilot side reads the field with pymavlink's own (w, x, y, z) quaternion
    assert np.allclose(
        quaternion.QuaternionBase(list(decoded.q)).dcm, QUARTER_TURN_Z, atol=1e-6
    )


def test_every_stated_mavlink_parameter_is_documented_so_by_the_generated_code() -> (
    None
):
    """Each `*_send`/`*_encode` parameter the stub states in radians or (w, x, y, z) is documented so in the
    installed dialect's docstring (MAVLink's message definitions)."""
    library = knowledge_base().libraries["pymavlink"]
    checked = 0
    for api in library.apis.values():
        owner, _, method = api.qualified_name.rpartition(".")
        if not owner.endswith("common.MAVLink"):
            continue
        doc = getattr(common.MAVLink, method).__doc__ or ""
        for parameter in api.signatures[0].parameters:
            geometry = parameter.geometry
            if geometry is None or (
                geometry.angle_unit is None and geometry.quaternion_order is None
            ):
                continue
            row = next(
                line
                for line in doc.splitlines()
                if line.strip().startswith(parameter.name + " ")
            )
            if geometry.angle_unit == RADIANS:
                assert "[rad]" in row, (method, parameter.name, row)
            else:
                assert geometry.quaternion_order == SCALAR_FIRST and re.search(
                    r"w, x, y, z", row
                ), (method, parameter.name, row)
            checked += 1
    assert checked >= 20
