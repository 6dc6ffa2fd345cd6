"""Which frames an expression lives in (a value's frame, an operator's dst and src) and the evidence:
explicit declarations first, then library semantics, data flow and products composed by
`geolint.algebra`, then names read in one naming order (`T_a_b` dst-first or src-first)."""

from __future__ import annotations

import ast
from ast import AST, Add, AnnAssign, Attribute, BinOp, Call, MatMult, Mult, Name, Sub, Subscript, USub, UnaryOp
from typing import Final, Literal, Sequence, TYPE_CHECKING

from geolint import algebra
from geolint.algebra import Kind
from geolint.factbase import bosdyn
from geolint.factbase import vocabulary as vocab
from geolint.factbase.declarations import declared_call_frames
from geolint.factbase.fact_types import DST_FIRST, SRC_FIRST, FrameFact
from geolint.factbase.index import Binding, ParamBinding
from geolint.factbase.kinds import valid_kind
from geolint.factbase.syntax import last_name, positional_args, string
from geolint.semantic.names import NameFrames, frames_of_name, is_monogram_name, order_dependent, same_frame

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

EXTRINSICS_EVIDENCE: Final = "states camera extrinsics"  # the evidence of a name read by its extrinsics word alone
# Words that make an extrinsics-named pose a relative one: `init_rel_w2c = inv(c2w_new @ w2c_last)`
# is a world-to-world correction that `w2c_ref @ rel_w2c` applies, named after the pose it corrects.
RELATIVE_WORDS: Final = frozenset({"rel", "relative", "delta", "diff", "residual", "incr", "increment", "update", "correction", "corr"})

_OPERATOR_KINDS: Final = {"rotation": Kind.ROTATION, "transform": Kind.TRANSFORM}


def frames_of(facts: FactBase, node: AST, order: str = DST_FIRST) -> NameFrames | None:
    """The frames of an expression (operator: dst/src; value: frame) with `T_a_b` names read
    in `order`, or None."""
    fact = frame_fact(facts, node, order)
    return None if fact is None else fact.frames


def frame_fact(facts: FactBase, node: AST, order: str = DST_FIRST) -> FrameFact | None:
    return facts.cached("frames", node, _frames, order)


def name_frames(facts: FactBase, name: str, order: str) -> FrameFact | None:
    """What a name states, read in `order` (only `T_a_b` / `R_a_b` depend on it)."""
    stated = frames_of_name(name, facts.config)
    if stated is None:
        return _extrinsics_frames(facts, name)
    if "_tform_" in name:
        return bosdyn.name_fact(name, stated)  # Boston Dynamics' `odom_tform_body` states its direction
    if facts.config.naming.monogram and is_monogram_name(name):
        # read only in projects that use the library that defines the notation, where `X_WB` is B's
        # pose in W by that library's documented convention: as strong as a declaration
        return FrameFact(stated, (f"name `{name}` (monogram notation)",), True)
    if facts.order_names_mixed and order_dependent(name):
        return None
    if order == SRC_FIRST and stated.is_operator and order_dependent(name):
        return FrameFact(stated.inverted(), (f"name `{name}` (src-first)",))
    return FrameFact(stated, (f"name `{name}`" + (" (dst-first)" if order_dependent(name) else ""),))


def _extrinsics_frames(facts: FactBase, name: str) -> FrameFact | None:
    """`c2w`, `pose_w2c`, `"cam_R_w2c"`: a camera-extrinsics word that states its direction."""
    declared = vocab.DECLARING_ATTRIBUTES.get(name)
    if declared is not None:
        return FrameFact(declared, (f"`{name}` ({vocab.DECLARING_ATTRIBUTE_SOURCES[name]})",), True)
    parts = name.lower().split("_")
    if RELATIVE_WORDS.intersection(parts):
        return None  # `rel_w2c`, `delta_c2w`: a correction named after the pose it corrects (world to world)
    found = {vocab.EXTRINSICS_TOKENS[part] for part in parts if part in vocab.EXTRINSICS_TOKENS}
    if len(found) == 1 and len(parts) <= 3:
        return FrameFact(found.pop(), (f"`{name}` {EXTRINSICS_EVIDENCE}",))
    return None


def _frames(facts: FactBase, node: AST, order: str) -> FrameFact | None:
    if isinstance(node, Name):
        return _frames_of_variable(facts, node, order)
    if isinstance(node, Attribute):
        return _frames_of_attribute(facts, node, order)
    if isinstance(node, Subscript):
        return _frames_of_subscript(facts, node, order)
    if isinstance(node, UnaryOp) and isinstance(node.op, USub):
        inner = frame_fact(facts, node.operand, order)
        return inner if inner is not None and not inner.frames.is_operator else None
    if isinstance(node, Call):
        return _frames_of_call(facts, node, order)
    if isinstance(node, BinOp):
        return _frames_of_binary(facts, node, order)
    return None


