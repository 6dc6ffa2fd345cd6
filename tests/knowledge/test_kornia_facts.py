"""kornia's versioned facts in stubs/, checked against the kornia that is installed (skipped where it is
not: it needs torch, which the dev extra does not install): the overload the installed version selects
states the order it really reads."""

from __future__ import annotations

import ast
import importlib.metadata

import numpy as np
import pytest
from packaging.version import Version

from geolint.factbase.project_pins import Pins
from geolint.knowledge import agreed, bind, knowledge_base
from tests.knowledge.facts_helpers import QUARTER_TURN_Z, _quarter_turn

torch = pytest.importorskip("torch")
conversions = pytest.importorskip("kornia.geometry.conversions")


def test_the_installed_version_reads_the_order_its_overload_states() -> None:
    installed = Version(importlib.metadata.version("kornia"))
    pins = Pins(locked={"kornia": installed})
    api = knowledge_base().api("kornia.geometry.quaternion_to_rotation_matrix")
    assert api is not None
    node = ast.parse("quaternion_to_rotation_matrix(q)", mode="eval").body
    assert isinstance(node, ast.Call)
    bounds = bind(api, node, lambda specifier: pins.allow_only("kornia", specifier))
    order = agreed(bounds, lambda bound: bound.signature.parameter("quaternion").geometry.quaternion_order)  # type: ignore[union-attr]
    assert order is not None
    matrix = conversions.quaternion_to_rotation_matrix(torch.tensor(_quarter_turn(order), dtype=torch.float64))
    assert np.allclose(matrix.numpy(), QUARTER_TURN_Z)
