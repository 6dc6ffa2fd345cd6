"""What a variable's NAME says about its value: its geometric kind and its coordinate frames.

Pure functions of a name and the config, shared by the lint rules, the frames-graph command,
the mypy plugin and the editor server. Names are split into whole tokens (`_`-separated), so
`n` (a count), `normalize`, `pointer` or `np.random.normal` never read as geometry. When a
name could be read two ways, the answer is None: a wrong guess costs more than silence.

Conventions understood (each one switchable in `[tool.geolint.naming]`):

- dst_first:  `T_world_cam`, `R_world_cam`   (maps cam into world)
- prefix_t:   `world_T_cam`, `world_R_cam`, Boston Dynamics' `world_tform_cam` (a statement: see factbase.bosdyn)
- monogram:   Drake `X_WB`, `R_WB` (pose of B in W), `p_BQ` (position of Q measured in B)
- from_style: `world_from_cam`; values `point_in_cam`, `normals_in_world`
- to_style:   `cam_to_world`, pytransform3d `cam2world` (src first)
- suffix:     `p_world`, `v_cam`, `points_cam`, `normals_world` (`v_cam` states a frame, not a kind)
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache
from typing import Final, Literal

# The one kind vocabulary. A name states POINT, TRANSFORM, ROTATION or DIRECTION; DIRECTION stands for
# every free vector a name can state (`normal`, `axis`, `velocity`): a name cannot tell a unit vector from
# a velocity, and both only rotate.
from geolint.algebra import Kind
from geolint.lint_types import Config

Operator = Literal["transform", "rotation", "unknown"]


@dataclass(frozen=True)
class NameFrames:
    """The frames a name states.

    For an operator (a transform or rotation) `dst` and `src` are set: it maps values
    expressed in `src` into `dst`. For a value (point, vector) only `frame` is set.
    `operator` says which kind of operator the name denotes ("unknown" when the
    convention does not say, e.g. `cam2world` may be a 3x3 or a 4x4).
    """

    dst: str | None = None
    src: str | None = None
    frame: str | None = None
    operator: Operator | None = None

    @property
    def is_operator(self) -> bool:
        return self.dst is not None and self.src is not None

    def inverted(self) -> NameFrames:
        """The frames of the inverse operator (what `.T` of a rotation or `inv(T)` gives)."""
        return NameFrames(dst=self.src, src=self.dst, operator=self.operator)


# --- vocabulary -------------------------------------------------------------------------

DIRECTION_WORDS: Final = frozenset(
    {
        "normal", "normals", "binormal", "binormals", "nrm", "nrms", "dir", "dirs", "direction",
        "directions", "axis", "approach", "heading", "velocity", "velocities", "vel", "vels",
        "acc", "accel", "acceleration", "gravity", "force", "forces", "torque", "torques", "omega",
        "tangent", "tangents",
    }
)  # fmt: skip
POINT_WORDS: Final = frozenset(
    {
        "point", "points", "pts", "pt", "position", "positions", "pos", "centroid", "centroids",
        "vertex", "vertices", "verts", "origin", "landmark", "landmarks",
    }
)  # fmt: skip
TRANSFORM_WORDS: Final = frozenset({"pose", "poses", "transform", "tf", "extrinsic", "extrinsics"})
# One-letter kind prefixes that need a frame after them to mean anything (`p_world`):
# `p` alone is a probability or a polynomial as often as a point.
POINT_PREFIXES: Final = frozenset({"p"})
# One-letter prefixes that state a value's frame but not its kind: `v_cam` is a vector or a velocity
# in kinematics code and a mesh's vertices in graphics code (`v_world = torch.Tensor(vertices)`).
FRAMED_VALUE_PREFIXES: Final = frozenset({"v"})

# Tokens that turn a geometric word into something else: `n_points` is a count,
# `normal_idx` an index, `point_size` a scalar. Any of them in a name means "not geometry".
NON_GEOMETRIC_TOKENS: Final = frozenset(
    {
        "n", "num", "nb", "count", "counts", "cnt", "idx", "index", "indices", "ids", "id", "len",
        "length", "lengths", "size", "sizes", "shape", "dim", "dims", "ndim", "mask", "masks",
        "norm", "norms", "magnitude", "mag", "scale", "name", "names", "str", "label", "labels",
        "key", "keys", "type", "types", "dtype", "err", "error", "errors", "tol", "std", "var",
        "sigma", "noise", "weight", "weights", "sign", "signs", "flag", "flags", "valid", "is",
        "has", "use", "threshold", "thresh", "limit", "limits", "angle", "angles", "dist",
        "distance", "distances", "radius", "color", "colors", "colour", "file", "path", "fmt",
        "format", "msg", "topic", "frame", "frames", "field", "fields", "offset", "offsets", "step",
        "steps", "cov", "covariance", "matrix", "mat", "kw", "kwargs", "args", "arg", "func", "fn",
        "cb", "callback", "map", "dict", "list", "set", "tuple", "str", "text", "order",
        "random", "sample", "samples", "dist", "pdf", "cdf", "test", "expected",
    }
)  # fmt: skip

# Qualifiers that look like a frame after a kind word but are not one (`pos_des`, `p_h`).
NOT_A_FRAME: Final = frozenset(
    {
        "new", "old", "prev", "previous", "next", "cur", "curr", "current", "des", "desired", "cmd",
        "ref", "err", "min", "max", "tmp", "temp", "est", "hat", "init", "initial", "start", "end",
        "first", "last", "mean", "avg", "sum", "list", "arr", "array", "np", "vec", "vector", "h",
        "hom", "homog", "homogeneous", "norm", "normalized", "unit", "scaled", "sorted", "filtered",
        "local", "global", "all", "other", "a", "b", "i", "j", "k", "x", "y", "z", "w", "out", "in",
        "res", "result", "copy", "orig", "original", "raw", "flat", "t", "true", "pred", "gt",
        "target", "goal", "offset", "delta", "diff", "rel", "abs", "3d", "2d", "xyz", "uv",
        "px", "mm", "m", "cm", "rad", "deg", "left", "right", "up", "down", "value", "values", "val",
        "vals", "iter", "adj", "corrected", "pred", "obs", "sq", "squared", "dot", "cross", "inv",
        "opt", "optim", "optimized", "optimised", "refined", "final", "best", "noisy", "perturbed",
    }
)  # fmt: skip

# Representations, not frames: `deg2rad`, `quat2mat`, `euler_to_matrix` are conversions.
NOT_A_FRAME_IN_CONVERSION: Final = frozenset(
    {
        "deg", "rad", "degrees", "radians", "str", "string", "int", "float", "bytes", "hex", "bin",
        "dec", "quat", "quaternion", "mat", "matrix", "euler", "axangle", "axis", "angle", "rotvec",
        "rpy", "ypr", "list", "dict", "tuple", "array", "np", "numpy", "torch", "tensor", "json",
        "yaml", "pose", "transform", "tf", "se3", "so3", "homogeneous", "rot", "rotation", "trans",
        "vec", "vector", "pq", "dual", "mrp", "compact", "exp", "log", "screw", "twist", "id",
        "idx", "index", "name", "unicode", "ascii", "utf8", "camel", "snake", "py", "c", "cpp",
        "xyz", "xyzw", "wxyz", "ros", "msg", "points", "point", "pts", "url", "path", "file",
    }
)  # fmt: skip

# Frame words the conventions WITHOUT an explicit transform letter need (`cam2world`,
# `world_from_cam`, `p_world`): without them `herm2poly`, `module_from_spec` and `p_neg`
# would read as frames. Trailing digits are ignored (`cam0`, `link3`); `frame-aliases`
# entries count as known too.
KNOWN_FRAMES: Final = frozenset(
    {
        "world", "map", "odom", "base", "body", "cam", "camera", "optical", "color", "depth", "rgb",
        "ir", "lidar", "laser", "velodyne", "radar", "imu", "gps", "sensor", "tool", "tcp", "ee",
        "eef", "effector", "flange", "wrist", "hand", "gripper", "finger", "grasp", "object", "obj",
        "table", "marker", "tag", "board", "robot", "link", "joint", "head", "torso", "pelvis", "foot",
        "arm", "shoulder", "elbow", "mount", "platform", "vehicle", "car", "ego", "ned", "enu", "ecef",
        "mocap", "vicon", "scene", "mesh", "model", "part", "bin", "tray", "shelf", "workspace",
        "ground", "floor", "cube", "box", "plane", "screen", "image", "img", "pixel", "ndc", "clip",
        "view", "eye", "light", "parent", "child", "src", "dst", "source", "dest", "fixed", "moving",
        "anchor", "hip", "knee", "ankle", "chassis", "drone", "uav", "ship", "boat",
        "stereo", "projector", "kinect", "realsense", "zed", "lens",
    }
)  # fmt: skip

TRANSFORM_LETTERS: Final = frozenset({"T", "X", "H"})
ROTATION_LETTERS: Final = frozenset({"R"})
_MONOGRAM_FRAME: Final = r"[A-Z][0-9]*"
_MONOGRAM_OPERATOR: Final = re.compile(rf"^([TXHR])_({_MONOGRAM_FRAME})({_MONOGRAM_FRAME})$")
_MONOGRAM_VALUE: Final = re.compile(rf"^([pv])_({_MONOGRAM_FRAME})({_MONOGRAM_FRAME})$")
_FRAME_WORD: Final = re.compile(r"^[a-z][a-z0-9]*$")
_TO_STYLE_COMPACT: Final = re.compile(r"^([A-Za-z][A-Za-z0-9]*?)2([A-Za-z][A-Za-z0-9]*)$")


def tokens(name: str) -> tuple[str, ...]:
    """The whole `_`-separated tokens of a name, lower-cased, without leading/trailing underscores."""
    return tuple(token.lower() for token in name.strip("_").split("_") if token)



# Plural point and direction words: as the first word of a two-word name they are not a modifier
# (`vertex_normals`, normals at vertices) but a head noun of their own (`VERTICES_AXIS`).
PLURAL_WORDS: Final = frozenset(
    {
        "centroids", "landmarks", "points", "positions", "pts", "vertices", "verts", "binormals",
        "directions", "dirs", "forces", "normals", "nrms", "tangents", "torques", "velocities", "vels",
    }
)  # fmt: skip


# --- kind --------------------------------------------------------------------------------


def kind_of_name(name: str, config: Config = Config()) -> Kind | None:
    """The geometric kind a name states, or None when it states none (or two).

    `normals`, `surface_normal`, `ray_dir`, `points_cam`, `p_world`, `T_world_cam` have a kind;
    `n`, `n_points`, `normal_idx`, `direction_name`, `p` do not.
    """
    return _kind_of_name(name, config.extra_direction_names, config.extra_point_names, config.naming)


@lru_cache(maxsize=8192)
def _kind_of_name(name, extra_directions, extra_points, naming) -> Kind | None:  # type: ignore[no-untyped-def]
    frames = _frames_of_name(name, naming)
    if frames is not None and frames.is_operator:
        return Kind.ROTATION if frames.operator == "rotation" else Kind.TRANSFORM
    parts = tokens(name)
    if not parts or any(part in NON_GEOMETRIC_TOKENS for part in parts):
        return None
    directions = DIRECTION_WORDS | {word.lower() for word in extra_directions}
    points = POINT_WORDS | {word.lower() for word in extra_points}
    kinds = set()
    # The head noun of a compound is usually its last token (`surface_normal`, `ray_dir`),
    # but a frame suffix comes after it (`normals_world`, `points_in_cam`).
    candidates = [parts[-1]]
    if len(parts) >= 3 and (parts[-1] in KNOWN_FRAMES or parts[-1] in NOT_A_FRAME):
        candidates.append(parts[-2])  # `grasp_point_cam`, `contact_normal_world`
    if (frames is not None and frames.frame is not None) or all(part in NOT_A_FRAME for part in parts[1:]):
        candidates.append(parts[0])
    for part in candidates:
        if part in directions:
            kinds.add(Kind.DIRECTION)
        elif part in points:
            kinds.add(Kind.POINT)
        elif part in TRANSFORM_WORDS and part == parts[-1]:
            kinds.add(Kind.TRANSFORM)
    if frames is not None and frames.frame is not None and len(parts) >= 2:
        if parts[0] in POINT_PREFIXES:
            kinds.add(Kind.POINT)
    if len(kinds) != 1:
        return None
    kind = kinds.pop()
    other = points if kind == Kind.DIRECTION else directions
    return None if _other_kind_spoils(parts, other) else kind


def _other_kind_spoils(parts: tuple[str, ...], other: frozenset[str] | set[str]) -> bool:
    """Whether a word of the other kind leaves the name's kind in doubt. `vertex_normals` and
    `point_velocity` are a modifier and a head noun; in a longer name (`origin_projected_on_screw_axis`)
    a word of the other kind means we cannot tell, and a modifier is singular: `vertices_axis` may be
    the axis's vertices."""
    if len(parts) > 2 and any(part in other for part in parts):
        return True
    return any(part in other and part in PLURAL_WORDS for part in parts[:-1])


