"""Camera extrinsics conventions stated by data: which way a camera pose maps, world to camera
(w2c) or camera to world (c2w), and which part of it a value is (the pose, its rotation, its
translation).

Evidence, strongest first:

1. data conventions: string keys of datasets and file formats (BOP `"cam_R_w2c"` / `"cam_t_w2c"`,
   NeRF transforms.json `"transform_matrix"`, `meta["c2w"]`), library attributes (pycolmap
   `image.cam_from_world`, `image.projection_center()`, COLMAP `image.qvec` / `image.tvec` /
   `image.qvec2rotmat()`, by name on any object: COLMAP's own `Image` is a namedtuple of its scripts,
   and pycolmap's images come out of dicts no type reaches), the library attributes the stubs type as
   camera poses (`geolint.knowledge`: Blender's `scene.camera.matrix_world`, av2's `extrinsics`, with
   their camera axes), followed through local data flow (flow-sensitive: a name rebound to
   its own inverse holds the inverse from there on), inverses, transposes of rotations, blocks
   written into a 4x4 (`T = np.eye(4); T[:3, :3] = R; T[:3, 3] = t`), `[R | t]` concatenations
   and the hand-written inverse translation `-R.T @ t`;
2. names whose direction is in the word itself (`c2w`, `pose_w2c`, `world_to_camera`,
   `cam_from_world`, ORB-SLAM's `Tcw` / `Twc`): order-independent;
3. `T_a_b` names with one camera frame, read in the project's naming order (`geolint.factbase.conventions`):
   only when every open reading agrees; explicit evidence (`Extrinsic.explicit`) only where the project
   states its order.

A pycolmap attribute's frames belong to its owner (`image1.cam_from_world` is camera 1's), but
its direction does not: every `cam_from_world` maps world into a camera. This module answers only
the direction, so two owners never conflict here.

The same evidence says, where the data states it, which way the camera's own axes point
(`Extrinsic.axes`): COLMAP and BOP poses are in OpenCV axes, NeRF transforms.json's in OpenGL
axes; a name may say it (`c2w_opengl`). Inverting a pose keeps its camera axes; permuting its
columns or writing into it in place (`c2w[:3, 1:3] *= -1`, the usual conversion) loses them.

Every question answers None when the evidence is missing or contradictory.
"""

from __future__ import annotations

import ast
from ast import AST, Attribute, BinOp, Call, Div, MatMult, Mult, Name, Slice, Starred, Subscript, USub, UnaryOp
import re
from dataclasses import dataclass, replace
from functools import lru_cache
from typing import Final, TYPE_CHECKING

from geolint.algebra import Kind
from geolint.factbase import dataflow, library_calls
from geolint.factbase.memo import NodeMemo
from geolint.factbase.syntax import is_full_slice, is_slice_upto, number, string, walk_within
from geolint.factbase.pose_parts import (
    call_name,
    int_value,
    is_column_slice_from,
    matmul_operands,
    matrix_indices,
    peel_same_value,
    transposed_operand,
)
from geolint.factbase.reaching import Unpacked, binding_of, scope_of, statement_of, value_of
from geolint.knowledge import Geometry, KnowledgeBase, knowledge_base
from geolint.knowledge.markers import CameraAxes

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase, FrameFact

W2C: Final = "w2c"
C2W: Final = "c2w"
POSE: Final = "pose"
ROTATION: Final = "rotation"
TRANSLATION: Final = "translation"

# How strong the evidence is: data conventions, an order-independent name, a `T_a_b` name.
DATA: Final = "data"
NAME: Final = "name"
ORDERED_NAME: Final = "ordered-name"

DIRECTION_WORDS: Final = {W2C: "world-to-camera", C2W: "camera-to-world"}

