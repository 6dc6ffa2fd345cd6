"""What one file of a ROS project states about its tf tree: the transforms it publishes (parent ->
child) and the frames it looks up (target <- source).

Read from the places real projects state them:

- Python nodes, ROS 1 and ROS 2: the calls the knowledge base marks with `TfFrame` roles (tf2's
  `Buffer.lookup_transform(target, source, t)`, `can_transform`, ROS 1 tf's `lookupTransform`,
  `TransformBroadcaster.sendTransform(t, q, time, child, parent)`, tf2's `sendTransform(msg)`,
  whose `TransformStamped` gives `header.frame_id` -> `child_frame_id`);
- Python launch files: a launch action the knowledge base marks with `LaunchNode` parts
  (`Node(package="tf2_ros", executable="static_transform_publisher", arguments=[...])`), whose command
  line its package's METADATA.toml describes;
- XML launch files (ROS 1 `.launch`, ROS 2 `.launch.xml`): `<node pkg= type=|exec= args=>`, with
  `$(arg name)` / `$(var name)` read from the file's `<arg>` defaults;
- URDF and xacro: each `<joint>`'s `<parent link>` -> `<child link>` (what robot_state_publisher
  publishes), with `${name}` read from the file's `<xacro:property>` values.

A frame is kept as text when the file fixes it (`frame_ids.frame_string`), else None: a publication
with an unknown frame still says the project publishes something this file cannot name.
"""

from __future__ import annotations

import ast
import re
import xml.parsers.expat
from ast import Attribute, Call, FunctionDef, List, Name, Return, Starred, Tuple
from dataclasses import dataclass, replace
from typing import Any, Final, Iterable, Iterator, TypeVar

from geolint.factbase.frame_ids import CHILD_PATH, PARENT_PATH, StampedFrames, frame_string
from geolint.factbase.library_calls import knowledge, tf_roles
from geolint.factbase.index import module_constant
from geolint.factbase.reaching import Unpacked, resolve, scope_of
from geolint.factbase.ros_parameters import parameter_key, yaml_keys
from geolint.knowledge import Executable, KnowledgeBase

URDF_SUFFIXES: Final = (".urdf", ".xacro")
XML_LAUNCH_SUFFIXES: Final = (".launch", ".launch.xml")
_SUBSTITUTION: Final = re.compile(r"\$\((?:arg|var)\s+([\w-]+)\)")
_PROPERTY: Final = re.compile(r"\$\{\s*([A-Za-z_]\w*)\s*\}")
_MAX_XML_BYTES: Final = 4_000_000


@dataclass(frozen=True, order=True)
class Place:
    """Where a statement is: a file, and the 1-based line and 0-based columns of its text."""

    path: str
    line: int
    column: int = 0
    end_line: int = 0
    end_column: int = 0



@dataclass(frozen=True)
class Published:
    """A transform the project publishes: `parent` -> `child` (None: a frame the file does not fix)."""

    parent: str | None
    child: str | None
    how: str  # "sendTransform", "static_transform_publisher", "URDF joint"...
    place: Place
    parameters: tuple[tuple[str, str], ...] = ()  # (role, parameter) for a frame that is a parameter's declared default
    identity: bool = False  # a command line that publishes the identity transform (either way round the same)


@dataclass(frozen=True)
class LookedUp:
    """A transform the project asks tf for: from `source` into `target`."""

    target: str | None
    source: str | None
    how: str
    place: Place
    parameters: tuple[tuple[str, str], ...] = ()  # (role, parameter) for a frame that is a parameter's declared default


@dataclass(frozen=True)
class FileFrames:
    published: tuple[Published, ...] = ()
    looked_up: tuple[LookedUp, ...] = ()
    parameters_set: frozenset[str] = frozenset()  # the ROS parameters a launch or parameter file sets (`parameter_key`)

    def __bool__(self) -> bool:
        return bool(self.published or self.looked_up or self.parameters_set)


_Statement = TypeVar("_Statement", Published, LookedUp, "Published | LookedUp")


def settled(statement: _Statement, overridden: frozenset[str]) -> _Statement:
    """The statement with each frame that is the default of a parameter the project sets made unknown:
    the default is not what runs."""
    changes: dict[str, Any] = {role: None for role, parameter in statement.parameters if parameter_key(parameter) in overridden}
    return replace(statement, **changes) if changes else statement


