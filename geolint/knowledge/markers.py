"""Markers that the knowledge base's stubs (`stubs/<library>/...pyi`) use beside geolint's typing
vocabulary. The stubs are read as data by `geolint.knowledge.reader`, never imported; these names
exist so that a stub reads as valid, importable Python and so that each marker has one definition
with its meaning.

- ``@versions(">=1.14")`` on a function, an overload or a class: the fact holds only for those
  versions of the library's distribution (a PEP 440 specifier). The linter uses it only when the
  project's pinned versions all satisfy it, and says nothing when it cannot tell.
- ``@any_receiver(when_imported=(...))`` on a class: its methods are recognised by their name on any
  object (pybullet's ``BulletClient`` wraps the module's functions; Isaac Sim's pose setters exist on
  every prim class), optionally only in modules that import one of the given modules
  (``unless_imported``: and none of those, a library whose same-named methods mean something else).
- ``Annotated[T, CameraAxes.OPENCV]``: the camera axes of a pose or of image coordinates (OpenCV: x
  right, y down, z forward; OpenGL/Blender: x right, y up, z backward; PyTorch3D: x left, y up, z forward).
- ``Annotated[T, ArrayOperation.INVERSE]`` (``TRANSPOSE``, ``MATMUL``, ``EINSUM``) on the return of an array
  namespace's function (numpy, torch, jax.numpy, cupy...): what it does to the matrices it is given.
- ``Annotated[T, ROW_VECTORS]``: the library applies its matrices to row vectors (``p @ R``), so a
  matrix it is given or returns is the transpose of the column-vector one.
- ``Annotated[T, STACKED]``: the parameter also accepts a stack (``(..., 4)`` quaternions, ``(N, 3)``
  points).
- ``Annotated[str, TfFrame.TARGET]``: a tf frame id and its role in the call (a lookup's target or
  source frame, a published transform's parent or child frame); ``TfFrame.PUBLISHED`` on a transform
  message (or a list of them) that the call publishes, each from ``header.frame_id`` (the parent) to
  ``child_frame_id`` (the child).
- ``Annotated[str, LaunchNode.PACKAGE]`` (and ``EXECUTABLE``, ``ARGUMENTS``): the parts of a launch
  action that starts a ROS executable, whose command line a package's METADATA.toml may describe
  (``[executables.static_transform_publisher]``).
- ``Annotated[str, RosParameter.NAME]`` (and ``DEFAULT``, ``DECLARATIONS``): a ROS parameter a call
  declares or reads, and the default it declares (``node.declare_parameter("frame_id", "base_link")``,
  ``rospy.get_param("~frame_id", "base_link")``); ``DECLARATIONS`` on a list of ``(name, default)``
  tuples (rclpy's ``declare_parameters``), ``NAMESPACE`` on the prefix it puts before each name.
"""

from __future__ import annotations

from typing import Callable, Final, TypeVar

_Decorated = TypeVar("_Decorated")


def versions(specifier: str) -> Callable[[_Decorated], _Decorated]:
    """The fact below holds for these versions of the library (PEP 440, e.g. ``">=1.14"``)."""

    def mark(decorated: _Decorated) -> _Decorated:
        return decorated

    return mark


def any_receiver(*, when_imported: tuple[str, ...] = (), unless_imported: tuple[str, ...] = ()) -> Callable[[_Decorated], _Decorated]:
    """The class's methods are recognised by name on any object (in modules importing `when_imported`, and
    none of `unless_imported`)."""

    def mark(decorated: _Decorated) -> _Decorated:
        return decorated

    return mark


class CameraAxes:
    """Camera axis conventions, as `Annotated` metadata."""

    OPENCV: Final = "opencv"  # x right, y down, z forward (OpenCV, COLMAP, ROS optical frames)
    OPENGL: Final = "opengl"  # x right, y up, z backward (OpenGL, Blender, nerfstudio, instant-ngp)
    PYTORCH3D: Final = "pytorch3d"  # x left, y up, z forward


class TfFrame:
    """The role of a tf frame id in a call, as `Annotated` metadata."""

    TARGET: Final = "target"  # a lookup's frame to express data in (the transform maps into it)
    SOURCE: Final = "source"  # a lookup's frame the data is in (the transform maps from it)
    PARENT: Final = "parent"  # a published transform's parent frame (its header.frame_id)
    CHILD: Final = "child"  # a published transform's child frame (its child_frame_id)
    PUBLISHED: Final = "published"  # transform messages the call publishes, parent -> child each


class LaunchNode:
    """The parts of a launch action that runs a ROS executable, as `Annotated` metadata."""

    PACKAGE: Final = "package"
    EXECUTABLE: Final = "executable"
    ARGUMENTS: Final = "arguments"  # its command line, a list of strings
    COMMAND: Final = "command"  # a whole process's command line: `ros2 run <package> <executable> ...`


class RosParameter:
    """The parts of a call that declares or reads a ROS parameter, as `Annotated` metadata."""

    NAME: Final = "name"
    DEFAULT: Final = "default"  # the value the parameter has when nothing overrides it
    DECLARATIONS: Final = "declarations"  # a list of (name, default[, descriptor]) tuples
    NAMESPACE: Final = "namespace"  # put before each declared name, with a dot


class ArrayOperation:
    """What an array namespace's function does to the matrices it is given, as `Annotated` metadata on its
    return (`def inv(a) -> Annotated[object, ArrayOperation.INVERSE]`): what the pose rules see through."""

    TRANSPOSE: Final = "transpose"  # swaps the last two axes (`np.transpose(R)`, `torch.transpose(R, -1, -2)`)
    INVERSE: Final = "inverse"  # the matrix inverse (`np.linalg.inv`, `torch.inverse`)
    MATMUL: Final = "matmul"  # the matrix product of its two arguments (`np.dot`, `torch.bmm`)
    EINSUM: Final = "einsum"  # a product spelled by subscripts (`np.einsum("ij,nj->ni", R, p)`)
    # pads with a constant: widths as (before, after) pairs per axis, the last axis last (`np.pad`)...
    PAD_PER_AXIS: Final = "pad_per_axis"
    # ... or as (left, right) of the last axis first, then the one before it (`torch.nn.functional.pad`)
    PAD_LAST_AXIS_FIRST: Final = "pad_last_axis_first"
    # learned-feature operations: the result is a feature map sampled at or pooled over its inputs, never
    # coordinates, whatever the variable is called (`tpv_pts = F.grid_sample(plane, loc)`)
    FEATURES: Final = "features"
    # its argument's values as an array, unchanged (`np.asarray(point)`: the same point)
    AS_ARRAY: Final = "as_array"
    # the first argument flattened with the second's values after it (`np.append(p, 1)`: p with w = 1)
    APPEND_FLAT: Final = "append_flat"


ROW_VECTORS: Final = "row vectors"
STACKED: Final = "stacked"