OPENCV: Final = CameraAxes.OPENCV
OPENGL: Final = CameraAxes.OPENGL
PYTORCH3D: Final = CameraAxes.PYTORCH3D
AXES_WORDS: Final = {
    OPENCV: "OpenCV axes (x right, y down, z forward)",
    OPENGL: "OpenGL axes (x right, y up, z back)",
    PYTORCH3D: "PyTorch3D axes (x left, y up, z forward)",
}
# The camera axes each data convention uses, with where that is stated:
# COLMAP, doc/format.rst (images.txt): "the X axis points to the right, the Y axis to the bottom, and the Z
# axis to the front as seen from the image"; BOP, docs/bop_datasets_format.md: "The camera coordinate system
# is as in OpenCV"; nerfstudio, docs/quickstart/data_conventions.md: transforms.json cameras use "the
# OpenGL/Blender (and original NeRF) coordinate convention [...] +X is right, +Y is up, and +Z is pointing back".
_COLMAP_AXES: Final = OPENCV
_BOP_AXES: Final = OPENCV
_TRANSFORMS_JSON_AXES: Final = OPENGL

# String keys of datasets and file formats that state a convention: (direction, part, where from, camera axes).
EXTRINSIC_KEYS: Final[dict[str, tuple[str, str, str, str | None]]] = {
    "cam_R_w2c": (W2C, ROTATION, "BOP scene_camera.json", _BOP_AXES),
    "cam_t_w2c": (W2C, TRANSLATION, "BOP scene_camera.json", _BOP_AXES),
    "transform_matrix": (C2W, POSE, "NeRF transforms.json", _TRANSFORMS_JSON_AXES),
    "c2w": (C2W, POSE, "key", None),
    "w2c": (W2C, POSE, "key", None),
    "cam2world": (C2W, POSE, "key", None),
    "world2cam": (W2C, POSE, "key", None),
    "camera_to_world": (C2W, POSE, "key", None),
    "world_to_camera": (W2C, POSE, "key", None),
    "cam_to_world": (C2W, POSE, "key", None),
    "world_to_cam": (W2C, POSE, "key", None),
}
# Attributes with a library's meaning (COLMAP's `Image` namedtuple, pycolmap's `Image`).
EXTRINSIC_ATTRIBUTES: Final[dict[str, tuple[str, str, str, str | None]]] = {
    "cam_from_world": (W2C, POSE, "pycolmap Image.cam_from_world", _COLMAP_AXES),
    "qvec": (W2C, ROTATION, "COLMAP Image.qvec", _COLMAP_AXES),
    "tvec": (W2C, TRANSLATION, "COLMAP Image.tvec", _COLMAP_AXES),
}
# Methods called without arguments: (direction, part, where from, camera axes).
EXTRINSIC_METHODS: Final[dict[str, tuple[str, str, str, str | None]]] = {
    "cam_from_world": (W2C, POSE, "pycolmap Image.cam_from_world()", _COLMAP_AXES),
    "qvec2rotmat": (W2C, ROTATION, "COLMAP Image.qvec2rotmat()", _COLMAP_AXES),
    "projection_center": (C2W, TRANSLATION, "pycolmap Image.projection_center()", _COLMAP_AXES),
}
# Camera-axes words inside names that also say their direction (`c2w_opengl`, `w2c_cv`)
_AXES_TOKENS: Final = {
    OPENCV: OPENCV, "cv": OPENCV, "colmap": OPENCV, OPENGL: OPENGL, "gl": OPENGL, "blender": OPENGL,
    PYTORCH3D: PYTORCH3D, "p3d": PYTORCH3D,
}  # fmt: skip (the conventions' own names, and their short forms)
# Direction words inside names (`pose_c2w`, `R_w2c`) and phrases (`world_to_camera`).
_NAME_TOKENS: Final = {
    "c2w": C2W, "w2c": W2C, "cam2world": C2W, "world2cam": W2C, "camera2world": C2W, "world2camera": W2C,
    "cam2w": C2W, "w2cam": W2C,
}  # fmt: skip
_PHRASE: Final = re.compile(r"(?:^|_)(cam|camera|world)s?_(to|from)_(cam|camera|world)s?(?:_|$)")
_COMPACT: Final = re.compile(r"^_*(?:self\.)?([TRt]|pose)_?(cw|wc)$")  # ORB-SLAM's Tcw (camera from world), Twc
_CAMERA_FRAME: Final = re.compile(r"(?:cam|camera)[0-9]*[a-z]?|c[0-9]*")
_ROTATION_TOKENS: Final = frozenset({"R", "rot", "rotation", "rotmat", "Rot"})
_TRANSLATION_TOKENS: Final = frozenset({"t", "trans", "translation", "tvec", "transl"})
_BLOCK_MAKERS: Final = frozenset({"eye", "identity", "zeros", "empty"})
_INVERSES: Final = frozenset({"inv", "inverse", "pinv", "Inverse", "inverted"})
_JOINS: Final = frozenset({"concatenate", "hstack", "vstack", "column_stack", "cat", "concat", "row_stack"})
_PASS_ON: Final = frozenset({"tolist", "matrix"})


