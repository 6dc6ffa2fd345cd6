"""The plugin class: dispatch tables only. Each ``get_*_hook`` is a dictionary lookup by fully qualified name;
the typing tricks live in the feature modules named in the tables.
"""

from __future__ import annotations

import sys
from functools import partial
from typing import Any, Callable

from mypy.errors import CompileError
from mypy.nodes import Import, MypyFile
from mypy.options import Options
from mypy.plugin import (
    AnalyzeTypeContext,
    AttributeContext,
    ClassDefContext,
    FunctionContext,
    FunctionSigContext,
    MethodContext,
    MethodSigContext,
    Plugin,
    ReportConfigContext,
)
from mypy.types import FunctionLike, Type

from geolint.mypy import (
    config,
    frame_names,
    fullnames as names,
    generic_calls,
    knowledge_calls,
    markers,
    numpy_calls,
    operators,
    runtime_values,
    string_frame_prepass,
    string_frames,
)
from geolint.knowledge.markers import ArrayOperation
from geolint.mypy.geometry import FRAMED_CLASSES

ARITY = {
    names.TRANSFORM: 2,
    names.ROTATION_MATRIX: 2,
    names.TRANSFORM_MATRIX: 2,
    names.TRANSLATION: 2,
    names.NEGATED_ROTATION: 2,
    names.ORIGIN_OFFSET: 3,
}

FUNCTION_HOOKS: dict[str, Callable[[FunctionContext], Type]] = {
    names.AS_POINTS: markers.mark,
    names.AS_VECTORS: markers.mark,
    names.AS_DIRECTIONS: markers.mark,
    names.AS_ROTATION: markers.mark,
    names.AS_TRANSFORM: markers.mark,
    names.AS_TRANSLATION: markers.mark,
}

# the array library's functions, by what their stub says they do (`ArrayOperation`)
ARRAY_OPERATION_HOOKS: dict[str, Callable[[FunctionContext], Type]] = {
    ArrayOperation.MATMUL: numpy_calls.dot,
    ArrayOperation.AS_ARRAY: numpy_calls.asarray,
    ArrayOperation.APPEND_FLAT: numpy_calls.append,
    ArrayOperation.INVERSE: numpy_calls.inverse,
}

_OPERATOR_RECEIVERS = [
    names.POINT,
    names.VECTOR,
    names.DIRECTION,
    names.TRANSFORM,
    names.POINT_CLOUD,
    names.TWIST,
    names.WRENCH,
    names.COVARIANCE,
    names.POINT_ARRAY,
    names.VECTOR_ARRAY,
    names.DIRECTION_ARRAY,
    names.ROTATION_MATRIX,
    names.TRANSFORM_MATRIX,
    names.TRANSLATION,
    names.HOMOGENEOUS_POINTS,
    names.HOMOGENEOUS_VECTORS,
    names.VECTOR_WITH_W1,
    names.ORIGIN_OFFSET,
    names.NEGATED_ROTATION,
]

METHOD_HOOKS: dict[str, Callable[[MethodContext], Type]] = {
    f"{receiver}.{operator}": operators.method_hook(operator)
    for receiver in _OPERATOR_RECEIVERS
    for operator in names.OPERATORS
}
# A plain ndarray's reflected operators: reached only when a runtime value's own operator refused the array.
for _reflected in ("__rmatmul__", "__radd__", "__rsub__"):
    METHOD_HOOKS[f"{names.NDARRAY}.{_reflected}"] = operators.method_hook(_reflected)
METHOD_HOOKS[f"{names.TRANSFORM_MATRIX}.__getitem__"] = numpy_calls.transform_matrix_item
METHOD_HOOKS[f"{names.TRANSFORM}.identity"] = markers.identity
for _value in names.COORDINATE_VALUES:
    METHOD_HOOKS[f"{_value}.__getitem__"] = runtime_values.batch_item
    METHOD_HOOKS[f"{_value}.is_close"] = runtime_values.is_close

METHOD_SIGNATURE_HOOKS: dict[str, Callable[[MethodSigContext], FunctionLike]] = {
    f"{receiver}.{operator}": operators.signature_hook(operator)
    for receiver in _OPERATOR_RECEIVERS
    for operator in names.OPERATORS
}


ATTRIBUTE_HOOKS: dict[str, Callable[[AttributeContext], Type]] = {
    f"{names.TRANSFORM}.{attribute}": numpy_calls.transform_part(attribute)
    for attribute in ("matrix", "rotation", "translation")
}