# --- frames ------------------------------------------------------------------------------


def frames_of_name(name: str, config: Config = Config()) -> NameFrames | None:
    """The frames a name states, or None when it states none or could be read two ways.

    Frame words go through `config.frame_aliases` (e.g. cam -> camera) so that
    `T_world_camera` and `p_cam` agree when the user says they do.
    """
    frames = _frames_of_name(name, config.naming, _alias_words(config))
    if frames is None or not config.frame_aliases:
        return frames
    aliases = {key.lower(): value.lower() for key, value in config.frame_aliases.items()}

    def canon(frame: str | None) -> str | None:
        return None if frame is None else aliases.get(frame, frame)

    return NameFrames(canon(frames.dst), canon(frames.src), canon(frames.frame), frames.operator)


def _alias_words(config: Config) -> frozenset[str]:
    if not config.frame_aliases:
        return frozenset()
    return frozenset(word.lower() for pair in config.frame_aliases.items() for word in pair)


@lru_cache(maxsize=8192)
def _frames_of_name(name: str, naming, known: frozenset[str] = frozenset()) -> NameFrames | None:  # type: ignore[no-untyped-def]
    readings = {reading for reading in _readings(name.strip("_"), naming, known) if reading is not None}
    return readings.pop() if len(readings) == 1 else None


