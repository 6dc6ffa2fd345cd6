"""Library calls, answered from the knowledge base (`geolint.knowledge`, the stubs in `stubs/`): which
API a call is, what each argument is for it, and what it returns. No library is named here.

A call is resolved to an API by its qualified name (through the module's imports), by the library
class of the object it is called on (`r.as_quat()` where `r = Rotation.from_quat(q)`), by the one
star-imported stub module that defines the name, or by the method name of an `@any_receiver` class
in a module that imports what the class asks for. Then it is bound to the overloads it may be using;
a question is answered only when all of them agree (`geolint.knowledge.agreed`).
"""

from __future__ import annotations

import ast
from ast import AST, Attribute, BinOp, Call, Constant, If, Import, ImportFrom, Mult, Name
from typing import TYPE_CHECKING, Callable, Final, Sequence, TypeVar

from geolint.factbase.index import ParamBinding
from geolint.factbase.project_files import module_path
from geolint.factbase.project_pins import Pins, pins_for
from geolint.algebra import HOMOGENEOUS, Kind
from geolint.knowledge import (
    RADIANS,
    Api,
    Bound,
    Geometry,
    KnowledgeBase,
    Signature,
    agreed,
    bind,
    knowledge_base,
)

if TYPE_CHECKING:  # the fact base asks this module; it needs the class only for its annotations
    from geolint.factbase.model import FactBase

_Answer = TypeVar("_Answer")
_TYPE_DEPTH: Final = 8  # a library object passed through this many names and calls


def knowledge(facts: FactBase) -> KnowledgeBase:
    del facts  # one knowledge base per process; the parameter keeps the door open for a project's own stubs
    return knowledge_base()


def called_api(facts: FactBase, call: Call) -> Api | None:
    """The library API `call` calls, or None."""
    return facts.cached("library api", call, _called_api)  # guarded: `x = x.step()` asks for its own receiver


def library_call(facts: FactBase, call: Call) -> list[Bound]:
    """The overloads of a library API that `call` may be using, with its arguments bound ([]: not a
    known library call, or no overload fits)."""
    return facts.memoised("library call", call, lambda: _library_call(facts, call))


def _library_call(facts: FactBase, call: Call) -> list[Bound]:
    api = called_api(facts, call)
    if api is None:
        return []
    pins = pins_for(facts.path) if not facts.path.startswith("<") else Pins()
    # a fact marked `@versions(...)` counts only when the project's declared versions all satisfy it
    bounds = bind(api, call, lambda specifier: pins.allow_only(api.library, specifier))
    return _narrowed_by_class(facts, bounds) if len(bounds) > 1 else bounds


def _narrowed_by_class(facts: FactBase, bounds: list[Bound]) -> list[Bound]:
    """The overloads an argument's library class tells apart (pyrender's `Scene.add(obj, pose=...)`, whose
    pose is a camera's when `obj` is one of its cameras): where overloads type the argument's parameter with
    different classes and its class is known, those typed with its class stay, else those that leave the
    parameter untyped. An argument of unknown class keeps every overload open."""
    for name in bounds[0].arguments:
        argument = bounds[0].arguments[name]
        if not all(bound.arguments.get(name) is argument for bound in bounds):
            continue
        classes = [_parameter_class(bound, name) for bound in bounds]
        if len(set(classes)) < 2:
            continue
        held = library_type(facts, argument)
        if held is None:
            continue
        typed = [bound for bound, class_name in zip(bounds, classes) if class_name == held]
        bounds = typed or [bound for bound, class_name in zip(bounds, classes) if class_name is None]
        if not bounds:
            return []
    return bounds


def _parameter_class(bound: Bound, name: str) -> str | None:
    """The library class an overload types a parameter with (`obj: PerspectiveCamera`), when that is all it states."""
    parameter = bound.signature.parameter(name)
    geometry = parameter.geometry if parameter is not None else None
    return geometry.type_name if geometry is not None and geometry == Geometry(type_name=geometry.type_name) else None


def quaternion_inputs(facts: FactBase, call: Call) -> list[tuple[ast.expr, str]]:
    """(argument, component order) for each argument the call reads as a whole quaternion."""
    return _argument_facts(facts, call, "quaternion_order")