def flip(direction: str) -> str:
    return W2C if direction == C2W else C2W


def is_camera_frame(word: str | None) -> bool:
    return word is not None and _CAMERA_FRAME.fullmatch(word.lower()) is not None


def frames_direction(frames: tuple[str, ...]) -> str | None:
    """The direction of a pose between a camera and one other frame (a stub's `(dst, src)`: `("camera",
    "world")` w2c, `("world", "camera")` c2w, `("camera", "egovehicle")` w2c too); None for any other frames."""
    if len(frames) != 2 or is_camera_frame(frames[0]) == is_camera_frame(frames[1]):
        return None
    return W2C if is_camera_frame(frames[0]) else C2W


@dataclass(frozen=True)
class Axes:
    """Which way a camera's own axes point (`CameraAxes` values), where that is stated, how strongly."""

    convention: str
    source: str
    strength: str = DATA

    @property
    def description(self) -> str:
        return AXES_WORDS[self.convention]


@dataclass(frozen=True)
class Extrinsic:
    """A value that is (part of) a camera pose: `direction` w2c or c2w, `part` pose/rotation/translation,
    and the camera axes it is in when the evidence states them."""

    direction: str
    part: str
    evidence: tuple[str, ...]
    strength: str = DATA
    axes: Axes | None = None
    order_stated: bool = False  # an ORDERED_NAME read in the naming order the project states

    def inverted(self, how: str) -> Extrinsic:
        """The inverse pose (part): the same camera, so the same camera axes."""
        return replace(self, direction=flip(self.direction), evidence=(*self.evidence, how))

    def as_part(self, part: str, how: str = "") -> Extrinsic:
        return replace(self, part=part, evidence=(*self.evidence, how) if how else self.evidence)

    def with_axes(self, axes: Axes | None) -> Extrinsic:
        return replace(self, axes=axes)

    @property
    def description(self) -> str:
        what = {POSE: "pose", ROTATION: "rotation", TRANSLATION: "translation"}[self.part]
        return f"{DIRECTION_WORDS[self.direction]} {what}"

    @property
    def explicit(self) -> bool:
        """Data, a name that says its direction in so many words, or a `T_a_b` name read in the naming
        order the project states (`naming = "dst-first"`, or its declarations in one order)."""
        return self.strength in (DATA, NAME) or self.order_stated


def _part_of_tokens(tokens: list[str]) -> str:
    if any(token in _ROTATION_TOKENS for token in tokens):
        return ROTATION
    if any(token in _TRANSLATION_TOKENS for token in tokens):
        return TRANSLATION
    return POSE


def name_extrinsic(facts: FactBase, name: str) -> Extrinsic | None:
    """What a name states about camera extrinsics, or None (also when the readings disagree)."""
    bare = name.strip("_")
    compact = _COMPACT.match(bare)
    if compact:
        letter, frames = compact.groups()
        part = ROTATION if letter == "R" else TRANSLATION if letter == "t" else POSE
        return Extrinsic(W2C if frames == "cw" else C2W, part, (f"name `{name}` (ORB-SLAM: T_cw maps world into camera)",), NAME)
    tokens = bare.split("_")
    lowered = [token.lower() for token in tokens]
    directions = {_NAME_TOKENS[token.rstrip("s")] for token in lowered if token.rstrip("s") in _NAME_TOKENS}
    phrase = _PHRASE.search(bare.lower())
    if phrase:
        first, word, last = phrase.groups()
        src, dst = (first, last) if word == "to" else (last, first)
        if is_camera_frame(src) != is_camera_frame(dst):
            directions.add(C2W if is_camera_frame(src) else W2C)
    if directions:
        if len(directions) != 1 or len(tokens) > 4:
            return None
        conventions = {_AXES_TOKENS[token] for token in lowered if token in _AXES_TOKENS}
        axes = Axes(conventions.pop(), f"name `{name}`", NAME) if len(conventions) == 1 else None
        return Extrinsic(directions.pop(), _part_of_tokens(tokens), (f"name `{name}`",), NAME, axes)
    found: set[tuple[str, str] | None] = set()
    evidence: tuple[str, ...] = ()
    for order in facts.readings():
        fact = facts.name_frames(name, order) or _camera_pose_name(facts, bare, order)
        if fact is None or not fact.frames.is_operator:
            return None
        frames = fact.frames
        if is_camera_frame(frames.dst) == is_camera_frame(frames.src):
            return None
        direction = W2C if is_camera_frame(frames.dst) else C2W
        found.add((direction, ROTATION if frames.operator == "rotation" else POSE))
        evidence = fact.evidence
    if len(found) != 1:
        return None
    direction, part = found.pop()  # type: ignore[misc]
    return Extrinsic(direction, part, evidence, ORDERED_NAME, order_stated=facts.names_stated)


