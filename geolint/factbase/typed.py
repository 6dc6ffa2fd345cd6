"""Frames stated by geolint's own types: the runtime's `Transform["world", "cam"]`, `Point[World]` and
geolint.typing's array annotations (`TransformMatrix["world", "cam"]`, `PointArray[Camera]`).

A type is a declaration, as strong as `from_frame=`/`to_frame=`: a partly annotated function
(`def to_world(T: TransformMatrix["world", "cam"], p_base)`) gives the frame rules one declared side
whatever the project's naming convention. A frame is a string (`"cam"`), `Literal["cam"]`, or a
`Frame` subclass (`class Camera(Frame, name="cam")`; without `name=`, the class name lower-cased).
The frames graph reads transforms the same way.
"""

from __future__ import annotations

from typing import Final

import ast
from ast import AST, Attribute, ClassDef, Constant, Module, Name, Subscript

from geolint.factbase.syntax import last_name
from geolint.semantic.names import NameFrames, Operator

# geolint's generic types by what they state: operators take (Dst, Src), values one frame
OPERATOR_TYPES: Final[dict[str, Operator]] = {
    "Transform": "transform",
    "TransformMatrix": "transform",
    "RotationMatrix": "rotation",
}
VALUE_TYPES: Final = frozenset(
    {
        "Point", "Vector", "Direction", "PointCloud", "Twist", "Wrench",
        "PointArray", "VectorArray", "DirectionArray", "HomogeneousPoints", "HomogeneousVectors",
    }
)  # fmt: skip


def frame_classes(module: Module) -> dict[str, str]:
    """The module's `Frame` subclasses: class name -> the frame it names."""
    classes = {}
    for node in ast.walk(module):
        if isinstance(node, ClassDef) and any(last_name(base) == "Frame" for base in node.bases):
            declared = next(
                (
                    keyword.value.value
                    for keyword in node.keywords
                    if keyword.arg == "name" and isinstance(keyword.value, Constant) and isinstance(keyword.value.value, str)
                ),
                None,
            )
            classes[node.name] = declared or node.name
    return classes


def type_frame(node: ast.expr, classes: dict[str, str]) -> str | None:
    """The frame one type argument names: `"cam"`, `Literal["cam"]`, `Camera`, `frames.Camera`."""
    if isinstance(node, Constant) and isinstance(node.value, str) and node.value:
        return node.value.lower()
    if isinstance(node, (Name, Attribute)):
        name = last_name(node)
        assert name is not None
        return classes.get(name, name).lower()
    if isinstance(node, Subscript) and last_name(node.value) == "Literal":
        return type_frame(node.slice, classes)
    return None


def typed_frames(annotation: AST | None, classes: dict[str, str]) -> NameFrames | None:
    """What a geolint type states (`Transform[A, B]`: maps B into A; `Point[F]`: in F), else None.
    The caller decides the subscripted name is geolint's (this reads the text of the type only)."""
    if not isinstance(annotation, Subscript):
        return None
    head = last_name(annotation.value)
    arguments = annotation.slice.elts if isinstance(annotation.slice, ast.Tuple) else [annotation.slice]
    if head in OPERATOR_TYPES and len(arguments) == 2:
        dst, src = (type_frame(argument, classes) for argument in arguments)
        if dst is not None and src is not None:
            return NameFrames(dst=dst, src=src, operator=OPERATOR_TYPES[head])
    if head in VALUE_TYPES and len(arguments) == 1:
        frame = type_frame(arguments[0], classes)
        if frame is not None:
            return NameFrames(frame=frame)
    return None