def expected_quaternion_order(facts: FactBase, call: Call) -> tuple[str, ast.expr | None] | None:
    """(order, argument) of the quaternion a known library call reads: a whole-quaternion argument, or
    (order, None) for a constructor of the four components in that order. None: not known."""
    inputs = quaternion_inputs(facts, call)
    if inputs:
        argument, order = inputs[0]
        return order, argument
    components = agreed(library_call(facts, call), lambda bound: bound.signature.components)
    return (components, None) if components is not None else None


def spread_quaternion(facts: FactBase, call: Call) -> ast.expr | None:
    """`Quaternion(*q)` into a known constructor of four components: `q`."""
    bounds = library_call(facts, call)
    if not bounds or agreed(bounds, lambda bound: bound.signature.components) is None:
        return None
    spread = {id(bound.spread) for bound in bounds}
    return bounds[0].spread if len(spread) == 1 else None


def quaternion_stacks(facts: FactBase, call: Call) -> bool:
    """Whether the quaternion a known library call reads may be an (N, 4) stack (`STACKED` in its stub)."""
    inputs = quaternion_inputs(facts, call)
    if not inputs:
        return False
    argument = inputs[0][0]
    return agreed(
        library_call(facts, call),
        lambda bound: next((_stacked(bound, name) for name, given in bound.arguments.items() if given is argument), False),
    ) is True


def _stacked(bound: Bound, name: str) -> bool:
    parameter = bound.signature.parameter(name)
    return parameter is not None and parameter.geometry is not None and parameter.geometry.stacked


def quaternion_output(facts: FactBase, call: Call) -> str | None:
    """The component order of the quaternion the call returns, or None."""
    return agreed(library_call(facts, call), lambda bound: _returned(bound).quaternion_order)


def angle_inputs(facts: FactBase, call: Call) -> list[tuple[ast.expr, str]]:
    """(argument, unit) for each argument the call reads as angles."""
    return _argument_facts(facts, call, "angle_unit")


def _argument_facts(facts: FactBase, call: Call, field: str) -> list[tuple[ast.expr, str]]:
    """(argument, the stub's `field` for its parameter), for the arguments every candidate overload
    binds to the same parameter and states the same value for."""
    bounds = library_call(facts, call)
    if not bounds:
        return []
    found: list[tuple[ast.expr, str]] = []
    for parameter in bounds[0].signature.parameters:
        argument = bounds[0].arguments.get(parameter.name)
        if argument is None or not all(bound.arguments.get(parameter.name) is argument for bound in bounds):
            continue
        values = {_parameter_geometry(bound, parameter.name, field) for bound in bounds}
        value = values.pop() if len(values) == 1 else None
        if isinstance(value, str):
            found.append((argument, value))
    return found


def angle_arguments(facts: FactBase, call: Call, unit: str, *, whatever_the_keywords: bool = False) -> list[ast.expr]:
    """The arguments a known library call reads as angles in `unit` (`geolint.knowledge.RADIANS` or
    `DEGREES`); [] when the stub says none, or its overloads disagree (`degrees=flag`). With
    `whatever_the_keywords`, only parameters in that unit in every overload of the API (`glRotatef`'s
    angle, not `from_euler(..., degrees=True)`'s, which a keyword chose)."""
    found = [argument for argument, stated in angle_inputs(facts, call) if stated == unit]
    if not whatever_the_keywords or not found:
        return found
    bounds = library_call(facts, call)
    api = called_api(facts, call)
    names = {name for name, argument in bounds[0].arguments.items() if any(argument is chosen for chosen in found)} if bounds else set()
    fixed = {name for name in names if api is not None and all(_states_unit(signature, name, unit) for signature in api.signatures)}
    return [argument for name, argument in bounds[0].arguments.items() if name in fixed] if bounds else []


def rotation_vector_arguments(facts: FactBase, call: Call) -> list[ast.expr]:
    """The arguments a known library call reads as rotation vectors (an axis times an angle in radians:
    `RotationVector` in its stub)."""
    bounds = library_call(facts, call)
    if not bounds:
        return []
    return [
        argument
        for argument, _ in angle_inputs(facts, call)
        if agreed(bounds, lambda bound: next((_is_rotation_vector(bound, name) for name, given in bound.arguments.items() if given is argument), False))
    ]


