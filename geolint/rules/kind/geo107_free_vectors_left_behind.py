"""GEO107 free-vectors-left-behind: positions rotated into a new frame, their free vectors and headings not."""

from __future__ import annotations

import ast
from ast import (
    AST, AnnAssign, Assign, AsyncFunctionDef, Attribute, AugAssign, BinOp, Call, ClassDef, Constant, FunctionDef,
    IfExp, MatMult, Name, Slice, Starred, Subscript, USub, UnaryOp,
)
import re
from dataclasses import dataclass
from typing import AbstractSet, Final

from geolint.algebra import FREE, Kind
from geolint.factbase.index import ParamBinding
from geolint.factbase.model import OPERATORS, is_scalar_annotation, last_name, positional_args, string, transposed_value, walk_within
from geolint.factbase.point_transforms import first_point_transform, read_outside_returns, returned_names
from geolint.rules.fact_rule import FactRule
from geolint.rules.base import Invalid, Valid
from geolint.semantic.names import KNOWN_FRAMES, NON_GEOMETRIC_TOKENS, NOT_A_FRAME, POINT_WORDS, frames_of_name, tokens

# Members (attributes, dict keys) that hold positions of an object: rotated AND translated.
_POSITION_WORDS = POINT_WORDS | {
    "center", "centre", "centers", "centres", "xyz", "location", "locations", "loc", "locs",
    "keypoints", "kpts", "corners",
}  # fmt: skip
# Members that hold free vectors of the same object: rotated only, never left behind.
_FREE_WORDS: Final = frozenset(
    {
        "normal", "normals", "binormal", "binormals", "tangent", "tangents", "velocity", "velocities",
        "vel", "vels", "velo", "axis", "axes", "direction", "directions", "dir", "dirs", "force",
        "forces", "torque", "torques", "accel", "acceleration", "accelerations", "omega", "approach",
        "gravity",
    }
)  # fmt: skip
# Members that hold the object's orientation (an angle or a rotation): rotating positions changes it.
_ORIENTATION_WORDS: Final = frozenset({"heading", "headings", "yaw", "yaws", "orientation", "orientations", "ry", "rot_y", "rotation_y"})
# Column labels of a box layout written in a docstring or comment (`[x, y, z, dx, dy, dz, heading, vx, vy]`).
_VELOCITY_COLUMNS: Final = {"vx": 0, "vy": 1, "vz": 2, "vel_x": 0, "vel_y": 1, "vel_z": 2, "v_x": 0, "v_y": 1, "v_z": 2}
_HEADING_COLUMNS: Final = frozenset({"heading", "yaw", "ry", "rz", "rot_y", "rot_z", "rotation_y", "heading_angle"})
# Names of operands that rotate (a rotation matrix, a pose): a product with one of them moves a position.
_OPERATOR_TOKENS: Final = frozenset(
    {"r", "rot", "rotation", "rotmat", "rmat", "pose", "poses", "transform", "transformation", "tf", "extrinsic",
     "extrinsics", "c2w", "w2c", "se3", "so3", "rotation_matrix"}
)  # fmt: skip
# ... unless the name also says it is something else (a translation only, intrinsics, a scale).
_NOT_OPERATOR_TOKENS: Final = frozenset(
    {"k", "intrinsic", "intrinsics", "proj", "projection", "calib", "scale", "scaling", "translation", "shift", "offset",
     "noise", "angle", "angles", "axis", "vec", "vector", "quat", "quaternion", "euler", "deg", "rad"}
)  # fmt: skip
_ROTATING_CALL: Final = re.compile(r"rotat|transform_points|apply_transform|quaternion_rotate|quat_apply", re.IGNORECASE)
_ROTATION_MAKER: Final = re.compile(r"rot|euler|quat2mat|as_matrix|rodrigues|axangle2mat", re.IGNORECASE)
# Calls that only read a value (a finding stays possible when the free vector is passed to them).
_READERS: Final = frozenset({"len", "print", "isinstance", "type", "id", "repr", "str", "norm", "vector_norm"})
_STACKERS: Final = frozenset({"hstack", "column_stack", "concatenate", "cat", "concat", "stack", "dstack"})
_LAYOUT_START: Final = re.compile(r"[\[(<]\s*x\s*,\s*y\s*,\s*z\s*,")


@dataclass(frozen=True)
class _Member:
    """A part of one object: `box.center`, `sample["normals"]`, or columns `boxes[:, 7:9]`."""

    owner: str  # the object's source text (`box`, `data_dict["gt_boxes"]`)
    name: str | None  # the attribute or key
    columns: frozenset[int] | None  # for column slices of an array
    node: ast.expr

    def label(self) -> str:
        return self.name or ""


