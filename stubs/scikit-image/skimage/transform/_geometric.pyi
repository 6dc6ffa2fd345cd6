from typing import overload

from geolint.typing import Radians, RotationMatrix, Translation

class AffineTransform:
    """Source: skimage/transform/_geometric.py (0.26.0), AffineTransform: "rotation : float, optional Rotation angle,
    clockwise, as radians. Only available for 2D."; "shear : float or 2-tuple of float, optional The x and y shear
    angles, clockwise"; _srst2matrix passes both to math.cos, math.sin and math.tan, and the `rotation` and `shear`
    properties return `math.atan2(...)`, radians. Keyword-only since 0.26 (`matrix` the one positional parameter).
    Checked numerically (tests/knowledge/test_image_and_scene_facts.py)."""

    def __init__(
        self, matrix: object = ..., *, scale: object = ..., shear: Radians = ..., rotation: Radians = ...,
        translation: object = ..., dimensionality: int | None = ...,
    ) -> None: ...
    @property
    def rotation(self) -> Radians: ...
    @property
    def shear(self) -> Radians: ...

class EuclideanTransform:
    """Source: skimage/transform/_geometric.py (0.26.0), EuclideanTransform: "rotation : float or sequence of float,
    optional Rotation angle, clockwise, in radians. If given as a vector, it is interpreted as Euler rotation angles";
    _rt2matrix builds `[[cos_r, -sin_r], [sin_r, cos_r]]` from `math.cos(rotation)` in 2D and, in 3D,
    `_euler_rotation_matrix(rotation)` = `Rotation.from_euler('XYZ', angles=angles, degrees=False)`. Its `rotation`
    property is an angle in 2D and a 3x3 matrix in 3D, so it is not stated. Checked numerically
    (tests/knowledge/test_image_and_scene_facts.py)."""

    # two forms, the same parameters: 2D (`rotation` one angle) and 3D (`rotation` three Euler angles); two overloads, so
    # that the class is not read as a record whose `.rotation` holds radians (in 3D it holds the 3x3 matrix)
    @overload
    def __init__(self, matrix: object = ..., *, rotation: Radians = ..., translation: object = ..., dimensionality: int | None = ...) -> None: ...
    @overload
    def __init__(self, matrix: object = ..., *, rotation: Radians = ..., translation: object = ..., dimensionality: int | None = ...) -> None: ...

class SimilarityTransform:
    """Source: skimage/transform/_geometric.py (0.26.0), SimilarityTransform(matrix=None, *, scale=None, rotation=None,
    translation=None, dimensionality=None): "rotation : float, optional Rotation angle, clockwise, as radians"; a
    subclass of EuclideanTransform, whose _rt2matrix builds the rotation (3D: Euler angles, radians)."""

    # 2D and 3D, as EuclideanTransform
    @overload
    def __init__(self, matrix: object = ..., *, scale: object = ..., rotation: Radians = ..., translation: object = ..., dimensionality: int | None = ...) -> None: ...
    @overload
    def __init__(self, matrix: object = ..., *, scale: object = ..., rotation: Radians = ..., translation: object = ..., dimensionality: int | None = ...) -> None: ...

class EssentialMatrixTransform:
    """Source: skimage/transform/_geometric.py (0.26.0), EssentialMatrixTransform(*, rotation=None, translation=None,
    matrix=None, dimensionality=None): "rotation : (3, 3) array_like, optional Rotation matrix of the relative camera
    motion", "translation : (3, 1) array_like, optional Translation vector of the relative camera motion. The vector
    must have unit length"; _rt2matrix checks `rotation.shape != (3, 3)` and a unit determinant."""

    def __init__(self, *, rotation: RotationMatrix = ..., translation: Translation = ..., matrix: object = ..., dimensionality: int | None = ...) -> None: ...