def _is_rotation_vector(bound: Bound, name: str) -> bool:
    parameter = bound.signature.parameter(name)
    geometry = parameter.geometry if parameter is not None else None
    return geometry is not None and geometry.kind is Kind.ROTATION and geometry.angle_unit == RADIANS


def choosing_keywords(facts: FactBase, call: Call) -> list[str]:
    """The keywords of a known library call that choose its overload (`degrees=True`), as written."""
    bounds = library_call(facts, call)
    if not bounds:
        return []
    chosen = {
        given.arg for given in call.keywords
        for bound in bounds
        if given.arg is not None and (parameter := bound.signature.parameter(given.arg)) is not None and parameter.literal is not None
    }  # fmt: skip
    return [f"{given.arg}={ast.unparse(given.value)}" for given in call.keywords if given.arg in chosen]


def _states_unit(signature: Signature, name: str, unit: str) -> bool:
    parameter = signature.parameter(name)
    return parameter is None or (parameter.geometry is not None and parameter.geometry.angle_unit == unit)


def may_read_angles(facts: FactBase, called: str, unit: str) -> bool:
    """Whether a call named `called` (`FactBase.called_name`) may be a known API that reads angles in
    `unit`: the cheap first test, before the call is resolved."""
    return called in knowledge(facts).names_reading("angle_unit", unit)


def angle_output(facts: FactBase, call: Call) -> str | None:
    """The unit of the angles the call returns: an angle or an array of them, or a tuple of nothing but
    angles in one unit (`mat2euler`'s three). None: not angles, or not known."""
    return agreed(library_call(facts, call), lambda bound: _angle_unit(_returned(bound)))


_ARRAY_KINDS: Final = frozenset({Kind.POINT, Kind.VECTOR, Kind.DIRECTION, Kind.ROTATION, Kind.TRANSFORM})


def returned_kind(facts: FactBase, call: Call) -> Kind | None:
    """The kind of the matrix or array the call returns (`as_matrix()`: a rotation, `transform_from(R, p)`:
    a transform, `create_from_depth_image(...)`: points), when every open overload says the same. A
    quaternion or an angle is not answered here (their order and unit have questions of their own)."""
    return agreed(library_call(facts, call), lambda bound: _array_kind(_returned(bound)))


def _array_kind(geometry: Geometry) -> Kind | None:
    if geometry.quaternion_order is not None or geometry.angle_unit is not None:
        return None
    return geometry.kind if geometry.kind in _ARRAY_KINDS else None


def returned_part(facts: FactBase, call: Call, position: int | None) -> Geometry | None:
    """What a known library call returns (position None) or element `position` of the tuple it returns,
    when every open overload says the same."""

    def part(bound: Bound) -> Geometry | None:
        returned = _returned(bound)
        if position is None:
            return returned
        return returned.items[position] if position < len(returned.items) else None

    return agreed(library_call(facts, call), part)


def returns_euler_angles(facts: FactBase, call: Call) -> bool:
    """Whether the call returns a tuple of three angles in one unit (`euler_from_quaternion(q)`)."""
    return agreed(library_call(facts, call), lambda bound: len(_returned(bound).items) == 3 and _angle_unit(_returned(bound)) is not None) is True


_MOVED_KINDS: Final = (Kind.POINT, Kind.VECTOR, Kind.DIRECTION)


def moved_arguments(facts: FactBase, call: Call) -> list[tuple[ast.expr, Kind]]:
    """(argument, kind) for each argument a known library call moves by a rigid transform, as the kind it
    moves it as: a point is translated (`transform_points(x, T)`, `vector_to_point(x)`, w = 1), a vector
    or direction only rotated (`translate=False`, `transform_normals(x)`, w = 0). [] when the overloads
    the call may be using disagree (`translate=flag`)."""
    bounds = library_call(facts, call)
    if not bounds or not all(bound.signature.applies_transform for bound in bounds):
        return []
    return [(argument, Kind(kind)) for argument, kind in _argument_facts(facts, call, "kind") if kind in _MOVED_KINDS]