def _camera_pose_name(facts: FactBase, name: str, order: str) -> FrameFact | None:
    """`H_camZ_V`, `T_camL_world`: a `T_a_b` name whose camera word carries a suffix the general
    name reader does not take as a frame (a capital letter), read in `order`."""
    tokens = name.split("_")
    if len(tokens) != 3:  # most names: before the imports, a microsecond each
        return None
    from geolint.factbase.fact_types import DST_FIRST, FrameFact
    from geolint.semantic.names import NameFrames, ROTATION_LETTERS, TRANSFORM_LETTERS

    if tokens[0] not in TRANSFORM_LETTERS | ROTATION_LETTERS or facts.order_names_mixed:
        return None
    first, second = tokens[1], tokens[2]
    if is_camera_frame(first) == is_camera_frame(second):
        return None
    if not all(re.fullmatch(r"[A-Za-z][A-Za-z0-9]*", word) for word in (first, second)):
        return None
    dst, src = (first, second) if order == DST_FIRST else (second, first)
    frames = NameFrames(dst=dst.lower(), src=src.lower(), operator="rotation" if tokens[0] in ROTATION_LETTERS else "transform")
    return FrameFact(frames, (f"name `{name}` ({order})",))


_STUB_PARTS: Final = {Kind.TRANSFORM: POSE, Kind.ROTATION: ROTATION, Kind.TRANSLATION: TRANSLATION}


def stub_extrinsic(geometry: Geometry, what: str, library: str) -> Extrinsic | None:
    """A camera pose (part) a stub states (`TransformMatrix["camera", "world"]`, with its `CameraAxes`
    when stated), as the data evidence of `what` (an attribute, a parameter) of `library`; None when the
    stub states no pose between a camera and another frame."""
    part = _STUB_PARTS.get(geometry.kind) if geometry.kind is not None else None
    direction = frames_direction(geometry.frames)
    if part is None or direction is None:
        return None
    source = f"{what} ({library} stub: {DIRECTION_WORDS[direction]})"
    axes = Axes(geometry.camera_axes, f"{what} ({library} stub)") if geometry.camera_axes is not None else None
    return Extrinsic(direction, part, (source,), DATA, axes)


@lru_cache(maxsize=4)
def camera_pose_attributes(kb: KnowledgeBase) -> frozenset[str]:
    """The names of the library attributes whose stubs state a camera pose (part)."""
    return frozenset(
        api.qualified_name.rpartition(".")[2]
        for api in kb.apis()
        if api.is_attribute
        and any(signature.returns is not None and stub_extrinsic(signature.returns, "", api.library) for signature in api.signatures)
    )


@lru_cache(maxsize=4)
def camera_pose_packages(kb: KnowledgeBase) -> frozenset[str]:
    """The import names of the libraries whose stubs state a camera pose (part) a call takes or an attribute
    holds: what a module must name for a library to state one."""
    return frozenset(
        package
        for api in kb.apis()
        if any(
            stub_extrinsic(geometry, "", api.library) is not None
            for signature in api.signatures
            for geometry in (signature.returns, *(parameter.geometry for parameter in signature.parameters))
            if geometry is not None
        )
        for package in kb.libraries[api.library].packages
    )


