"""GEO206 caller-transform-mutated: a function rewrites part of a transform its caller passed in."""

from __future__ import annotations

from typing import Final

import ast
import re
from ast import (
    AST,
    Assign,
    AsyncFunctionDef,
    Attribute,
    AugAssign,
    Call,
    Constant,
    For,
    FunctionDef,
    Load,
    Module,
    Name,
    Return,
    Subscript,
    While,
)

from geolint.factbase import ModuleIndex, index_of
from geolint.factbase.model import is_slice_upto, statements_under
from geolint.factbase.pose_parts import int_value, matrix_indices
from geolint.factbase.reaching import parameter_of, reaching_bindings, value_of
from geolint.rules.base import AstRule, Invalid, Valid
from geolint.rules.triggers import AllOf

# Attribute words that name a part of a transform or pose message (geometry_msgs Transform/Pose).
_PART_ATTRIBUTES: Final = frozenset({"translation", "rotation", "position", "orientation"})
# Function names that announce an in-place update.
_MUTATOR_NAME: Final = re.compile(r"^_*(set|update|apply|reset|zero|fill|write|assign|modify|normalize|init|populate)_|inplace|in_place|_$")


class CallerTransformMutated(AstRule):
    """A function rewrites the translation or rotation of a transform it received, without copying it.

    ## What it does
    Flags, inside a function that returns a value other than that parameter, an assignment into
    the translation or rotation of one of its parameters (or of a local name that is still that
    parameter):
    `T[:3, 3] = 0`, `T[:3, :3] = R`, `T[2, 3] += dz`, `poses[:, :3, 3] -= center`,
    `transform.transform.translation.x = 0.0`, `pose.orientation.w = 1.0`. A copy first
    (`T = T.copy()`, `copy.deepcopy(transform)`, `np.array(T)`) makes it fine.

    ## Why is this bad?
    numpy arrays, tensors and ROS messages are passed by reference. A helper that zeroes the
    translation of the transform it was given (to rotate a vector, to compare orientations, to
    re-centre a scene) changes the caller's transform as well, and every later use of it by the
    caller, or by the tf buffer or cache that handed it out, silently sees the edited value.

    ## Example
    ```python
    def rotate_vector(vector, transform):
        transform.transform.translation.x = 0.0
        transform.transform.translation.y = 0.0
        transform.transform.translation.z = 0.0
        return do_transform_point(vector, transform)
    ```

    ## Use instead
    ```python
    def rotate_vector(vector, transform):
        transform = copy.deepcopy(transform)
        transform.transform.translation.x = 0.0
        transform.transform.translation.y = 0.0
        transform.transform.translation.z = 0.0
        return do_transform_point(vector, transform)
    ```

    ## Fix safety
    There is no automatic fix: copying changes what the caller sees, and some callers may rely
    on the update.

    ## Known problems
    Functions that are meant to update their argument are recognised only by returning nothing,
    by returning the argument itself, by writing other arguments' elements in place and returning
    those (an in-place API such as `fill(uv, z, T)` that returns `uv, z`: the transform it
    rewrites is taken for a scratch slot of that API, though a caller could still be surprised),
    or by their name (`set_*`, `update_*`, `apply_*`, `*_inplace`, a trailing underscore); an
    in-place helper that also returns a status value is flagged. Callers are read in the module only:
    a helper whose every call there passes a name the caller never reads again is left alone, but
    callers in other modules are not seen, and one that passes a copy is judged all the same.
    """

    code = "GEO206"
    name = "caller-transform-mutated"
    triggers = AllOf(r"\.(?:translation|rotation|position|orientation)\.[xyzw]\s*[-+*/]?=|\[[^\]\n]*3\s*\]\s*[-+*/]?=")

    VALID = [
        Valid("def f(T, p):\n    T = T.copy()\n    T[:3, 3] = 0\n    return T @ p\n"),
        Valid("def set_translation(T, t):\n    T[:3, 3] = t\n    return T\n"),
        Valid("def center(T, c):\n    T[:3, 3] -= c\n"),  # returns nothing: an in-place helper
        Valid("import copy\ndef f(tf, v):\n    tf = copy.deepcopy(tf)\n    tf.transform.translation.x = 0.0\n    return apply(tf, v)\n"),
        Valid("import numpy as np\ndef f(R, t):\n    T = np.eye(4)\n    T[:3, 3] = t\n    return T\n"),
        Valid("class Node:\n    def f(self, v):\n        self.pose.position.x = v\n        return self.pose\n"),
        Valid("def f(K, s):\n    K[:2, 2] *= s\n    return K\n"),
        Valid("def f(poses, c):\n    poses[:, :3, 3] -= c\n    return poses, c\n"),  # handed back: the caller rebinds
        Valid("def snap(obj, y):\n    obj.translation = y\n    return True\n"),  # moving a simulated object
        Valid(  # its one caller never reads its own `poses` again
            "def center(poses, c):\n    poses[:, :3, 3] -= c\n    return R @ poses\n"
            "def load(self, poses, c):\n    self.poses = center(poses, c)\n    return self.poses\n"
        ),
        Valid(  # the caller rebinds `poses` before it reads the name again
            "def center(poses, c):\n    poses[:, :3, 3] -= c\n    return R @ poses\n"
            "def load(poses, c):\n    centred = center(poses, c)\n    poses = []\n    poses.append(centred)\n    return poses\n"
        ),
        Valid(  # an in-place API: fills uv and z and hands them back; T's translation is its scratch slot
            "def reproject(uv, z, T, A):\n    for i in range(len(uv)):\n        T[:3, 3] = lift(uv[i], z[i])\n"
            "        p = (A @ T)[:3, 3]\n        z[i] = p[2]\n        uv[i] = p[:2] / p[2]\n    return uv, z\n"
        ),
    ]
    INVALID = [
        Invalid(
            "def f(T, p):\n    T[:3, 3] = 0\n    return T @ p\n",
            message="`f` rewrites part of the transform its caller passed as `T` (`T[:3, 3]`), so the caller's transform changes too; copy it first (`T.copy()`, `copy.deepcopy(T)`)",
            range=(2, 5, 2, 13),
        ),
        Invalid(
            "def rotate_only(vector, transform):\n    transform.transform.translation.x = 0.0\n"
            "    return do_transform_vector3(vector, transform)\n"
        ),
        Invalid("def f(poses, center, pts):\n    out = poses\n    out[:, :3, 3] -= center\n    return pts @ out\n"),
        Invalid("def heading(pose):\n    pose.pose.orientation.w = 1.0\n    return yaw_of(pose)\n"),
        Invalid(  # the caller reads `poses` after the call
            "def center(poses, c):\n    poses[:, :3, 3] -= c\n    return R @ poses\n"
            "def load(poses, c):\n    centred = center(poses, c)\n    return poses, centred\n"
        ),
        Invalid(  # returns a parameter it never writes: not an in-place API
            "def reproject(uv, T, A):\n    T[:3, 3] = lift(uv)\n    return uv, A @ T\n"
        ),
    ]

    def check(self, tree: Module) -> None:
        index = index_of(tree)
        # from the writes to a transform's part, few in any module, to the function each is in
        # (not every statement of every function)
        for statement in index.nodes(Assign, AugAssign):
            targets = statement.targets if isinstance(statement, Assign) else [statement.target]  # type: ignore[attr-defined]
            for target in targets:
                root = _transform_part_root(target)
                if root is None:
                    continue
                function = index.scope_of(statement).node
                if not isinstance(function, (FunctionDef, AsyncFunctionDef)):
                    continue  # module or class level: no caller's argument
                if _MUTATOR_NAME.search(function.name) or not _returns_value(function):
                    continue
                parameter = _parameter_read_by(root, index)
                if parameter is None or parameter in ("self", "cls") or _returns_name(function, {parameter, root.id}):
                    continue  # returned: an update-and-return helper whose caller rebinds
                if _returns_name(function, _parameters_written_in_place(function, index) - {parameter}):
                    continue  # an in-place API: it fills other arguments and hands them back
                if _no_caller_reads_it_again(function, parameter, index):
                    continue  # every call in the module passes a name its caller never reads after the call
                self.report(
                    target,
                    f"`{function.name}` rewrites part of the transform its caller passed as "
                    f"`{parameter}` (`{ast.unparse(target)}`), so the caller's transform changes "
                    f"too; copy it first (`{parameter}.copy()`, `copy.deepcopy({parameter})`)",
                )