def moving_as(facts: FactBase, call: Call, argument: ast.expr, wanted: frozenset[Kind]) -> tuple[str, str] | None:
    """How to make a known library call move `argument` as one of `wanted`, from the stubs: `("keyword",
    "translate=False")`, a keyword value that picks an overload that does, or `("name", "transform_normals")`,
    the API beside it (same module or class, the argument in the same place) that does. None: neither."""
    bounds = library_call(facts, call)
    api = called_api(facts, call)
    name = next((name for name, given in bounds[0].arguments.items() if given is argument), None) if bounds else None
    if api is None or name is None:
        return None
    def moves_as_wanted(signature: Signature) -> bool:
        parameter = signature.parameter(name)
        return parameter is not None and parameter.geometry is not None and parameter.geometry.kind in wanted

    chosen = _keyword_choosing(api, call, moves_as_wanted)
    if chosen is not None:
        return "keyword", chosen
    position = [parameter.name for parameter in bounds[0].signature.parameters].index(name)
    owner = api.qualified_name.rpartition(".")[0]
    twins = [other for other in knowledge(facts).apis() if other is not api and other.qualified_name.rpartition(".")[0] == owner and _moves_at(other, position, wanted)]
    if len(twins) > 1:  # `vector_to_direction(v)` over `vectors_to_directions(V)`: the same parameter name too
        twins = [other for other in twins if all(signature.parameters[position].name == name for signature in other.signatures)]
    return ("name", twins[0].qualified_name.rpartition(".")[2]) if len(twins) == 1 else None


def unit_keyword(facts: FactBase, call: Call, unit: str) -> str | None:
    """The keyword value that makes a known library call read its angles in `unit` (`degrees=True` for
    scipy's `from_euler`), when the call does not give that keyword. None: no such keyword."""
    api = called_api(facts, call)
    if api is None:
        return None
    return _keyword_choosing(api, call, lambda signature: any(_angle_unit(parameter.geometry) == unit for parameter in signature.parameters if parameter.geometry is not None))


def _keyword_choosing(api: Api, call: Call, holds: Callable[[Signature], bool]) -> str | None:
    """`name=value`: the one keyword the call does not give whose one literal value picks an overload for
    which `holds`."""
    given = {keyword.arg for keyword in call.keywords}
    for signature in api.signatures:
        if not holds(signature):
            continue
        choices = [other for other in signature.parameters if other.literal is not None and other.keyword and other.name not in given]
        if len(choices) == 1 and len(choices[0].literal or ()) == 1:
            return f"{choices[0].name}={choices[0].literal[0]!r}"  # type: ignore[index]
    return None


def stated_poses(facts: FactBase, call: Call) -> list[tuple[ast.expr, str, tuple[str, str]]]:
    """(argument, parameter, (dst, src)) for each argument a known library call reads as a transform between
    two named frames (`extrinsic: TransformMatrix["camera", "world"]`: world-to-camera), when every overload
    the call may be using agrees."""
    return _agreed_per_argument(facts, call, _pose_frames)


def _agreed_per_argument(facts: FactBase, call: Call, answer: Callable[[Bound, ast.expr], _Answer | None]) -> list[tuple[ast.expr, str, _Answer]]:
    """(argument, parameter, answer) for each argument of a known library call on which every overload the call
    may be using gives the same answer, not None."""
    bounds = library_call(facts, call)
    found: list[tuple[ast.expr, str, _Answer]] = []
    for name, argument in bounds[0].arguments.items() if bounds else ():
        stated = {answer(bound, argument) for bound in bounds}
        agreed_answer = stated.pop() if len(stated) == 1 else None
        if agreed_answer is not None:
            found.append((argument, name, agreed_answer))
    return found


def _argument_geometry(bound: Bound, argument: ast.expr) -> Geometry | None:
    """What the overload's parameter that `argument` fills is, as its stub says."""
    name = next((name for name, given in bound.arguments.items() if given is argument), None)
    parameter = bound.signature.parameter(name) if name is not None else None
    return parameter.geometry if parameter is not None else None


def _pose_frames(bound: Bound, argument: ast.expr) -> tuple[str, str] | None:
    geometry = _argument_geometry(bound, argument)
    if geometry is None or geometry.kind is not Kind.TRANSFORM or len(geometry.frames) != 2 or not all(geometry.frames):
        return None
    return geometry.frames[0], geometry.frames[1]


