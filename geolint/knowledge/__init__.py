"""The geometry knowledge base: what library APIs do with points, vectors, rotations and frames.

The facts are stubs in `stubs/<library>/` (typeshed's layout, geolint's typing vocabulary, a cited
source on every entry), read once per process by `geolint.knowledge.reader`. The linter's fact base and
the mypy plugin both ask `knowledge_base()`; no analysis module names a library.
"""

from __future__ import annotations

import os
from functools import lru_cache
from pathlib import Path

from geolint.knowledge.binding import Bound, agreed, bind
from geolint.knowledge.model import DEGREES, MONOGRAM, RADIANS, SCALAR_FIRST, SCALAR_LAST, Api, Executable, Geometry, Library, Parameter, Signature
from geolint.knowledge.reader import StubError, read_library

__all__ = [
    "DEGREES", "MONOGRAM", "RADIANS", "SCALAR_FIRST", "SCALAR_LAST", "Api", "Bound", "Executable", "Geometry", "KnowledgeBase", "Library",
    "Parameter", "Signature", "StubError", "agreed", "bind", "knowledge_base", "stubs_folder",
]  # fmt: skip

_ALIAS_HOPS = 8  # re-exports of re-exports; more is a cycle


class KnowledgeBase:
    """Every library's APIs by qualified name, with re-exports resolved."""

    def __init__(self, libraries: list[Library]) -> None:
        self.libraries = {library.name: library for library in libraries}
        self._apis: dict[str, Api] = {}
        self._aliases: dict[str, str] = {}
        self._by_method: dict[str, list[Api]] = {}
        self._roots: dict[str, Library] = {}
        self._conventional: dict[str, str] = {}
        self._extensions: dict[str, tuple[tuple[str, ...], str]] = {}
        self._names_reading: dict[tuple[str, str], frozenset[str]] = {}
        self._tf_apis: dict[str, list[Api]] = {}
        self._parameter_apis: dict[str, list[Api]] = {}
        self._executables: dict[tuple[str, str], Executable] = {}
        self._records: dict[str, dict[str, Geometry]] | None = None
        self._record_field_names: dict[str, frozenset[str]] = {}
        self._float_converted: frozenset[str] | None = None
        self._conventional_modules: dict[str, str] = {}
        self._frameless: dict[str, bool] = {}
        self._array_operations: dict[str, str] = {}
        for library in libraries:
            for name, target in library.extends.items():
                self._extensions[name] = (library.packages, target)
            self._conventional.update(library.conventional_names)
            self._conventional_modules.update(library.conventional_modules)
            self._apis.update(library.apis)
            self._aliases.update(library.aliases)
            for package in library.packages:
                self._roots[package] = library
            for api in library.apis.values():
                if api.receiver is not None and not api.is_class:
                    self._by_method.setdefault(api.qualified_name.rpartition(".")[2], []).append(api)
                if _names_tf_frames(api):
                    self._tf_apis.setdefault(api.qualified_name.rpartition(".")[2], []).append(api)
                if _names_ros_parameters(api):
                    self._parameter_apis.setdefault(api.qualified_name.rpartition(".")[2], []).append(api)
                operations = {signature.returns.array_operation for signature in api.signatures if signature.returns is not None}
                if len(operations) == 1 and None not in operations:
                    self._array_operations[api.qualified_name] = operations.pop()  # type: ignore[assignment]
            for executable in library.executables.values():
                self._executables[(executable.package, executable.name)] = executable
        self._array_libraries = frozenset(self._apis[name].library for name in self._array_operations)
        # each array library's namespace module: the shortest module holding its array functions (`numpy`,
        # `torch`, `jax.numpy`), where numpy's function names live
        operation_modules: dict[str, set[str]] = {}
        for name in self._array_operations:
            operation_modules.setdefault(self._apis[name].library, set()).add(name.rpartition(".")[0])
        self._namespace_modules = frozenset(min(modules, key=lambda module: (module.count("."), module)) for modules in operation_modules.values())
        # what is an array library's: every name of one whose values are arrays (METADATA.toml's `array_library`:
        # numpy, torch, jax), only the namespace module of one that has other APIs beside it (scipy.linalg)
        self._array_roots = frozenset(package for library in libraries if library.array_library for package in library.packages) | self._namespace_modules
        # asked per name and per file on the hot path: derived once here
        array_packages = {package for name in self._array_libraries for package in self.libraries[name].packages}
        self._array_module_names = frozenset(array_packages) | frozenset(
            name for name, module in self._conventional_modules.items() if module.partition(".")[0] in array_packages
        )
        self._monogram_packages = tuple(sorted(package for library in libraries if library.frame_naming == MONOGRAM for package in library.packages))

    def api(self, qualified_name: str) -> Api | None:
        """The API a qualified name means, through re-exports (`scipy.spatial.transform.Rotation.from_quat`)."""
        name = qualified_name
        for _ in range(_ALIAS_HOPS):
            found = self._apis.get(name)
            if found is not None:
                return found
            resolved = self._resolve_prefix(name)
            if resolved is None or resolved == name:
                return None
            name = resolved
        return None

    def _resolve_prefix(self, name: str) -> str | None:
        head, rest = name, ""
        while head:
            target = self._aliases.get(head)
            if target is not None:
                return target + rest
            head, dot, tail = head.rpartition(".")
            rest = f"{dot}{tail}{rest}" if head else rest
        return None

    def methods_named(self, name: str) -> list[Api]:
        """APIs of `@any_receiver` classes with this method name (pybullet's client methods...)."""
        return self._by_method.get(name, [])

    def tf_apis_named(self, name: str) -> list[Api]:
        """The APIs with this last name that take tf frame ids, publish transforms (`TfFrame` markers) or
        launch a ROS executable (`LaunchNode`): tf's lookups and broadcasters are recognised by method name,
        on whatever object holds them."""
        return self._tf_apis.get(name, [])

    def parameter_apis_named(self, name: str) -> list[Api]:
        """The APIs with this last name that declare or read a ROS parameter (`RosParameter` markers):
        recognised by method name too, as a node's `self.declare_parameter` is."""
        return self._parameter_apis.get(name, [])

    def tf_names(self) -> list[str]:
        """Every name a file must contain to state something about tf: the tf APIs' last names and the
        launched executables' names (a cheap test before a file is parsed)."""
        methods = {name for name, apis in self._tf_apis.items() if any(not api.is_class for api in apis)}
        return sorted(methods | {name for _, name in self._executables})

    def tf_packages(self) -> list[str]:
        """The import names of the libraries that have tf APIs (a module states tf facts only if it imports one)."""
        return sorted({package for apis in self._tf_apis.values() for api in apis for package in self.libraries[api.library].packages})

    def executable(self, package: str, name: str) -> Executable | None:
        """A ROS executable that publishes a transform from its command line (`tf2_ros`'s
        `static_transform_publisher`), by the package and name a launch file gives."""
        return self._executables.get((package, name))

    def extension(self, qualified_name: str, imported: list[str]) -> Api | None:
        """A name another package gains once a library is imported (`numpy.quaternion` after `import
        quaternion`), when one of `imported` (the module's imports) is that library."""
        found = self._extensions.get(qualified_name)
        if found is None:
            return None
        packages, target = found
        if not any(name.partition(".")[0] in packages for name in imported):
            return None
        return self.api(target)

    def conventional_name(self, name: str) -> str | None:
        """The library class a bare local name means by convention (METADATA.toml's `conventional_names`)."""
        return self._conventional.get(name)

    def array_module_names(self) -> frozenset[str]:
        """The names a file calls array namespaces by: their import names and the local names conventional
        for their modules (`np`, `jnp`, `la`, `F`), never values."""
        return self._array_module_names

    def api_as_written(self, dotted: str) -> Api | None:
        """The API a dotted name means as written in a file, without its imports (`np.linalg.inv`,
        `tft.rotation_matrix`): the name itself, else with its head read as the module it conventionally
        means (`numpy.linalg.inv`)."""
        found = self.api(dotted)
        if found is not None:
            return found
        head, dot, rest = dotted.partition(".")
        module = self._conventional_modules.get(head)
        return self.api(f"{module}{dot}{rest}") if module is not None else None

    def api_defined_as(self, fullname: str) -> Api | None:
        """The API a name means as a type checker spells it, after the module that defines it, which may
        be a private module of the package that re-exports it (`numpy._core.multiarray.dot` is
        `numpy.dot`, `numpy.linalg._linalg.inv` is `numpy.linalg.inv`): the name itself, else the same
        last name in each public module above the first private one, nearest first."""
        found = self.api(fullname)
        if found is not None:
            return found
        module, _, name = fullname.rpartition(".")
        parts = module.split(".")
        private = next((index for index, part in enumerate(parts) if part.startswith("_")), None)
        if private is None or parts[0] not in self._roots:
            return None
        for end in range(private, 0, -1):
            found = self.api(".".join((*parts[:end], name)))
            if found is not None:
                return found
        return None

    def array_operation(self, dotted: str) -> str | None:
        """What an array namespace's function does to matrices (`markers.ArrayOperation`), for a name as
        written (`np.linalg.inv`, `torch.bmm`)."""
        api = self.api_as_written(dotted)
        return self._array_operations.get(api.qualified_name) if api is not None else None

    def array_operation_names(self, *operations: str) -> frozenset[str]:
        """The last names of the array functions doing one of `operations` (`matmul`, `mm`, `bmm`...): a
        cheap first test on a call before its name is resolved."""
        return frozenset(name.rpartition(".")[2] for name, operation in self._array_operations.items() if operation in operations)

    def is_array_namespace(self, dotted: str) -> bool:
        """Whether a module name as written (`np`, `torch`, `jnp`) is an array namespace's: a library with
        array operations in its stub."""
        head = dotted.partition(".")[0]
        module = self._conventional_modules.get(head, head)
        library = self.library_of_module(module)
        return library is not None and library.name in self._array_libraries

    def in_array_library(self, qualified: str) -> bool:
        """Whether a qualified name (imports resolved) is in an array namespace's library
        (`torch.nn.functional.pad`, `jax.random.normal`, `numpy.linalg.inv`)."""
        parts = qualified.split(".")
        return any(".".join(parts[:end]) in self._array_roots for end in range(1, len(parts) + 1))

    def is_namespace_module(self, module: str) -> bool:
        """Whether a module (imports resolved) is an array namespace itself, where numpy's function names
        live (`numpy`, `torch`, `jax.numpy`, `cupy`), not one of its submodules."""
        return module in self._namespace_modules

    def conventional_array_module(self, name: str) -> str | None:
        """The array-library module a local name conventionally means (`np` -> `numpy`, `F` ->
        `torch.nn.functional`), for names a file uses without importing them."""
        module = self._conventional_modules.get(name)
        return module if module is not None and self.in_array_library(module) else None

    def converted_with_float(self, class_name: str) -> bool:
        """Whether numpy reads an instance of this library class as one number: its stub defines `__float__`
        and none of `__len__`, `__iter__`, `__array__` (pyquaternion's Quaternion, whose float() is w)."""
        api = self.api(class_name)
        return api is not None and api.qualified_name in self.classes_converted_with_float()

    def classes_converted_with_float(self) -> frozenset[str]:
        if self._float_converted is None:
            methods: dict[str, set[str]] = {}
            for name in self._apis:
                owner, _, method = name.rpartition(".")
                if method in ("__float__", "__len__", "__iter__", "__array__"):
                    methods.setdefault(owner, set()).add(method)
            self._float_converted = frozenset(owner for owner, found in methods.items() if found == {"__float__"})
        return self._float_converted

    def frameless_module(self, dotted: str) -> bool:
        """Whether `dotted` is in a module of stubbed functions none of which names a tf frame
        (`tf.transformations.quaternion_matrix`, or the module itself): a library's math helpers, beside its
        listeners and broadcasters."""
        parts = dotted.split(".")
        for end in range(len(parts), 1, -1):
            prefix = ".".join(parts[:end])
            found = self._frameless.get(prefix)
            if found is None:
                under = [api for name, api in self._apis.items() if name.startswith(prefix + ".")]
                found = self._frameless[prefix] = bool(under) and not any(_names_tf_frames(api) for api in under)
            if found:
                return True
        return False

    def monogram_packages(self) -> tuple[str, ...]:
        """The import names of the libraries whose users name frames in monogram notation (METADATA.toml's
        `frame_naming = "monogram"`: Drake's `X_WB`)."""
        return self._monogram_packages

    def library_of_module(self, module: str) -> Library | None:
        """The library whose import names include `module`'s top package."""
        return self._roots.get(module.partition(".")[0])

    def apis(self) -> list[Api]:
        return list(self._apis.values())

    def record_fields(self, class_name: str) -> dict[str, Geometry]:
        """The fields of a record class (a ROS message, a dataset record) that state something, with what
        each states: a class whose one constructor has a default for every parameter, which the stub lists
        in the record's field order; {} for any other name."""
        api = self.api(class_name)
        return self._record_classes().get(api.qualified_name, {}) if api is not None else {}

    def record_classes(self) -> list[str]:
        """The qualified names of the record classes (see `record_fields`)."""
        return list(self._record_classes())

    def record_field_names(self, field: str) -> frozenset[str]:
        """The names of the record fields whose geometry states `field` (`"kind"`, `"quaternion_order"`):
        a cheap first test by attribute name, before a value's class is looked for."""
        found = self._record_field_names.get(field)
        if found is None:
            records = self._record_classes().values()
            found = frozenset(name for fields in records for name, geometry in fields.items() if getattr(geometry, field) is not None)
            self._record_field_names[field] = found
        return found

    def _record_classes(self) -> dict[str, dict[str, Geometry]]:
        if self._records is None:
            self._records = {}
            for api in self._apis.values():
                if not api.is_class or len(api.signatures) != 1:
                    continue
                parameters = [parameter for parameter in api.signatures[0].parameters if not parameter.variadic]
                if parameters and all(parameter.has_default and parameter.keyword for parameter in parameters):
                    stated = {parameter.name: parameter.geometry for parameter in parameters if parameter.geometry is not None}
                    if stated:
                        self._records[api.qualified_name] = stated
        return self._records

    def names_reading(self, field: str, value: str) -> frozenset[str]:
        """The last parts of the qualified names of APIs with a parameter whose geometry states `value`
        for `field` (`names_reading("angle_unit", RADIANS)`: `euler2mat`, `from_euler`...): a cheap first
        test by called name, before a call is resolved."""
        key = (field, value)
        found = self._names_reading.get(key)
        if found is None:
            found = frozenset(
                api.qualified_name.rpartition(".")[2]
                for api in self._apis.values()
                if any(
                    parameter.geometry is not None and getattr(parameter.geometry, field) == value
                    for signature in api.signatures
                    for parameter in signature.parameters
                )
            )
            self._names_reading[key] = found
        return found


