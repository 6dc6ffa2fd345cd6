"""Read the knowledge base's stubs into `Api` values: the stubs are data, parsed with `ast`, never imported.

A library is a folder `stubs/<library>/` with a `METADATA.toml` (the distribution, the import names it
provides, the version its facts were checked against, where its source is) and typeshed-style `.pyi`
files laid out like the package (`stubs/scipy/scipy/spatial/transform/_rotation.pyi` is the module
`scipy.spatial.transform._rotation`). Annotations use geolint's typing vocabulary (`geolint.typing`) and
the markers of `geolint.knowledge.markers`; anything else says nothing (the value is not geometry, as
far as the stub knows).
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path

from geolint.algebra import Kind
from geolint.knowledge.model import (
    DEGREES,
    MONOGRAM,
    RADIANS,
    SCALAR_FIRST,
    SCALAR_LAST,
    Api,
    Executable,
    Geometry,
    Library,
    Parameter,
    Receiver,
    Signature,
)

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

# geolint.typing's names -> what an annotation with that name states
_PLAIN: dict[str, Geometry] = {
    "QuaternionXYZW": Geometry(kind=Kind.ROTATION, quaternion_order=SCALAR_LAST),
    "QuaternionWXYZ": Geometry(kind=Kind.ROTATION, quaternion_order=SCALAR_FIRST),
    "RotationVector": Geometry(kind=Kind.ROTATION, angle_unit=RADIANS),
    "Radians": Geometry(angle_unit=RADIANS),
    "Degrees": Geometry(angle_unit=DEGREES),
}
_FRAMED: dict[str, Kind] = {
    "PointArray": Kind.POINT,
    "VectorArray": Kind.VECTOR,
    "DirectionArray": Kind.DIRECTION,
    "RotationMatrix": Kind.ROTATION,
    "TransformMatrix": Kind.TRANSFORM,
    "Translation": Kind.TRANSLATION,
    "HomogeneousPoints": Kind.HOMOGENEOUS_POINT,
    "HomogeneousVectors": Kind.HOMOGENEOUS_VECTOR,
}
_OPTIONAL_WRAPPERS = frozenset({"Optional"})
_KEPT_DECORATORS = frozenset({"overload", "classmethod", "staticmethod", "property", "versions"})


class StubError(ValueError):
    """A stub the reader cannot read: names the file and line."""


def read_library(folder: Path) -> Library:
    """One `stubs/<library>/` folder."""
    metadata_path = folder / "METADATA.toml"
    try:
        metadata = tomllib.loads(metadata_path.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError) as error:
        raise StubError(f"{metadata_path}: {error}") from error
    library = Library(
        name=str(metadata.get("distribution", folder.name)),
        packages=tuple(metadata.get("packages", ())),
        checked=str(metadata.get("checked", "")),
        upstream=str(metadata.get("upstream", "")),
        conventional_names={str(name): str(target) for name, target in metadata.get("conventional_names", {}).items()},
        conventional_modules={str(name): str(target) for name, target in metadata.get("conventional_modules", {}).items()},
        extends={str(name): str(target) for name, target in metadata.get("extends", {}).items()},
        executables=_executables(metadata_path, metadata.get("executables", {})),
        recognised_with=tuple(str(name) for name in metadata.get("recognised_with", ())),
        ros_client=int(metadata["ros_client"]) if "ros_client" in metadata else None,
        frame_naming=_frame_naming(metadata_path, metadata.get("frame_naming")),
        strips_leading_slash=bool(metadata.get("strips_leading_slash", False)),
        array_library=bool(metadata.get("array_library", False)),
    )
    for stub in sorted(folder.rglob("*.pyi")):
        relative = stub.relative_to(folder).with_suffix("")
        parts = list(relative.parts)
        if parts[-1] == "__init__":
            parts.pop()
        _ModuleReader(library, ".".join(parts), stub, stub.relative_to(folder.parent).as_posix()).read()
    return library


def _frame_naming(path: Path, value: object) -> str | None:
    if value is not None and value != MONOGRAM:
        raise StubError(f"{path}: frame_naming = {value!r}: the one style known is {MONOGRAM!r}")
    return None if value is None else MONOGRAM


def _executables(path: Path, table: dict[str, dict[str, object]]) -> dict[str, Executable]:
    """METADATA.toml's `[executables.<name>]` tables: `package`, `static`, `positional = {"8" = [6, 7]}`
    (argument count -> positions of the parent and child frames), `options = {"--frame-id" = "parent"}`,
    `source`."""
    found = {}
    for name, entry in table.items():
        try:
            positional = {int(count): (int(places[0]), int(places[1])) for count, places in dict(entry.get("positional", {})).items()}  # type: ignore[call-overload]
            options = {str(flag): str(role) for flag, role in dict(entry.get("options", {})).items()}  # type: ignore[call-overload]
            found[name] = Executable(name, str(entry["package"]), bool(entry.get("static", False)), positional, options, str(entry.get("source", "")))
        except (KeyError, TypeError, ValueError, IndexError) as error:
            raise StubError(f"{path}: [executables.{name}]: {error!r}") from error
    return found


class _ModuleReader:
    """One `.pyi` file: its classes, functions, overloads and re-exports."""

    def __init__(self, library: Library, module: str, path: Path, label: str) -> None:
        self.library, self.module, self.path, self.label = library, module, path, label
        self.local: dict[str, str] = {}  # names bound in the stub -> qualified names
        self.type_aliases: dict[str, ast.expr] = {}  # `_Q = Annotated[QuaternionXYZW, STACKED]` -> its annotation

    def read(self) -> None:
        try:
            tree = ast.parse(self.path.read_text(encoding="utf-8"), str(self.path))
        except (OSError, SyntaxError) as error:
            raise StubError(f"{self.label}: {error}") from error
        self._bind_names(tree.body, self.module)
        self._read_body(tree.body, self.module, in_class=False, receiver=None, class_source="")

    def _bind_names(self, body: list[ast.stmt], prefix: str) -> None:
        for statement in body:
            if isinstance(statement, ast.ImportFrom):
                module = _absolute(statement, self.module, self.path.name == "__init__.pyi")
                for name in statement.names:
                    if name.name == "*":
                        continue
                    self.local[name.asname or name.name] = f"{module}.{name.name}"
                    target = f"{module}.{name.name}"
                    if name.asname == name.name and not module.startswith("geolint") and target != f"{prefix}.{name.name}":
                        # `from x import Y as Y`: a re-export
                        self.library.aliases[f"{prefix}.{name.name}"] = f"{module}.{name.name}"
            elif isinstance(statement, ast.Import):
                for name in statement.names:
                    self.local[name.asname or name.name.partition(".")[0]] = name.name if name.asname else name.name.partition(".")[0]
            elif isinstance(statement, (ast.ClassDef, ast.FunctionDef)):
                self.local[statement.name] = f"{prefix}.{statement.name}"
            elif isinstance(statement, ast.Assign) and len(statement.targets) == 1 and isinstance(statement.targets[0], ast.Name) and isinstance(statement.value, ast.Subscript):
                self.type_aliases[statement.targets[0].id] = statement.value  # a type alias, used as an annotation
            elif isinstance(statement, ast.Assign) and len(statement.targets) == 1 and isinstance(statement.targets[0], ast.Name):
                aliased = _dotted(statement.value)
                if aliased is not None:  # `quat2mat = quaternion_matrix`: the same API under a second name
                    head, _, rest = aliased.partition(".")
                    resolved = self.local.get(head, f"{prefix}.{head}")
                    self.library.aliases[f"{prefix}.{statement.targets[0].id}"] = f"{resolved}.{rest}" if rest else resolved

    def _read_body(self, body: list[ast.stmt], prefix: str, in_class: bool, receiver: Receiver | None, class_source: str) -> None:
        overloads: dict[str, list[Signature]] = {}
        sources: dict[str, str] = {}
        attributes: set[str] = set()
        for position, statement in enumerate(body):
            if isinstance(statement, ast.ClassDef):
                self._read_class(statement, prefix)
            elif isinstance(statement, ast.FunctionDef):
                overloads.setdefault(statement.name, []).append(self._signature(statement, in_class))
                source = _source_of(statement)
                if source:
                    sources[statement.name] = source
                if in_class and any(_last(decorator) == "property" for decorator in statement.decorator_list):
                    attributes.add(statement.name)
            elif isinstance(statement, ast.AnnAssign) and isinstance(statement.target, ast.Name):
                # `xquat: Annotated[QuaternionWXYZ, STACKED]`: an attribute, read like a property (a module's
                # constant too: `pi: Radians`)
                returns = self.geometry(statement.annotation)
                overloads.setdefault(statement.target.id, []).append(Signature((), returns, None, statement.lineno))
                attributes.add(statement.target.id)
                after = body[position + 1] if position + 1 < len(body) else None
                if isinstance(after, ast.Expr) and isinstance(after.value, ast.Constant) and isinstance(after.value.value, str):
                    sources[statement.target.id] = _source_of(after.value.value)
        for name, signatures in overloads.items():
            qualified = f"{prefix}.{name}"
            source = sources.get(name) or class_source
            if name == "__init__":
                continue  # the constructor is the class's entry
            self.library.apis[qualified] = Api(
                qualified, tuple(signatures), self.library.name, self.label, source, receiver=receiver, is_attribute=name in attributes
            )

    def _read_class(self, node: ast.ClassDef, prefix: str) -> None:
        qualified = f"{prefix}.{node.name}"
        receiver = None
        for decorator in node.decorator_list:
            if isinstance(decorator, ast.Call) and _last(decorator.func) == "any_receiver":
                receiver = Receiver(_module_names(decorator, "when_imported"), _module_names(decorator, "unless_imported"))
        source = _source_of(node)
        versions = _versions(node.decorator_list)
        constructors = [
            self._signature(statement, in_class=True)
            for statement in node.body
            if isinstance(statement, ast.FunctionDef) and statement.name == "__init__"
        ]
        if versions:
            constructors = [_with_versions(signature, versions) for signature in constructors]
        self.library.apis[qualified] = Api(qualified, tuple(constructors), self.library.name, self.label, source, is_class=True, receiver=receiver)
        self._bind_names(node.body, qualified)
        self._read_body(node.body, qualified, in_class=True, receiver=receiver, class_source=source)

    def _signature(self, node: ast.FunctionDef, in_class: bool) -> Signature:
        decorators = {_last(decorator.func if isinstance(decorator, ast.Call) else decorator) for decorator in node.decorator_list}
        unknown = {decorator for decorator in decorators if decorator is not None} - _KEPT_DECORATORS
        if unknown:
            raise StubError(f"{self.label}:{node.lineno}: unknown decorator {sorted(unknown)} (see geolint.knowledge.markers)")
        arguments = node.args
        positional = [*arguments.posonlyargs, *arguments.args]
        drop_first = in_class and "staticmethod" not in decorators
        receiver = None
        if drop_first and positional:
            receiver = self.geometry(positional[0].annotation) if positional[0].annotation is not None else None
            positional = positional[1:]
        defaults = [None] * (len([*arguments.posonlyargs, *arguments.args]) - len(arguments.defaults)) + list(arguments.defaults)
        if drop_first and defaults:
            defaults = defaults[1:]
        posonly = len(arguments.posonlyargs) - (1 if drop_first and arguments.posonlyargs else 0)
        parameters = [
            self._parameter(argument, positional=True, keyword=index >= posonly, has_default=default is not None)
            for index, (argument, default) in enumerate(zip(positional, defaults))
        ]
        if arguments.vararg is not None:
            parameters.append(Parameter(arguments.vararg.arg, positional=True, keyword=False, has_default=True, variadic=True))
        parameters += [
            self._parameter(argument, positional=False, keyword=True, has_default=default is not None)
            for argument, default in zip(arguments.kwonlyargs, arguments.kw_defaults)
        ]
        if arguments.kwarg is not None:  # `**options`: any other keyword fits, and says nothing
            parameters.append(Parameter(arguments.kwarg.arg, positional=False, keyword=True, has_default=True, variadic=True))
        returns = self.geometry(node.returns) if node.returns is not None else None
        return Signature(tuple(parameters), returns, _versions(node.decorator_list), node.lineno, receiver)

    def _parameter(self, argument: ast.arg, positional: bool, keyword: bool, has_default: bool) -> Parameter:
        annotation = argument.annotation
        literal = self._literal(annotation) if annotation is not None else None
        geometry = self.geometry(annotation) if annotation is not None and literal is None else None
        return Parameter(argument.arg, positional, keyword, has_default, geometry, literal)

    def _literal(self, node: ast.expr) -> tuple[object, ...] | None:
        if isinstance(node, ast.Subscript) and _last(node.value) == "Literal":
            items = node.slice.elts if isinstance(node.slice, ast.Tuple) else [node.slice]
            values = []
            for item in items:
                if not isinstance(item, ast.Constant):
                    raise StubError(f"{self.label}:{node.lineno}: Literal of a non-constant")
                values.append(item.value)
            return tuple(values)
        return None

    def geometry(self, node: ast.expr) -> Geometry | None:
        """What an annotation states, or None."""
        if isinstance(node, ast.Name) and node.id in self.type_aliases:
            aliased = self.type_aliases.pop(node.id)  # out while it is read: an alias of itself states nothing
            try:
                return self.geometry(aliased)
            finally:
                self.type_aliases[node.id] = aliased
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr):  # `X | None`
            sides = [side for side in (node.left, node.right) if not (isinstance(side, ast.Constant) and side.value is None)]
            return self.geometry(sides[0]) if len(sides) == 1 else None
        if isinstance(node, ast.Constant) and isinstance(node.value, str):  # a forward reference
            try:
                return self.geometry(ast.parse(node.value, mode="eval").body)
            except SyntaxError:
                return None
        name = _last(node.value if isinstance(node, ast.Subscript) else node)
        if name in _PLAIN and not isinstance(node, ast.Subscript):
            return _PLAIN[name]
        if name in _FRAMED and not isinstance(node, ast.Subscript):
            return Geometry(kind=_FRAMED[name])  # no frames stated
        if isinstance(node, ast.Subscript):
            items = list(node.slice.elts) if isinstance(node.slice, ast.Tuple) else [node.slice]
            if name in _FRAMED:
                return Geometry(kind=_FRAMED[name], frames=tuple(_frame(item) for item in items))
            if name == "Annotated" and items:
                base = self.geometry(items[0]) or Geometry()
                return _annotated(base, items[1:])
            if name in _OPTIONAL_WRAPPERS:
                return self.geometry(items[0])
            if name == "tuple":
                parts = tuple(self.geometry(item) or Geometry() for item in items)
                return Geometry(items=parts) if any(part != Geometry() for part in parts) else None
            return None
        dotted = _dotted(node)
        if dotted is not None and not dotted.startswith(("geolint", "typing", "np", "numpy")):
            head, _, rest = dotted.partition(".")
            qualified = self.local.get(head)
            if qualified is not None and not qualified.startswith(("typing", "geolint", "numpy", "builtins")):
                return Geometry(type_name=f"{qualified}.{rest}" if rest else qualified)
        return None


def _annotated(base: Geometry, markers: list[ast.expr]) -> Geometry:
    kind, camera_axes, row_vectors, stacked = base.kind, base.camera_axes, base.row_vectors, base.stacked
    tf_frame, launch_part, ros_parameter, array_operation = base.tf_frame, base.launch_part, base.ros_parameter, base.array_operation
    for marker in markers:
        name = _last(marker)
        if name in _FRAMED and kind is None:  # `Annotated[PointCloud, PointArray]`: a library object that holds points
            kind = _FRAMED[name]
        elif isinstance(marker, ast.Attribute) and _last(marker.value) == "CameraAxes":
            camera_axes = marker.attr.lower()
        elif name == "ROW_VECTORS":
            row_vectors = True
        elif name == "STACKED":
            stacked = True
        elif isinstance(marker, ast.Attribute) and _last(marker.value) == "TfFrame":
            tf_frame = marker.attr.lower()
        elif isinstance(marker, ast.Attribute) and _last(marker.value) == "LaunchNode":
            launch_part = marker.attr.lower()
        elif isinstance(marker, ast.Attribute) and _last(marker.value) == "RosParameter":
            ros_parameter = marker.attr.lower()
        elif isinstance(marker, ast.Attribute) and _last(marker.value) == "ArrayOperation":
            array_operation = marker.attr.lower()
    return Geometry(
        kind=kind,
        quaternion_order=base.quaternion_order,
        angle_unit=base.angle_unit,
        frames=base.frames,
        camera_axes=camera_axes,
        row_vectors=row_vectors,
        stacked=stacked,
        type_name=base.type_name,
        items=base.items,
        tf_frame=tf_frame,
        launch_part=launch_part,
        ros_parameter=ros_parameter,
        array_operation=array_operation,
    )


def _frame(node: ast.expr) -> str:
    """A frame argument: a string literal (`"camera"`, or `Literal["camera"]`, the same type, which linters
    do not read as a forward reference) names the frame; a type variable is generic ('')."""
    if isinstance(node, ast.Subscript) and _last(node.value) == "Literal":
        node = node.slice
    return node.value if isinstance(node, ast.Constant) and isinstance(node.value, str) else ""


def _module_names(decorator: ast.Call, keyword_name: str) -> tuple[str, ...]:
    modules = next((keyword.value for keyword in decorator.keywords if keyword.arg == keyword_name), None)
    names = tuple(_string(item) or "" for item in modules.elts) if isinstance(modules, (ast.Tuple, ast.List)) else ()
    return tuple(name for name in names if name)


def _versions(decorators: list[ast.expr]) -> str | None:
    for decorator in decorators:
        if isinstance(decorator, ast.Call) and _last(decorator.func) == "versions" and decorator.args:
            return _string(decorator.args[0])
    return None


def _with_versions(signature: Signature, versions: str) -> Signature:
    combined = versions if signature.versions is None else f"{versions},{signature.versions}"
    return Signature(signature.parameters, signature.returns, combined, signature.line, signature.receiver)


def _source_of(node: ast.FunctionDef | ast.ClassDef | str) -> str:
    """The docstring's `Source:` paragraph (the citation), joined into one line (an attribute's docstring is
    the string after it)."""
    doc = node if isinstance(node, str) else ast.get_docstring(node) or ""
    lines = doc.splitlines()
    for index, line in enumerate(lines):
        if line.strip().startswith("Source:"):
            cited = [line.strip()[len("Source:") :].strip()]
            for more in lines[index + 1 :]:
                if not more.strip():
                    break
                cited.append(more.strip())
            return " ".join(cited)
    return ""


def _absolute(node: ast.ImportFrom, module: str, is_package: bool) -> str:
    if not node.level:
        return node.module or ""
    parts = module.split(".")
    base = parts if is_package else parts[:-1]
    base = base[: len(base) - (node.level - 1)] if node.level > 1 else base
    return ".".join([*base, node.module] if node.module else base)


def _dotted(node: ast.expr) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        head = _dotted(node.value)
        return f"{head}.{node.attr}" if head else None
    return None


def _last(node: ast.expr) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return node.attr
    return None


def _string(node: ast.expr) -> str | None:
    return node.value if isinstance(node, ast.Constant) and isinstance(node.value, str) else None