def stated_camera_axes(facts: FactBase, call: Call) -> list[tuple[ast.expr, str, Geometry]]:
    """(argument, parameter, geometry) for each argument a known library call reads with stated camera axes
    (`extrinsic: Annotated[TransformMatrix["camera", "world"], CameraAxes.OPENCV]`), when every overload the
    call may be using states the same axes, kind and frames."""
    return _agreed_per_argument(facts, call, _axes_geometry)


def _axes_geometry(bound: Bound, argument: ast.expr) -> Geometry | None:
    geometry = _argument_geometry(bound, argument)
    if geometry is None or geometry.camera_axes is None:
        return None
    return Geometry(kind=geometry.kind, frames=geometry.frames, camera_axes=geometry.camera_axes)


def homogenizes(facts: FactBase, call: Call) -> bool:
    """Whether a known library call returns its input made homogeneous (`vector_to_point`: w = 1)."""
    return agreed(library_call(facts, call), lambda bound: _returned(bound).kind in HOMOGENEOUS) is True


def _moves_at(api: Api, position: int, wanted: frozenset[Kind]) -> bool:
    """Whether every overload of `api` applies a transform to its parameter at `position` as one of `wanted`."""
    def moves(signature: Signature) -> bool:
        parameters = signature.parameters
        geometry = parameters[position].geometry if position < len(parameters) else None
        return signature.applies_transform and geometry is not None and geometry.kind in wanted

    return bool(api.signatures) and all(moves(signature) for signature in api.signatures)


def _angle_unit(geometry: Geometry) -> str | None:
    if geometry.angle_unit is not None or not geometry.items:
        return geometry.angle_unit
    units = {part.angle_unit for part in geometry.items}
    return units.pop() if len(units) == 1 else None  # a None among them: not every part is an angle


def library_type(facts: FactBase, node: AST) -> str | None:
    """The qualified library class `node` is an instance of, when every way it gets its value says so."""
    return _library_type(facts, node, _TYPE_DEPTH)


def _library_type(facts: FactBase, node: AST, depth: int) -> str | None:
    if depth <= 0:
        return None
    if isinstance(node, Call):
        api = called_api(facts, node)
        if api is None:
            return _returned_by_helper(facts, node, depth)
        if api.is_class:
            return api.qualified_name
        return agreed(library_call(facts, node), lambda bound: _returned(bound).type_name)
    if isinstance(node, Name):
        return _type_of_name(facts, node, depth)
    if isinstance(node, BinOp) and isinstance(node.op, Mult):  # `r1 * r2`: what the left class's `__mul__` returns for r2
        product = _product(facts, node.left, depth - 1)
        if product is None:
            return None
        right = _library_type(facts, node.right, depth - 1)
        returned = {(signature.returns or Geometry()).type_name for signature in product.signatures if _takes_type(facts, signature, right)}
        return returned.pop() if len(returned) == 1 else None
    if isinstance(node, Attribute) and (held := _attribute_api(facts, node, depth)) is not None:
        return held[1].type_name  # `q.inverse`: a property that returns another library object
    if isinstance(node, Attribute) and isinstance(node.value, Name) and node.value.id == "self":
        stores = facts.index.self_attribute_stores.get(node.attr, [])  # `self.volume = ScalableTSDFVolume(...)`
        return _one_type(facts, stores, depth) if all(isinstance(value, ast.expr) for value in stores) else None
    return None


def _returned_by_helper(facts: FactBase, call: Call, depth: int) -> str | None:
    """`make_pose(q) * offset`: a function of this module every `return` of which is one library type."""
    if not isinstance(call.func, Name) or call.func.id not in facts.index.functions:
        return None
    scope = facts.index.scopes.get(facts.index.functions[call.func.id])
    return _one_type(facts, scope.returns, depth) if scope is not None and scope.returns else None


def _product(facts: FactBase, node: AST, depth: int) -> Api | None:
    """The `__mul__` of `node`'s library class."""
    owner = _library_type(facts, node, depth)
    return knowledge(facts).api(f"{owner}.__mul__") if owner is not None else None