class FreeVectorsLeftBehind(FactRule):
    """Positions are rotated into a new frame while the free vectors or heading of the same object are not.

    ## What it does
    Flags a function that rotates the positions of an object (by a rotation matrix, a pose, or a
    `rotate*` / `transform_points` helper) and leaves the object's free vectors (velocities,
    normals, axes, forces, directions) or its heading in the old frame. "The same object" is:

    - an attribute or dict key of the same owner: `box.center = R @ box.center` while the function
      reads `box.velocity` (or, for `self`, the class has `self.velocity`) and never updates it;
      the same for `box.yaw`, `box.heading`, `box.orientation`. An attribute must be stored as data
      somewhere in the module and not be a method or property there (trimesh's `vertex_normals`
      is recomputed from the moved vertices);
    - columns of the same array whose layout is written down in the module, in a docstring or
      comment naming the array (`gt_boxes: (N, 9) [x, y, z, dx, dy, dz, heading, vx, vy]`) or by a
      velocity-named slice of it (`vel = gt_boxes[:, 7:9]`): `gt_boxes[:, :3]` rotated (or one of
      its position columns mirrored, `gt_boxes[:, 1] = -gt_boxes[:, 1]`) while the velocity or
      heading columns are never written;
    - values returned, stacked into one array, or stored into one object together:
      `return points_world, normals`, `np.hstack([points_world, normals])`,
      `cloud.points = Vector3dVector(points_world)` next to `cloud.normals = Vector3dVector(normals)`,
      where `points_world` is a rotated position and `normals` a free vector the function never
      rotates.

    The rule stays silent when the free vector is written (also element by element, as in
    `self.future_orientations[m][h] = q * self.future_orientations[m][h]` inside loops and `if`s),
    rotated, or handed to any other call in the function, when the class stores the free-vector
    attribute as a number (`self.angular_velocity = float(w)`, an annotation `float` or `int`: a
    yaw rate has no direction to rotate), when the whole object is passed on or moved by a library (`pcd.transform(T)`,
    `mesh.apply_transform(T)`), when the move is a translation or scaling only, and when the free
    vector's name states its frame (`v_body`).

    ## Why is this bad?
    A rigid motion maps a point as `R p + t` and a free vector as `R v`. Moving only the positions
    splits one object across two frames: after a data-augmentation rotation the boxes still carry
    their old velocities and headings (the network learns velocities that disagree with the motion
    it sees), and after a frame change a cloud keeps normals that point the old way.

    ## Example
    ```python
    def global_rotation(gt_boxes, points, angle):
        \"\"\"gt_boxes: (N, 9) [x, y, z, dx, dy, dz, heading, vx, vy]\"\"\"
        R = rotation_about_z(angle)
        points[:, :3] = points[:, :3] @ R.T
        gt_boxes[:, :3] = gt_boxes[:, :3] @ R.T
        gt_boxes[:, 6] += angle
        return gt_boxes, points
    ```

    ## Use instead
    ```python
    def global_rotation(gt_boxes, points, angle):
        \"\"\"gt_boxes: (N, 9) [x, y, z, dx, dy, dz, heading, vx, vy]\"\"\"
        R = rotation_about_z(angle)
        points[:, :3] = points[:, :3] @ R.T
        gt_boxes[:, :3] = gt_boxes[:, :3] @ R.T
        gt_boxes[:, 6] += angle
        gt_boxes[:, 7:9] = gt_boxes[:, 7:9] @ R[:2, :2].T
        return gt_boxes, points
    ```

    ## Fix safety
    No fix is offered: which rotation the free vectors need (the 2D block of a yaw rotation, the
    full rotation, a sign flip for a mirror) has to be chosen by a person.

    ## Known problems
    Column layouts are read only from the module itself: a box array whose velocity columns are
    described in another file (a dataset class, a config) is not checked, so the commonest form of
    the bug (an augmentation written for 7-column boxes, later fed 9-column boxes) stays silent.
    Operators are recognised by name (`R`, `rot_mat`, `pose`, `T`, `T_a_b`), by a `[:3, :3]`
    block, or by what made them; a rotation in a variable named otherwise (`M`) is not seen.
    A scalar is recognised only by a `float(...)`/`int(...)` store or a `float`/`int` annotation in
    the class: a number stored otherwise under a free-vector name (`self.angular_velocity =
    msg.angular.z`) is still listed, and one cast with `float()` anywhere is never listed.
    """

    code = "GEO107"
    name = "free-vectors-left-behind"

    VALID = [
        Valid(
            "def rotate(self, q):\n"
            "    self.center = q.rotation_matrix @ self.center\n"
            "    self.orientation = q * self.orientation\n"
            "    self.velocity = q.rotation_matrix @ self.velocity\n"
        ),
        Valid(
            "def to_world(cloud, T):\n"
            "    pts = cloud[:, :3] @ T[:3, :3].T + T[:3, 3]\n"
            "    normals = cloud[:, 3:6] @ T[:3, :3].T\n"
            "    return pts, normals\n"
        ),
        Valid(
            "def shift(gt_boxes, t):\n"
            "    '''gt_boxes: (N, 9) [x, y, z, dx, dy, dz, heading, vx, vy]'''\n"
            "    gt_boxes[:, :3] = gt_boxes[:, :3] + t\n"
            "    return gt_boxes\n"
        ),
        Valid(
            "class Box:\n"
            "    def __init__(self, center, velocity, angular_velocity, futures):\n"
            "        self.center = center\n"
            "        self.velocity = velocity\n"
            "        self.future_orientations = futures\n"
            "        self.angular_velocity = float(angular_velocity)\n"
            "    def rotate(self, q):\n"
            "        self.center = q.rotation_matrix @ self.center\n"
            "        self.velocity = q.rotation_matrix @ self.velocity\n"
            "        if self.future_orientations is not None:\n"
            "            for i in range(self.n):\n"
            "                self.future_orientations[i] = q * self.future_orientations[i]\n"
        ),  # the futures are rotated element by element; a yaw rate is a number
        Valid(
            "def to_world(track, R):\n"
            "    track['pos'] = track['pos'] @ R.T\n"
            "    track['vel'] = track['vel'] @ R.T\n"
            "    return track\n"
        ),
    ]
    INVALID = [
        Invalid(
            "def annotate(box, token):\n"
            "    box.velocity = lookup_velocity(token)\n"
            "def box_to_ego(box, R):\n"
            "    box.center = R @ box.center\n"
            "    return box, box.velocity\n",
            message="`box.center` is rotated into a new frame here, but not the same object's `box.velocity` (free vector); rotate those too",
            range=(4, 5, 4, 15),
        ),
        Invalid(
            "def global_rotation(gt_boxes, rot):\n"
            "    '''gt_boxes: (N, 9) [x, y, z, dx, dy, dz, heading, vx, vy]'''\n"
            "    gt_boxes[:, :3] = gt_boxes[:, :3] @ rot.T\n"
            "    return gt_boxes\n"
        ),
        Invalid(
            "def to_world(positions_h, velocities, T_world_body):\n"
            "    pos = (T_world_body @ positions_h.T).T[:, :3]\n"
            "    return pos, velocities\n"
        ),
    ]

    def run(self) -> None:
        facts = self.facts
        layouts = _Layouts(facts.index.source)
        # the statements and expressions the checks read, grouped by the function they run in
        # (from the module index: no second walk of every function)
        bodies: dict[AST, list[AST]] = {}
        for node in facts.index.nodes(Assign, AugAssign, AnnAssign, Call, BinOp):
            owner = facts.index.scope_of(node).node
            if isinstance(owner, (FunctionDef, AsyncFunctionDef)):
                bodies.setdefault(owner, []).append(node)
        for function, body in bodies.items():
            scope = facts.index.scopes.get(function)
            if scope is None:
                continue
            self._check_members(function, body, layouts)
            self._check_returned_together(function, body, scope)

    # -- rotations -----------------------------------------------------------------------------
    def _is_operator(self, node: AST, depth: int = 0) -> bool:
        """Whether a product with `node` rotates what it multiplies (a rotation or a pose, maybe inverted)."""
        facts = self.facts
        node = _uninverted(node)
        qualified = facts.qualified_name(node.func) if isinstance(node, Call) else None
        if qualified and qualified.endswith("translation_matrix"):
            return False
        if facts.rotation_block_of(node) is not None:
            return True
        said = self._named_operator(node)
        return said if said is not None else self._built_operator(node, depth)

    def _named_operator(self, node: AST) -> bool | None:
        """What the name (or string key) of `node` says: an operator, not one, or nothing (None)."""
        word = string(node.slice) if isinstance(node, Subscript) else last_name(node)
        if word is None:
            return None
        parts = set(tokens(word))
        if parts & _NOT_OPERATOR_TOKENS:
            return False
        if word == "T" or word.startswith("T_") or word == "rotation_matrix" or parts & _OPERATOR_TOKENS:
            return True
        return True if self.facts.kind_of(node) in OPERATORS else None

    def _built_operator(self, node: AST, depth: int) -> bool:
        """A rotation made by a call (`Rz(a)`, `np.array([[cos, -sin], ...])`), or a product or a name
        of operators only."""
        facts = self.facts
        if isinstance(node, Call):
            if _ROTATION_MAKER.search(last_name(node.func) or ""):
                return True
            if last_name(node.func) in ("array", "tensor", "stack") and _mentions_cos_and_sin(node):
                return True
            product = facts.matmul(node)
            return product is not None and depth < 3 and self._is_operator(product.left, depth + 1) and self._is_operator(product.right, depth + 1)
        if isinstance(node, BinOp) and isinstance(node.op, MatMult) and depth < 3:
            return self._is_operator(node.left, depth + 1) and self._is_operator(node.right, depth + 1)
        if isinstance(node, Name) and depth < 3:
            bindings = facts.bindings(node) or []
            values = [binding for binding in bindings if isinstance(binding, ast.expr)]
            return bool(values) and len(values) == len(bindings) and all(self._is_operator(value, depth + 1) for value in values)
        return False

    def _rotation_in(self, value: AST, depth: int = 0) -> AST | None:
        """The product with an operator, or the rotating call, inside `value` (through one name), else None."""
        facts = self.facts
        for node in (value, *walk_within(value)):
            product = facts.matmul(node)
            if product is not None and (self._is_operator(product.left) or self._is_operator(product.right)):
                return node
            if isinstance(node, Call) and node.args and self._rotating_call(node):
                return node
        if isinstance(value, Name) and depth < 2:
            bindings = facts.bindings(value) or []
            values = [binding for binding in bindings if isinstance(binding, ast.expr)]
            if len(values) == 1 and len(bindings) == 1:
                return self._rotation_in(values[0], depth + 1)
        return None

    def _rotating_call(self, node: Call) -> bool:
        """`rotate_points_along_z(x, a)`, `transform_points(x, T)`, scipy `rot.apply(x)`."""
        name = last_name(node.func) or ""
        if _ROTATING_CALL.search(name):
            return True
        return name == "apply" and isinstance(node.func, Attribute) and self._is_operator(node.func.value)

    # -- members of one object -----------------------------------------------------------------
    def _member(self, node: AST) -> _Member | None:
        facts = self.facts
        if isinstance(node, Attribute) and not facts.is_module_like(node.value) and node.attr not in ("T", "mT"):
            return _Member(self.code_of(node.value), node.attr, None, node)
        if isinstance(node, Subscript):
            key = string(node.slice)
            if key is not None:
                return _Member(self.code_of(node.value), key, None, node)
            columns = _columns(node)
            if columns is not None:
                return _Member(self.code_of(node.value), None, columns, node)
        return None

    def _written_member(self, target: AST) -> _Member | None:
        """The member an assignment writes, also through element indices: `self.future_orientations[m][h] = q * ...`
        writes `self.future_orientations` (element by element, in a loop)."""
        member = self._member(target)
        while member is None and isinstance(target, Subscript):
            target = target.value
            member = self._member(target)
        return member

    def _check_members(self, function: AST, body: list[AST], layouts: _Layouts) -> None:
        stores = _stores(body)
        moves: list[tuple[_Member, ast.expr, str]] = []
        for target, value in stores:
            if not _may_hold_positions(target):
                continue
            member = self._member(target)
            if member is None:
                continue
            if member.name is not None and _role(member.name) == "position" and self._rotation_in(value) is not None:
                moves.append((member, target, "rotated"))
            elif member.columns is not None and member.columns <= {0, 1, 2} and len(member.columns) >= 2:
                if self._rotation_in(value) is not None:
                    moves.append((member, target, "rotated"))
            elif member.columns is not None and len(member.columns) == 1 and _mirrors(value, target):
                moves.append((member, target, "mirrored"))
        reported: set[str] = set()
        for member, target, how in moves:
            if member.owner in reported or not self._escapes(member.owner, function):
                continue
            if self._owner_passed_on(member.owner, body):
                continue
            left = self._left_behind(member, how, function, body, stores, layouts)
            if left:
                reported.add(member.owner)
                what = ", ".join(left)
                verb, fix = ("rotated into a new frame", "rotate") if how == "rotated" else ("mirrored", "mirror")
                self.report(target, f"`{self.code_of(target)}` is {verb} here, but not the same object's {what}; {fix} those too")

    def _left_behind(
        self, moved: _Member, how: str, function: AST, body: list[AST], stores: list[tuple[ast.expr, ast.expr]], layouts: _Layouts
    ) -> list[str]:
        written = [m for m in (self._written_member(target) for target, _ in stores) if m is not None and m.owner == moved.owner]
        touched = self._touched(body)
        if moved.name is not None:
            return self._members_left_behind(moved, function, body, written, touched)
        return self._columns_left_behind(moved, how, function, written, touched, layouts)

    def _members_left_behind(
        self, moved: _Member, function: AST, body: list[AST], written: list[_Member], touched: set[tuple[str, str | int | None]]
    ) -> list[str]:
        """`self.normals` when `self.points` moved: the named members that are free vectors or orientations."""
        found: list[str] = []
        candidates = self._named_members(moved, function, body)
        for name, role in candidates:
            # `self.normals = ...` (a property) writes `self.normals_`/`self._normals` too
            if any(m.name is not None and m.name.strip("_") == name.strip("_") for m in written):
                continue
            if any(owner == moved.owner and isinstance(member, str) and member.strip("_") == name.strip("_") for owner, member in touched):
                continue
            if moved.name in ("points",) and name in ("normals", "vertex_normals"):
                continue  # GEO104's case
            spelled = f"{moved.owner}[{name!r}]" if isinstance(moved.node, Subscript) else f"{moved.owner}.{name}"
            found.append(f"`{spelled}` ({'free vector' if role == 'free' else 'orientation'})")
        return found

    def _columns_left_behind(
        self, moved: _Member, how: str, function: AST, written: list[_Member], touched: set[tuple[str, str | int | None]], layouts: _Layouts
    ) -> list[str]:
        """The velocity and heading columns of a box array whose position columns moved."""
        found: list[str] = []
        layout = layouts.of(moved.owner, self.facts, function)
        if layout is None:
            return []
        velocity, heading, source = layout
        columns = moved.columns or frozenset()
        if how == "mirrored":
            axis = next(iter(columns))
            velocity_columns = {column for column, component in velocity.items() if component == axis}
        else:
            velocity_columns = set(velocity)
        written_columns = {column for m in written if m.columns is not None for column in m.columns}
        if any(m.columns is None and m.name is None for m in written) or (moved.owner, None) in touched:
            return []
        missing_velocity = sorted(column for column in velocity_columns if column not in written_columns)
        if missing_velocity and not any(_overlaps(moved.owner, column, touched) for column in missing_velocity):
            found.append(f"velocity column{'s' if len(missing_velocity) > 1 else ''} {_span(missing_velocity)} ({source})")
        mirrored_vertical = how == "mirrored" and not columns & {0, 1}
        if heading is not None and not mirrored_vertical and heading not in written_columns and not _overlaps(moved.owner, heading, touched):
            found.append(f"heading column {heading} ({source})")
        return found

    def _named_members(self, moved: _Member, function: AST, body: list[AST]) -> list[tuple[str, str]]:
        """Free-vector and orientation members of the moved object that the code shows exist as data.

        A dict key read in the function counts. An attribute must also be stored somewhere (in the
        class for `self`, anywhere in the module otherwise) and not be a method or property of the
        module: a property such as trimesh's `vertex_normals` is recomputed from the moved vertices.
        """
        facts = self.facts
        nodes: list[AST] = list(walk_within(function))
        if moved.owner == "self":
            cls = facts.parent(function)
            if not isinstance(cls, ClassDef):
                return []
            nodes = list(walk_within(cls, stop_at_functions=False))
        defined = {node.name for node in facts.index.nodes(FunctionDef, AsyncFunctionDef)}  # type: ignore[attr-defined]
        stored = {target.attr for scope in facts.index.scopes.values() for target, _ in scope.attribute_stores}
        seen: dict[str, str] = {}
        style_key = isinstance(moved.node, Subscript)
        for node in nodes:
            member = self._member(node)
            if member is None or member.owner != moved.owner or member.name is None or member.name == moved.name:
                continue
            if isinstance(member.node, Subscript) != style_key:
                continue
            if not style_key and (member.name in defined or member.name not in stored):
                continue
            role = _role(member.name)
            if role in ("free", "orientation") and not frames_of_name(member.name, facts.config):
                seen.setdefault(member.name, role)
        derived = self._derived_from(moved, nodes)
        return sorted((name, role) for name, role in seen.items() if name not in derived and not (role == "free" and self._stored_as_scalar(moved, name, nodes)))

    def _stored_as_scalar(self, moved: _Member, name: str, nodes: list[AST]) -> bool:
        """Whether the code stores the attribute as a number (`self.angular_velocity = float(w)`, an
        annotation `float`, a parameter annotated `float`): a yaw rate has no direction to rotate
        (asked of free vectors only: a heading stored as a float does turn with the positions)."""
        if isinstance(moved.node, Subscript):
            return False
        if moved.owner != "self":
            stores = [value for scope in self.facts.index.scopes.values() for target, value in scope.attribute_stores if target.attr == name]
            return any(self._scalar_value(value) for value in stores)
        for node in nodes:
            if isinstance(node, AnnAssign):
                target, values = node.target, [node.value]
                is_field = isinstance(target, Name) and target.id == name  # a dataclass field
                if (is_field or _is_self_attribute(target, name)) and is_scalar_annotation(node.annotation):
                    return True
                if not _is_self_attribute(target, name):
                    continue
            elif isinstance(node, Assign) and any(_is_self_attribute(target, name) for target in node.targets):
                values = [node.value]
            else:
                continue
            if any(value is not None and self._scalar_value(value) for value in values):
                return True
        return False

    def _scalar_value(self, value: ast.expr) -> bool:
        """`float(w)`, `int(n)`, `float(w) if ... else w`, or a parameter annotated `float`."""
        if isinstance(value, IfExp):
            return self._scalar_value(value.body) or self._scalar_value(value.orelse)
        if isinstance(value, Call) and isinstance(value.func, Name) and value.func.id in ("float", "int"):
            return True
        if isinstance(value, Name):
            bindings = self.facts.bindings(value) or []
            return bool(bindings) and all(
                isinstance(binding, ParamBinding) and binding.arg.annotation is not None and is_scalar_annotation(binding.arg.annotation)
                for binding in bindings
            )
        return False

    def _derived_from(self, moved: _Member, nodes: list[AST]) -> set[str]:
        """Members the code computes from the moved position (`self.direction = normalize(self.target -
        self.position)` in an orbit camera): they follow the position by themselves."""
        derived: set[str] = set()
        for node in nodes:
            if not isinstance(node, Assign):
                continue
            reads = [self._member(inner) for inner in walk_within(node.value)]
            if not any(m is not None and m.owner == moved.owner and m.name == moved.name for m in reads):
                continue
            for target in node.targets:
                member = self._member(target)
                if member is not None and member.owner == moved.owner and member.name is not None:
                    derived.add(member.name)
        return derived

    def _unwrapped(self, value: ast.expr) -> tuple[ast.expr, Call | None]:
        """`Vector3dVector(x)`, `np.asarray(x)`, `torch.from_numpy(x).float()` -> x and the wrapping call
        (a call of one argument that neither rotates nor multiplies); anything else as it is."""
        inner = _peel(value)
        if isinstance(inner, Name):
            return inner, value if isinstance(value, Call) else None
        if isinstance(value, Call) and len(value.args) == 1 and not value.keywords and not self._rotating_call(value):
            argument = _peel(value.args[0])
            if isinstance(argument, Name) and self.facts.matmul(value) is None:
                return argument, value
        return value, None

    def _touched(self, body: list[AST], skip_stackers: bool = False, skip_calls: AbstractSet[int] = frozenset()) -> set[tuple[str, str | int | None]]:
        """(owner, member) pairs handed to a call or a product in the function (maybe rotated there):
        a member by name or column number, a whole value with None."""
        facts = self.facts
        found: set[tuple[str, str | int | None]] = set()
        for node in body:
            operands: list[AST] = []
            if isinstance(node, Call) and last_name(node.func) not in _READERS and id(node) not in skip_calls:
                if not (skip_stackers and facts.is_array_call(node.func, *_STACKERS)):
                    operands = [*node.args, *(keyword.value for keyword in node.keywords)]
                    if isinstance(node.func, Attribute):
                        operands.append(node.func.value)
            product = facts.matmul(node)
            if product is not None:
                operands += [product.left, product.right]
            stack = list(operands)
            while stack:
                inner = stack.pop()
                member = self._member(inner)
                if member is not None:
                    if member.columns is not None:
                        found.update((member.owner, column) for column in member.columns)
                    else:
                        found.add((member.owner, member.name))
                    continue
                if isinstance(inner, (Name, Attribute, Subscript)):
                    found.add((self.code_of(inner), None))
                stack.extend(ast.iter_child_nodes(inner))
        return found

    def _escapes(self, owner: str, function: AST) -> bool:
        """Whether changes to `owner` reach the caller: `self`, a parameter (changed in place), or returned."""
        root = owner.split(".")[0].split("[")[0]
        scope = self.facts.index.scopes.get(function)
        if root == "self":
            return True
        if scope is not None and any(isinstance(b, ParamBinding) for b in scope.bindings.get(root, [])):
            return True
        if scope is None:
            return False
        for value in scope.returns:
            elements = value.elts if isinstance(value, (ast.Tuple, ast.List)) else value.values if isinstance(value, ast.Dict) else [value]
            if any(element is not None and self.code_of(element) == owner for element in elements):
                return True
        return False

    def _owner_passed_on(self, owner: str, body: list[AST]) -> bool:
        """Whether the whole object goes to another call (which may move its vectors), or is moved as a
        whole by a method (`pcd.transform(T)`, `mesh.apply_transform(T)`, `box.rotate(q)`, `self.update()`)."""
        for node in body:
            if not isinstance(node, Call) or last_name(node.func) in _READERS:
                continue
            if isinstance(node.func, Attribute) and self.code_of(node.func.value) == owner:
                if owner == "self" or _ROTATING_CALL.search(node.func.attr) or node.func.attr in ("transform", "apply_transform", "rotate"):
                    return True
            for argument in [*node.args, *(keyword.value for keyword in node.keywords)]:
                if isinstance(argument, Starred):
                    argument = argument.value
                if self.code_of(argument) == owner:
                    return True
        return False

    # -- returned (or stacked) together ----------------------------------------------------------
    def _check_returned_together(self, function: AST, body: list[AST], scope) -> None:  # type: ignore[no-untyped-def]
        groups = self._returned_or_stacked_together(body, scope)
        stored, wrappers = self._stored_together(body)
        groups += stored
        touched: set | None = None  # type: ignore[type-arg]
        for group in groups:
            names = [element for element in group if isinstance(element, Name)]
            if len(names) < 2 or not any(_role(name.id) == "free" for name in names):
                continue
            moved = [(name, site) for name in names for site in [self._moved_position(name, scope)] if site is not None]
            if not moved:
                continue
            if touched is None:  # built only for the few functions that get this far
                touched = self._touched(body, skip_stackers=True, skip_calls=wrappers)
            for vector in names:
                if not self._free_left_behind(vector, scope, touched, function, [name.id for name, _ in moved]):
                    continue
                position, site = moved[0]
                self.report(
                    site,
                    f"`{position.id}` is rotated into a new frame here, but not the free vector `{vector.id}` it is "
                    "passed on with; rotate that too",
                )
                return

    def _returned_or_stacked_together(self, body: list[AST], scope) -> list[list[ast.expr]]:  # type: ignore[no-untyped-def]
        """Values returned together (`return pts, normals`) or stacked together (`np.hstack([pts, normals])`)."""
        groups: list[list[ast.expr]] = []
        for value in scope.returns:
            if isinstance(value, (ast.Tuple, ast.List)):
                groups.append(list(value.elts))
            elif isinstance(value, ast.Dict):
                groups.append([v for v in value.values if v is not None])
        for node in body:
            if isinstance(node, Call) and last_name(node.func) in _STACKERS and self.facts.is_array_call(node.func, *_STACKERS):
                arguments = positional_args(node)
                if arguments and isinstance(arguments[0], (ast.List, ast.Tuple)):
                    groups.append(list(arguments[0].elts))
        return groups

    def _stored_together(self, body: list[AST]) -> tuple[list[list[ast.expr]], set[int]]:
        """Values stored into position and free-vector members of one object (`pcd.points =
        Vector3dVector(pts_world)`, `pcd.normals = ...`), and the wrapping calls (not rotations)."""
        wrappers: set[int] = set()
        by_owner: dict[str, list[ast.expr]] = {}
        for node in body:
            if isinstance(node, Assign) and len(node.targets) == 1 and isinstance(node.targets[0], (Attribute, Subscript)):
                word = node.targets[0].attr if isinstance(node.targets[0], Attribute) else string(node.targets[0].slice)
                if word is None or _role(word) not in ("position", "free"):
                    continue
                member = self._member(node.targets[0])
                if member is None or member.columns is not None:
                    continue
                value, wrapper = self._unwrapped(node.value)
                if wrapper is not None:
                    wrappers.add(id(wrapper))
                by_owner.setdefault(member.owner, []).append(value)
        return [values for values in by_owner.values() if len(values) > 1], wrappers

    def _moved_position(self, name: Name, scope) -> AST | None:  # type: ignore[no-untyped-def]
        """Where a local name is bound to a rotated position (`pts = (T @ pts_h.T).T[:, :3]`)."""
        for binding in scope.bindings.get(name.id, []):
            if not isinstance(binding, ast.expr):
                continue
            for node in (binding, *walk_within(binding)):
                product = self.facts.matmul(node)
                if product is not None:
                    for value, operator in ((product.left, product.right), (product.right, product.left)):
                        if self._is_position(value) and self._is_operator(operator):
                            return binding
                if isinstance(node, Call) and node.args and self._rotating_call(node):
                    if self._is_position(node.args[0]):
                        return binding
        return None

    def _is_position(self, node: AST) -> bool:
        facts = self.facts
        node = _peel(node)
        homogeneous = facts.homogeneous(node)
        if homogeneous is not None:
            node = _peel(homogeneous.inner)
        if facts.kind_of(node) == Kind.POINT:
            return True
        word = last_name(node) if not isinstance(node, Subscript) else string(node.slice)
        return word is not None and _role(word) == "position"

    def _free_left_behind(self, vector: Name, scope, touched, function: AST, moved: list[str]) -> bool:  # type: ignore[no-untyped-def]
        if vector.id in moved or _role(vector.id) != "free" or frames_of_name(vector.id, self.facts.config):
            return False
        if self.facts.kind_of(vector) not in FREE:
            return False
        bindings = scope.bindings.get(vector.id, [])
        if not bindings or vector.id in scope.augmented or vector.id in scope.subscript_stores:
            return False
        if any(owner == vector.id for owner, _ in touched):
            return False  # handed to a call or a product: maybe rotated there
        for binding in bindings:
            if isinstance(binding, ast.expr):
                if self._rotation_in(binding) is not None:
                    return False
                if any(isinstance(n, Name) and n.id in moved for n in (binding, *walk_within(binding))):
                    return False  # computed from the moved positions
            elif not isinstance(binding, ParamBinding):
                return False
        if (
            all(isinstance(binding, ParamBinding) for binding in bindings)
            and {"normal", "normals", "nrm", "nrms"} & set(tokens(vector.id))
            and vector.id in returned_names(scope.returns)
            and not read_outside_returns(function, vector.id)
            and first_point_transform(self.facts, function, body_only=True, parameters=scope.bindings) is not None
        ):
            return False  # GEO104 reports it
        return True