# words that read like frames but name something else: encodings (`image_to_base64`), and acronyms
# of the `A2B` shape (`I2C` a bus, `A2C` a learning algorithm, `P2P`, `E2E`)
_NOT_FRAMES: Final = frozenset({"base16", "base32", "base64", "base85"})
_ACRONYMS: Final = frozenset({"I2C", "A2C", "P2P", "B2B", "B2C", "E2E", "M2M", "D2D", "S2S", "V2V", "V2X"})


def _is_known_frame(word: str, known: frozenset[str]) -> bool:
    if word.lower() in _NOT_FRAMES:
        return False
    if re.fullmatch(_MONOGRAM_FRAME, word):
        return True  # `A2B`, `p_W`: one capital letter is a frame by convention
    stem = word.lower().rstrip("0123456789") or word.lower()
    return stem in KNOWN_FRAMES or stem in known or word.lower() in known


def _readings(name: str, naming, known: frozenset[str] = frozenset()):  # type: ignore[no-untyped-def]
    """Every reading of `name` under the enabled conventions (more than one means ambiguous)."""
    raw = name.split("_")
    if any(not part for part in raw):
        return
    if "_tform_" in name:
        if naming.prefix_t:
            yield tform_frames(name)
        return  # Boston Dynamics' `a_tform_b` is read that way or not at all
    if naming.monogram:
        monogram = _monogram_reading(name)
        if monogram is not None:
            yield monogram
            return  # `X_WB` is never also `X_<W>_<B>`
    if len(raw) == 3:
        yield from _three_word_readings(raw, naming, known)
    if len(raw) == 1 and naming.to_style:
        match = None if name in _ACRONYMS else _TO_STYLE_COMPACT.match(name)
        if match and _is_known_frame(match.group(1), known) and _is_known_frame(match.group(2), known):
            yield NameFrames(dst=match.group(2).lower(), src=match.group(1).lower(), operator="unknown")
    if len(raw) == 2 and naming.suffix:
        suffix = _suffix_reading(raw, known)
        if suffix is not None:
            yield suffix