def _no_caller_reads_it_again(function: FunctionDef | AsyncFunctionDef, parameter: str, index: ModuleIndex) -> bool:
    """The module calls `function` by name, and at every call the argument for `parameter` is a name whose
    value the calling scope never reads after the call, outside a loop (`self.poses = center(poses)`, and
    `poses` is done with or rebound): the write changes nothing anyone reads. False when there is no call."""
    arguments = function.args
    positional = [argument.arg for argument in (*arguments.posonlyargs, *arguments.args)]
    calls = [call for call in index.nodes(Call) if isinstance(call, Call) and isinstance(call.func, Name) and call.func.id == function.name]
    if not calls:
        return False
    reads: dict[tuple[int, str], list[Name]] = {}  # one walk per calling scope and name, however many calls it makes
    for call in calls:
        given = _argument_for(call, positional, parameter)
        if not isinstance(given, Name) or _in_loop(call, index):
            return False
        scope = index.scope_of(call)
        key = (id(scope.node), given.id)
        if key not in reads:
            reads[key] = [
                node
                for node in ast.walk(scope.node)
                if isinstance(node, Name) and node.id == given.id and isinstance(node.ctx, Load) and index.scope_of(node) is scope
            ]
        bindings = index.lookup(given.id, scope) or []
        passed = {id(binding) for binding in reaching_bindings(index, scope, given, bindings)}
        after = call.end_lineno or call.lineno
        for node in reads[key]:
            if node.lineno > after and passed & {id(binding) for binding in reaching_bindings(index, scope, node, bindings)}:
                return False  # a later read of the value it was handed (not of a later rebinding)
    return True


