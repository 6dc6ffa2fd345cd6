"""GEO207 invalid-tf-frame-id: a frame id that tf2 rejects or that breaks the tf tree."""

from __future__ import annotations

from typing import Final

import ast
from ast import (
    AST, Add, Assign, AsyncFunctionDef, Attribute, BinOp, Call, ClassDef, Constant, FunctionDef, Import, ImportFrom,
    JoinedStr, Module, Name,
)
import re

from geolint.factbase import index_of, ros_packages
from geolint.factbase.index import ModuleIndex, statement_list_fields
from geolint.factbase.frame_ids import frame_string
from geolint.factbase.pose_parts import call_name
from geolint.knowledge import knowledge_base
from geolint.rules.base import AstRule, Invalid, Valid
from geolint.rules.triggers import AllOf

# tf2 Buffer calls and the positions of their frame-id arguments (each one goes through
# validateFrameId or warnFrameId; `transform(obj, target_frame)` looks up obj's stamp and the target).
_FULL: Final = (0, 2, 4)  # target, target_time, source, source_time, fixed
_FRAME_ARGUMENTS: Final = {
    "lookup_transform": (0, 1), "can_transform": (0, 1), "lookup_transform_async": (0, 1), "wait_for_transform_async": (0, 1),
    "lookup_transform_full": _FULL, "can_transform_full": _FULL, "wait_for_transform_full_async": _FULL,
    "transform": (1,), "transform_full": (1, 3),
}  # fmt: skip
_BUFFER_ONLY: Final = frozenset({"transform", "transform_full"})
_BUFFER_NAME: Final = re.compile(r"(?i)(?:buffer|tf)\w*$")
_FRAME_KEYWORDS: Final = frozenset({"frame_id", "child_frame_id", "target_frame", "source_frame", "target", "source"})
# calls that hand TransformStamped messages to tf2's setTransform
_SETS_TRANSFORMS: Final = frozenset({"sendTransform", "send_transform", "set_transform", "set_transform_static", "setTransform"})
_TF2_TEXT: Final = re.compile(r"tf2_ros|rclpy")
TF2: Final = "tf2"  # the module uses tf2_ros or ROS 2 itself
ROS1_TF2: Final = "ros1-tf2"  # a ROS 1 module (rospy, message types) whose ROS package targets tf2
_STRAY: Final = re.compile(r"[\"'\s]")  # a quote or whitespace: never part of a frame id


