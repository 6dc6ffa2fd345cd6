"""pycolmap's facts in stubs/, checked against pycolmap where it installs (skipped where it does not: the
dev extra does not install it)."""

from __future__ import annotations

import numpy as np
import pytest

from tests.knowledge.facts_helpers import QUARTER_TURN_Z, _quarter_turn, _quaternion_parts, _same_rotation, _stated

pycolmap = pytest.importorskip("pycolmap")


def test_rotation3d_reads_and_holds_the_stated_order() -> None:
    order = _stated("pycolmap.Rotation3d", "Rotation3d(q)", "xyzw")
    rotation = pycolmap.Rotation3d(np.array(_quarter_turn(order)))
    assert np.allclose(rotation.matrix(), QUARTER_TURN_Z)
    held = _stated("pycolmap.Rotation3d.quat", "r.quat()", "return")
    assert _same_rotation(_quaternion_parts(rotation.quat, held), _quaternion_parts(_quarter_turn(held), held))  # type: ignore[arg-type]