# -- helpers ----------------------------------------------------------------------------------


def _role(word: str) -> str | None:
    parts = tokens(word)
    if not parts or set(parts) & (NON_GEOMETRIC_TOKENS - {"angle"}):
        return None
    if word.lower() in _ORIENTATION_WORDS or parts[-1] in _ORIENTATION_WORDS:
        return "orientation"
    # the head noun, before a frame or qualifier suffix (`xyz_cam`, `points_world`, `vel_new`)
    head = parts[-2] if len(parts) >= 2 and (parts[-1] in KNOWN_FRAMES or parts[-1] in NOT_A_FRAME) else parts[-1]
    if head in _FREE_WORDS:
        return "free"
    if head in _POSITION_WORDS:
        return "position"
    return None


def _is_self_attribute(target: AST, name: str) -> bool:
    return isinstance(target, Attribute) and target.attr == name and isinstance(target.value, Name) and target.value.id == "self"


def _may_hold_positions(target: AST) -> bool:
    """A cheap test before the owner's text is looked up: `x.center`, `x["points"]`, `x[:, :3]`, `x[:, 1]`."""
    if isinstance(target, Attribute):
        return _role(target.attr) == "position"
    if isinstance(target, Subscript):
        key = string(target.slice)
        if key is not None:
            return _role(key) == "position"
        columns = _columns(target)
        return columns is not None and columns <= {0, 1, 2}
    return False



