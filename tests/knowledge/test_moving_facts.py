"""What the stubs say a library call does to the points and vectors it is given, checked against the
library: a parameter typed `PointArray` is translated, `VectorArray` or `DirectionArray` only rotated;
`HomogeneousPoints` gets w = 1, `HomogeneousVectors` w = 0. Skipped where the library does not install."""

from __future__ import annotations

import numpy as np
import pytest

from geolint.algebra import Kind
from geolint.knowledge import knowledge_base

_SHIFT = np.eye(4)
_SHIFT[:3, 3] = [1.0, 0.0, 0.0]


def test_trimesh_transform_points_translates_as_its_overloads_say() -> None:
    trimesh = pytest.importorskip("trimesh")
    api = knowledge_base().api("trimesh.transform_points")
    assert api is not None and len(api.signatures) == 2
    for signature in api.signatures:
        translate = signature.parameter("translate")
        points = signature.parameter("points")
        assert translate is not None and translate.literal is not None and points is not None and points.geometry is not None
        moved = trimesh.transform_points(np.array([[0.0, 0.0, 1.0]]), _SHIFT, translate=translate.literal[0])
        translated = bool(np.allclose(moved, [[1.0, 0.0, 1.0]]))
        assert translated == (points.geometry.kind is Kind.POINT), (translate.literal, points.geometry.kind)


@pytest.mark.parametrize("name", ["vector_to_point", "vectors_to_points", "vector_to_direction", "vectors_to_directions"])
def test_pytransform3d_homogeneous_w_is_what_the_stub_says(name: str) -> None:
    transformations = pytest.importorskip("pytransform3d.transformations")
    api = knowledge_base().api(f"pytransform3d.transformations.{name}")
    assert api is not None
    returns = api.signatures[0].returns
    assert returns is not None and returns.kind in (Kind.HOMOGENEOUS_POINT, Kind.HOMOGENEOUS_VECTOR)
    value = np.array([[1.0, 2.0, 3.0]]) if name.startswith("vectors") else np.array([1.0, 2.0, 3.0])
    w = np.atleast_2d(getattr(transformations, name)(value))[:, 3]
    assert np.all(w == (1.0 if returns.kind is Kind.HOMOGENEOUS_POINT else 0.0))