def _names_ros_parameters(api: Api) -> bool:
    return any(
        parameter.geometry is not None and parameter.geometry.ros_parameter is not None
        for signature in api.signatures
        for parameter in signature.parameters
    )


def _names_tf_frames(api: Api) -> bool:
    return any(
        parameter.geometry is not None and (parameter.geometry.tf_frame is not None or parameter.geometry.launch_part is not None)
        for signature in api.signatures
        for parameter in signature.parameters
    )


def stubs_folder() -> Path:
    """Where the stubs are: `$GEOLINT_STUBS` when set (a folder of the same layout, read instead of the
    shipped one), else inside the wheel (`geolint/_stubs`), else the checkout's `stubs/`."""
    return _stubs_folder(os.environ.get("GEOLINT_STUBS") or None)


@lru_cache(maxsize=8)
def _stubs_folder(chosen: str | None) -> Path:  # asked for every library call: stat the folders once
    if chosen:
        return Path(chosen)
    package = Path(__file__).resolve().parent.parent
    for candidate in (package / "_stubs", package.parent / "stubs"):
        if candidate.is_dir():
            return candidate
    return package.parent / "stubs"


def knowledge_base(folder: Path | None = None) -> KnowledgeBase:
    """The knowledge base read from `folder` (default: `stubs_folder()`), once per process and folder."""
    return _read(folder or stubs_folder())


@lru_cache(maxsize=None)
def _read(root: Path) -> KnowledgeBase:
    libraries = [read_library(path) for path in sorted(root.iterdir()) if (path / "METADATA.toml").is_file()] if root.is_dir() else []
    return KnowledgeBase(libraries)
