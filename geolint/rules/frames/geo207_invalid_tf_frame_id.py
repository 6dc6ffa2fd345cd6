"""GEO207 invalid-tf-frame-id: a literal frame id that tf2 rejects or that breaks the tf tree."""

from __future__ import annotations

import ast

from geolint.factbase.pose_parts import call_name
from geolint.rules.base import AstRule, Invalid, Valid
from geolint.rules.triggers import AllOf

# tf2 calls whose leading positional arguments are frame ids, and how many of them.
_FRAME_ARGUMENTS = {"lookup_transform": 2, "can_transform": 2, "lookup_transform_async": 2, "wait_for_transform_async": 2}
_FRAME_KEYWORDS = frozenset({"frame_id", "child_frame_id", "target_frame", "source_frame", "target", "source"})


class InvalidTfFrameId(AstRule):
    """A literal frame id that tf2 rejects or that breaks the tf tree.

    ## What it does
    In a module that uses tf2 (`tf2_ros`, or ROS 2's `rclpy`), flags a string literal used as a
    frame id that:

    - starts with a slash (`"/map"`) in `header.frame_id`, `child_frame_id`, a `frame_id=`
      keyword, or the frame arguments of `lookup_transform` / `can_transform`;
    - names the same frame as parent and child of one transform
      (`t.header.frame_id = "base_link"`, `t.child_frame_id = "base_link"`);
    - gives a child a second parent: in a module that publishes static transforms, one function
      sets up two transforms with the same literal `child_frame_id` and different literal
      `header.frame_id` (outside mutually exclusive `if`/`else` arms).

    ## Why is this bad?
    tf2 frame ids never start with a slash (REP 105; the `tf_prefix` convention of ROS 1 `tf`
    is gone): `lookup_transform("/map", ...)` raises `InvalidArgumentException`, and a published
    `"/base_link"` is a frame no one else names. A transform from a frame to itself is dropped
    with a `TF_SELF_TRANSFORM` error. tf is a tree: a frame with two parents makes the tree flip
    between them on every update, and every lookup through that frame alternates between two
    answers.

    ## Example
    ```python
    transform = buffer.lookup_transform("/map", "base_link", rclpy.time.Time())
    ```

    ## Use instead
    ```python
    transform = buffer.lookup_transform("map", "base_link", rclpy.time.Time())
    ```

    ## Fix safety
    Dropping the leading slash is offered as an unsafe fix (a frame published elsewhere with the
    slash, by ROS 1 code, would need the same change). The other two cases have no fix.

    ## Known problems
    Only literal frame ids are checked. A module that imports neither `tf2_ros` nor `rclpy`
    (ROS 1 `tf` code) is left alone, since ROS 1 `tf` accepted leading slashes.
    """

    code = "GEO207"
    name = "invalid-tf-frame-id"
    triggers = AllOf(r"tf2_ros|rclpy", r"frame|lookup_transform|can_transform")

    VALID = [
        Valid("import tf2_ros\nt = buffer.lookup_transform('map', 'base_link', stamp)\n"),
        Valid("import tf\nt = listener.lookupTransform('/map', '/base_link', stamp)\n"),  # ROS 1 tf
        Valid("import tf2_ros\nmsg.header.frame_id = 'map'\nmsg.child_frame_id = 'odom'\n"),
        Valid(
            "import tf2_ros\ndef publish(sim):\n    t = TransformStamped()\n    if sim:\n        t.header.frame_id = 'world'\n"
            "        t.child_frame_id = 'camera'\n    else:\n        t.header.frame_id = 'base'\n"
            "        t.child_frame_id = 'camera'\n    static_broadcaster.sendTransform(t)\n"
        ),
        Valid("import tf2_ros\nlabel = '/map'\n"),  # not used as a frame id
    ]
    INVALID = [
        Invalid(
            "import tf2_ros\nt = buffer.lookup_transform('/map', 'base_link', stamp)\n",
            expected_fix="import tf2_ros\nt = buffer.lookup_transform('map', 'base_link', stamp)\n",
        ),
        Invalid("import rclpy\nmsg.header.frame_id = '/camera_link'\n"),
        Invalid("import tf2_ros\nh = Header(frame_id='/odom')\n"),
        Invalid("import tf2_ros\nt.header.frame_id = 'base_link'\nt.child_frame_id = 'base_link'\n"),
        Invalid(
            "from tf2_ros import StaticTransformBroadcaster\ndef publish(b):\n    a = TransformStamped()\n"
            "    a.header.frame_id = 'base_link'\n    a.child_frame_id = 'camera_link'\n"
            "    c = TransformStamped()\n    c.header.frame_id = 'world'\n    c.child_frame_id = 'camera_link'\n"
            "    b.sendTransform([a, c])\n"
        ),
    ]

    def check(self, tree: ast.Module) -> None:
        parents: dict[ast.AST, ast.AST] = {}
        for node in ast.walk(tree):
            for child in ast.iter_child_nodes(node):
                parents[child] = node
        static = "StaticTransformBroadcaster" in self.context.source or "static_transform" in self.context.source
        for node in ast.walk(tree):
            for literal in _frame_literals(node):
                if literal.value.startswith("/"):  # type: ignore[union-attr]
                    self.report(
                        literal,
                        f"tf2 frame ids never start with '/': {literal.value!r} is rejected by lookups "
                        "(InvalidArgumentException) and matches no frame others publish (REP 105)",
                        replacement=repr(literal.value.lstrip("/")),  # type: ignore[union-attr]
                        applicability="unsafe",
                        fix_description="drop the leading slash",
                    )
            if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef)):
                self._check_transforms_of(node, parents, static)

    def _check_transforms_of(self, scope: ast.AST, parents: dict[ast.AST, ast.AST], static: bool) -> None:
        """Self-transforms, and a child given two parents, among the literal frames set in one scope."""
        frames: dict[str, dict[str, ast.Assign]] = {}  # message text -> {"parent"/"child": assignment}
        for statement in _own_statements(scope):
            if not isinstance(statement, ast.Assign) or len(statement.targets) != 1:
                continue
            role_and_message = _frame_field(statement.targets[0])
            value = statement.value
            if role_and_message is None or not (isinstance(value, ast.Constant) and isinstance(value.value, str)):
                continue
            role, message = role_and_message
            frames.setdefault(message, {})[role] = statement
        parents_of_child: dict[str, list[tuple[str, ast.Assign]]] = {}
        for fields in frames.values():
            parent, child = fields.get("parent"), fields.get("child")
            if parent is None or child is None:
                continue
            parent_id, child_id = parent.value.value.lstrip("/"), child.value.value.lstrip("/")  # type: ignore[attr-defined]
            if parent_id == child_id:
                self.report(
                    child.value,
                    f"the transform's parent and child are both {child_id!r}: tf2 drops a transform from "
                    "a frame to itself (TF_SELF_TRANSFORM)",
                )
                continue
            parents_of_child.setdefault(child_id, []).append((parent_id, child))
        if not static:
            return
        for child_id, found in parents_of_child.items():
            first_parent, first = found[0]
            for parent_id, assignment in found[1:]:
                if parent_id != first_parent and not _exclusive(first, assignment, parents):
                    self.report(
                        assignment.value,
                        f"frame {child_id!r} is given a second parent: {first_parent!r} at line "
                        f"{first.lineno} and {parent_id!r} here; tf is a tree, and a frame with two "
                        "parents flips between them",
                    )