def _frames_of_attribute(facts: FactBase, node: Attribute, order: str) -> FrameFact | None:
    """`T.T` (the inverse of a rotation), a declaring attribute (`.cam_from_world`), or the attribute's name."""
    if node.attr in ("T", "mT"):
        inner = frame_fact(facts, node.value, order)
        if inner is not None and inner.frames.is_operator:
            return FrameFact(inner.frames.inverted(), inner.evidence, inner.declared)
        return inner
    if facts.is_module_like(node.value):
        return None
    declared = vocab.DECLARING_ATTRIBUTES.get(node.attr)
    if declared is not None:
        return FrameFact(declared, (f"`.{node.attr}` ({vocab.DECLARING_ATTRIBUTE_SOURCES[node.attr]})",), True)
    return name_frames(facts, node.attr, order)


def _frames_of_subscript(facts: FactBase, node: Subscript, order: str) -> FrameFact | None:
    """`meta["c2w"]` (the key states the convention), `T[:3, :3]` (the rotation of T), `T[:3, 3]` (a
    point in T's dst), `points[i]` (the frame of the points)."""
    key = string(node.slice)
    if key is not None:
        if key in vocab.DECLARING_ATTRIBUTES:
            return _extrinsics_frames(facts, key)
        return name_frames(facts, key, order) if key.isidentifier() else None
    inner = frame_fact(facts, node.value, order)
    if inner is None:
        return None
    frames = inner.frames
    if frames.is_operator:
        if facts.rotation_block_of(node) is not None:
            return FrameFact(NameFrames(dst=frames.dst, src=frames.src, operator="rotation"), inner.evidence, inner.declared)
        if facts.translation_of(node) is not None:
            return FrameFact(NameFrames(frame=frames.dst), inner.evidence, inner.declared)
        return None
    return inner


def _frames_of_binary(facts: FactBase, node: BinOp, order: str) -> FrameFact | None:
    """`p + v` (a value keeps its frame), `A @ B` and `T * x` (a product)."""
    if isinstance(node.op, (Add, Sub)):
        left, right = frame_fact(facts, node.left, order), frame_fact(facts, node.right, order)
        if left is not None and not left.frames.is_operator and (right is None or right.frames == left.frames):
            return left
        if right is not None and not right.frames.is_operator and left is None:
            return right
        return None
    if isinstance(node.op, MatMult):
        return _frames_of_product(facts, node.left, node.right, order)
    if isinstance(node.op, Mult):
        left = frame_fact(facts, node.left, order)
        if left is not None and left.frames.is_operator and left.frames.operator == "transform":
            return _frames_of_product(facts, node.left, node.right, order)
    return None


def _frames_of_variable(facts: FactBase, node: Name, order: str) -> FrameFact | None:
    return facts.of_bindings("variable frames", node, _frames_of_bindings, order)


def _frames_of_bindings(facts: FactBase, name: str, bindings: Sequence[Binding], order: str) -> FrameFact | None:
    if any(_rebinds_own_inverse(facts, name, binding) for binding in bindings):
        return None  # `world2cam = inv(world2cam)`: the name holds both directions
    declared = [fact for fact in (_declared_frames(facts, b) for b in bindings if isinstance(b, ast.expr)) if fact is not None]
    declared += [fact for fact in (_typed_frames(facts, name, b) for b in bindings) if fact is not None]
    if declared:
        frames = {fact.frames for fact in declared}
        return declared[0] if len(frames) == 1 else None
    stated = name_frames(facts, name, order)
    if stated is not None:
        return stated
    readings = set()
    found = []
    for binding in bindings:
        if not isinstance(binding, ast.expr):
            return None
        fact = frame_fact(facts, binding, order)
        found.append(fact)
        readings.add(None if fact is None else fact.frames)
    if len(readings) == 1 and found and found[0] is not None:
        return found[0]
    return None


def _rebinds_own_inverse(facts: FactBase, name: str, binding: Binding) -> bool:
    if not isinstance(binding, Call):
        return False
    inner = None
    if last_name(binding.func) in vocab.INVERSE_FUNCTIONS and binding.args:
        inner = binding.args[0]
    elif isinstance(binding.func, Attribute) and binding.func.attr in vocab.INVERSE_METHODS:
        inner = binding.func.value
    return isinstance(inner, Name) and inner.id == name


def _typed_frames(facts: FactBase, name: str, binding: Binding) -> FrameFact | None:
    """Frames a geolint type states for a parameter or an annotated assignment
    (`T: TransformMatrix["world", "cam"]`, `p: Point[Camera] = ...`)."""
    if isinstance(binding, ParamBinding):
        annotation = binding.arg.annotation
    else:
        statement = facts.parent(binding) if isinstance(binding, ast.expr) else None
        annotated = isinstance(statement, AnnAssign) and isinstance(statement.target, Name)
        annotation = statement.annotation if annotated and statement.target.id == name else None  # type: ignore[union-attr]
    if not isinstance(annotation, Subscript) or not (facts.qualified_name(annotation.value) or "").startswith("geolint"):
        return None
    from geolint.factbase import typed

    frames = typed.typed_frames(annotation, _frame_classes(facts, annotation))
    if frames is None:
        return None
    return FrameFact(frames, (f"annotation `{ast.unparse(annotation)}` at line {annotation.lineno}",), True)