class GeolintPlugin(Plugin):
    def __init__(self, options: Options) -> None:
        super().__init__(options)
        try:
            self.settings = config.load(options.config_file)
        except config.PluginConfigError as error:
            # mypy reports a CompileError like its own blocking errors (exit 2), not as an internal error
            raise CompileError([str(error)]) from None
        _expose_settings_to_daemon(self.settings)
        self.type_analyze_hooks: dict[str, Callable[[AnalyzeTypeContext], Type]] = {
            fullname: partial(
                string_frames.analyze_framed_subscript,
                fullname=fullname,
                arity=ARITY.get(fullname, 1),
                settings=self.settings,
            )
            for fullname in FRAMED_CLASSES
        }

    def report_config_data(self, ctx: ReportConfigContext) -> Any:
        return self.settings.cache_key()

    def get_additional_deps(self, file: MypyFile) -> list[tuple[int, str, int]]:
        # Hooks build geolint.typing types (np.asarray(Point[F]) -> PointArray[F]) in modules that import
        # only the runtime: make sure that module is part of the build whenever geolint is.
        # The same moment (parsed, not yet analyzed) is the one chance to protect string frames.
        if file.fullname.startswith("geolint"):
            return []
        string_frame_prepass.protect_string_frames(file)  # also where a project module re-exports geolint's
        return [(10, names.TYPING_MODULE, -1)] if _imports_geolint(file) else []

    def get_base_class_hook(self, fullname: str) -> Callable[[ClassDefContext], None] | None:
        return frame_names.record_declared_name if fullname == names.FRAME else None

    def get_type_analyze_hook(self, fullname: str) -> Callable[[AnalyzeTypeContext], Type] | None:
        return self.type_analyze_hooks.get(fullname)

    def get_function_hook(self, fullname: str) -> Callable[[FunctionContext], Type] | None:
        return FUNCTION_HOOKS.get(fullname) or _array_function_hook(fullname) or knowledge_calls.hook_for(fullname)

    def get_function_signature_hook(self, fullname: str) -> Callable[[FunctionSigContext], FunctionLike] | None:
        return generic_calls.check_frames  # any function may be frame-generic; the hook returns at once if not

    def get_method_signature_hook(self, fullname: str) -> Callable[[MethodSigContext], FunctionLike] | None:
        return METHOD_SIGNATURE_HOOKS.get(fullname)

    def get_method_hook(self, fullname: str) -> Callable[[MethodContext], Type] | None:
        return METHOD_HOOKS.get(fullname) or _ufunc_call_hook(fullname) or knowledge_calls.hook_for(fullname)

    def get_attribute_hook(self, fullname: str) -> Callable[[AttributeContext], Type] | None:
        return ATTRIBUTE_HOOKS.get(fullname)


def _expose_settings_to_daemon(settings: config.PluginConfig) -> None:
    """Make the settings part of the plugin's version as mypy records it.

    ``dmypy run`` loads the plugins again on every run and restarts the daemon when a plugin module's
    ``__version__`` (or file) differs from the one it started with; the daemon's analyzed modules are not
    re-validated through ``report_config_data``, so this is what makes a changed ``[geolint-mypy]`` reach it.
    """
    version = settings.version_tag()
    for module_name in {__name__, __name__.rpartition(".")[0]}:
        module = sys.modules.get(module_name)
        if module is not None:
            module.__version__ = version  # type: ignore[attr-defined]


def _imports_geolint(file: MypyFile) -> bool:
    for node in file.imports:
        ids = [name for name, _ in node.ids] if isinstance(node, Import) else [getattr(node, "id", "")]
        if any(name == "geolint" or name.startswith("geolint.") for name in ids):
            return True
    return False


class GeolintPluginForMypy1(GeolintPlugin):
    """mypy 1.x checks a reflected operator under the forward name (``array.__matmul__(T)`` for the reflected
    half of ``T @ array``), so a plain ndarray's forward operators need the hook there too."""

    def get_method_hook(self, fullname: str) -> Callable[[MethodContext], Type] | None:
        return METHOD_HOOKS.get(fullname) or LEGACY_NDARRAY_HOOKS.get(fullname) or _ufunc_call_hook(fullname) or knowledge_calls.hook_for(fullname)


def _array_function_hook(fullname: str) -> Callable[[FunctionContext], Type] | None:
    operation = numpy_calls.array_operation(fullname)
    return None if operation is None else ARRAY_OPERATION_HOOKS.get(operation)


def _ufunc_call_hook(fullname: str) -> Callable[[MethodContext], Type] | None:
    """`np.matmul` is a ufunc object: its call is a method call on the ufunc's class, told apart by the callee."""
    if fullname.endswith(".__call__") and numpy_calls.is_array_library_method(fullname):
        return numpy_calls.matmul_ufunc_call
    return None


LEGACY_NDARRAY_HOOKS = {
    f"{names.NDARRAY}.{operator}": operators.method_hook(operator) for operator in ("__matmul__", "__add__", "__sub__")
}


def plugin(version: str) -> type[Plugin]:
    """mypy's entry point (``plugins = geolint.mypy``); `version` is mypy's, see docs/typing.md."""
    major = int(version.split(".", 1)[0]) if version[:1].isdigit() else 2
    return GeolintPluginForMypy1 if major < 2 else GeolintPlugin
