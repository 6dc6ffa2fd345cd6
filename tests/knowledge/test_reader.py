"""The stub reader: overloads told apart by Literal keywords, re-exports, versions, receivers, citations."""

from __future__ import annotations

import ast
import textwrap
from pathlib import Path

import pytest

from geolint.algebra import Kind
from geolint.knowledge import (
    SCALAR_FIRST,
    SCALAR_LAST,
    KnowledgeBase,
    StubError,
    agreed,
    bind,
)
from geolint.knowledge.reader import read_library


def _library(tmp_path: Path, files: dict[str, str], packages: str = '["rotlib"]') -> KnowledgeBase:
    folder = tmp_path / "rotlib"
    folder.mkdir()
    (folder / "METADATA.toml").write_text(f'distribution = "rotlib"\npackages = {packages}\nchecked = "2.0"\nupstream = "x"\n')
    for name, text in files.items():
        path = folder / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text))
    return KnowledgeBase([read_library(folder)])


def _call(source: str) -> ast.Call:
    node = ast.parse(source, mode="eval").body
    assert isinstance(node, ast.Call)
    return node


STUB = '''
from typing import Literal, overload
from geolint.knowledge.markers import any_receiver, versions
from geolint.typing import Degrees, PointArray, QuaternionWXYZ, QuaternionXYZW, Radians, TransformMatrix

@overload
def to_matrix(q: QuaternionXYZW, *, scalar_first: Literal[False] = ...) -> object:
    """Source: rotlib/core.py, to_matrix."""
@overload
def to_matrix(q: QuaternionWXYZ, *, scalar_first: Literal[True]) -> object: ...
@versions(">=2")
def euler(angles: Degrees) -> object:
    """Source: rotlib 2.0 changelog: degrees from 2.0 on."""
@versions("<2")
def euler(angles: Radians) -> object: ...
def move(points: PointArray["world"], pose: TransformMatrix["camera", "world"]) -> PointArray["camera"]:
    """Source: rotlib/core.py, move."""
class Quat:
    """Source: rotlib/quat.py, Quat(w, x, y, z)."""
    def __init__(self, w: float, x: float, y: float, z: float) -> None: ...
    @property
    def elements(self) -> QuaternionWXYZ: ...
@any_receiver(when_imported=("rotlib.sim",))
class Client:
    """Source: rotlib/sim.py: the client's methods wrap the module's functions."""
    def getQuat(self, body: int) -> QuaternionXYZW: ...
quat2mat = to_matrix
'''


def test_overloads_are_told_apart_by_literal_keywords(tmp_path: Path) -> None:
    kb = _library(tmp_path, {"rotlib/core.pyi": STUB})
    api = kb.api("rotlib.core.to_matrix")
    assert api is not None and api.source == "rotlib/core.py, to_matrix."

    def order(source: str) -> str | None:
        return agreed(bind(api, _call(source)), lambda bound: bound.signature.parameter("q").geometry.quaternion_order)  # type: ignore[union-attr]

    assert order("to_matrix(q)") == SCALAR_LAST
    assert order("to_matrix(q, scalar_first=False)") == SCALAR_LAST
    assert order("to_matrix(q, scalar_first=True)") == SCALAR_FIRST
    assert order("to_matrix(q, scalar_first=flag)") is None  # decided at run time: both overloads remain
    assert order("to_matrix(q, scalar_first=True, extra=1)") is None  # no overload takes `extra`
    assert order("to_matrix()") is None  # `q` is required


def test_the_bound_argument_is_the_parameter_given_by_position_or_keyword(tmp_path: Path) -> None:
    kb = _library(tmp_path, {"rotlib/core.pyi": STUB})
    api = kb.api("rotlib.core.move")
    assert api is not None
    (bound,) = bind(api, _call("move(pose=T, points=cloud)"))
    assert ast.unparse(bound.arguments["points"]) == "cloud"
    geometry = bound.signature.parameter("pose").geometry  # type: ignore[union-attr]
    assert geometry is not None and geometry.kind == Kind.TRANSFORM and geometry.frames == ("camera", "world")
    assert bound.signature.returns is not None and bound.signature.returns.frames == ("camera",)


def test_versioned_overloads_count_only_when_the_versions_hold(tmp_path: Path) -> None:
    kb = _library(tmp_path, {"rotlib/core.pyi": STUB})
    api = kb.api("rotlib.core.euler")
    assert api is not None
    call = _call("euler(a)")
    unit = lambda bound: bound.signature.parameter("angles").geometry.angle_unit  # type: ignore[union-attr]
    assert agreed(bind(api, call), unit) is None  # version unknown: no overload counts
    assert agreed(bind(api, call, lambda spec: spec == ">=2"), unit) == "degrees"
    assert agreed(bind(api, call, lambda spec: spec == "<2"), unit) == "radians"
    assert agreed(bind(api, call, lambda spec: True), unit) is None  # a pin that allows both: the overloads disagree