def is_monogram_name(name: str) -> bool:
    """Whether a name is written in monogram notation (`X_WB`, `R_WB`, `p_BQ`), however `naming` reads names."""
    return _monogram_reading(name) is not None


def _monogram_reading(name: str) -> NameFrames | None:
    """Drake's monogram names: `X_WB` (an operator), `p_BQ` (a value in frame B)."""
    match = _MONOGRAM_OPERATOR.match(name)
    if match:
        letter, dst, src = match.groups()
        return NameFrames(dst=dst.lower(), src=src.lower(), operator=_operator(letter))
    match = _MONOGRAM_VALUE.match(name)
    if match:
        return NameFrames(frame=match.group(2).lower())
    return None


def _three_word_readings(raw: list[str], naming, known: frozenset[str]):  # type: ignore[no-untyped-def]
    """`T_world_cam` (dst-first), `world_T_cam` (prefix T), `world_from_cam`, `cam_to_world`, `points_in_cam`."""
    first, middle, last = raw
    if naming.dst_first and first in TRANSFORM_LETTERS | ROTATION_LETTERS:
        if is_frame(middle) and is_frame(last):
            yield NameFrames(dst=middle.lower(), src=last.lower(), operator=_operator(first))
    if naming.prefix_t and middle in TRANSFORM_LETTERS | ROTATION_LETTERS:
        if is_frame(first) and is_frame(last):
            yield NameFrames(dst=first.lower(), src=last.lower(), operator=_operator(middle))
    lowered = [part.lower() for part in raw]
    both_known = _is_known_frame(first, known) and _is_known_frame(last, known)
    if naming.from_style and lowered[1] == "from" and both_known:
        yield NameFrames(dst=lowered[0], src=lowered[2], operator="unknown")
    if naming.to_style and lowered[1] == "to" and both_known:
        yield NameFrames(dst=lowered[2], src=lowered[0], operator="unknown")
    if naming.from_style and lowered[1] == "in" and lowered[0] in _VALUE_HEADS and _is_known_frame(last, known):
        yield NameFrames(frame=lowered[2])