class CameraPoseText:
    """A rule's gate: text that may read a camera pose a library's stub states, an attribute that holds
    one (`.matrix_world`, `.extrinsics`) or the name of a library whose calls take one (`open3d`,
    `pyrender`), from the knowledge base."""

    @property
    def pattern(self) -> str:
        """The same test as one regex (for display and for the prefilter's tests), read from the knowledge base."""
        kb = knowledge_base()
        words = [re.escape(package) for package in camera_pose_packages(kb)] + [re.escape(f".{name}") for name in camera_pose_attributes(kb)]
        return "|".join(sorted(words))

    def search(self, source: str, /) -> bool:
        kb = knowledge_base()
        return any(package in source for package in camera_pose_packages(kb)) or any(
            f".{name}" in source for name in camera_pose_attributes(kb)
        )


def key_extrinsic(key: str) -> Extrinsic | None:
    """What a string key states (`"cam_R_w2c"`, `"transform_matrix"`, `"c2w"`)."""
    known = EXTRINSIC_KEYS.get(key)
    if known is None:
        return None
    direction, part, source, convention = known
    axes = Axes(convention, f"key {key!r} ({source})") if convention is not None else None
    return Extrinsic(direction, part, (f"key {key!r} ({source}: {DIRECTION_WORDS[direction]})",), DATA, axes)