def _uninverted(node: AST) -> AST:
    """`inv(T)`, `T.inverse()`, `T.inv()`: T (an inverse rotates as much as what it inverts)."""
    node = _peel(node)
    if isinstance(node, Call) and last_name(node.func) in ("inv", "inverse", "pinv") and node.args:
        node = _peel(node.args[0])
    if isinstance(node, Call) and isinstance(node.func, Attribute) and node.func.attr in ("inv", "inverse", "inverted"):
        node = _peel(node.func.value)
    return node


# Methods that return their array's values in its shape (copies, dtype and device moves, `.numpy()`).
_COPY_METHODS: Final = frozenset({"copy", "clone", "float", "double", "astype", "to", "detach", "cpu", "numpy", "contiguous"})


def _peel(node: AST) -> AST:
    """Through transposes, copies and dtype moves (`x.T`, `np.asarray(x)`, `x.float()`)."""
    for _ in range(8):
        inner = transposed_value(node)
        if inner is not None:
            node = inner
            continue
        if isinstance(node, Call):
            name = last_name(node.func)
            if isinstance(node.func, Attribute) and name in _COPY_METHODS:
                node = node.func.value
                continue
            if name in ("asarray", "array", "as_tensor", "tensor", "from_numpy", "ascontiguousarray") and node.args:
                node = node.args[0]
                continue
        break
    return node