def _frame_classes(facts: FactBase, annotation: AST) -> dict[str, str]:
    """The `Frame` subclasses an annotation may name: this module's, and those it imports from project
    modules (`from arm.frames import Base`, where `class Base(Frame, name="base_link")`)."""
    from geolint.factbase import typed

    classes = facts.module_fact("frame_classes", lambda: typed.frame_classes(facts.index.tree))
    imported = {
        node.id: facts.index.imports[node.id]
        for node in ast.walk(annotation)
        if isinstance(node, Name) and node.id not in classes and node.id in facts.index.imports
    }
    if not imported or not facts.cross_module:
        return classes
    found = dict(classes)
    for local, qualified in imported.items():
        defining = facts.defining_module(qualified, facts.path)
        if defining is not None:
            other, name = defining
            declared = other.module_fact("frame_classes", lambda: typed.frame_classes(other.index.tree)).get(name)  # noqa: B023
            if declared is not None:
                found[local] = declared
    return found


def _declared_frames(facts: FactBase, value: ast.expr) -> FrameFact | None:
    """Frames a call states explicitly: `from_frame=`/`to_frame=`, `.as_frames(a, b)`, `lookup_transform(target, source, t)`."""
    if not isinstance(value, Call):
        return None
    declared = declared_call_frames(value)
    if declared is None:
        return None
    frames, how = declared
    return FrameFact(frames, (f"{how} at line {value.lineno}",), True)


def _frames_of_call(facts: FactBase, node: Call, order: str) -> FrameFact | None:
    declared = _declared_frames(facts, node) or bosdyn.helper_frames(facts, node)
    if declared is not None:
        return declared
    homogeneous = facts.homogeneous(node)
    if homogeneous is not None:  # [x, 1] lives where x lives
        inner = frame_fact(facts, homogeneous.inner, order)
        return inner if inner is not None and not inner.frames.is_operator else None
    func = node.func
    positional = positional_args(node)
    product = facts.matmul(node)
    if product is not None:
        return _frames_of_product(facts, product.left, product.right, order)
    if isinstance(func, Attribute) and func.attr in vocab.INVERSE_METHODS and not facts.is_module_like(func.value):
        inner = frame_fact(facts, func.value, order)
        return FrameFact(inner.frames.inverted(), inner.evidence, inner.declared) if inner is not None and inner.frames.is_operator else None
    if last_name(func) in vocab.INVERSE_FUNCTIONS and len(positional) == 1:
        inner = frame_fact(facts, positional[0], order)
        return FrameFact(inner.frames.inverted(), inner.evidence, inner.declared) if inner is not None and inner.frames.is_operator else None
    if positional and facts.is_array_call(func, *vocab.PASSTHROUGH_FUNCTIONS):
        return frame_fact(facts, positional[0], order)
    if isinstance(func, Attribute) and func.attr in vocab.PASSTHROUGH_METHODS and not facts.is_module_like(func.value):
        return frame_fact(facts, func.value, order)
    return None


def _frames_of_product(facts: FactBase, left_node: AST, right_node: AST, order: str) -> FrameFact | None:
    left_fact, right_fact = frame_fact(facts, left_node, order), frame_fact(facts, right_node, order)
    if left_fact is None or right_fact is None:
        return None
    left, right = left_fact.frames, right_fact.frames
    evidence = left_fact.evidence + right_fact.evidence
    # a result is declared when the operands its frames come from are
    if left.is_operator and right.is_operator:
        composed = algebra.compose_frames(_algebra_frames(left), _algebra_frames(right), same=_known_same)
        if composed.problem is not None:
            return None
        declared = left_fact.declared and right_fact.declared
        return FrameFact(NameFrames(dst=composed.frames.dst, src=composed.frames.src, operator=_composed_operator(left, right)), evidence, declared)
    if left.is_operator and right.frame is not None:
        applied = algebra.apply_frames(_algebra_frames(left), _algebra_frames(right)).frames
        return FrameFact(NameFrames(frame=applied.frame), evidence, left_fact.declared)
    if right.is_operator and left.frame is not None:
        # row vectors: `x @ M` applies M.T
        applied = algebra.apply_frames(_algebra_frames(right).inverted(), _algebra_frames(left)).frames
        return FrameFact(NameFrames(frame=applied.frame), evidence, right_fact.declared)
    return None


def _algebra_frames(frames: NameFrames) -> algebra.Frames:
    return algebra.Frames(dst=frames.dst, src=frames.src, frame=frames.frame)


def _known_same(first: str | None, second: str | None) -> bool:
    """Frames a composition joins: the same by `same_frame`; two it cannot compare join nothing."""
    return same_frame(first, second) is True


def _composed_operator(left: NameFrames, right: NameFrames) -> Literal["rotation", "transform"]:
    """What `algebra.apply` makes of two composed operators; one of unknown size composes as a transform."""
    kinds = [_OPERATOR_KINDS.get(frames.operator or "", Kind.TRANSFORM) for frames in (left, right)]
    return "rotation" if valid_kind(algebra.apply(*kinds)) == Kind.ROTATION else "transform"