class InvalidTfFrameId(AstRule):
    """A frame id that tf2 rejects or that breaks the tf tree.

    ## What it does
    In tf2 code, flags a frame id that starts with a slash (`"/map"`) where tf2 looks it up:

    - the frame arguments of tf2_ros `Buffer` calls: `lookup_transform`, `can_transform`, their
      `_full` forms, and the target of `transform`;
    - the stamp of a message: `header.frame_id`, a `frame_id=` keyword, ROS 1's positional
      `Header(seq, stamp, frame_id)`, and (ROS 2) `child_frame_id`.

    The frame id may be a literal, a module constant, or built from them (`"/" + "map"`,
    `"%s/%s" % ("", "gps")`, an f-string of constants). tf2 code is a module that imports `tf2_ros`
    or `rclpy`, or a ROS 1 module (`rospy`, message imports) whose ROS package targets tf2: its
    `package.xml` depends on a tf2 package and not on `tf`, or one of its modules imports `tf2_ros`,
    `tf2_py`, `tf2_geometry_msgs`, `tf2_sensor_msgs` or `tf2_kdl`.

    In the same modules, and for every frame above including a `TransformStamped`'s, it flags a quote or whitespace in a frame id's literal text (the whole
    id, or a literal part of one built at run time: `prefix + '"vision'`, `f"{ns}/base link"`).

    It also flags a transform whose parent and child are the same frame
    (`t.header.frame_id = "base_link"`, `t.child_frame_id = "base_link"`), and, in a module that
    publishes static transforms, a child given two literal parents in one function (outside
    mutually exclusive `if`/`else` arms).

    ## Why is this bad?
    tf2 frame ids never start with a slash (REP 105; ROS 1 `tf`'s `tf_prefix` spelling is gone).
    tf2's lookups reject one: `lookupTransform` throws `InvalidArgumentException` and
    `canTransform` logs a warning and returns false (ros/geometry2 noetic-devel,
    `tf2/src/buffer_core.cpp` `validateFrameId` and `warnFrameId`, lines 121-166, called at 623-624,
    657-659 and 810-812; the same in ros2/geometry2). A message stamped `"/camera_link"` therefore cannot be
    transformed: tf2_ros `Buffer.transform` looks up `msg.header.frame_id`
    (`tf2_ros/src/tf2_ros/buffer_interface.py:65`) and Noetic's rviz looks up each display's stamp
    unchanged (`rviz/src/rviz/frame_manager.cpp:228`), so the data is not shown. A frame id is a name such as `base_link` (URDF link names, the
    frames of drivers and broadcasters): a quote or a space in one is a typo that makes it another
    frame, which nothing publishes, so every lookup of it fails and rviz shows nothing. A transform
    from a frame to itself is dropped with a `TF_SELF_TRANSFORM` error. tf is a tree: a frame with two
    parents makes the tree flip between them on every update.

    ## Example
    ```python
    transform = buffer.lookup_transform("/map", "base_link", rclpy.time.Time())
    ```

    ## Use instead
    ```python
    transform = buffer.lookup_transform("map", "base_link", rclpy.time.Time())
    ```

    ## Fix safety
    Dropping the leading slash of a literal is offered as an unsafe fix (a frame published
    elsewhere with the slash, by ROS 1 code, would need the same change). Built frame ids, stray
    quotes and whitespace (which character was meant is a guess) and the other two cases have no fix.

    ## Known problems
    Where tf2 itself strips the slash the rule is silent: the frames of a `TransformStamped` (built
    here, or handed to `sendTransform` / `set_transform`), since tf2's `setTransform` strips them
    (`buffer_core.cpp:214-216`; ros2/geometry2 rolling `buffer_core.cpp:208-209`), as does the C++ `tf2_ros::MessageFilter`
    for the messages it queues (`message_filter.h:306`, since 0.5.10) before the consumer's own
    lookup. A ROS 1 module that uses `tf` itself (a listener, a broadcaster; `tf.transformations`
    alone does not count), or whose package shows no tf2 evidence (a `package.xml` naming both `tf`
    and tf2 packages is half-way, and says nothing), is left alone: Noetic's `tf`
    strips a leading slash before asking tf2 (`tf/src/tf.cpp:195-243`, `tf/src/tf/listener.py:44-69`),
    and older `tf` accepted `tf_prefix` names; so a half-way package's marker stamped `"/camera"`
    goes unreported although Noetic's rviz rejects it. In ROS 1 code `child_frame_id` is not checked (read by
    `setTransform`, which strips it, or by odometry consumers). Frame ids read at run time
    (parameters, attributes such as `self.frame_id`) are not followed, nor frame ids built in a
    helper function (`"%s/%s" % (prefix, frame)` with a `tf_prefix` parameter). A quote or space
    is looked for only in literal text that reaches a frame-id position above, not in a template
    (`"%s %s" % ...`, `"{} {}".format(...)`) whose arguments are unknown.
    """

    code = "GEO207"
    name = "invalid-tf-frame-id"
    triggers = AllOf(r"tf2_ros|rclpy|rospy|_msgs", r"frame|lookup_transform|can_transform|Header|\.transform")

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
        # tf2's setTransform strips the slash of a TransformStamped's frames
        Valid("import tf2_ros\nt = TransformStamped()\nt.header.frame_id = '/world'\nt.child_frame_id = '/robot'\nb.sendTransform(t)\n"),
        Valid("import tf2_ros\nb.sendTransform(TransformStamped(header=Header(frame_id='/world'), child_frame_id='/robot'))\n"),
        # ROS 1 `tf` code (Noetic's tf strips the slash), and rospy code with no tf2 evidence
        Valid("import rospy\nimport tf\nlistener = tf.TransformListener()\npub.publish(PointStamped(Header(0, now, '/world'), p))\n"),
        Valid("import rospy\nfrom std_msgs.msg import Header\nheader = Header()\nheader.frame_id = '/camera_link'\n"),
        Valid("import tf2_ros\nmsg.header.frame_id = rospy.get_param('~frame_id', '/gps')\n"),  # read at run time
        Valid("import tf2_ros\ncloud = cloud.transform(T_world_cam)\nmesh.transform(T, '/tmp/mesh.ply')\n"),
        Valid("import rclpy\nmsg.header.frame_id = prefix + 'vision'\nlog.info('frame: ' + msg.header.frame_id)\n"),
        Valid("import rclpy\nmsg.header.frame_id = '%s %s' % (a, b)\n"),  # a template: its arguments are unknown
    ]
    INVALID = [
        Invalid(
            "import tf2_ros\nt = buffer.lookup_transform('/map', 'base_link', stamp)\n",
            expected_fix="import tf2_ros\nt = buffer.lookup_transform('map', 'base_link', stamp)\n",
            message="tf2 frame ids never start with '/': `lookup_transform` raises InvalidArgumentException for '/map' (can_transform returns False)",
            range=(2, 29, 2, 35),
        ),
        Invalid("import rclpy\nmsg.header.frame_id = '/camera_link'\n"),
        Invalid("import tf2_ros\nh = Header(frame_id='/odom')\n"),
        Invalid("import tf2_ros\npub.publish(PointStamped(Header(0, rospy.Time.now(), '/world'), point))\n"),  # ROS 1 Header
        Invalid("import tf2_ros\nPREFIX = ''\nfix.header.frame_id = '%s/%s' % (PREFIX, 'gps')\n"),
        Invalid("import tf2_ros\nmarker.header.frame_id = '/' + 'map'\n"),
        Invalid("import tf2_ros\np = buffer.transform(pose, '/map', rospy.Duration(0.1))\n"),
        Invalid("import tf2_ros\nt = buffer.lookup_transform_full('map', then, 'odom', now, '/world')\n"),
        Invalid("import tf2_ros\nt.header.frame_id = 'base_link'\nt.child_frame_id = 'base_link'\n"),
        # a stray quote or space in a frame id's literal text (a TransformStamped's too)
        Invalid("import rclpy\nodom.header.frame_id = node.frame_prefix + '\"vision'\n"),
        Invalid("import tf2_ros\nt = TransformStamped()\nt.child_frame_id = 'base_link '\nb.sendTransform(t)\n"),
        Invalid("import tf2_ros\nt = buffer.lookup_transform(f'{ns}/base link', 'map', stamp)\n"),
        Invalid(
            "from tf2_ros import StaticTransformBroadcaster\ndef publish(b):\n    a = TransformStamped()\n"
            "    a.header.frame_id = 'base_link'\n    a.child_frame_id = 'camera_link'\n"
            "    c = TransformStamped()\n    c.header.frame_id = 'world'\n    c.child_frame_id = 'camera_link'\n"
            "    b.sendTransform([a, c])\n"
        ),
    ]

    def check(self, tree: Module) -> None:
        dialect = self._dialect(tree)
        if dialect is None:
            return
        index = index_of(tree)
        parents = index.parents
        static = "StaticTransformBroadcaster" in self.context.source or "static_transform" in self.context.source
        transforms = _TransformMessages(tree, parents)
        for node in index.nodes(Assign, Call):
            for site, value, role, slash_checked in _frame_sites(node, dialect, transforms, parents):
                text = frame_string(value, index)
                if not (slash_checked and text is not None and text.startswith("/")):
                    self._check_characters(site, value, text, index)
                    continue
                literal = isinstance(value, Constant)
                shown = repr(text) if literal else f"{ast.unparse(value)} (= {text!r})"
                if role == "lookup":
                    problem = f"`{site}` raises InvalidArgumentException for {shown} (can_transform returns False)"
                else:
                    problem = (
                        f"{shown} in `{site}` is no tf2 frame: looking the stamp up (rviz, "
                        "`Buffer.transform`) raises InvalidArgumentException"
                    )
                self.report(
                    value,
                    f"tf2 frame ids never start with '/': {problem}",
                    replacement=repr(text.lstrip("/")) if literal else None,
                    applicability="unsafe",
                    fix_description="drop the leading slash" if literal else "",
                )
        for scope in (tree, *index.nodes(FunctionDef, AsyncFunctionDef)):
            self._check_transforms_of(scope, parents, static)

    def _check_characters(self, site: str, value: ast.expr, text: str | None, index: ModuleIndex) -> None:
        """A quote or whitespace in the literal text of a frame id (all of it, or a literal part)."""
        parts = [text] if text is not None else _literal_parts(value, index)
        for part in parts:
            stray = _STRAY.search(part)
            if stray is None:
                continue
            what = "whitespace" if stray.group().isspace() else "a quote"
            if text is None:
                shown = f"`{ast.unparse(value)}` (literal part {part!r})"
            else:
                shown = repr(text) if isinstance(value, Constant) else f"`{ast.unparse(value)}` (= {text!r})"
            self.report(
                value,
                f"frame id {shown} in `{site}` contains {what}: frame ids are names such as 'base_link', "
                "so this one names a frame nothing publishes and looking it up fails",
            )
            return

    def _dialect(self, tree: Module) -> str | None:
        """TF2 for a tf2 or ROS 2 module, ROS1_TF2 for a ROS 1 module whose package targets tf2, else None."""
        if _TF2_TEXT.search(self.context.source):
            return TF2
        index = index_of(tree)
        imported = _imported_modules(index)
        if not any(_is_ros_client(name) or name.split(".")[0].endswith("_msgs") for name in imported):
            return None
        if _uses_old_tf(index, imported):
            return None  # `tf` code: Noetic's tf strips the slash itself (tf.cpp strip_leading_slash)
        return ROS1_TF2 if ros_packages.package_targets_tf2(self.context.path) else None

    def _check_transforms_of(self, scope: AST, parents: dict[AST, AST], static: bool) -> None:
        """Self-transforms, and a child given two parents, among the literal frames set in one scope."""
        frames: dict[str, dict[str, Assign]] = {}  # message text -> {"parent"/"child": assignment}
        for statement in _own_statements(scope):
            if not isinstance(statement, Assign) or len(statement.targets) != 1:
                continue
            role_and_message = _frame_field(statement.targets[0])
            value = statement.value
            if role_and_message is None or not (isinstance(value, Constant) and isinstance(value.value, str)):
                continue
            role, message = role_and_message
            frames.setdefault(message, {})[role] = statement
        parents_of_child: dict[str, list[tuple[str, Assign]]] = {}
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


