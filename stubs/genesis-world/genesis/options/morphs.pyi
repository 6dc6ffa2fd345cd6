from geolint.typing import Degrees, PointArray, QuaternionWXYZ

# Every morph takes its initial pose as keywords: `pos`, `euler` (degrees, scipy's extrinsic x-y-z) or
# `quat` (w, x, y, z). The other options (`file`, `scale`, `fixed`, ...) say nothing about geometry.

class Morph:
    """Source: genesis/options/morphs.py (0.4.5, 7bf5f6a), Morph: "The initial euler angle of the entity in degrees at
    creation time. This follows scipy's extrinsic x-y-z rotation convention." (lines 78-80), "The initial quaternion
    (w-x-y-z convention) of the entity at creation time." (81-82); the conversion is
    `gu.xyz_to_quat(np.array(euler), rpy=True, degrees=True)` (117)."""

    def __init__(self, *, pos: PointArray = ..., euler: Degrees = ..., quat: QuaternionWXYZ = ..., **options: object) -> None: ...

class Box(Morph):
    """Source: genesis/options/morphs.py (0.4.5), Box: a Morph (pos, euler in degrees, quat w-x-y-z)."""

    def __init__(self, *, pos: PointArray = ..., euler: Degrees = ..., quat: QuaternionWXYZ = ..., **options: object) -> None: ...

class Sphere(Morph):
    """Source: genesis/options/morphs.py (0.4.5), Sphere: a Morph (pos, euler in degrees, quat w-x-y-z)."""

    def __init__(self, *, pos: PointArray = ..., euler: Degrees = ..., quat: QuaternionWXYZ = ..., **options: object) -> None: ...

class Cylinder(Morph):
    """Source: genesis/options/morphs.py (0.4.5), Cylinder: a Morph (pos, euler in degrees, quat w-x-y-z)."""

    def __init__(self, *, pos: PointArray = ..., euler: Degrees = ..., quat: QuaternionWXYZ = ..., **options: object) -> None: ...

class Plane(Morph):
    """Source: genesis/options/morphs.py (0.4.5), Plane: a Morph (pos, euler in degrees, quat w-x-y-z)."""

    def __init__(self, *, pos: PointArray = ..., euler: Degrees = ..., quat: QuaternionWXYZ = ..., **options: object) -> None: ...

class Mesh(Morph):
    """Source: genesis/options/morphs.py (0.4.5), Mesh (a FileMorph): "The euler angles of the entity in degrees as a
    rotational offset. This follows scipy's extrinsic x-y-z rotation convention." (833-835); quat w-x-y-z (836)."""

    def __init__(self, *, pos: PointArray = ..., euler: Degrees = ..., quat: QuaternionWXYZ = ..., **options: object) -> None: ...

class URDF(Morph):
    """Source: genesis/options/morphs.py (0.4.5), URDF (a FileMorph): pos, euler in degrees (extrinsic x-y-z), quat w-x-y-z."""

    def __init__(self, *, pos: PointArray = ..., euler: Degrees = ..., quat: QuaternionWXYZ = ..., **options: object) -> None: ...

class MJCF(Morph):
    """Source: genesis/options/morphs.py (0.4.5), MJCF (a FileMorph): pos, euler in degrees (extrinsic x-y-z), quat w-x-y-z."""

    def __init__(self, *, pos: PointArray = ..., euler: Degrees = ..., quat: QuaternionWXYZ = ..., **options: object) -> None: ...