class ExtrinsicsEvidence:
    """The extrinsics facts of one module: `of(node)` says which camera pose (part) an expression
    is, from data first and names last. Built on the fact base (names, readings, imports) and its
    flow analysis (`geolint.factbase.reaching`: what a local name certainly holds)."""

    def __init__(self, facts: FactBase) -> None:
        self.facts = facts
        self.index = facts.index
        self._facts: NodeMemo[Extrinsic] = NodeMemo(max_depth=40)
        self._edited: dict[tuple[int, str], bool] = {}  # (scope, name) -> `_edited_in_place`, asked at every use

    def of(self, node: AST) -> Extrinsic | None:
        return self._facts.get(id(node), lambda: self._of(node))

    # -- the evaluation ------------------------------------------------------------------------
    def _of(self, node: AST) -> Extrinsic | None:
        if not isinstance(node, ast.expr):
            return None
        peeled = peel_same_value(node)
        if peeled is not node:
            return self.of(peeled)
        if isinstance(node, Name):
            return self._of_name(node)
        if isinstance(node, Attribute):
            return self._of_attribute(node)
        if isinstance(node, Subscript):
            return self._of_subscript(node)
        if isinstance(node, Call):
            return self._of_call(node)
        if isinstance(node, UnaryOp) and isinstance(node.op, USub):
            return self._of_product(node.operand, negated=True)
        if isinstance(node, BinOp) and isinstance(node.op, MatMult):
            return self._of_product(node, negated=False)
        if isinstance(node, BinOp) and isinstance(node.op, (Mult, Div)):
            # a translation in other units (`t * 0.001`, `t / 1000.0`) is the same translation
            scaled = node.left if number(node.right) is not None else node.right if number(node.left) is not None and isinstance(node.op, Mult) else None
            found = self.of(scaled) if scaled is not None else None
            return found if found is not None and found.part == TRANSLATION else None
        return None

    def _of_name(self, node: Name) -> Extrinsic | None:
        found = self._of_value_named(node)
        if found is not None and found.axes is not None and self._edited_in_place(node):
            return found.with_axes(None)  # `c2w[:3, 1:3] *= -1`: the usual change of camera axes
        return found

    def _edited_in_place(self, node: Name) -> bool:
        """Whether the function edits the array `node` names other than by writing camera-pose blocks of the
        same axes into it (`T[:3, :3] = R_colmap`): in place anywhere, before or after `node` (an edit after
        a use still reaches an array stored by reference)."""
        scope = self.index.scope_of(node)
        key = (id(scope.node), node.id)
        edited = self._edited.get(key)
        if edited is None:
            stores = scope.subscript_stores.get(node.id, [])
            edited = self._edited[key] = (
                dataflow.updates_in_place(self.index, scope, node.id)
                or any(_axes_of(self.of(value)) is None for _, value in stores)
                or len(self.block_parts(stores)) < len(stores)
            )
        return edited

    def _of_value_named(self, node: Name) -> Extrinsic | None:
        value = value_of(self.index, node)
        if isinstance(value, ast.expr):
            found = self.of(value)
            if found is not None:
                return found
            built = self.built_from_blocks(node, value)
            if built is not None:
                return built
        elif isinstance(value, Unpacked):
            return None
        return name_extrinsic(self.facts, node.id)

    def _of_attribute(self, node: Attribute) -> Extrinsic | None:
        if node.attr in ("T", "mT"):
            return self._transposed(node.value, f"`.{node.attr}`")
        stated = self._stub_attribute(node)  # before the module test: `bpy.context.scene.camera` reads like a module
        if stated is not None:
            return stated
        if self.facts.is_module_like(node.value):
            return None
        known = EXTRINSIC_ATTRIBUTES.get(node.attr)
        if known is not None:
            direction, part, source, convention = known
            axes = Axes(convention, f"`.{node.attr}` ({source})") if convention is not None else None
            return Extrinsic(direction, part, (f"`.{node.attr}` ({source}: {DIRECTION_WORDS[direction]})",), DATA, axes)
        if node.attr in ("rotation", "translation"):
            owner = self.of(node.value)
            if owner is not None and owner.part == POSE:
                return owner.as_part(ROTATION if node.attr == "rotation" else TRANSLATION)
            return None
        return name_extrinsic(self.facts, node.attr)

    def _stub_attribute(self, node: Attribute) -> Extrinsic | None:
        """What a library attribute holds by its stub (`scene.camera.matrix_world`: camera-to-world in
        OpenGL axes; av2's `camera.extrinsics`: ego-to-camera in OpenCV axes)."""
        held = library_calls.attribute_geometry(self.facts, node)
        return stub_extrinsic(held[1], f"`.{node.attr}`", held[0].library) if held is not None else None

    def _of_subscript(self, node: Subscript) -> Extrinsic | None:
        key = string(node.slice)
        if key is not None:
            return key_extrinsic(key)
        base = self.of(node.value)
        if base is None or base.part != POSE:
            return None
        indices = matrix_indices(node)
        if indices is None:
            index = node.slice
            if isinstance(index, Slice) and is_slice_upto(index, 3) or isinstance(index, ast.List):
                return base  # `[:3]` drops the bottom row; `[[1, 0, 2, 3]]` permutes world axes
            return None
        _, row, column = indices
        rows_of_pose = is_slice_upto(row, 3) or is_slice_upto(row, 4) or is_full_slice(row) or isinstance(row, ast.List)
        if is_slice_upto(row, 3) and is_slice_upto(column, 3):
            return base.as_part(ROTATION)
        if is_slice_upto(row, 3) and (int_value(column) in (3, -1) or is_column_slice_from(column, 3)):
            return base.as_part(TRANSLATION)
        if rows_of_pose and (is_slice_upto(column, 4) or is_full_slice(column)):
            return base
        if rows_of_pose and isinstance(column, ast.List):
            return base.with_axes(None)  # `c2w[:, [1, 0, 2, 3]]`: the camera's axes permuted
        return None

    def _of_call(self, node: Call) -> Extrinsic | None:
        func = node.func
        name = call_name(node)
        if isinstance(func, Attribute) and not node.args and not node.keywords:
            known = EXTRINSIC_METHODS.get(func.attr)
            if known is not None and not self.facts.is_module_like(func.value):
                direction, part, source, convention = known
                axes = Axes(convention, f"`.{func.attr}()` ({source})") if convention is not None else None
                return Extrinsic(direction, part, (f"`.{func.attr}()` ({source}: {DIRECTION_WORDS[direction]})",), DATA, axes)
            if func.attr in _PASS_ON:
                return self.of(func.value)
        operand = transposed_operand(node)
        if operand is not None:
            return self._transposed(operand, f"`{name}`", inverse=name in _INVERSES)
        if name in ("qvec2rotmat", "quat2mat", "quaternion_to_matrix") and len(node.args) == 1:
            inner = self.of(node.args[0])
            return inner if inner is not None and inner.part == ROTATION else None
        if name in _JOINS and node.args and isinstance(node.args[0], (ast.List, ast.Tuple)):
            return self._joined(node.args[0].elts)
        if self.facts.matmul(node) is not None:
            return self._of_product(node, negated=False)
        return None

    def _transposed(self, operand: ast.expr, how: str, inverse: bool = False) -> Extrinsic | None:
        """A transpose inverts a rotation; an inverse inverts a rotation or a pose."""
        inner = self.of(operand)
        if inner is None or inner.part == TRANSLATION or inner.part == POSE and not inverse:
            return None
        return inner.inverted(f"inverted by {how}")

    def _joined(self, elements: list[ast.expr]) -> Extrinsic | None:
        """`[R | t]` (and `[[R | t]; bottom]`): a pose when its known parts agree."""
        parts = [self.of(element) for element in elements if not isinstance(element, Starred)]
        known = [part for part in parts if part is not None]
        if not known or len({part.direction for part in known}) != 1:
            return None
        kinds = {part.part for part in known}
        if kinds == {ROTATION, TRANSLATION} or kinds == {POSE} and len(known) == 1:
            first = known[0]
            return Extrinsic(
                first.direction, POSE, tuple(e for part in known for e in part.evidence), _weakest(known), _common_axes(known)
            )
        return None

    def _of_product(self, node: AST, negated: bool) -> Extrinsic | None:
        """`-R.T @ t` with R and t of one direction is the translation of the inverse pose
        (the camera centre when R, t are world-to-camera); row form `-t @ R` likewise."""
        while isinstance(node, UnaryOp) and isinstance(node.op, USub):
            node, negated = node.operand, not negated
        operands = matmul_operands(node)
        if operands is None:
            return None
        left, right = operands
        while isinstance(left, UnaryOp) and isinstance(left.op, USub):
            left, negated = left.operand, not negated
        while isinstance(right, UnaryOp) and isinstance(right.op, USub):
            right, negated = right.operand, not negated
        if not negated:
            return None
        first, second = self.of(left), self.of(right)
        if first is None or second is None:
            return None
        if first.part == ROTATION and second.part == TRANSLATION and first.direction != second.direction:
            rotation, translation = first, second  # column form: -(R_c2w) t_w2c
        elif first.part == TRANSLATION and second.part == ROTATION and first.direction == second.direction:
            rotation, translation = second.inverted("row form"), first  # `-t @ R` is -(R.T t)
        else:
            return None
        return Extrinsic(
            rotation.direction,
            TRANSLATION,
            (*translation.evidence, "inverse translation -R.T @ t"),
            _weakest([rotation, translation]),
            _common_axes([rotation, translation]),
        )

    # -- a 4x4 assembled from blocks -------------------------------------------------------------
    def block_stores(
        self, name: Name, before: ast.stmt | None = None, binding: object = None
    ) -> list[tuple[Subscript, ast.expr]]:
        """`T[:3, :3] = ...` / `T[:3, 3] = ...` writes into the value `name` reads (the same binding;
        for an assignment's own target, pass `binding=id(statement)`), in its function, before
        `before` when given."""
        index = self.index
        if binding is None:
            binding = binding_of(index, name)
        if binding is None:
            return []
        stores = []
        for target, value in scope_of(index, name).subscript_stores.get(name.id, ()):
            assert isinstance(target.value, Name)
            if before is not None and (target.lineno, target.col_offset) >= (before.lineno, before.col_offset):
                continue
            if binding_of(index, target.value) == binding:
                stores.append((target, value))
        return stores

    def built_from_blocks(self, name: Name, value: ast.expr) -> Extrinsic | None:
        """`T = np.eye(4)` whose rotation and translation blocks are then written: the pose the
        blocks state, when every known block agrees."""
        if not is_blank_matrix(value):
            return None
        parts = self.block_parts(self.block_stores(name, statement_of(self.index, name)))
        if not parts:
            return None
        directions = {part.direction for _, part in parts}
        if len(directions) != 1:
            return None
        known = [part for _, part in parts]
        axes = _common_axes(known)
        return Extrinsic(directions.pop(), POSE, tuple(e for part in known for e in part.evidence), _weakest(known), axes)

    def block_parts(self, stores: list[tuple[Subscript, ast.expr]]) -> list[tuple[ast.expr, Extrinsic]]:
        """The rotation and translation blocks among `stores` whose values are known extrinsics parts."""
        found = []
        for target, value in stores:
            indices = matrix_indices(target)
            if indices is None or indices[0] or not is_slice_upto(indices[1], 3):
                continue
            column = indices[2]
            if is_slice_upto(column, 3):
                wanted = ROTATION
            elif not isinstance(column, Slice) and int_value(column) in (3, -1):
                wanted = TRANSLATION
            else:
                continue
            part = self.of(value)
            if part is not None and part.part == wanted:
                found.append((value, part))
        return found