def _takes_type(facts: FactBase, signature: Signature, class_name: str | None) -> bool:
    """Whether an operator overload takes an operand of this library class (None: not a library object)."""
    operand = next((parameter.geometry for parameter in signature.parameters), None)
    taken = knowledge(facts).api(operand.type_name) if operand is not None and operand.type_name is not None else None
    return class_name is not None and taken is not None and taken.qualified_name == class_name


def translating_product(facts: FactBase, node: AST) -> str | None:
    """The library class of `node` when `node * value` moves `value` as a point, R p + t (PyKDL's `Frame`,
    spatialmath's `SE3`): its `__mul__` is a transform's and takes points, by its stub. Named as the library
    and the class (`PyKDL.Frame`, `spatialmath.SE3`)."""
    product = _product(facts, node, _TYPE_DEPTH)
    if product is None or not any(_translates_points(signature) for signature in product.signatures):
        return None
    owner = product.qualified_name.rpartition(".")[0]
    return f"{owner.partition('.')[0]}.{owner.rpartition('.')[2]}"


def _translates_points(signature: Signature) -> bool:
    receiver = signature.receiver
    return receiver is not None and receiver.kind is Kind.TRANSFORM and any(
        parameter.geometry is not None and parameter.geometry.kind is Kind.POINT for parameter in signature.parameters
    )


def attribute_geometry(facts: FactBase, node: Attribute) -> tuple[Api, Geometry] | None:
    """What an attribute of a library object holds, from its stub (`q.elements` of a pyquaternion
    `Quaternion`: w, x, y, z; `data.xquat` in a module that imports MuJoCo: a stack of w, x, y, z), with
    the API that says so. None: not a known library attribute."""
    return facts.cached("library attribute", node, _attribute_of)


def _attribute_of(facts: FactBase, node: Attribute) -> tuple[Api, Geometry] | None:
    return _attribute_api(facts, node, _TYPE_DEPTH)


def _attribute_api(facts: FactBase, node: Attribute, depth: int) -> tuple[Api, Geometry] | None:
    kb = knowledge(facts)
    owner = _library_type(facts, node.value, depth - 1)
    api = kb.api(f"{owner}.{node.attr}") if owner is not None else _any_receiver(facts, kb, node.attr)
    if api is None or not api.is_attribute:
        return None
    held = {signature.returns for signature in api.signatures}
    geometry = held.pop() if len(held) == 1 else None
    return (api, geometry) if geometry is not None else None


def _type_of_name(facts: FactBase, node: Name, depth: int) -> str | None:
    bound = facts.bindings(node) or []
    if len(bound) == 1 and isinstance(bound[0], ParamBinding) and bound[0].arg.annotation is not None:
        return _annotated_type(facts, bound[0].arg.annotation)  # `client: airsim.MultirotorClient`
    others = [binding for binding in bound if binding is not node]
    values = [binding for binding in others if isinstance(binding, ast.expr)]
    return _one_type(facts, values, depth) if len(values) == len(others) else None  # a parameter, a loop: unknown


def _one_type(facts: FactBase, values: Sequence[AST], depth: int) -> str | None:
    """The one library type every value has; None for none, or for values that disagree."""
    if not values:
        return None
    types = {_library_type(facts, value, depth - 1) for value in values}
    return types.pop() if len(types) == 1 else None


def _annotated_type(facts: FactBase, annotation: ast.expr) -> str | None:
    """The library class an annotation names (`airsim.MultirotorClient`, `"Rotation"`), through the imports."""
    if isinstance(annotation, Constant) and isinstance(annotation.value, str):
        try:
            annotation = ast.parse(annotation.value, mode="eval").body
        except SyntaxError:
            return None
    if not isinstance(annotation, (Name, Attribute)):
        return None
    qualified = facts.qualified_name(annotation)
    api = knowledge(facts).api(qualified) if qualified is not None else None
    return api.qualified_name if api is not None and api.is_class else None


