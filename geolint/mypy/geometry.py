"""The plugin's view of a mypy type: which geometric kind it is and in which frames it lives.

The typing trick: a frame is just a type argument. ``Point[World]`` carries the instance type ``World``;
a string frame ``Point["camera"]`` carries ``Literal["camera"]`` (see `string_frames`). Comparing frames is
therefore comparing types, and a frame that is a TypeVar (``Point[F]`` in a generic function) compares equal
only to the same TypeVar, which keeps frame-generic functions checkable. A frame we cannot read (Any, a
union) is "unknown" and silences every check that would need it: precision first.
"""

from __future__ import annotations

from dataclasses import dataclass

from mypy.nodes import TypeInfo
from mypy.plugin import CheckerPluginInterface
from mypy.subtypes import is_same_type
from mypy.types import AnyType, Instance, ProperType, Type, UnionType, get_proper_type

from geolint.algebra import Kind
from geolint.mypy import frame_names, fullnames as names

RUNTIME = "runtime"
ARRAY = "array"

# Kind names shared by both families: `geolint.algebra.Kind`'s, so the plugin and the shared table speak of
# one vocabulary (`algebra.shared_kind` reads them back as `Kind`).
POINT = Kind.POINT.value
VECTOR = Kind.VECTOR.value
DIRECTION = Kind.DIRECTION.value
TRANSFORM = Kind.TRANSFORM.value
ROTATION = Kind.ROTATION.value
TRANSLATION = Kind.TRANSLATION.value
HOMOGENEOUS_POINT = Kind.HOMOGENEOUS_POINT.value
HOMOGENEOUS_VECTOR = Kind.HOMOGENEOUS_VECTOR.value
TWIST = Kind.TWIST.value
WRENCH = Kind.WRENCH.value
# Carriers only the plugin has (the table has no kind for them; their rules live in the plugin's `algebra`).
VECTOR_WITH_W1 = "vector with w=1"
CLOUD = "point cloud"
COVARIANCE = "covariance"
ORIGIN_OFFSET = "origin offset"  # (in, from, to): what R @ t gives in a hand-written composition
NEGATED_ROTATION = "negated rotation"  # -R: only its product with a translation means something

KIND_OF_FULLNAME: dict[str, tuple[str, str]] = {
    names.POINT: (RUNTIME, POINT),
    names.VECTOR: (RUNTIME, VECTOR),
    names.DIRECTION: (RUNTIME, DIRECTION),
    names.TRANSFORM: (RUNTIME, TRANSFORM),
    names.POINT_CLOUD: (RUNTIME, CLOUD),
    names.TWIST: (RUNTIME, TWIST),
    names.WRENCH: (RUNTIME, WRENCH),
    names.COVARIANCE: (RUNTIME, COVARIANCE),
    names.POINT_ARRAY: (ARRAY, POINT),
    names.VECTOR_ARRAY: (ARRAY, VECTOR),
    names.DIRECTION_ARRAY: (ARRAY, DIRECTION),
    names.ROTATION_MATRIX: (ARRAY, ROTATION),
    names.TRANSFORM_MATRIX: (ARRAY, TRANSFORM),
    names.TRANSLATION: (ARRAY, TRANSLATION),
    names.HOMOGENEOUS_POINTS: (ARRAY, HOMOGENEOUS_POINT),
    names.HOMOGENEOUS_VECTORS: (ARRAY, HOMOGENEOUS_VECTOR),
    names.VECTOR_WITH_W1: (ARRAY, VECTOR_WITH_W1),
    names.ORIGIN_OFFSET: (ARRAY, ORIGIN_OFFSET),
    names.NEGATED_ROTATION: (ARRAY, NEGATED_ROTATION),
}
FULLNAME_OF_KIND = {value: key for key, value in KIND_OF_FULLNAME.items()}

# How users read each kind in messages.
DISPLAY_NAME = {fullname: fullname.rsplit(".", 1)[1] for fullname in KIND_OF_FULLNAME}

# Generic classes whose frame arguments may be strings (the string-frame hook is registered for these).
FRAMED_CLASSES = tuple(KIND_OF_FULLNAME)


@dataclass(frozen=True)
class Geo:
    """A geometric value's kind and frames (one frame, or ``(dst, src)`` for transforms and rotations)."""

    family: str
    kind: str
    frames: tuple[ProperType, ...]

    @property
    def frame(self) -> ProperType:
        return self.frames[0]

    @property
    def dst(self) -> ProperType:
        return self.frames[0]

    @property
    def src(self) -> ProperType:
        return self.frames[-1]

    def with_frames(self, *frames: ProperType, kind: str | None = None) -> Geo:
        return Geo(self.family, kind or self.kind, tuple(frames))


def read(typ: Type) -> Geo | None:
    """The `Geo` of a type, or None when it is not one of geolint's framed kinds."""
    proper = get_proper_type(typ)
    if not isinstance(proper, Instance):
        return None
    family_kind = KIND_OF_FULLNAME.get(proper.type.fullname)
    if family_kind is None or not proper.args:
        return None
    family, kind = family_kind
    return Geo(family, kind, tuple(get_proper_type(arg) for arg in proper.args))


def build(api: CheckerPluginInterface, geo: Geo) -> Type | None:
    """The mypy type for a `Geo`, or None when its class is not loaded in this build.

    An origin offset that starts at the origin of the frame it is expressed in is that frame's translation.
    """
    if geo.kind == ORIGIN_OFFSET and same_frame(geo.frames[0], geo.frames[1]):
        geo = Geo(geo.family, TRANSLATION, (geo.frames[0], geo.frames[2]))
    fullname = FULLNAME_OF_KIND.get((geo.family, geo.kind))
    if fullname is None:
        return None
    info = lookup_class(api, fullname)
    if info is None:
        return None
    return Instance(info, list(geo.frames))


def lookup_class(api: CheckerPluginInterface, fullname: str) -> TypeInfo | None:
    """A top-level class by full name, or None when its module is not in this build.

    (mypy's ``named_generic_type`` walks the package's symbol tables, where a submodule such as
    ``geolint.typing`` only appears once the package imports it; the module table always has it.)
    """
    module_name, _, class_name = fullname.rpartition(".")
    module = getattr(api, "modules", {}).get(module_name)
    symbol = module.names.get(class_name) if module is not None else None
    node = symbol.node if symbol is not None else None
    return node if isinstance(node, TypeInfo) else None


def is_known(frame: ProperType) -> bool:
    """Whether a frame is precise enough to compare (not Any, not a union of frames)."""
    return not isinstance(frame, (AnyType, UnionType))


def same_frame(first: ProperType, second: ProperType) -> bool | None:
    """True/False when both frames are known, None when either is unknown (then nobody reports).

    A frame class and a string frame with its runtime name are the same frame (see `frame_names`).
    """
    if not (is_known(first) and is_known(second)):
        return None
    if is_same_type(first, second):
        return True
    first_name = frame_names.frame_name(first)
    return first_name is not None and first_name == frame_names.frame_name(second)


def misread_string_frame(geo: Geo) -> Instance | None:
    """A frame that is one of Python's builtin classes (``map``, ``filter``, ``range``...): a string frame that
    mypy looked up as a name because the plugin could not tell the subscripted name was geolint's class (an
    alias such as ``Located = Point``). ``str`` and ``object`` are left alone: they can be meant as frames."""
    for frame in geo.frames:
        if (
            isinstance(frame, Instance)
            and frame.type.fullname.startswith("builtins.")
            and frame.type.fullname not in ("builtins.str", "builtins.object")
        ):
            return frame
    return None
