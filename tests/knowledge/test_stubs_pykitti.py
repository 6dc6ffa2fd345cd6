"""pykitti's facts in stubs/pykitti, checked against pykitti where it installs (skipped where it does not: the dev
extra does not install it). The unit and kinds are read from the stub."""

from __future__ import annotations

import math

import numpy as np
import pytest

from geolint.algebra import Kind
from geolint.knowledge import RADIANS
from tests.knowledge.facts_helpers import QUARTER_TURN_Z, _stated

utils = pytest.importorskip("pykitti.utils")

_QUARTER_TURN_X = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
_QUARTER_TURN_Y = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]])


@pytest.mark.parametrize(
    ("name", "expected"),
    [("rotx", _QUARTER_TURN_X), ("roty", _QUARTER_TURN_Y), ("rotz", QUARTER_TURN_Z)],
)
def test_elementary_rotations_read_the_stated_unit(
    name: str, expected: np.ndarray
) -> None:
    unit = _stated(f"pykitti.utils.{name}", f"{name}(t)", "t", field="angle_unit")
    assert unit == RADIANS
    assert (
        _stated(f"pykitti.utils.{name}", f"{name}(t)", "return", field="kind")
        is Kind.ROTATION
    )
    matrix = getattr(utils, name)(math.pi / 2)
    assert np.allclose(matrix, expected)
    assert abs(np.linalg.det(matrix) - 1.0) < 1e-12 and np.allclose(
        matrix @ matrix.T, np.eye(3)
    )


def test_transform_from_rot_trans_makes_the_stated_pose() -> None:
    assert (
        _stated(
            "pykitti.utils.transform_from_rot_trans",
            "transform_from_rot_trans(R, t)",
            "return",
            field="kind",
        )
        is Kind.TRANSFORM
    )
    assert (
        _stated(
            "pykitti.utils.transform_from_rot_trans",
            "transform_from_rot_trans(R, t)",
            "t",
            field="kind",
        )
        is Kind.TRANSLATION
    )
    t = np.array([1.0, 2.0, 3.0])
    pose = utils.transform_from_rot_trans(QUARTER_TURN_Z, t)
    assert pose.shape == (4, 4)
    point = np.array([1.0, 0.0, 0.0, 1.0])
    assert np.allclose(
        pose @ point, [1.0, 3.0, 3.0, 1.0]
    )  # R p + t: the rotation first, then the translation


def test_pose_from_oxts_packet_returns_a_rotation_and_a_translation() -> None:
    parts = _stated(
        "pykitti.utils.pose_from_oxts_packet",
        "pose_from_oxts_packet(packet, scale)",
        "return",
        field="items",
    )
    assert [part.kind for part in parts] == [Kind.ROTATION, Kind.TRANSLATION]  # type: ignore[attr-defined]

    class Packet:
        lat, lon, alt = 0.0, 0.0, 10.0
        roll, pitch, yaw = 0.0, 0.0, math.pi / 2  # radians, as rotz reads them

    rotation, translation = utils.pose_from_oxts_packet(Packet(), 1.0)
    assert np.allclose(rotation, QUARTER_TURN_Z)
    assert np.allclose(translation, [0.0, 0.0, 10.0])