def _called_api(facts: FactBase, call: Call) -> Api | None:
    kb = knowledge(facts)
    func = call.func
    qualified = branch_qualified_name(facts, func)
    if qualified is not None and not shadowed_by_project(facts, qualified):
        found = kb.api(qualified)
        if found is not None and _resolved_through_imports(facts, func):
            return found
        if found is None and _resolved_through_imports(facts, func):
            extended = kb.extension(qualified, imported_modules(facts))
            if extended is not None:
                return extended
    if isinstance(func, Attribute):
        receiver = _library_type(facts, func.value, _TYPE_DEPTH)
        if receiver is not None:  # its class's method, or one every object has where the module allows it
            return kb.api(f"{receiver}.{func.attr}") or _any_receiver(facts, kb, func.attr)
        conventional = _conventional(facts, kb, func.value)
        if conventional is not None:
            return kb.api(f"{conventional}.{func.attr}")
        return _any_receiver(facts, kb, func.attr)
    if isinstance(func, Name) and func.id not in facts.index.imports:
        return _star_imported(facts, kb, func)
    return None


class ImportBranches:
    """Names the module imports in more than one arm of a module-level `if` (`if ROS_VERSION == 1: from
    tf.transformations import quaternion_multiply` / `elif ROS_VERSION == 2: from transforms3d.quaternions
    import qmult as quaternion_multiply`): local name -> [(qualified name, the `if`'s test, arm)]. The
    index keeps the last import only; a call inside a function branch on the same test, in the same arm,
    is resolved to that arm's import instead (`branch_qualified_name`)."""

    def __init__(self, facts: FactBase) -> None:
        found: dict[str, list[tuple[str, str, bool]]] = {}
        for statement in facts.index.tree.body:
            if isinstance(statement, If):
                _collect_branch_imports(statement, found)
        self.alternatives = {name: arms for name, arms in found.items() if len({qualified for qualified, _, _ in arms}) > 1}


def _collect_branch_imports(node: If, found: dict[str, list[tuple[str, str, bool]]]) -> None:
    test = ast.dump(node.test)
    for arm, body in ((True, node.body), (False, node.orelse)):
        for statement in body:
            if isinstance(statement, ImportFrom) and statement.module and not statement.level:
                for alias in statement.names:
                    if alias.name != "*":
                        found.setdefault(alias.asname or alias.name, []).append((f"{statement.module}.{alias.name}", test, arm))
            elif isinstance(statement, If) and not arm and len(body) == 1:
                _collect_branch_imports(statement, found)  # `elif`


def branch_qualified_name(facts: FactBase, func: AST) -> str | None:
    """`facts.qualified_name(func)`, except for a name imported in several arms of a module-level `if`
    and called inside a branch on the same test: that arm's import."""
    qualified = facts.qualified_name(func)
    if not isinstance(func, Name) or not facts.index.imports.get(func.id):
        return qualified
    arms = facts.shared(ImportBranches).alternatives.get(func.id)
    if not arms:
        return qualified
    child: AST = func
    current = facts.parent(func)
    while current is not None:
        if isinstance(current, If):
            test = ast.dump(current.test)
            in_body = any(statement is child for statement in current.body)
            for candidate, guard, arm in arms:
                if guard == test and arm == in_body:
                    return candidate
        child = current
        current = facts.parent(current)
    return qualified


def shadowed_by_project(facts: FactBase, qualified: str) -> bool:
    """Whether the top package of `qualified` is a module of the project, as its imports resolve
    (`transformations.py` beside a ROS node that runs `from transformations import ...`: a vendored
    copy, which Python imports first, not the library the stubs describe)."""
    if facts.path.startswith("<"):
        return False
    return module_path(qualified.partition(".")[0], facts.path) is not None


def _resolved_through_imports(facts: FactBase, func: AST) -> bool:
    """Whether the qualified name came from an import, not from the spelling alone (a local `Rotation`
    class of the project is not scipy's)."""
    node = func
    while isinstance(node, Attribute):
        node = node.value
    return isinstance(node, Name) and node.id in facts.index.imports


def _conventional(facts: FactBase, kb: KnowledgeBase, node: AST) -> str | None:
    """A name that means a library class by convention when the module imports no such name
    (`R.from_quat(q)` in a snippet): the stubs' `conventional_names`."""
    if not isinstance(node, Name) or node.id in facts.index.imports:
        return None
    return kb.conventional_name(node.id)