def _axes_of(found: Extrinsic | None) -> Axes | None:
    return found.axes if found is not None else None


def _common_axes(parts: list[Extrinsic]) -> Axes | None:
    """The camera axes every part states, or None (also when one part states none)."""
    axes = [part.axes for part in parts]
    first = axes[0]
    if first is None or any(other is None or other.convention != first.convention for other in axes):
        return None
    return first


def _weakest(parts: list[Extrinsic]) -> str:
    order = (ORDERED_NAME, NAME, DATA)
    return min((part.strength for part in parts), key=order.index)


def is_blank_matrix(value: ast.expr) -> bool:
    """`np.eye(4)`, `np.identity(4)`, `torch.eye(4)`, `np.zeros((4, 4))`."""
    if not isinstance(value, Call) or call_name(value) not in _BLOCK_MAKERS or not value.args:
        return False
    size = value.args[0]
    if isinstance(size, (ast.Tuple, ast.List)):
        return [int_value(element) for element in size.elts] in ([4, 4], [3, 4])
    return int_value(size) == 4


def mentions(value: ast.expr, target: ast.expr) -> bool:
    """Whether the value reads the target (`c2w = c2w[[1, 0, 2, 3]]`, `f["m"] = inv(f["m"])`)."""
    text = ast.unparse(target)
    for node in walk_within(value):
        if isinstance(node, Name) and isinstance(target, Name) and node.id == target.id:
            return True
        if isinstance(node, type(target)) and not isinstance(target, Name) and ast.unparse(node) == text:
            return True
    return False