def _frame_sites(
    node: AST, dialect: str, transforms: _TransformMessages, parents: dict[AST, AST]
) -> list[tuple[str, ast.expr, str, bool]]:
    """(where, value, "lookup" or "stamp", whether a leading slash breaks it) for each frame id this node (an
    assignment, a call) sets or asks for."""
    found: list[tuple[str, ast.expr, str, bool]] = []
    if isinstance(node, Assign):
        for target in node.targets:
            field = _frame_field(target)
            if field is None:
                continue
            # a TransformStamped: tf2's setTransform strips the slash (buffer_core.cpp); ROS 1's child frame:
            # read by tf2's setTransform (stripped) or by odometry consumers
            stripped = transforms.holds(field[1], node) or field[0] == "child" and dialect == ROS1_TF2
            found.append((ast.unparse(target), node.value, "stamp", not stripped))
    elif isinstance(node, Call):
        name = call_name(node) or ""
        positions = _FRAME_ARGUMENTS.get(name, ())
        if name in _BUFFER_ONLY and not _BUFFER_NAME.search(ast.unparse(node.func.value) if isinstance(node.func, Attribute) else ""):
            positions = ()  # `transform` is a common name: only on a receiver named like a tf buffer
        if isinstance(node.func, Attribute):
            found.extend((name, node.args[position], "lookup", True) for position in positions if position < len(node.args))
        inside_transform = transforms.built_by(node, parents)
        if name == "Header" and len(node.args) >= 3:  # ROS 1 Header(seq, stamp, frame_id)
            found.append(("Header(seq, stamp, frame_id)", node.args[2], "stamp", not inside_transform))
        for keyword in node.keywords:
            if keyword.arg in _FRAME_KEYWORDS and _is_frame_call(node, keyword.arg):
                role = "lookup" if name in _FRAME_ARGUMENTS else "stamp"
                stripped = role == "stamp" and (inside_transform or name == "TransformStamped")
                stripped = stripped or keyword.arg == "child_frame_id" and dialect == ROS1_TF2
                found.append((name if role == "lookup" else f"{keyword.arg}=", keyword.value, role, not stripped))
    return found