def _frame_literals(node: ast.AST) -> list[ast.Constant]:
    """String literals used as frame ids by this node (an assignment, a call)."""
    found: list[ast.expr] = []
    if isinstance(node, ast.Assign) and any(_frame_field(target) is not None for target in node.targets):
        found.append(node.value)
    elif isinstance(node, ast.Call):
        count = _FRAME_ARGUMENTS.get(call_name(node) or "")
        if count is not None and isinstance(node.func, ast.Attribute):
            found.extend(node.args[:count])
        found.extend(keyword.value for keyword in node.keywords if keyword.arg in _FRAME_KEYWORDS and _is_frame_call(node, keyword.arg))
    return [value for value in found if isinstance(value, ast.Constant) and isinstance(value.value, str)]


def _is_frame_call(call: ast.Call, keyword: str | None) -> bool:
    """`target=`/`source=` are frame ids only for tf2 calls; `frame_id=` everywhere."""
    return keyword in ("frame_id", "child_frame_id") or call_name(call) in _FRAME_ARGUMENTS


def _frame_field(target: ast.expr) -> tuple[str, str] | None:
    """("parent" or "child", the message's text) for `m.header.frame_id` / `m.child_frame_id`."""
    if not isinstance(target, ast.Attribute):
        return None
    if target.attr == "child_frame_id":
        return "child", ast.unparse(target.value)
    if target.attr == "frame_id" and isinstance(target.value, ast.Attribute) and target.value.attr == "header":
        return "parent", ast.unparse(target.value.value)
    return None


def _own_statements(scope: ast.AST) -> list[ast.stmt]:
    found: list[ast.stmt] = []
    stack = list(reversed(getattr(scope, "body", [])))
    while stack:
        statement = stack.pop()
        found.append(statement)
        if isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            continue
        for field in ("finalbody", "orelse", "handlers", "body"):
            stack.extend(reversed(getattr(statement, field, [])))
    return found


def _exclusive(first: ast.AST, second: ast.AST, parents: dict[ast.AST, ast.AST]) -> bool:
    """The two statements sit in different arms of one `if`/`try`/`match` (never both run)."""
    chain: dict[ast.AST, ast.AST] = {}
    node: ast.AST | None = first
    while node is not None:
        parent = parents.get(node)
        if parent is not None:
            chain[parent] = node
        node = parent
    node = second
    while node is not None:
        parent = parents.get(node)
        if parent in chain:
            return _arm_of(parent, chain[parent]) != _arm_of(parent, node)
        node = parent
    return False


def _arm_of(owner: ast.AST, child: ast.AST) -> str:
    for field in ("body", "orelse", "handlers", "finalbody", "cases"):
        if child in getattr(owner, field, []):
            return field if field != "handlers" and field != "cases" else f"{field}{id(child)}"
    return ""