def _any_receiver(facts: FactBase, kb: KnowledgeBase, method: str) -> Api | None:
    candidates = kb.methods_named(method)
    if not candidates:
        return None
    imported = imported_modules(facts)
    fitting = [
        api
        for api in candidates
        if api.receiver is not None
        and (not api.receiver.when_imported or any(name.startswith(api.receiver.when_imported) for name in imported))
        and not (api.receiver.unless_imported and any(name.startswith(api.receiver.unless_imported) for name in imported))
    ]
    return fitting[0] if len(fitting) == 1 else None


def _star_imported(facts: FactBase, kb: KnowledgeBase, func: Name) -> Api | None:
    if not facts.index.star_imports or facts.index.lookup(func.id, facts.index.scope_of(func)):
        return None
    found = {
        api
        for module in facts.index.star_imports
        if not shadowed_by_project(facts, module) and (api := kb.api(f"{module}.{func.id}")) is not None
    }
    return found.pop() if len(found) == 1 else None


def imported_modules(facts: FactBase) -> list[str]:
    """Every module and name the module imports, dotted in full (`import omni.isaac.core.prims` too)."""
    return facts.module_fact(
        "imported modules",
        lambda: [
            *facts.index.imports.values(),
            *(node.module for node in facts.index.nodes(ImportFrom) if node.module),  # type: ignore[attr-defined]
            *(alias.name for node in facts.index.nodes(Import) for alias in node.names),  # type: ignore[attr-defined]
        ],
    )


def _parameter_geometry(bound: Bound, name: str, field: str) -> object:
    parameter = bound.signature.parameter(name)
    geometry = parameter.geometry if parameter is not None else None
    return getattr(geometry, field) if geometry is not None else None


def _returned(bound: Bound) -> Geometry:
    return bound.signature.returns or Geometry()


def tf_roles(facts: FactBase, call: Call) -> tuple[Api, dict[str, ast.expr]] | None:
    """The tf frame ids a call names, by role (`markers.TfFrame`: "target"/"source" for a lookup,
    "parent"/"child" for a ROS 1 broadcast, "published" for the transform messages it publishes), with
    the API that says so; or the parts of a launch action (`markers.LaunchNode`), or of a ROS
    parameter's declaration or reading (`markers.RosParameter`: "name", "default"). A method is also
    recognised by its name alone, on an object the module does not type (a buffer passed in, a
    `self.broadcaster` set elsewhere), in a module that imports the library; overloads and
    same-named methods of several classes count when they agree on each role."""
    return facts.memoised("tf roles", call, lambda: _tf_roles(facts, call))


def _tf_roles(facts: FactBase, call: Call) -> tuple[Api, dict[str, ast.expr]] | None:
    bounds = library_call(facts, call)
    if bounds:
        api = called_api(facts, call)
        return _agreed_roles(api, bounds) if api is not None else None
    if not isinstance(call.func, Attribute):
        return None
    kb = knowledge(facts)
    named = call.func.attr
    candidates = [api for api in (*kb.tf_apis_named(named), *kb.parameter_apis_named(named)) if not api.is_class]
    if not candidates:
        return None
    imported = {name.partition(".")[0] for name in imported_modules(facts)}
    found: list[tuple[Api, Bound]] = []
    for api in candidates:
        library = kb.libraries.get(api.library)
        if library is not None and imported.intersection((*library.packages, *library.recognised_with)):
            found += [(api, bound) for bound in bind(api, call)]
    if not found:
        return None
    return _agreed_roles(found[0][0], [bound for _, bound in found])


def _agreed_roles(api: Api, bounds: list[Bound]) -> tuple[Api, dict[str, ast.expr]] | None:
    """role -> argument, for the roles every overload binds to the same argument."""
    maps = []
    for bound in bounds:
        roles: dict[str, ast.expr] = {}
        for parameter in bound.signature.parameters:
            geometry = parameter.geometry
            role = None if geometry is None else geometry.tf_frame or geometry.launch_part or geometry.ros_parameter
            argument = bound.argument(parameter)
            if role is not None and isinstance(argument, ast.expr):
                roles[role] = argument
        maps.append(roles)
    agreed_roles = {role: argument for role, argument in maps[0].items() if all(other.get(role) is argument for other in maps[1:])}
    return (api, agreed_roles) if agreed_roles else None