def frame_name(text: str | None) -> str | None:
    """A frame id as tf2 compares it: ROS 1 tf's leading slash dropped (GEO207 reports the slash)."""
    if text is None:
        return None
    name = text.strip().lstrip("/")
    return name or None


# -- Python ---------------------------------------------------------------------------------------
@dataclass(frozen=True)
class PythonStatement:
    """A statement of the linted module, with the call that makes it (for a finding's range)."""

    statement: Published | LookedUp
    call: Call


def python_statements(facts, path: str) -> list[PythonStatement]:  # type: ignore[no-untyped-def]
    """The tf statements of one module, in source order."""
    index = facts.index
    kb = knowledge(facts)
    values = FrameValues(facts)
    stamps: StampedFrames | None = None
    found: list[PythonStatement] = []
    for node in index.nodes(Call):
        assert isinstance(node, Call)
        answer = tf_roles(facts, node)
        if answer is None:
            continue
        api, roles = answer
        place = _place_of(node, path)
        how = node.func.attr if isinstance(node.func, Attribute) else api.qualified_name.rpartition(".")[2]
        if "target" in roles or "source" in roles:
            (target, source), parameters = values.frames(roles, ("target", "source"))
            found.append(PythonStatement(LookedUp(target, source, how, place, parameters), node))
        elif "parent" in roles or "child" in roles:
            (parent, child), parameters = values.frames(roles, ("parent", "child"))
            found.append(PythonStatement(Published(parent, child, how, place, parameters), node))
        elif "published" in roles:
            if stamps is None:
                stamps = StampedFrames(index)
            for stamped, parameters in _published_messages(roles["published"], node, values, stamps):
                found.append(PythonStatement(Published(stamped.get("parent"), stamped.get("child"), how, place, parameters), node))
        elif "command" in roles:  # `ExecuteProcess(cmd=["ros2", "run", "tf2_ros", "static_transform_publisher", ...])`
            command = _command_line(roles["command"], index)
            run = _ros_run(command) if command is not None else None
            executable = kb.executable(run[0], run[1]) if run is not None else None
            if executable is not None and run is not None:
                parent, child = command_line_frames(executable, run[2])
                identity = publishes_identity(executable, run[2])
                found.append(PythonStatement(Published(parent, child, executable.name, place, identity=identity), node))
        elif "executable" in roles:
            executable = _launched(kb, roles, index)
            if executable is not None:
                arguments = _command_line(roles.get("arguments"), index)
                parent, child = (None, None) if arguments is None else command_line_frames(executable, arguments)
                identity = arguments is not None and publishes_identity(executable, arguments)
                found.append(PythonStatement(Published(parent, child, executable.name, place, identity=identity), node))
    return found


def _frame(node: ast.expr | None, index) -> str | None:  # type: ignore[no-untyped-def]
    return None if node is None else frame_name(frame_string(node, index))


_PARAMETER_VALUE: Final = frozenset({"value", "string_value"})  # rclpy's Parameter.value, ParameterValue.string_value
_VALUE_DEPTH: Final = 5


