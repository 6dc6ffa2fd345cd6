"""How the plugin's messages spell geometric types: ``Transform[World <- Camera]``, ``Point["camera"]``.

Two-frame kinds read like Drake's monogram ``X_WC``: the destination first, an arrow, then the source, so a
message shows at a glance which inner frames disagree.
"""

from __future__ import annotations

from mypy.types import Instance, LiteralType, ProperType, TypeVarType

from geolint.mypy import frame_names
from geolint.mypy.geometry import DISPLAY_NAME, FULLNAME_OF_KIND, Geo

TWO_FRAME_KINDS = frozenset({"transform", "rotation", "translation", "negated rotation"})


def frame_text(frame: ProperType) -> str:
    """A frame as the user wrote it: a class name (with its runtime name when declared with ``name=``), a quoted
    string frame, or a TypeVar's name."""
    if isinstance(frame, Instance):
        runtime_name = frame_names.frame_name(frame)
        if runtime_name is not None and runtime_name != frame.type.name:
            return f'{frame.type.name} ("{runtime_name}")'
        return frame.type.name
    if isinstance(frame, LiteralType) and isinstance(frame.value, str):
        return f'"{frame.value}"'
    if isinstance(frame, TypeVarType):
        return frame.name
    return "?"


def kind_text(geo: Geo) -> str:
    fullname = FULLNAME_OF_KIND[(geo.family, geo.kind)]
    return DISPLAY_NAME[fullname]


def geo_text(geo: Geo) -> str:
    """``Point[World]``, ``Transform[World <- Camera]``, ``OriginOffset[Camera -> Body, in World]``."""
    if geo.kind == "origin offset":
        axes, start, end = geo.frames
        return f"{kind_text(geo)}[{frame_text(start)} -> {frame_text(end)}, in {frame_text(axes)}]"
    if geo.kind in TWO_FRAME_KINDS:
        return f"{kind_text(geo)}[{frame_text(geo.dst)} <- {frame_text(geo.src)}]"
    return f"{kind_text(geo)}[{frame_text(geo.frame)}]"


def applied_to_wrong_frame(transform: Geo, value: Geo) -> str:
    expected = value.with_frames(transform.src, *value.frames[1:])
    return f"{geo_text(transform)} applied to {geo_text(value)}: expected a {geo_text(expected)}"


def rows_in_wrong_frame(value: Geo, rotation: Geo) -> str:
    return (
        f"{geo_text(value)} @ {geo_text(rotation)} (row vectors): expected rows in "
        f"{frame_text(rotation.dst)}; to map rows from {frame_text(rotation.src)}, multiply by R.T"
    )


def composed_across_frames(left: Geo, right: Geo) -> str:
    expected = right.with_frames(left.src, right.src)
    return f"{geo_text(left)} composed with {geo_text(right)}: expected a {geo_text(expected)}"


def mixed_frames(operator: str, left: Geo, right: Geo) -> str:
    return f"{geo_text(left)} {operator} {geo_text(right)}: the operands live in different frames"


def points_added(left: Geo, right: Geo) -> str:
    return (
        f"{geo_text(left)} + {geo_text(right)}: adding two points has no geometric meaning; "
        "subtract them for a vector, or add a vector to a point"
    )


def point_subtracted_from_vector(left: Geo, right: Geo) -> str:
    return f"{geo_text(left)} - {geo_text(right)}: a vector minus a point has no geometric meaning"


def translation_added_to_vector(operator: str, vector: Geo, translation: Geo) -> str:
    return (
        f"{geo_text(vector)} {operator} {geo_text(translation)}: a translation added to a "
        f"{vector.kind}; vectors and directions take the rotation only (R @ v)"
    )


def different_kinds(operator: str, left: Geo, right: Geo) -> str:
    return f"{geo_text(left)} {operator} {geo_text(right)}: the operands are different kinds"


def offsets_do_not_chain(operator: str, left: Geo, right: Geo) -> str:
    return (
        f"{geo_text(left)} {operator} {geo_text(right)}: one offset does not start where the other ends "
        "(a composition reads R_ab @ t_bc + t_ab)"
    )


def bad_affine_weights(sample: Geo, point_weight: float) -> str:
    return (
        f"a combination of {kind_text(sample)}s: the point weights sum to {point_weight:g}, not 1 (a point) "
        "or 0 (a vector), so the result depends on where the origin is"
    )


def compared_across(receiver: Geo, other: Geo) -> str:
    if receiver.kind != other.kind:
        return (
            f"{geo_text(receiver)}.is_close({geo_text(other)}): always False, a {receiver.kind} is never a "
            f"{other.kind}"
        )
    return f"{geo_text(receiver)}.is_close({geo_text(other)}): always False, the values live in different frames"


def translation_through_matrix(transform: Geo, value: Geo) -> str:
    return (
        f"{geo_text(transform)} applied to {geo_text(value)}: the vector was homogenized with w=1, so the "
        "full matrix adds its translation; use w=0 or the rotation block"
    )


def translating_call(call: str, value: Geo) -> str:
    return (
        f"{call} translates its input, but {geo_text(value)} is a {value.kind}: "
        "vectors and directions take the rotation only"
    )


def vector_made_point(call: str, value: Geo) -> str:
    return (
        f"{call} gives {geo_text(value)} w=1, so a 4x4 transform will add its translation to it; "
        "use vector_to_direction (w=0)"
    )


def raw_array_operand(operator: str, value: Geo) -> str:
    wrap = "Point" if value.kind == "transform" else "Vector"
    frame = frame_text(value.src if value.kind == "transform" else value.frame)
    return (
        f"{geo_text(value)} {operator} a raw ndarray: its kind and frame are unknown (the runtime refuses it); "
        f"wrap it first, e.g. {wrap}[{frame}](array)"
    )


def misread_string_frame(value: Geo, frame: Instance) -> str:
    return (
        f'{geo_text(value)}: the frame "{frame.type.name}" was read as Python\'s builtin {frame.type.name}, not as a '
        f"string frame (the plugin rewrites string frames where the class is imported by name, not through an "
        f'alias); write {kind_text(value)}[Literal["{frame.type.name}"]]'
    )


def generic_frames_disagree(
    callee: str, variable: str, first: tuple[ProperType, str, Geo], second: tuple[ProperType, str, Geo]
) -> str:
    """Two arguments of a frame-generic call give its type variable two frames."""
    (frame_a, name_a, value_a), (frame_b, name_b, value_b) = first, second
    return (
        f'{callee}(): frame {variable} is {frame_text(frame_a)} from "{name_a}" ({geo_text(value_a)}) but '
        f'{frame_text(frame_b)} from "{name_b}" ({geo_text(value_b)})'
    )
