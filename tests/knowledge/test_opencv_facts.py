"""OpenCV's facts in stubs/, checked against cv2 where it installs (skipped where it does not: the dev
extra does not install OpenCV)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.knowledge.facts_helpers import QUARTER_TURN_Z, _stated

cv2 = pytest.importorskip("cv2")


def test_get_rotation_matrix_2d_reads_degrees() -> None:
    assert _stated("cv2.getRotationMatrix2D", "getRotationMatrix2D(c, a, s)", "angle", "angle_unit") == "degrees"
    # a quarter turn counter-clockwise on the image, whose y axis points down: the transpose of the
    # z-up quarter turn's upper-left block
    matrix = cv2.getRotationMatrix2D((0.0, 0.0), 90.0, 1.0)
    assert np.allclose(matrix[:, :2], QUARTER_TURN_Z[:2, :2].T)


def test_rodrigues_reads_a_rotation_vector_in_radians() -> None:
    assert _stated("cv2.Rodrigues", "Rodrigues(r)", "src", "angle_unit") == "radians"
    matrix, _ = cv2.Rodrigues(np.array([0.0, 0.0, math.pi / 2]))
    assert np.allclose(matrix, QUARTER_TURN_Z)