def _mentions_cos_and_sin(node: AST) -> bool:
    called = {last_name(inner.func) for inner in ast.walk(node) if isinstance(inner, Call)}
    named = {inner.id for inner in ast.walk(node) if isinstance(inner, Name)}
    return bool({"cos", "sin"} <= called or {"rot_cos", "rot_sin"} <= named or {"cos", "sin"} <= named or {"c", "s"} <= named)


def _int(node: AST | None) -> int | None:
    if isinstance(node, Constant) and type(node.value) is int:
        return node.value
    return None


def _is_batch(node: AST) -> bool:
    if isinstance(node, Slice):
        return node.lower is None and node.upper is None and node.step is None
    if isinstance(node, Constant):
        return node.value is None or node.value is Ellipsis
    return isinstance(node, Attribute) and node.attr == "newaxis"


def _columns(node: Subscript) -> frozenset[int] | None:
    """`x[:, 0:3]` -> {0, 1, 2}, `x[..., 7]` -> {7}, `x[None, :, :3]` -> {0, 1, 2}; rows are not columns."""
    index = node.slice
    parts = list(index.elts) if isinstance(index, ast.Tuple) else [index]
    if len(parts) < 2 or not all(_is_batch(part) for part in parts[:-1]):
        return None
    last = parts[-1]
    if isinstance(last, Slice):
        if last.step is not None:
            return None
        lower = 0 if last.lower is None else _int(last.lower)
        upper = _int(last.upper)
        if lower is None or upper is None or not 0 <= lower < upper <= 64:
            return None
        return frozenset(range(lower, upper))
    value = _int(last)
    return None if value is None or value < 0 else frozenset({value})