def _literal_parts(value: ast.expr, index: ModuleIndex) -> list[str]:
    """The literal text of a frame id built at run time: the known operands of a `+` chain and the
    literal pieces of an f-string (`prefix + '"vision'`: '"vision')."""
    if isinstance(value, BinOp) and isinstance(value.op, Add):
        parts = []
        for operand in (value.left, value.right):
            text = frame_string(operand, index)
            parts.extend([text] if text is not None else _literal_parts(operand, index))
        return parts
    if isinstance(value, JoinedStr):
        return [piece.value for piece in value.values if isinstance(piece, Constant) and isinstance(piece.value, str)]
    return []


class _TransformMessages:
    """The messages that are transforms (`TransformStamped`): their frames go to tf2's setTransform,
    which strips a leading slash (geometry2 noetic-devel tf2/src/buffer_core.cpp:214-216; ROS 2
    rolling :208-209), so a slash there breaks nothing."""

    def __init__(self, tree: Module, parents: dict[AST, AST]) -> None:
        self._parents = parents
        self._by_scope: dict[AST, set[str]] = {}
        self._tree = tree

    def holds(self, message: str, node: AST) -> bool:
        if ".transforms[" in message or message.endswith(".transform"):
            return True
        scope = _enclosing(node, self._parents, (FunctionDef, AsyncFunctionDef))
        if message in self._of(scope or self._tree):
            return True
        if message.startswith("self."):  # stored on the object by another method
            owner = _enclosing(node, self._parents, (ClassDef,))
            return owner is not None and message in self._of(owner)
        return False

    def built_by(self, call: Call, parents: dict[AST, AST]) -> bool:
        """`call` is an argument (`header=Header(...)`) of a `TransformStamped(...)`."""
        parent = parents.get(call)
        if isinstance(parent, ast.keyword):
            parent = parents.get(parent)
        return isinstance(parent, Call) and call_name(parent) == "TransformStamped"

    def _of(self, scope: AST) -> set[str]:
        known = self._by_scope.get(scope)
        if known is None:
            known = self._by_scope[scope] = _transform_names(scope)
        return known