class FrameValues:
    """The frame id an expression of a module holds: an exact string (`frame_ids.frame_string`), or the
    default the module declares for the ROS parameter it reads (`declare_parameter("odom_frame",
    "odom")` then `get_parameter("odom_frame").value`, `rospy.get_param("~frame_id", "base_link")`),
    through local names and `self` attributes whose every store agrees. A default comes with the
    parameter's name: a launch or parameter file of the project may set it (`settled`)."""

    def __init__(self, facts) -> None:  # type: ignore[no-untyped-def]
        self.facts = facts
        self.index = facts.index
        self._declared: dict[str, set[str | None]] | None = None

    def frames(self, roles: dict[str, ast.expr], wanted: tuple[str, ...]) -> tuple[tuple[str | None, ...], tuple[tuple[str, str], ...]]:
        """The frame of each wanted role (None where unknown), and (role, parameter) for those that are defaults."""
        frames: list[str | None] = []
        parameters: list[tuple[str, str]] = []
        for role in wanted:
            node = roles.get(role)
            frame, parameter = self.frame(node) if node is not None else (None, None)
            frames.append(frame)
            if parameter is not None and frame is not None:
                parameters.append((role, parameter))
        return tuple(frames), tuple(parameters)

    def frame(self, node: ast.expr, depth: int = _VALUE_DEPTH) -> tuple[str | None, str | None]:
        """(frame, the parameter whose default it is, or None)."""
        text = frame_string(node, self.index)
        if text is not None:
            return frame_name(text), None
        if depth <= 0:
            return None, None
        if isinstance(node, Name):
            value: ast.expr | Unpacked | None = resolve(self.index, node)
            if isinstance(value, Name):  # a global the reading scope does not rebind
                value = None if value.id in scope_of(self.index, value).bindings else module_constant(self.index, value.id)
            return self.frame(value, depth - 1) if isinstance(value, ast.expr) and not isinstance(value, Name) else (None, None)
        if isinstance(node, Attribute) and isinstance(node.value, Name) and node.value.id == "self":
            stores = self.index.self_attribute_stores.get(node.attr, [])
            found = {self.frame(value, depth - 1) if isinstance(value, ast.expr) else (None, None) for value in stores}
            return found.pop() if len(found) == 1 else (None, None)
        return self._parameter_default(node, depth)

    def _parameter_default(self, node: ast.expr, depth: int) -> tuple[str | None, str | None]:
        """The default of a parameter read: `<read>.value`, `<read>.get_parameter_value().string_value`,
        or a read that returns the value itself (ROS 1's `get_param`)."""
        read = node
        if isinstance(read, Attribute) and read.attr in _PARAMETER_VALUE:
            read = read.value
            if isinstance(read, Call) and isinstance(read.func, Attribute) and read.func.attr == "get_parameter_value":
                read = read.func.value
            if isinstance(read, Name):
                value = resolve(self.index, read)
                read = value if isinstance(value, ast.expr) else read
        elif not isinstance(read, Call):
            return None, None
        if not isinstance(read, Call):
            return None, None
        answer = tf_roles(self.facts, read)
        if answer is None or "name" not in answer[1]:
            return None, None
        _, roles = answer
        name = frame_string(roles["name"], self.index)
        if name is None:
            return None, None
        if "default" in roles:
            default = frame_string(roles["default"], self.index)
        else:
            defaults = self._declarations().get(parameter_key(name), set())
            default = defaults.pop() if len(defaults) == 1 else None
        return (frame_name(default), name) if default is not None else (None, None)

    def _declarations(self) -> dict[str, set[str | None]]:
        """parameter key -> the defaults the module declares for it (several: unknown)."""
        if self._declared is None:
            self._declared = {}
            for node in self.index.nodes(Call):
                answer = tf_roles(self.facts, node)
                if answer is None:
                    continue
                roles = answer[1]
                for name, default in _declared_pairs(roles, self.index):
                    self._declared.setdefault(parameter_key(name), set()).add(default)
        return {key: set(values) for key, values in self._declared.items()}


def _declared_pairs(roles: dict[str, ast.expr], index) -> Iterator[tuple[str, str | None]]:  # type: ignore[no-untyped-def]
    """(name, default text or None) of each parameter a call declares with a default."""
    if "name" in roles and "default" in roles:
        name = frame_string(roles["name"], index)
        if name is not None:
            yield name, frame_string(roles["default"], index)
    declarations = roles.get("declarations")
    if isinstance(declarations, (List, Tuple)):
        namespace = frame_string(roles["namespace"], index) if "namespace" in roles else ""
        for declaration in declarations.elts:
            if isinstance(declaration, (List, Tuple)) and len(declaration.elts) >= 2:
                name = frame_string(declaration.elts[0], index)
                if name is not None and namespace is not None:
                    yield f"{namespace}.{name}" if namespace else name, frame_string(declaration.elts[1], index)


def _published_messages(argument: ast.expr, call: Call, values: FrameValues, stamps: StampedFrames) -> Iterator[tuple[dict[str, str | None], tuple[tuple[str, str], ...]]]:
    """({"parent": ..., "child": ...}, parameters) of each `TransformStamped` a `sendTransform` call
    publishes: a name stamped before the call, a list of them, or a message built with keywords."""
    for message in argument.elts if isinstance(argument, (List, Tuple)) else [argument]:
        roles: dict[str, ast.expr] = {}
        if isinstance(message, Name):
            for role, path in (("parent", PARENT_PATH), ("child", CHILD_PATH)):
                stamped = stamps.frame_before(message, call, path)
                if stamped is not None:
                    roles[role] = stamped
        elif isinstance(message, Attribute) and isinstance(message.value, Name) and message.value.id == "self":
            for role, path in (("parent", PARENT_PATH), ("child", CHILD_PATH)):
                stamped = stamps.frame_of_attribute(message.attr, path)
                if stamped is not None:
                    roles[role] = stamped
        elif isinstance(message, Call):  # `TransformStamped(header=Header(frame_id="map"), child_frame_id="odom")`
            keywords = {keyword.arg: keyword.value for keyword in message.keywords if keyword.arg}
            header = keywords.get("header")
            header_keywords = {keyword.arg: keyword.value for keyword in header.keywords if keyword.arg} if isinstance(header, Call) else {}
            roles = {role: value for role, value in (("parent", header_keywords.get("frame_id")), ("child", keywords.get("child_frame_id"))) if value is not None}
        (parent, child), parameters = values.frames(roles, ("parent", "child"))
        yield {"parent": parent, "child": child}, parameters