def _suffix_reading(raw: list[str], known: frozenset[str]) -> NameFrames | None:
    """`p_cam`, `normal_world`: a value word and a frame."""
    head, frame = raw[0].lower(), raw[1]
    # One capital letter is a frame in Drake's two-letter `p_BQ`, not in `v_T` (tendon speed).
    word_frame = not re.fullmatch(_MONOGRAM_FRAME, frame)
    if head in _VALUE_HEADS and frame.lower() not in _VALUE_HEADS and word_frame and _is_known_frame(frame, known):
        return NameFrames(frame=frame.lower())
    return None


_VALUE_HEADS = DIRECTION_WORDS | POINT_WORDS | POINT_PREFIXES | FRAMED_VALUE_PREFIXES

# The frames of Boston Dynamics' SDK whose names have several words (bosdyn.client.frame_helpers).
TFORM_COMPOUND_FRAMES: Final = frozenset(
    {
        "flat_body", "desired_tool", "gaze_target", "fl_foot", "fr_foot", "hl_foot", "hr_foot",
        "desired_tool_at_end", "measured_tool_at_start",
    }
)  # fmt: skip


def tform_frames(name: str) -> NameFrames | None:
    """Boston Dynamics' `a_tform_b` (`odom_tform_body`): the pose of b in a, mapping b into a.

    Each side is one frame word or one of the SDK's compound frames (`flat_body_tform_body`);
    anything else (`last_odom_tform_body`, `se3_a_tform_b`, `vision_tform_goal`) is not read:
    a qualifier or a waypoint word would be taken for a frame."""
    dst, separator, src = name.strip("_").partition("_tform_")
    if not separator or not all(_is_tform_frame(side) for side in (dst, src)):
        return None
    return NameFrames(dst=dst, src=src, operator="transform")