def _mirrors(value: AST, target: AST) -> bool:
    """`x[:, 1] = -x[:, 1]`: a mirror of one position column."""
    return isinstance(value, UnaryOp) and isinstance(value.op, USub) and ast.unparse(value.operand) == ast.unparse(target)


def _stores(body: list[AST]) -> list[tuple[ast.expr, ast.expr]]:
    """(target, value) of every assignment in the function; tuple targets give each element."""
    found: list[tuple[ast.expr, ast.expr]] = []
    for node in body:
        if isinstance(node, Assign):
            for target in node.targets:
                elements = target.elts if isinstance(target, (ast.Tuple, ast.List)) else [target]
                found.extend((element, node.value) for element in elements)
        elif isinstance(node, (AugAssign, AnnAssign)) and node.value is not None:
            found.append((node.target, node.value))
    return found


def _overlaps(owner: str, column: int, touched: set) -> bool:  # type: ignore[type-arg]
    return (owner, column) in touched


def _span(columns: list[int]) -> str:
    if len(columns) > 1 and columns == list(range(columns[0], columns[-1] + 1)):
        return f"{columns[0]}:{columns[-1] + 1}"
    return ", ".join(str(column) for column in columns)


class _Layouts:
    """Column layouts of arrays written down in a module: `boxes: (N, 9) [x, y, z, dx, dy, dz, heading, vx, vy]`
    in a docstring or comment, or `vel = boxes[:, 7:9]`."""

    def __init__(self, source: str) -> None:
        self.source = source
        self._cache: dict[str, tuple[dict[int, int], int | None, str] | None] = {}

    def of(self, owner: str, facts, function: AST) -> tuple[dict[int, int], int | None, str] | None:  # type: ignore[no-untyped-def]
        """(velocity column -> axis, heading column, where it was read) for the array `owner`: a layout
        written in the function itself first, else one elsewhere in the module."""
        lines = self.source.splitlines()
        first, last = function.lineno, function.end_lineno or function.lineno  # type: ignore[attr-defined]
        inside = self._find(owner, facts, list(enumerate(lines[first - 1 : last], start=first)), slices=False)
        if inside is not None:
            return inside
        if owner not in self._cache:
            self._cache[owner] = self._find(owner, facts, list(enumerate(lines, start=1)), slices=True)
        return self._cache[owner]

    def _find(self, owner: str, facts, numbered: list[tuple[int, str]], slices: bool) -> tuple[dict[int, int], int | None, str] | None:  # type: ignore[no-untyped-def]
        word = re.findall(r"\w+", owner)
        if not word:
            return None
        last = word[-1]
        for number, line in numbered:
            if not re.search(rf"\b{re.escape(last)}\b", line):
                continue
            match = _LAYOUT_START.search(line)
            if match is None or match.start() < line.find(last):
                continue
            labels = _layout_labels(line[match.start() :])
            velocity = {column: _VELOCITY_COLUMNS[label] for column, label in enumerate(labels) if label in _VELOCITY_COLUMNS}
            heading = next((column for column, label in enumerate(labels) if label in _HEADING_COLUMNS), None)
            if velocity or heading is not None:
                return velocity, heading, f"layout on line {number}"
        # `vel = boxes[:, 7:9]`: a velocity-named slice of the same array
        for node in facts.index.nodes(Assign) if slices else []:
            if len(node.targets) != 1 or not isinstance(node.targets[0], Name) or not isinstance(node.value, Subscript):
                continue
            name = node.targets[0].id
            if _role(name) != "free" or not set(tokens(name)) & {"vel", "vels", "velo", "velocity", "velocities"}:
                continue
            columns = _columns(node.value)
            if columns is not None and facts.code_of(node.value.value) == owner and min(columns) >= 3 and len(columns) <= 3:
                ordered = sorted(columns)
                return {column: axis for axis, column in enumerate(ordered)}, None, f"`{name}` on line {node.lineno}"
        return None


def _layout_labels(text: str) -> list[str]:
    """The top-level labels of `[x, y, z, dx, dy, dz, heading, [vx], [vy]]` (optional marks removed)."""
    depth = 0
    collected = []
    for character in text:
        if character in "[(<":
            depth += 1
            if depth == 1:
                continue
        elif character in "])>":
            depth -= 1
            if depth == 0:
                break
        collected.append(character)
    labels = []
    for item in "".join(collected).split(","):
        label = item.strip(" []()<>?*'\"").lower()
        if label:
            labels.append(label)
    return labels