def _launched(kb: KnowledgeBase, roles: dict[str, ast.expr], index) -> Executable | None:  # type: ignore[no-untyped-def]
    package = roles.get("package")
    name = roles.get("executable")
    package_text = frame_string(package, index) if package is not None else None
    name_text = frame_string(name, index) if name is not None else None
    if package_text is None or name_text is None:
        return None
    return kb.executable(package_text, name_text)


def _command_line(node: ast.expr | None, index) -> list[str | None] | None:  # type: ignore[no-untyped-def]
    """A launch action's `arguments`: a list of strings (None for an element known at run time only),
    or `"0 0 0 0 0 0 map odom".split()`; None when the list itself is not fixed here."""
    if isinstance(node, (List, Tuple)):
        if any(isinstance(element, Starred) for element in node.elts):
            return None
        return [frame_string(element, index) for element in node.elts]
    if isinstance(node, Call) and isinstance(node.func, Attribute) and node.func.attr == "split" and not node.args and not node.keywords:
        text = frame_string(node.func.value, index)
        return None if text is None else list(text.split())
    return None


def _ros_run(words: list[str | None]) -> tuple[str, str, list[str | None]] | None:
    """(package, executable, its arguments) of `ros2 run PACKAGE EXECUTABLE ...`, `rosrun PACKAGE
    EXECUTABLE ...` or an installed executable's path (`/opt/ros/humble/lib/PACKAGE/EXECUTABLE ...`);
    None for another command."""
    parts = (words[0] or "").split("/") if words else []
    if len(parts) >= 3 and parts[-3] == "lib":
        return parts[-2], parts[-1], words[1:]
    for start in range(len(words)):
        if words[start] == "rosrun":
            rest = words[start + 1 :]
        elif words[start] == "ros2" and start + 1 < len(words) and words[start + 1] == "run":
            rest = words[start + 2 :]
        else:
            continue
        options = 0
        while options < len(rest) and (rest[options] or "").startswith("-"):
            options += 1  # `ros2 run --prefix ...` style options before the package
        package, executable = (rest[options : options + 2] + [None, None])[:2]
        if package is None or executable is None:
            return None
        return package, executable, rest[options + 2 :]
    return None


def command_line_frames(executable: Executable, arguments: Iterable[str | None]) -> tuple[str | None, str | None]:
    """(parent, child) from a static transform publisher's command line, as its METADATA.toml describes it:
    the `--frame-id`-style options when given, else the positions for that many arguments."""
    words = list(arguments)
    if "--ros-args" in words:
        words = words[: words.index("--ros-args")]
    roles: dict[str, str | None] = {}
    for position, word in enumerate(words):
        role = executable.options.get(word) if word is not None else None
        if role is not None:
            roles[role] = words[position + 1] if position + 1 < len(words) else None
    if roles:
        parent, child = roles.get("parent"), roles.get("child")
    else:
        places = executable.positional.get(len(words))
        if places is None:
            return None, None
        parent, child = words[places[0]], words[places[1]]
    if _number(parent) is not None or _number(child) is not None:
        return None, None  # a number where a frame goes: another program's command line (ROS 1 tf's period)
    return frame_name(parent), frame_name(child)


def publishes_identity(executable: Executable, arguments: Iterable[str | None]) -> bool:
    """Whether a static transform publisher's command line gives the identity transform: every number
    of the transform 0 (the words before the frames, or the values of its options), but a quaternion's
    w, which is 1."""
    words = list(arguments)
    if "--ros-args" in words:
        words = words[: words.index("--ros-args")]
    if any(word in executable.options for word in words if word is not None):
        values = {word: words[position + 1] if position + 1 < len(words) else None for position, word in enumerate(words) if word is not None and word.startswith("--")}
        numbers = [(value, name == "--qw") for name, value in values.items() if name not in executable.options]
    else:
        places = executable.positional.get(len(words))
        if places is None:
            return False
        transform = words[: min(places)]
        numbers = [(value, len(transform) == 7 and position == 6) for position, value in enumerate(transform)]
    return all(_number(value) == (1.0 if is_w else 0.0) for value, is_w in numbers)