def _transform_names(scope: AST) -> set[str]:
    """Texts of the messages a scope builds as `TransformStamped()` or hands to a broadcaster."""
    names: set[str] = set()
    for node in ast.walk(scope):
        if isinstance(node, Assign) and isinstance(node.value, Call) and call_name(node.value) == "TransformStamped":
            names.update(ast.unparse(target) for target in node.targets)
        elif isinstance(node, Call) and call_name(node) in _SETS_TRANSFORMS:
            for argument in node.args[:1]:
                items = argument.elts if isinstance(argument, (ast.List, ast.Tuple)) else [argument]
                names.update(ast.unparse(item) for item in items)
    return names


def _enclosing(node: AST, parents: dict[AST, AST], kinds: tuple[type, ...]) -> AST | None:
    current = parents.get(node)
    while current is not None and not isinstance(current, kinds):
        current = parents.get(current)
    return current


def _is_ros_client(module: str) -> bool:
    library = knowledge_base().library_of_module(module)
    return library is not None and library.ros_client is not None


def _imported_modules(index: ModuleIndex) -> list[str]:
    found: list[str] = []
    for node in index.nodes(Import, ImportFrom):
        if isinstance(node, Import):
            found.extend(alias.name for alias in node.names)
        elif isinstance(node, ImportFrom) and node.module and not node.level:
            found.append(node.module)
    return found