def _is_tform_frame(side: str) -> bool:
    return side in TFORM_COMPOUND_FRAMES or "_" not in side and side.islower() and is_frame(side)


def _operator(letter: str) -> Operator:
    return "rotation" if letter in ROTATION_LETTERS else "transform"


def is_frame(word: str) -> bool:
    """A token that can name a frame: a lower-case word or a one-letter upper-case frame."""
    if re.fullmatch(_MONOGRAM_FRAME, word):
        return True
    lowered = word.lower()
    if lowered in KNOWN_FRAMES and _FRAME_WORD.match(word):
        return True  # `T_map_odom`: ROS's `map` is a frame even though `depth_map` is not geometry
    return bool(_FRAME_WORD.match(word)) and lowered not in NOT_A_FRAME and lowered not in NON_GEOMETRIC_TOKENS


def _is_conversion_frame(word: str) -> bool:
    """A frame in `a2b` / `a_to_b` / `a_from_b`, where a representation name means a conversion."""
    if re.fullmatch(_MONOGRAM_FRAME, word):
        return True  # pytransform3d's `A2B`
    lowered = word.lower()
    if lowered in NOT_A_FRAME_IN_CONVERSION or lowered in NOT_A_FRAME or lowered in NON_GEOMETRIC_TOKENS:
        return False
    return bool(re.fullmatch(r"[A-Za-z][A-Za-z0-9]*", word))


# Point words that mean geometry almost always; `pos`, `position`, `point`, `origin` are also
# file offsets, cursor positions and sympy tuples, so they need more evidence (see GEO103).
STRONG_POINT_WORDS: Final = frozenset({"vertex", "vertices", "verts", "centroid", "centroids", "landmark", "landmarks"})


def states_geometry(name: str, config: Config = Config()) -> bool:
    """Whether a point-like name is geometric beyond doubt: a strong point word, or a frame
    (`p_world`, `points_cam`, `gripper_position_base`)."""
    parts = tokens(name)
    if STRONG_POINT_WORDS & set(parts):
        return True
    frames = frames_of_name(name, config)
    if frames is not None and frames.frame is not None:
        return True
    return len(parts) >= 2 and parts[-1] in KNOWN_FRAMES and kind_of_name(name, config) is not None


def same_frame(first: str | None, second: str | None) -> bool | None:
    """Whether two frame names are the same frame; None when they cannot be compared.

    A one-letter monogram frame (`W`) and a word (`world`) are never compared: they
    come from different conventions and `W` may well mean `world`. Nor is a word and its
    abbreviation (`cam` and `camera`, `base` and `base_link`): they usually name one frame,
    and `frame-aliases` can say so when a check is wanted. Nor is a word and its misspelling by
    one letter (`word` for `world`).
    """
    if first is None or second is None:
        return None
    if _is_letter_frame(first) != _is_letter_frame(second):
        return None
    first, second = first.lower(), second.lower()
    if first != second and (first.startswith(second) or second.startswith(first)):
        return None
    if _one_letter_apart(first, second):
        return None  # `T_word_body` next to `T_world_tcp`: a misspelling, not another frame
    return first == second


def _one_letter_apart(first: str, second: str) -> bool:
    """Whether two words of four letters or more differ by one inserted letter (`word`, `world`)."""
    shorter, longer = sorted((first, second), key=len)
    if len(longer) != len(shorter) + 1 or len(shorter) < 4 or not longer.isalpha():
        return False
    return any(longer[:i] + longer[i + 1 :] == shorter for i in range(len(longer)))


def _is_letter_frame(frame: str) -> bool:
    return bool(re.fullmatch(r"[A-Za-z][0-9]*", frame))


def order_dependent(name: str) -> bool:
    """Whether the frames a name states depend on the project's order convention: `T_a_b` and
    `R_a_b` map b into a in dst-first code and a into b in src-first code (autolab_core's
    `T_obj_world`). Every other convention says its direction in words (`a_from_b`, `a2b`,
    `a_T_b`, Drake's `X_AB`)."""
    raw = name.strip("_").split("_")
    return len(raw) == 3 and raw[0] in TRANSFORM_LETTERS | ROTATION_LETTERS