def _argument_for(call: Call, positional: list[str], parameter: str) -> ast.expr | None:
    position = positional.index(parameter) if parameter in positional else len(call.args)
    if position < len(call.args):
        return call.args[position]
    return next((given.value for given in call.keywords if given.arg == parameter), None)


def _in_loop(node: AST, index: ModuleIndex) -> bool:
    """Inside a `for` or `while` of its own scope (a later iteration may read what an earlier one wrote)."""
    scope = index.scope_of(node).node
    current = index.parent(node)
    while current is not None and current is not scope:
        if isinstance(current, (For, While)):
            return True
        current = index.parent(current)
    return False


def _returns_value(function: FunctionDef | AsyncFunctionDef) -> bool:
    return any(
        isinstance(node, Return) and node.value is not None and not (isinstance(node.value, Constant) and node.value.value is None)
        for node in _own_statements(function)
    )


def _returns_name(function: FunctionDef | AsyncFunctionDef, names: set[str]) -> bool:
    """Some `return` hands back one of `names` (alone or in a tuple)."""
    for statement in _own_statements(function):
        if isinstance(statement, Return) and statement.value is not None:
            returned = statement.value.elts if isinstance(statement.value, (ast.Tuple, ast.List)) else [statement.value]
            if any(isinstance(value, Name) and value.id in names for value in returned):
                return True
    return False


def _parameters_written_in_place(function: FunctionDef | AsyncFunctionDef, index: ModuleIndex) -> set[str]:
    """The parameters whose elements the function stores into (`uv[i] = ...`, `out[:, 0] += d`)."""
    written = set()
    for statement in _own_statements(function):
        targets = statement.targets if isinstance(statement, Assign) else [statement.target] if isinstance(statement, AugAssign) else []
        for target in targets:
            if isinstance(target, Subscript) and isinstance(target.value, Name):
                parameter = _parameter_read_by(target.value, index)
                if parameter is not None:
                    written.add(parameter)
    return written


def _own_statements(function: AST) -> list[AST]:
    """The statements of a function, not of the functions and classes defined inside it."""
    return statements_under(function, into_definitions=False)


def _transform_part_root(target: ast.expr) -> Name | None:
    """The name whose translation or rotation `target` writes: `T[:3, 3]`, `tf.transform.translation.x`."""
    if isinstance(target, Subscript) and isinstance(target.value, Name):
        indices = matrix_indices(target)
        if indices is None:
            return None
        _, row, column = indices
        translation_column = int_value(column) in (3, -1)
        if is_slice_upto(row, 3) and (translation_column or is_slice_upto(column, 3)):
            return target.value
        if int_value(row) in (0, 1, 2) and translation_column:
            return target.value
        return None
    # A component of a message field: `tf.transform.translation.x`, `pose.orientation.w`.
    if not (isinstance(target, Attribute) and target.attr in ("x", "y", "z", "w")):
        return None
    part = target.value
    if not (isinstance(part, Attribute) and part.attr in _PART_ATTRIBUTES):
        return None
    node = part.value
    while isinstance(node, Attribute):
        node = node.value
    return node if isinstance(node, Name) else None


def _parameter_read_by(name: Name, index: ModuleIndex) -> str | None:
    """The parameter `name` still is where it is written (through plain aliases `out = T`)."""
    for _ in range(6):
        if parameter_of(index, name) is not None:
            return name.id
        value = value_of(index, name)
        if not isinstance(value, Name):
            return None
        name = value
    return None