def _number(word: str | None) -> float | None:
    try:
        return float(word) if word is not None else None
    except ValueError:
        return None


def _place_of(node: ast.AST, path: str) -> Place:
    return Place(
        path,
        getattr(node, "lineno", 0),
        getattr(node, "col_offset", 0),
        getattr(node, "end_lineno", 0) or 0,
        getattr(node, "end_col_offset", 0) or 0,
    )


# -- XML: launch files and URDF -------------------------------------------------------------------
@dataclass(frozen=True)
class _Element:
    tag: str
    attributes: dict[str, str]
    line: int
    column: int
    parent: int  # the index of the enclosing element, -1 at the root


def _elements(text: str, keep_text: frozenset[str] = frozenset()) -> tuple[list[_Element], dict[int, str]] | None:
    """Every element of an XML text, in document order, with its line (expat, a real parser), and the
    text inside the elements whose tag is in `keep_text`; None when the text is not well-formed XML."""
    parser = xml.parsers.expat.ParserCreate()
    elements: list[_Element] = []
    texts: dict[int, list[str]] = {}
    open_elements: list[int] = []

    def start(tag: str, attributes: dict[str, str]) -> None:
        elements.append(_Element(tag, attributes, parser.CurrentLineNumber, parser.CurrentColumnNumber, open_elements[-1] if open_elements else -1))
        open_elements.append(len(elements) - 1)

    def end(tag: str) -> None:
        open_elements.pop()

    def characters(data: str) -> None:
        if open_elements and elements[open_elements[-1]].tag in keep_text:
            texts.setdefault(open_elements[-1], []).append(data)

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    if keep_text:
        parser.CharacterDataHandler = characters
    try:
        parser.Parse(text, True)
    except xml.parsers.expat.ExpatError:
        return None
    return elements, {position: "".join(parts) for position, parts in texts.items()}


def xml_frames(kb: KnowledgeBase, path: str, text: str) -> FileFrames:
    """The publications of an XML launch file or a URDF/xacro file ([] for anything else, or XML that does
    not parse)."""
    if len(text) > _MAX_XML_BYTES:
        return FileFrames()
    parsed = _elements(text, keep_text=frozenset({"rosparam"}))
    if parsed is None:
        return FileFrames()
    elements, texts = parsed
    if path.endswith(URDF_SUFFIXES) or any(element.tag == "robot" for element in elements[:1]):
        return FileFrames(tuple(_joints(elements, path)))
    return FileFrames(tuple(_launched_publishers(kb, elements, path)), parameters_set=_launch_parameters(elements, texts))


def _launch_parameters(elements: list[_Element], texts: dict[int, str]) -> frozenset[str]:
    """The parameters an XML launch file sets: `<param name=...>`, `<rosparam param=...>` and the keys
    of a `<rosparam>`'s YAML text."""
    found: set[str] = set()
    for position, element in enumerate(elements):
        if element.tag == "param" and "name" in element.attributes:
            found.add(parameter_key(element.attributes["name"]))
        elif element.tag == "rosparam":
            if "param" in element.attributes:
                found.add(parameter_key(element.attributes["param"]))
            if "$(" not in texts.get(position, "$("):
                found.update(yaml_keys(texts[position]))
    return frozenset(found)


def _joints(elements: list[_Element], path: str) -> Iterator[Published]:
    properties = {
        element.attributes["name"]: element.attributes["value"]
        for element in elements
        if element.tag.endswith("property") and "name" in element.attributes and "value" in element.attributes
    }
    for position, element in enumerate(elements):
        if element.tag != "joint":
            continue
        links = {child.tag: child.attributes.get("link") for child in elements[position + 1 :] if child.parent == position and child.tag in ("parent", "child")}
        parent, child = (_substituted(links.get(role), properties, _PROPERTY) for role in ("parent", "child"))
        if "parent" in links and "child" in links:
            kind = element.attributes.get("type", "")
            yield Published(frame_name(parent), frame_name(child), f"URDF {kind} joint".replace("  ", " "), Place(path, element.line, element.column))


