"""What the knowledge base knows about one library API, as frozen values.

A stub (`stubs/<library>/<package>/...pyi`) is read into one `Api` per qualified name. An `Api` has
one `Signature` per overload; each parameter and each return carries the `Geometry` its annotation
states (`QuaternionWXYZ`, `PointArray[F]`, `Degrees`, `Annotated[..., CameraAxes.OPENCV]` ...), and a
parameter annotated `Literal[...]` is what tells overloads apart (`scalar_first: Literal[True]`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from geolint.algebra import HOMOGENEOUS, Kind

SCALAR_LAST = "xyzw"
SCALAR_FIRST = "wxyz"
RADIANS = "radians"
DEGREES = "degrees"
MONOGRAM = "monogram"  # METADATA.toml's `frame_naming`: Drake's `X_WB` (B's pose in W), `p_BQ`


@dataclass(frozen=True)
class Geometry:
    """What a value is, as far as the stub says: every field None/empty when it says nothing of it."""

    kind: Kind | None = None
    quaternion_order: str | None = None  # SCALAR_LAST or SCALAR_FIRST
    angle_unit: str | None = None  # RADIANS or DEGREES
    frames: tuple[str, ...] = ()  # (frame,) for points and vectors, (dst, src) for rotations and transforms
    camera_axes: str | None = None  # markers.CameraAxes values
    row_vectors: bool = False
    stacked: bool = False
    type_name: str | None = None  # the qualified class the value is an instance of (a library class)
    items: tuple[Geometry, ...] = ()  # the parts of a returned tuple
    tf_frame: str | None = None  # markers.TfFrame values: the role of a tf frame id (or of published transforms)
    launch_part: str | None = None  # markers.LaunchNode values: a part of a launched ROS executable
    ros_parameter: str | None = None  # markers.RosParameter values: a part of a declared or read ROS parameter
    array_operation: str | None = None  # markers.ArrayOperation values: what an array function does to matrices


@dataclass(frozen=True)
class Parameter:
    name: str
    positional: bool  # may be given by position
    keyword: bool  # may be given by keyword
    has_default: bool
    geometry: Geometry | None = None
    literal: tuple[object, ...] | None = None  # `Literal[...]`: the values this overload accepts
    variadic: bool = False  # *args (positional), **kwargs (keyword)


@dataclass(frozen=True)
class Signature:
    """One overload: its parameters (without `self`/`cls`), what it returns, the versions it holds for."""

    parameters: tuple[Parameter, ...]
    returns: Geometry | None
    versions: str | None  # a PEP 440 specifier, or None: every version
    line: int  # in the stub, for messages and citations
    receiver: Geometry | None = None  # a method's annotated `self`: what the object it is called on is

    @property
    def components(self) -> str | None:
        """`wxyz` / `xyzw` when the parameters are a quaternion's four components by name, in order."""
        letters = "".join(parameter.name for parameter in self.parameters if parameter.name in ("w", "x", "y", "z") and parameter.positional)
        return letters if letters in (SCALAR_FIRST, SCALAR_LAST) else None

    @property
    def applies_transform(self) -> bool:
        """Whether the overload applies a rigid transform to what it is given: it takes one, is a method
        of one, or makes its input homogeneous (w = 1 or 0, for a 4x4 to be applied to)."""
        kinds = [parameter.geometry.kind for parameter in self.parameters if parameter.geometry is not None]
        return (
            Kind.TRANSFORM in kinds
            or (self.receiver is not None and self.receiver.kind is Kind.TRANSFORM)
            or (self.returns is not None and self.returns.kind in HOMOGENEOUS)
        )

    def parameter(self, name: str) -> Parameter | None:
        return next((parameter for parameter in self.parameters if parameter.name == name), None)


@dataclass(frozen=True)
class Receiver:
    """`@any_receiver`: the class's methods are recognised by name on any object."""

    when_imported: tuple[str, ...] = ()
    unless_imported: tuple[str, ...] = ()  # not in modules that import one of these


@dataclass(frozen=True)
class Api:
    """A function, method or class (its constructor) of a library, by qualified name."""

    qualified_name: str
    signatures: tuple[Signature, ...]
    library: str  # the stubs/ folder (the distribution) it comes from
    stub: str  # the stub file, relative to stubs/
    source: str  # the docstring's `Source:` citation
    is_class: bool = False
    receiver: Receiver | None = None
    is_attribute: bool = False  # a property or an annotated attribute: read, not called (`q.elements`)

    @property
    def states_geometry(self) -> bool:
        """Whether a signature says something of geometry beyond the class it returns or takes
        (`concatenate(rotations) -> Rotation` states nothing the rules read; `as_quat()` does)."""
        return any(
            _geometric(geometry)
            for signature in self.signatures
            for geometry in (signature.returns, signature.receiver, *(parameter.geometry for parameter in signature.parameters))
        ) or any(signature.components for signature in self.signatures)


def _geometric(geometry: Geometry | None) -> bool:
    if geometry is None:
        return False
    stated = (geometry.kind, geometry.quaternion_order, geometry.angle_unit, geometry.camera_axes)
    return any(value is not None for value in stated) or geometry.row_vectors or any(_geometric(part) for part in geometry.items)


@dataclass(frozen=True)
class Executable:
    """A ROS executable that publishes a transform named on its command line (`static_transform_publisher
    x y z yaw pitch roll parent child`), as METADATA.toml's `[executables.<name>]` states it: what a launch
    file's `args` mean."""

    name: str
    package: str  # the ROS package that ships it (`pkg=` / `package=` in a launch file)
    static: bool  # publishes on /tf_static (latched) rather than /tf
    positional: dict[int, tuple[int, int]]  # number of arguments -> the positions of (parent, child)
    options: dict[str, str]  # `--frame-id` -> TfFrame role ("parent" / "child")
    source: str  # where the command line is documented


@dataclass(frozen=True)
class Library:
    """A `stubs/<library>/` folder: METADATA.toml and what its stubs define."""

    name: str  # the distribution's name on PyPI (or the project's, for what is not on PyPI)
    packages: tuple[str, ...]  # import names it provides
    checked: str  # the version the facts were checked against
    upstream: str  # where the library's source or documentation is
    apis: dict[str, Api] = field(default_factory=dict)
    aliases: dict[str, str] = field(default_factory=dict)  # a re-export or second name -> what it names
    # local names that mean one of its classes even where a file shows no import (`R` for scipy's Rotation)
    conventional_names: dict[str, str] = field(default_factory=dict)
    # names another package gains once this library is imported (`numpy.quaternion`) -> what they are
    extends: dict[str, str] = field(default_factory=dict)
    executables: dict[str, Executable] = field(default_factory=dict)  # ROS executables, by name
    # modules whose import makes the library's methods recognisable by name alone (its companions:
    # a node that imports tf2_geometry_msgs is handed a tf2 buffer)
    recognised_with: tuple[str, ...] = ()
    ros_client: int | None = None  # 1 or 2: a ROS client library (a module that imports it is a ROS node)
    # local names that mean one of its modules where a file shows no import (`np` for numpy)
    conventional_modules: dict[str, str] = field(default_factory=dict)
    # its frame ids may start with a slash: it strips one itself before asking tf2 (ROS 1's tf)
    strips_leading_slash: bool = False
    array_library: bool = False  # METADATA.toml's `array_library`: its values are arrays (numpy, torch, jax)
    # how code that imports it names frames: "monogram" (Drake's `X_WB`, `p_BQ`: the frames are in the name)
    frame_naming: str | None = None