def test_aliases_classes_components_and_receivers(tmp_path: Path) -> None:
    kb = _library(tmp_path, {"rotlib/core.pyi": STUB, "rotlib/__init__.pyi": "from rotlib.core import Quat as Quat\n"})
    assert kb.api("rotlib.core.quat2mat") is kb.api("rotlib.core.to_matrix")
    quat = kb.api("rotlib.Quat")  # the package re-exports it
    assert quat is not None and quat.is_class and quat.signatures[0].components == SCALAR_FIRST
    elements = kb.api("rotlib.Quat.elements")
    assert elements is not None and elements.signatures[0].returns.quaternion_order == SCALAR_FIRST  # type: ignore[union-attr]
    (client,) = kb.methods_named("getQuat")
    assert client.receiver is not None and client.receiver.when_imported == ("rotlib.sim",)
    assert kb.library_of_module("rotlib.core.x") is kb.libraries["rotlib"]


@pytest.mark.parametrize(
    ("text", "problem"),
    [
        ("def f(q: int) -> None:\n    pass\nf(\n", "rotlib/rotlib/core.pyi"),
        ("@weird\ndef f() -> None: ...\n", "unknown decorator"),
        ("from typing import Literal\ndef f(a: Literal[x]) -> None: ...\n", "Literal of a non-constant"),
    ],
)
def test_a_bad_stub_is_a_clear_error_naming_the_file(tmp_path: Path, text: str, problem: str) -> None:
    with pytest.raises(StubError, match=problem):
        _library(tmp_path, {"rotlib/core.pyi": text})


def test_a_type_alias_states_what_its_annotation_states(tmp_path: Path) -> None:
    kb = _library(
        tmp_path,
        {
            "rotlib/__init__.pyi": '''
            from geolint.knowledge.markers import STACKED
            from geolint.typing import QuaternionXYZW
            from typing_extensions import Annotated
            _Q = Annotated[QuaternionXYZW, STACKED]
            _Loop = Annotated[_Loop, STACKED]
            def normalize(q: _Q) -> _Q:
                """Source: rotlib/core.py, normalize."""
            def looped(q: _Loop) -> None:
                """Source: rotlib/core.py, looped."""
            '''
        },
    )
    api = kb.api("rotlib.normalize")
    assert api is not None
    (signature,) = api.signatures
    returned = signature.returns
    assert returned is not None and returned.quaternion_order == SCALAR_LAST and returned.stacked
    assert signature.parameters[0].geometry == returned
    looped = kb.api("rotlib.looped")
    assert looped is not None and looped.signatures[0].parameters[0].geometry is not None  # read once, then nothing more


def test_keywords_caught_by_options_bind_and_say_nothing(tmp_path: Path) -> None:
    kb = _library(
        tmp_path,
        {"rotlib/core.pyi": "from geolint.typing import Degrees\n\ndef spawn(*, euler: Degrees = ..., **options: object) -> None:\n    '''Source: x.'''\n"},
    )
    api = kb.api("rotlib.core.spawn")
    assert api is not None
    (bound,) = bind(api, _call("spawn(file='a.urdf', euler=e, fixed=True)"))
    assert set(bound.arguments) == {"euler"}
    stub_without_options = "from geolint.typing import Degrees\n\ndef spawn(*, euler: Degrees = ...) -> None:\n    '''Source: x.'''\n"
    (tmp_path / "other").mkdir()
    strict = _library(tmp_path / "other", {"rotlib/core.pyi": stub_without_options}).api("rotlib.core.spawn")
    assert strict is not None and bind(strict, _call("spawn(file='a.urdf', euler=e)")) == []


def test_a_record_class_s_fields_are_its_defaulted_constructor_parameters(tmp_path: Path) -> None:
    """A message or dataset record is a class whose one constructor gives every field a default: its fields
    are what the linter reads on `msg.field` (the kind of a 3-vector, the class a field holds, a quaternion's
    order). A constructor with a required parameter is not a record."""
    kb = _library(
        tmp_path,
        {
            "rotlib/msg.pyi": """
                from typing import Annotated
                from geolint.typing import QuaternionWXYZ, VectorArray

                class Vec:
                    def __init__(self, x: float = ..., y: float = ..., z: float = ...) -> None: ...

                class Motion:
                    def __init__(self, header: object = ..., rate: Annotated[Vec, VectorArray] = ..., *, q: QuaternionWXYZ = ..., **more: object) -> None: ...

                class Solver:
                    def __init__(self, rate: VectorArray, tolerance: float = ...) -> None: ...
            """
        },
    )
    fields = kb.record_fields("rotlib.msg.Motion")
    assert {name: (geometry.type_name, geometry.kind, geometry.quaternion_order) for name, geometry in fields.items()} == {
        "rate": ("rotlib.msg.Vec", Kind.VECTOR, None),
        "q": (None, Kind.ROTATION, SCALAR_FIRST),
    }
    assert kb.record_fields("rotlib.msg.Solver") == {} and kb.record_fields("rotlib.msg.Vec") == {}
    assert kb.record_classes() == ["rotlib.msg.Motion"]
    assert kb.record_field_names("quaternion_order") == {"q"} and kb.record_field_names("kind") == {"rate", "q"}