_CAMERA_CLOUD_MAKERS: Final = frozenset({"create_from_rgbd_image", "create_from_depth_image"})
_CLOUD_MOVES: Final = frozenset({"transform", "rotate", "translate", "scale"})


def camera_frame_cloud(evidence: ExtrinsicsEvidence, receiver: ast.expr, use: AST) -> str | None:
    """Why `receiver` is an Open3D point cloud still in the camera frame where `use` runs: made by
    `PointCloud.create_from_rgbd_image` / `create_from_depth_image` without an extrinsic (with one,
    Open3D puts the cloud in the world frame), and not moved since. None otherwise."""
    if not isinstance(receiver, Name):
        return None
    index = evidence.index
    made = value_of(index, receiver)
    if not isinstance(made, Call) or call_name(made) not in _CAMERA_CLOUD_MAKERS:
        return None
    if "PointCloud" not in (evidence.facts.qualified_name(made.func) or ""):
        return None
    if len(made.args) >= 3 or any(keyword.arg in ("extrinsic", "extrinsics") for keyword in made.keywords):
        return None
    binding = binding_of(index, receiver)
    made_at = statement_of(index, made)
    used_at = statement_of(index, use)
    if made_at is None or used_at is None or binding is None:
        return None
    start, end = (made_at.lineno, made_at.col_offset), (used_at.lineno, used_at.col_offset)
    for call in evidence.facts.index.nodes(Call):
        func = call.func  # type: ignore[attr-defined]
        if not (isinstance(func, Attribute) and func.attr in _CLOUD_MOVES and isinstance(func.value, Name)):
            continue
        if func.value.id != receiver.id or call is use:
            continue
        position = (call.lineno, call.col_offset)  # type: ignore[attr-defined]
        if start < position < end and binding_of(index, func.value) == binding:
            return None  # moved in between: its frame is no longer the camera's for sure
    return f"`{receiver.id}` is an Open3D cloud in the camera frame (`{call_name(made)}` at line {made.lineno}, no extrinsic)"