def _uses_old_tf(index: ModuleIndex, imported: list[str]) -> bool:
    """The module uses a tf library that strips a leading slash itself (ROS 1 `tf`: a listener, a
    broadcaster, tf messages), by its METADATA.toml, and not only its frame-free helpers (`tf.transformations`,
    the quaternion and matrix functions tf2 code imports as well)."""
    kb = knowledge_base()

    def strips(name: str) -> bool:
        library = kb.library_of_module(name)
        return library is not None and library.strips_leading_slash

    def lenient(name: str) -> bool:
        return strips(name) and not kb.frameless_module(name)

    if not any(strips(name) for name in imported):
        return False
    packages: set[str] = set()  # `import tf`: read through its attributes
    for node in index.nodes(Import, ImportFrom):
        if isinstance(node, ImportFrom) and node.module and not node.level:
            if any(lenient(f"{node.module}.{alias.name}") for alias in node.names):
                return True
        elif isinstance(node, Import):
            if any("." in alias.name and lenient(alias.name) for alias in node.names):
                return True
            packages.update(alias.asname or alias.name for alias in node.names if "." not in alias.name and strips(alias.name))
    return any(
        isinstance(node, Attribute) and isinstance(node.value, Name) and node.value.id in packages
        and lenient(f"{index.imports.get(node.value.id, node.value.id)}.{node.attr}")
        for node in index.nodes(Attribute)
    )


def _is_frame_call(call: Call, keyword: str | None) -> bool:
    """`target=`/`source=` are frame ids only for tf2 calls; `frame_id=` everywhere."""
    return keyword in ("frame_id", "child_frame_id") or call_name(call) in _FRAME_ARGUMENTS


def _frame_field(target: ast.expr) -> tuple[str, str] | None:
    """("parent" or "child", the message's text) for `m.header.frame_id` / `m.child_frame_id`, and
    ("parent", "header") for a `header.frame_id` of its own (`header = Header()`)."""
    if not isinstance(target, Attribute):
        return None
    if target.attr == "child_frame_id":
        return "child", ast.unparse(target.value)
    if target.attr == "frame_id" and isinstance(target.value, Attribute) and target.value.attr == "header":
        return "parent", ast.unparse(target.value.value)
    if target.attr == "frame_id" and isinstance(target.value, Name) and target.value.id.lower().endswith("header"):
        return "parent", target.value.id
    return None


def _own_statements(scope: AST) -> list[ast.stmt]:
    found: list[ast.stmt] = []
    stack = list(reversed(getattr(scope, "body", [])))
    while stack:
        statement = stack.pop()
        found.append(statement)
        if isinstance(statement, (FunctionDef, AsyncFunctionDef, ClassDef)):
            continue
        fields = statement_list_fields(statement)
        for field in ("finalbody", "orelse", "handlers", "body"):
            if field in fields:
                stack.extend(reversed(getattr(statement, field)))
    return found


def _exclusive(first: AST, second: AST, parents: dict[AST, AST]) -> bool:
    """The two statements sit in different arms of one `if`/`try`/`match` (never both run)."""
    chain: dict[AST, AST] = {}
    node: AST | None = first
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


def _arm_of(owner: AST, child: AST) -> str:
    for field in ("body", "orelse", "handlers", "finalbody", "cases"):
        if child in getattr(owner, field, []):
            return field if field != "handlers" and field != "cases" else f"{field}{id(child)}"
    return ""