def _launched_publishers(kb: KnowledgeBase, elements: list[_Element], path: str) -> Iterator[Published]:
    arguments = {
        element.attributes["name"]: element.attributes.get("value", element.attributes.get("default"))
        for element in elements
        if element.tag == "arg" and "name" in element.attributes
    }
    for element in elements:
        if element.tag != "node":
            continue
        package = element.attributes.get("pkg")
        name = element.attributes.get("type", element.attributes.get("exec"))
        executable = kb.executable(package, name) if package and name else None
        if executable is None:
            continue
        command = element.attributes.get("args")
        words = _words(command, arguments) if command is not None else None
        parent, child = command_line_frames(executable, words) if words is not None else (None, None)
        identity = words is not None and publishes_identity(executable, words)
        yield Published(parent, child, executable.name, Place(path, element.line, element.column), identity=identity)


_UNKNOWN: Final = "\0"


def _words(command: str, values: dict[str, str | None]) -> list[str | None]:
    """A launch file's `args` split into words, a word with a substitution the file does not fix None."""

    def value(match: re.Match[str]) -> str:
        found = values.get(match.group(1))
        return _UNKNOWN if found is None or "$" in found else found

    return [None if _UNKNOWN in word or "$(" in word else word for word in _SUBSTITUTION.sub(value, command).split()]


def _substituted(text: str | None, values: dict[str, str], pattern: re.Pattern[str]) -> str | None:
    """`text` with each `${name}` replaced by the file's value; None when one is unknown."""
    if text is None:
        return None
    unknown = False

    def value(match: re.Match[str]) -> str:
        nonlocal unknown
        found = values.get(match.group(1))
        if found is None or "$" in found:  # a macro's parameter, an expression: known only when expanded
            unknown = True
            return ""
        return found

    result = pattern.sub(value, text)
    return None if unknown or "$(" in result or "${" in result else result


# -- the frames a looked-up transform maps between, followed through names ------------------------
_LOOKUP_DEPTH: Final = 4


def lookup_frames(facts, node: ast.expr, depth: int = _LOOKUP_DEPTH) -> LookedUp | None:  # type: ignore[no-untyped-def]
    """The lookup a transform comes from, when every way it can be bound says the same: a name bound to
    `buffer.lookup_transform(target, source, t)`, an attribute `self.t` that the class sets only to
    lookups of the same frames, or a call of a function of the module whose every return is one."""
    if depth <= 0:
        return None
    index = facts.index
    if isinstance(node, Name):
        value = resolve(index, node)
        return lookup_frames(facts, value, depth - 1) if isinstance(value, ast.expr) and value is not node else None
    if isinstance(node, Attribute) and isinstance(node.value, Name) and node.value.id == "self":
        stores = index.self_attribute_stores.get(node.attr, [])
        return _agreed_lookup([lookup_frames(facts, value, depth - 1) if isinstance(value, ast.expr) else None for value in stores])
    if not isinstance(node, Call):
        return None
    answer = tf_roles(facts, node)
    if answer is not None:
        api, roles = answer
        if "target" in roles and "source" in roles:
            how = node.func.attr if isinstance(node.func, Attribute) else api.qualified_name.rpartition(".")[2]
            return LookedUp(_frame(roles["target"], index), _frame(roles["source"], index), how, _place_of(node, facts.path))
        return None
    function = _called_function(index, node)
    if function is None:
        return None
    returns = [statement.value for statement in ast.walk(function) if isinstance(statement, Return) and statement.value is not None]
    return _agreed_lookup([lookup_frames(facts, value, depth - 1) for value in returns])


def _agreed_lookup(found: list[LookedUp | None]) -> LookedUp | None:
    if not found or any(lookup is None for lookup in found):
        return None
    frames = {(lookup.target, lookup.source) for lookup in found if lookup is not None}
    return found[0] if len(frames) == 1 else None


def _called_function(index, call: Call) -> FunctionDef | None:  # type: ignore[no-untyped-def]
    """The one function of the module a call names: `helper(...)` or `self.helper(...)`."""
    func = call.func
    if isinstance(func, Name):
        name = func.id
    elif isinstance(func, Attribute) and isinstance(func.value, Name) and func.value.id == "self":
        name = func.attr
    else:
        return None
    found = [node for node in index.nodes(FunctionDef) if isinstance(node, FunctionDef) and node.name == name]
    return found[0] if len(found) == 1 else None
