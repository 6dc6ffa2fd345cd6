"""Recall by shape family: for every knowledge-base API a rule is meant to guard, one bug and its correct twin.

A shape family is one kind of slip, generated for every API of the knowledge base (`stubs/`) that
could suffer it. Each case is a small module written twice: the bug (marked `# bug` on the one line
that holds the slip) and its twin, identical except on that line, where the value is right. The real
CLI is run once over all of them, and each family is scored:

- a bug is caught when a finding of the family's rule lands on the bug file's `# bug` line;
- a twin is flagged (a false positive) when it has any finding of that rule.

Families:

- `degrees-on-radian-apis` (GEO302): every API with a parameter the stubs state in radians is given
  `angle_deg` (a function parameter whose name says degrees); the twin gives `np.radians(angle_deg)`.
- `quaternion-order` (GEO301): every API with a parameter whose quaternion order the stubs state is
  given a quaternion spelled out from named components in the other order (`np.array([qx, qy, qz,
  qw])` where w comes first); the twin spells it in the API's own order.
- `directions-through-point-apis` (GEO101): every API the stubs state as applying a transform to a
  parameter they type as points is given a direction by each name GEO101 reads (`normals`, `normal`,
  `direction`); the twin moves it the way the stub states (the keyword that picks the vector overload,
  `translate=False`, or the API beside it, `transform_normals`), or gives the API `points` where the
  stub states no way.
- `extrinsics-direction` (GEO209): every API with a parameter the stubs type as a transform between
  the camera and the world is given the other direction, named by each word GEO209 reads (`c2w`,
  `cam2world`, `Twc`, `T_world_cam`...) and read from each attribute whose stub returns that direction
  (Blender's `scene.camera.matrix_world`); the twin is its inverse.
- `camera-axes` (GEO216): every such parameter whose camera axes the stubs state is given a pose in
  other axes, named so (`w2c_gl`) and read from each attribute whose stub states other axes, inverted
  where the camera is on the other side; the twin flips the axes on the camera's side first.

Four more families are about spellings, not APIs: `transpose-as-inverse` (GEO204),
`directions-through-products` (GEO101), `monogram-compose` (GEO202) and `monogram-apply` (GEO201);
`spellings.py` beside this file writes them and says what each generates.

A call is written the way code resolved by its imports calls it: `import <module>` then
`<module>.<function>(...)` or `<module>.<Class>.<static method>(...)`, a constructor as
`<module>.<Class>(...)`, and an instance method through an object made by the class's constructor
(`obj = <module>.<Class>(...)`, `obj.<method>(...)`). A name in a private module is spelled through
the public re-export the stubs declare (`scipy.spatial.transform.Rotation`), and the methods of a
private `@any_receiver` mixin (recognised by name on any object) are called on a parameter `obj`.
Every other required parameter gets a plain name (a parameter of the case function); a `Literal`
parameter that picks the overload is given its literal when leaving it out would leave the overload
ambiguous. Before a case is kept, the knowledge base's own binder
(`geolint.knowledge.bind`) must match the call to overloads that all state the family's geometry for
the chosen parameter; an API that cannot be called so (its fact is only in version-pinned overloads,
its overloads stay ambiguous, a method missing from its stub...) is skipped, with the reason printed,
and counted neither caught nor missed.

    python benchmarks/shape_families/run.py                          # every family
    python benchmarks/shape_families/run.py --family quaternion-order --show-misses
    python benchmarks/shape_families/run.py --markdown /tmp/families.md --keep /tmp/cases

The exit status is 0 whatever the linter finds (findings are data); it is 1 only when the linter
itself fails to run.
"""

from __future__ import annotations

import argparse
import ast
import json
import subprocess
import sys
import tempfile
import time
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache
from itertools import takewhile
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent
for folder in (REPO, HERE):  # geolint, and the families in the module beside this one
    if str(folder) not in sys.path:
        sys.path.insert(0, str(folder))

import spellings

from geolint import knowledge
from geolint.algebra import FREE, Kind
from geolint.knowledge import (
    RADIANS,
    SCALAR_FIRST,
    SCALAR_LAST,
    Api,
    Geometry,
    KnowledgeBase,
    Parameter,
    Signature,
)

BUG_MARK = "# bug"
SELECT = "GEO1,GEO2,GEO3"
OBJECT = "obj"  # the instance an instance method is called on
SOURCE = "source"  # the object a source attribute is read from
RESERVED = {"np", OBJECT, SOURCE, "case", "points"}


@dataclass(frozen=True)
class Slip:
    """What a family passes to the chosen parameter: the wrong value, the right one, and the names
    both read (parameters of the case function). A family with several sources of the wrong value labels
    each (`variant`); the value may need imports and lines before the call (`setup`). The twin may call
    another API beside the one of the bug (`twin_callee`, its last name) or add a keyword (`twin_keyword`)."""

    bug: str
    twin: str
    names: tuple[str, ...]
    variant: str = ""
    imports: tuple[str, ...] = ()
    setup: tuple[str, ...] = ()
    twin_callee: str | None = None
    twin_keyword: str | None = None


@dataclass(frozen=True)
class Family:
    name: str
    code: str  # the rule expected to catch the bug
    # the value a parameter's geometry asks for (RADIANS, an order), or None when the family skips it
    wanted: Callable[[Geometry], str | None] = lambda geometry: None
    slip: Callable[[str], Slip] | None = None  # from what the parameter asks for
    # several slips for one API: (what the parameter asks for, the knowledge base, the API) -> slips
    slips: Callable[[str, KnowledgeBase, Api, Parameter], list[Slip]] | None = None
    applies: Callable[[Signature], bool] = lambda signature: True  # the overloads the family is about
    # a family about spellings rather than APIs: its cases are written by `spellings`
    drafts: Callable[[KnowledgeBase], tuple[list[spellings.Draft], list[spellings.Dropped]]] | None = None


def _radians(geometry: Geometry) -> str | None:
    return geometry.angle_unit if geometry.angle_unit == RADIANS else None


def _degrees_slip(_unit: str) -> Slip:
    return Slip(bug="angle_deg", twin="np.radians(angle_deg)", names=("angle_deg",))


def _order(geometry: Geometry) -> str | None:
    return geometry.quaternion_order if geometry.quaternion_order in (SCALAR_FIRST, SCALAR_LAST) else None


def _spelled(order: str) -> str:
    return "np.array([" + ", ".join(f"q{letter}" for letter in order) + "])"


def _order_slip(order: str) -> Slip:
    other = SCALAR_LAST if order == SCALAR_FIRST else SCALAR_FIRST
    return Slip(bug=_spelled(other), twin=_spelled(order), names=("qw", "qx", "qy", "qz"))


@dataclass(frozen=True)
class Case:
    family: str
    api: str
    library: str  # the stubs/ folder the API comes from
    stem: str  # the file names: <stem>__bug.py and <stem>__twin.py
    bug: str  # module text
    twin: str
    bug_line: int  # 1-based: the line marked `# bug`
    variant: str = ""  # the slip's or spelling's label, when one API gives several cases

    @property
    def label(self) -> str:
        return f"{self.api} [{self.variant}]" if self.variant else self.api


@dataclass(frozen=True)
class Skipped:
    family: str
    api: str
    library: str
    reason: str
    variant: str = ""

    @property
    def label(self) -> str:
        return f"{self.api} [{self.variant}]" if self.variant else self.api


# the binder matches the call to overloads of which only some state the fact (they differ by a type)
AMBIGUOUS = "the binder matches overloads that do not all state it"


class Skip(Exception):
    """An API this generator cannot call reliably (the message says why)."""


# --- writing a call ---------------------------------------------------------------------------


def stub_folder(api: Api) -> str:
    return api.stub.partition("/")[0]


def stub_module(api: Api) -> str:
    """The module the API's stub describes: `pytransform3d/pytransform3d/rotations/__init__.pyi` ->
    `pytransform3d.rotations`."""
    parts = Path(api.stub).with_suffix("").parts[1:]
    if parts and parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


@cache
def _method_decorators(stub: str) -> dict[str, set[str]]:
    """`Class.method` (nested classes dotted) -> the decorators of its definitions in the stub."""
    tree = ast.parse((knowledge.stubs_folder() / stub).read_text(encoding="utf-8"))
    found: dict[str, set[str]] = {}

    def visit(body: list[ast.stmt], prefix: str) -> None:
        for statement in body:
            if isinstance(statement, ast.ClassDef):
                inner = f"{prefix}{statement.name}."
                for item in statement.body:
                    if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)):
                        names = {d.id if isinstance(d, ast.Name) else d.attr if isinstance(d, ast.Attribute) else "call" for d in item.decorator_list}
                        found.setdefault(inner + item.name, set()).update(names)
                visit(statement.body, inner)
            elif isinstance(statement, ast.If):
                visit(statement.body, prefix)
                visit(statement.orelse, prefix)

    visit(tree.body, "")
    return found


def _unversioned(api: Api) -> list[Signature]:
    """The overloads that hold whatever the version: the linter counts a `@versions` overload only when
    a project pins the library, and the generated cases pin nothing."""
    return [signature for signature in api.signatures if signature.versions is None]


def _is_required(parameter: Parameter) -> bool:
    return not parameter.has_default and not parameter.variadic


def _neutral(name: str, taken: set[str]) -> str:
    """A plain name for a filler argument: the parameter's own, unless it says a unit or an order (it
    would be evidence of its own) or is taken (an imported module, the family's names)."""
    lowered = name.lower()
    if any(word in lowered for word in ("deg", "rad", "wxyz", "xyzw")):
        name = "value"
    chosen, number = name, 1
    while chosen in taken:
        chosen, number = f"{name}_{number}", number + 1
    return chosen


def _arguments(
    signature: Signature, target: Parameter | None, value: str, literals: bool, taken: set[str]
) -> tuple[list[str], list[str]]:
    """The argument list of a call to `signature` (`value` for `target`) and the plain names it reads.
    Required parameters get plain names; `Literal[...]` parameters get their first literal when they have
    no default, or when `literals` is set (to pin the overload); the rest are left out."""
    given: dict[str, str] = {}
    names: list[str] = []
    for parameter in signature.parameters:
        if parameter is target:
            given[parameter.name] = value
        elif parameter.literal is not None and (literals or not parameter.has_default):
            given[parameter.name] = repr(parameter.literal[0])
        elif _is_required(parameter):
            name = _neutral(parameter.name, taken | set(names))
            given[parameter.name] = name
            names.append(name)
    positional: list[str] = []
    keywords: list[str] = []
    in_prefix = True  # by position while no parameter before has been left out
    for parameter in signature.parameters:
        text = given.get(parameter.name)
        if text is None or parameter.variadic:
            in_prefix = False
        elif parameter.literal is not None and parameter.keyword:
            keywords.append(f"{parameter.name}={text}")  # `degrees=False` reads better than a bare `False`
            in_prefix = False
        elif parameter.positional and in_prefix:
            positional.append(text)
        elif parameter.keyword:
            keywords.append(f"{parameter.name}={text}")
        else:
            raise Skip(f"positional-only parameter `{parameter.name}` after one left out")
    return positional + keywords, names


def _binds_to(api: Api, call: str, target: str, value: str, family: Family, wanted: str) -> bool:
    """Whether the knowledge base's binder matches `call` to overloads that all give `value` to
    `target` and state `wanted` for it."""
    node = ast.parse(call, mode="eval").body
    assert isinstance(node, ast.Call)
    bounds = knowledge.bind(api, node)
    if not bounds:
        return False
    for bound in bounds:
        given = bound.arguments.get(target)
        parameter = bound.signature.parameter(target)
        if given is None or ast.unparse(given) != ast.unparse(ast.parse(value, mode="eval").body):
            return False
        if parameter is None or parameter.geometry is None or family.wanted(parameter.geometry) != wanted:
            return False
    return True


@dataclass
class _Shape:
    """How the API is reached: the module to import, the dotted path from it, and for a method called
    on an object, the class that object is made from (or None: any object, named `obj`)."""

    module: str
    path: str  # `func`, `Class`, `Class.method`
    instance: bool = False
    owner: Api | None = None  # the class an instance method's object is made from


def _private(dotted: str) -> bool:
    return any(part.startswith("_") and not part.startswith("__") for part in dotted.split("."))


def _public_spelling(kb: KnowledgeBase, api: Api, module: str, path: str) -> tuple[str, str]:
    """(module, path) as code imports them: through a re-export of the stubs (`scipy.spatial.transform.
    Rotation` for `scipy.spatial.transform._rotation.Rotation`) when the stub's module or class is private
    and a public name resolves to the same API; else as the stub has it."""
    if not _private(module) and not _private(path):
        return module, path
    parts = path.split(".")
    found = []
    for library in kb.libraries.values():
        for alias, target in library.aliases.items():
            if _private(alias):
                continue
            for count in range(1, len(parts) + 1):
                if target == ".".join([module, *parts[:count]]):
                    public_module, _, name = alias.rpartition(".")
                    public_path = ".".join([name, *parts[count:]])
                    resolved = kb.api(f"{public_module}.{public_path}")
                    if public_module and resolved is not None and resolved.qualified_name == api.qualified_name:
                        found.append((public_module, public_path))
    return min(found, key=lambda spelled: (len(".".join(spelled)), spelled)) if found else (module, path)


def _shape(kb: KnowledgeBase, api: Api) -> _Shape:
    module = stub_module(api)
    if not module or not api.qualified_name.startswith(module + "."):
        raise Skip(f"its name is outside its stub's module `{module}`")
    path = api.qualified_name[len(module) + 1 :]
    if api.is_attribute:
        raise Skip("an attribute: read, not called")
    if "." not in path or api.is_class:
        return _Shape(*_public_spelling(kb, api, module, path))
    owner_path, _, method = path.rpartition(".")
    owner = kb.api(f"{module}.{owner_path}")
    if owner is None or not owner.is_class:
        raise Skip(f"`{owner_path}` is no class of the knowledge base")
    decorators = _method_decorators(api.stub).get(path)
    if decorators is None:
        raise Skip("the method is not defined in its stub's class body")
    if decorators & {"staticmethod", "classmethod"}:
        return _Shape(*_public_spelling(kb, api, module, path))
    if api.receiver is not None and _private(owner_path):
        # a private mixin whose methods are recognised by name on any object (`@any_receiver`): code
        # calls them on the objects it is handed, in a module that imports the library's public package
        public = ".".join(takewhile(lambda part: not part.startswith("_"), module.split(".")))
        return _Shape(public, method, instance=True, owner=None)
    public_module, public_owner = _public_spelling(kb, owner, module, owner_path)
    return _Shape(public_module, f"{public_owner}.{method}", instance=True, owner=owner)


def _constructor(owner: Api, taken: set[str]) -> tuple[str, list[str]]:
    """The arguments of the simplest constructor call of `owner`: the unversioned overload with the
    fewest required parameters and no required `Literal`."""
    signatures = _unversioned(owner)
    usable = [s for s in signatures if not any(p.literal is not None and not p.has_default for p in s.parameters)]
    if owner.signatures and not usable:
        raise Skip("no constructor overload to make the object with")
    if not usable:
        return "", []
    signature = min(usable, key=lambda s: sum(_is_required(p) for p in s.parameters))
    arguments, names = _arguments(signature, None, "", literals=False, taken=taken)
    return ", ".join(arguments), names


def _slips(kb: KnowledgeBase, family: Family, api: Api, wanted: str, target: Parameter) -> list[Slip]:
    if family.slips is not None:
        return family.slips(wanted, kb, api, target)
    return [family.slip(wanted)] if family.slip is not None else []


def build_cases(kb: KnowledgeBase, family: Family, api: Api) -> tuple[list[Case], list[Skipped]]:
    """The bug and twin modules of `family` for `api`, one per slip the family has for it; the slips no
    call can be written for are skipped, with the reason."""
    candidates = [
        (signature, parameter, wanted)
        for signature in _unversioned(api)
        if family.applies(signature)
        for parameter in signature.parameters
        if parameter.geometry is not None and (wanted := family.wanted(parameter.geometry)) is not None
    ]
    if not candidates:
        raise Skip("stated only in version-pinned overloads (the cases pin no versions)")
    shape = _shape(kb, api)
    variants = [slip.variant for slip in _slips(kb, family, api, candidates[0][2], candidates[0][1])]
    if not variants:
        raise Skip("the knowledge base states no source of the other value")
    cases: list[Case] = []
    skipped: list[Skipped] = []
    for variant in variants:
        reason = "no call binds to overloads that all state it"
        for signature, target, wanted in candidates:
            slip = next((slip for slip in _slips(kb, family, api, wanted, target) if slip.variant == variant), None)
            if slip is None:
                continue
            try:
                cases.append(_build(kb, family, api, shape, signature, target, wanted, slip))
                break
            except Skip as skip:
                reason = str(skip)
        else:
            skipped.append(Skipped(family.name, api.qualified_name, stub_folder(api), reason, variant))
    return cases, skipped


def _build(kb: KnowledgeBase, family: Family, api: Api, shape: _Shape, signature: Signature, target: Parameter, wanted: str, slip: Slip) -> Case:
    top = shape.module.partition(".")[0]
    taken = RESERVED | {top} | set(slip.names)
    setup = "".join(f"    {line}\n" for line in slip.setup)
    names: list[str] = []
    if shape.owner is not None:  # an object made by its class's constructor
        owner_path, _, method = shape.path.rpartition(".")
        constructor_arguments, names = _constructor(shape.owner, taken)
        setup += f"    {OBJECT} = {shape.module}.{owner_path}({constructor_arguments})\n"
        callee = f"{OBJECT}.{method}"
    elif shape.instance:  # any object: a parameter of the case function
        names = [OBJECT]
        callee = f"{OBJECT}.{shape.path}"
    else:
        callee = f"{shape.module}.{shape.path}"
    twin_callee, twin_api = callee, api
    if slip.twin_callee is not None:
        twin_callee = f"{callee.rpartition('.')[0]}.{slip.twin_callee}"
        twin_api = kb.api(f"{api.qualified_name.rpartition('.')[0]}.{slip.twin_callee}")  # type: ignore[assignment]
        if twin_api is None:
            raise Skip(f"`{slip.twin_callee}` is not in the knowledge base")
    reason = "no call binds to overloads that all state it"
    for literals in (False, True):
        try:
            bug_arguments, call_names = _arguments(signature, target, slip.bug, literals, taken | set(names))
            twin_arguments, _ = _arguments(signature, target, slip.twin, literals, taken | set(names))
        except Skip as skipped:
            reason = str(skipped)
            break
        if slip.twin_keyword is not None:
            twin_arguments = [*twin_arguments, slip.twin_keyword]
        bug_call = f"{callee}({', '.join(bug_arguments)})"
        twin_call = f"{twin_callee}({', '.join(twin_arguments)})"
        if not _binds_to(api, bug_call, target.name, slip.bug, family, wanted):
            if knowledge.bind(api, ast.parse(bug_call, mode="eval").body):  # type: ignore[arg-type]
                reason = AMBIGUOUS
            continue
        if twin_api is api and slip.twin_keyword is None:
            if not _binds_to(api, twin_call, target.name, slip.twin, family, wanted):
                continue
        elif not knowledge.bind(twin_api, ast.parse(twin_call, mode="eval").body):  # type: ignore[arg-type]
            continue  # the twin's API or keyword binds, whatever it states
        parameters = list(dict.fromkeys([*slip.names, *names, *call_names]))
        return _case(family, api, shape.module, setup, parameters, bug_call, twin_call, slip.variant, slip.imports)
    raise Skip(reason)


def _case(
    family: Family, api: Api, module: str, setup: str, parameters: list[str], bug_call: str, twin_call: str,
    variant: str = "", imports: tuple[str, ...] = (),
) -> Case:  # fmt: skip
    lines = list(dict.fromkeys(["import numpy as np", *imports, f"import {module}"]))
    head = (
        f'"""Generated by benchmarks/shape_families/run.py: {family.name}, `{api.qualified_name}`{_variant_note(variant)}."""\n\n'
        + "\n".join(lines)
        + f"\n\n\ndef case({', '.join(parameters)}):\n{setup}"
    )
    bug = f"{head}    return {bug_call}  {BUG_MARK}\n"
    twin = f"{head}    return {twin_call}\n"
    return _checked(family, api.qualified_name, stub_folder(api), variant, bug, twin, head.count("\n") + 1)


def _variant_note(variant: str) -> str:
    return f" ({variant})" if variant else ""


def _checked(family: Family, name: str, library: str, variant: str, bug: str, twin: str, bug_line: int) -> Case:
    for text in (bug, twin):
        ast.parse(text)  # a generated case is valid Python, or the generator is wrong
    label = f"{name}__{variant}" if variant else name
    stem = f"{family.name}__{''.join(c if c.isalnum() or c == '_' else '-' for c in label)}"  # no dots: one suffix per file name
    return Case(family.name, name, library, stem, bug, twin, bug_line, variant)


def _drafted(family: Family, draft: spellings.Draft) -> Case:
    """A spelling family's draft as the two modules."""
    head = (
        f'"""Generated by benchmarks/shape_families/run.py: {family.name}, `{draft.api}`{_variant_note(draft.variant)}."""\n\n'
        + "\n".join(draft.imports)
        + f"\n\n\ndef case({', '.join(draft.parameters)}):\n"
        + "".join(f"    {line}\n" for line in draft.before)
    )
    tail = "".join(f"    {line}\n" for line in draft.after)
    bug = f"{head}    {draft.bug}  {BUG_MARK}\n{tail}"
    twin = f"{head}    {draft.twin}\n{tail}"
    return _checked(family, draft.api, draft.library, draft.variant, bug, twin, head.count("\n") + 1)


def targets(family: Family, kb: KnowledgeBase) -> list[Api]:
    """The APIs with a parameter whose geometry asks for what the family gets wrong (any overload the
    family is about); none for a spelling family."""
    if family.drafts is not None:
        return []
    return sorted(
        (
            api
            for api in kb.apis()
            if any(
                p.geometry is not None and family.wanted(p.geometry) is not None
                for s in api.signatures
                if family.applies(s)
                for p in s.parameters
            )
        ),
        key=lambda api: api.qualified_name,
    )


def generate(family: Family, kb: KnowledgeBase | None = None) -> tuple[list[Case], list[Skipped]]:
    kb = kb or knowledge.knowledge_base()
    cases: list[Case] = []
    skipped: list[Skipped] = []
    stems: set[str] = set()
    found: list[Case] = []
    if family.drafts is not None:
        drafts, dropped = family.drafts(kb)
        found = [_drafted(family, draft) for draft in drafts]
        skipped += [Skipped(family.name, item.api, item.library, item.reason) for item in dropped]
    for api in targets(family, kb):
        try:
            built, left_out = build_cases(kb, family, api)
        except Skip as reason:
            skipped.append(Skipped(family.name, api.qualified_name, stub_folder(api), str(reason)))
            continue
        found += built
        skipped += left_out
    for case in found:
        if case.stem in stems:
            skipped.append(Skipped(family.name, case.api, case.library, "its file name repeats another case's", case.variant))
            continue
        stems.add(case.stem)
        cases.append(case)
    return cases, skipped


# --- the families about poses and directions an API is given ------------------------------------

DIRECTION_NAMES = ("normals", "normal", "direction")  # what GEO101 reads as directions by name


def _moved_as_point(geometry: Geometry) -> str | None:
    return "point" if geometry.kind is Kind.POINT else None


def _applies_transform(signature: Signature) -> bool:
    return signature.applies_transform


def _moves_as_free(signature: Signature, name: str) -> bool:
    parameter = signature.parameter(name)
    return parameter is not None and parameter.geometry is not None and parameter.geometry.kind in FREE


def _free_at(signature: Signature, position: int) -> bool:
    return position < len(signature.parameters) and _moves_as_free(signature, signature.parameters[position].name)


def _direction_twin(kb: KnowledgeBase, api: Api, target: Parameter) -> dict[str, str]:
    """How the stubs say to move a direction through this API: the one literal keyword that picks an
    overload moving the parameter as a vector (`translate=False`), or the API beside it (same owner, the
    argument in the same place, the same parameter name if several) that moves it so (`transform_normals`);
    {} when they state neither."""
    for signature in _unversioned(api):
        if not _moves_as_free(signature, target.name):
            continue
        choices = [p for p in signature.parameters if p.literal is not None and p.keyword]
        if len(choices) == 1 and len(choices[0].literal or ()) == 1:
            return {"twin_keyword": f"{choices[0].name}={choices[0].literal[0]!r}"}  # type: ignore[index]
    owner = api.qualified_name.rpartition(".")[0]
    position = next(
        (s.parameters.index(target) for s in _unversioned(api) if target in s.parameters), 0
    )  # fmt: skip
    beside = [
        other
        for other in kb.apis()
        if other is not api and other.qualified_name.rpartition(".")[0] == owner
        and any(_free_at(signature, position) for signature in _unversioned(other))
    ]  # fmt: skip
    if len(beside) > 1:
        beside = [other for other in beside if any(_moves_as_free(signature, target.name) for signature in _unversioned(other))]
    return {"twin_callee": beside[0].qualified_name.rpartition(".")[2]} if len(beside) == 1 else {}


def _direction_slips(_wanted: str, kb: KnowledgeBase, api: Api, target: Parameter) -> list[Slip]:
    """A direction by each name the rule reads; the twin moves it the way the stub states (its keyword
    or the API beside it), or, where the stub states no way, gives the API what it moves: `points`."""
    twin = _direction_twin(kb, api, target)
    return [
        Slip(bug=name, twin=name if twin else "points", names=(name,) if twin else (name, "points"), variant=name, **twin)  # type: ignore[arg-type]
        for name in DIRECTION_NAMES
    ]


def _pose_direction(geometry: Geometry) -> str | None:
    """`w2c` / `c2w` for a transform the stub states between the camera and the world."""
    if geometry.kind is not Kind.TRANSFORM:
        return None
    directions: dict[tuple[str, ...], str] = {("camera", "world"): "w2c", ("world", "camera"): "c2w"}
    return directions.get(geometry.frames)


# Names that say a pose's direction in the word, as GEO209 reads them (its docs): the other direction's
POSE_NAMES = {
    "c2w": ("c2w", "cam2world", "camera_to_world", "world_from_cam", "Twc", "T_world_cam"),
    "w2c": ("w2c", "world2cam", "world_to_camera", "cam_from_world", "Tcw", "T_cam_world"),
}


def reach(kb: KnowledgeBase, api: Api, taken: set[str], depth: int = 0) -> tuple[tuple[str, ...], tuple[str, ...], str, tuple[str, ...]]:
    """How code reads an attribute the stubs state: (imports, setup lines, expression, parameters).
    A module's attribute by its name (`bpy.context`); a public class's through an object made by its
    constructor; a private class's through the attribute of another that holds one (`bpy.context.scene.
    camera.matrix_world`, the stubs' `type_name`)."""
    if not api.is_attribute or depth > 6:
        raise Skip("a source that is not an attribute")
    owner_name, _, attribute = api.qualified_name.rpartition(".")
    owner = kb.api(owner_name)
    if owner is None:
        if kb.library_of_module(owner_name) is None:
            raise Skip(f"`{owner_name}` is neither a module nor a class of the knowledge base")
        return (f"import {owner_name}",), (), api.qualified_name, ()
    if not owner.is_class:
        raise Skip(f"`{owner_name}` is no class")
    if not _private(owner_name):
        module = stub_module(owner)
        module, path = _public_spelling(kb, owner, module, owner_name[len(module) + 1 :])
        arguments, made_from = _constructor(owner, taken)
        return (f"import {module}",), (f"{SOURCE} = {module}.{path}({arguments})",), f"{SOURCE}.{attribute}", tuple(made_from)
    holders = [
        other
        for other in kb.apis()
        if other.is_attribute and any(s.returns is not None and s.returns.type_name == owner_name for s in _unversioned(other))
    ]
    if len(holders) != 1:
        raise Skip(f"the private class `{owner_name}` is held by {len(holders)} attributes")
    imports, setup, expression, names = reach(kb, holders[0], taken, depth + 1)
    return imports, setup, f"{expression}.{attribute}", names


def _returned(api: Api) -> Geometry | None:
    returns = {s.returns for s in _unversioned(api) if s.returns is not None}
    return returns.pop() if len(returns) == 1 else None


def _extrinsics_slips(wanted: str, kb: KnowledgeBase, api: Api, _target: Parameter) -> list[Slip]:
    """The other direction, from each name that states it and each attribute whose stub returns it;
    the twin is its inverse."""
    other = "c2w" if wanted == "w2c" else "w2c"
    slips = [Slip(bug=name, twin=f"np.linalg.inv({name})", names=(name,), variant=name) for name in POSE_NAMES[other]]
    for source in sorted(kb.apis(), key=lambda a: a.qualified_name):
        returned = _returned(source)
        if returned is None or _pose_direction(returned) != other:
            continue
        try:
            imports, setup, expression, names = reach(kb, source, RESERVED | set(api.qualified_name.split(".")))
        except Skip:
            continue
        value = f"np.asarray({expression})"
        slips.append(Slip(bug=value, twin=f"np.linalg.inv({value})", names=names, variant=source.qualified_name, imports=imports, setup=setup))
    return slips


# The camera axes that point the other way between two conventions (markers.CameraAxes: OpenCV x right,
# y down, z forward; OpenGL x right, y up, z back; PyTorch3D x left, y up, z forward), as the diagonal
# that flips them.
FLIPS = {
    frozenset({"opencv", "opengl"}): "np.diag([1, -1, -1, 1])",
    frozenset({"opencv", "pytorch3d"}): "np.diag([-1, -1, 1, 1])",
    frozenset({"opengl", "pytorch3d"}): "np.diag([-1, 1, -1, 1])",
}


# The words a name states camera axes with (GEO216's docs: `c2w_opengl`, `w2c_cv`)
AXES_WORDS = {"opencv": ("opencv", "cv"), "opengl": ("opengl", "gl"), "pytorch3d": ("pytorch3d", "p3d")}


def _axes_of(geometry: Geometry) -> str | None:
    """`opencv:camera,world`: a pose's stated camera axes and frames."""
    if geometry.kind is not Kind.TRANSFORM or geometry.camera_axes is None or "camera" not in geometry.frames:
        return None
    return f"{geometry.camera_axes}:{','.join(geometry.frames)}"


def _axes_slips(wanted: str, kb: KnowledgeBase, api: Api, _target: Parameter) -> list[Slip]:
    """A pose in other camera axes, named so (`w2c_gl`) and from each attribute whose stub states them,
    turned to the sink's direction (inverted when the camera is on the other side); the twin flips the
    axes on the camera's side first (`w2c_gl` -> `np.diag([1, -1, -1, 1]) @ w2c_gl`)."""
    axes, frames = wanted.split(":")
    camera_at = frames.split(",").index("camera")
    slips = []
    direction = "c2w" if camera_at == 1 else "w2c"
    for other, words in AXES_WORDS.items():  # a name that states other axes, as GEO216 reads them
        if other == axes:
            continue
        flip = FLIPS[frozenset({axes, other})]
        for word in words:
            name = f"{direction}_{word}"
            twin = f"{name} @ {flip}" if camera_at == 1 else f"{flip} @ {name}"
            slips.append(Slip(bug=name, twin=twin, names=(name,), variant=name))
    for source in sorted(kb.apis(), key=lambda a: a.qualified_name):
        returned = _returned(source)
        stated = _axes_of(returned) if returned is not None else None
        if stated is None or stated.startswith(axes + ":"):
            continue
        source_axes = stated.partition(":")[0]
        flip = FLIPS[frozenset({axes, source_axes})]
        try:
            imports, setup, expression, names = reach(kb, source, RESERVED | set(api.qualified_name.split(".")))
        except Skip:
            continue
        value = f"np.asarray({expression})"
        flipped = f"{value} @ {flip}" if returned.frames.index("camera") == 1 else f"{flip} @ {value}"  # type: ignore[union-attr]
        bug, twin = value, flipped
        if returned.frames.index("camera") != camera_at:  # type: ignore[union-attr]
            bug, twin = f"np.linalg.inv({value})", f"np.linalg.inv({flipped})"
        slips.append(Slip(bug=bug, twin=twin, names=names, variant=source.qualified_name, imports=imports, setup=setup))
    return slips


FAMILIES = {
    family.name: family
    for family in (
        Family("degrees-on-radian-apis", "GEO302", _radians, _degrees_slip),
        Family("quaternion-order", "GEO301", _order, _order_slip),
        Family("transpose-as-inverse", "GEO204", drafts=spellings.transpose_drafts),
        Family("directions-through-products", "GEO101", drafts=spellings.direction_product_drafts),
        Family("directions-through-point-apis", "GEO101", _moved_as_point, slips=_direction_slips, applies=_applies_transform),
        Family("extrinsics-direction", "GEO209", _pose_direction, slips=_extrinsics_slips),
        Family("camera-axes", "GEO216", _axes_of, slips=_axes_slips),
        Family("monogram-compose", "GEO202", drafts=spellings.monogram_compose_drafts),
        Family("monogram-apply", "GEO201", drafts=spellings.monogram_apply_drafts),
    )
}


# --- running and scoring ----------------------------------------------------------------------


def write_cases(cases: list[Case], folder: Path) -> None:
    for case in cases:
        (folder / f"{case.stem}__bug.py").write_text(case.bug, encoding="utf-8")
        (folder / f"{case.stem}__twin.py").write_text(case.twin, encoding="utf-8")


def run_linter(folder: Path) -> tuple[list[dict[str, object]], list[str]]:
    """The CLI's JSON findings over `folder`, and the command that produced them."""
    command = [sys.executable, "-m", "geolint", "check", "--no-cache", "--format", "json", "--select", SELECT, str(folder)]
    # run from the cases' folder: no configuration of this repository applies to them
    result = subprocess.run(command, cwd=folder, capture_output=True, text=True, check=False)
    if result.returncode not in (0, 1):
        raise RuntimeError(f"geolint exited {result.returncode}:\n{result.stderr[-4000:]}")
    return json.loads(result.stdout or "[]"), command


@dataclass
class Score:
    family: str
    code: str
    cases: int = 0
    caught: int = 0
    twins_flagged: int = 0
    skipped: int = 0
    missed: list[str] = field(default_factory=list)
    flagged: list[str] = field(default_factory=list)

    @property
    def percent(self) -> float:
        return 100.0 * self.caught / self.cases if self.cases else 0.0


def score(family: Family, cases: list[Case], skipped: list[Skipped], findings: list[dict[str, object]]) -> Score:
    """Bugs caught (a finding of the family's code on the `# bug` line) and twins flagged (any finding
    of that code), by file name: findings are matched on their path's last part."""
    lines: dict[str, set[int]] = {}
    for finding in findings:
        if finding.get("code") == family.code:
            lines.setdefault(Path(str(finding["path"])).name, set()).add(int(finding["line"]))  # type: ignore[call-overload]
    result = Score(family.name, family.code, cases=len(cases), skipped=len(skipped))
    for case in cases:
        if case.bug_line in lines.get(f"{case.stem}__bug.py", set()):
            result.caught += 1
        else:
            result.missed.append(case.label)
        if lines.get(f"{case.stem}__twin.py"):
            result.twins_flagged += 1
            result.flagged.append(case.label)
    return result


def table(scores: list[Score], markdown: bool = False) -> str:
    header = ["family", "rule", "cases", "caught", "caught %", "twins flagged", "skipped"]
    rows = [[s.family, s.code, str(s.cases), str(s.caught), f"{s.percent:.1f}", str(s.twins_flagged), str(s.skipped)] for s in scores]
    if markdown:
        lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
        return "\n".join(lines + ["| " + " | ".join(row) + " |" for row in rows]) + "\n"
    widths = [max(len(row[i]) for row in [header, *rows]) for i in range(len(header))]

    def render(row: list[str]) -> str:  # the family left-aligned, the figures right-aligned
        return "  ".join(cell.ljust(width) if i == 0 else cell.rjust(width) for i, (cell, width) in enumerate(zip(row, widths)))

    return "\n".join([render(header), render(["-" * width for width in widths]), *map(render, rows)]) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--family", choices=sorted(FAMILIES), help="run one family only")
    parser.add_argument("--show-misses", action="store_true", help="list the APIs missed, the twins flagged and the skipped APIs")
    parser.add_argument("--markdown", metavar="FILE", type=Path, help="also write the table as Markdown to FILE")
    parser.add_argument("--keep", metavar="DIR", type=Path, help="write the cases to DIR (kept) instead of a temporary folder")
    args = parser.parse_args(argv)

    families = [FAMILIES[args.family]] if args.family else list(FAMILIES.values())
    kb = knowledge.knowledge_base()
    generated = {family.name: generate(family, kb) for family in families}
    with tempfile.TemporaryDirectory(prefix="shape_families_") as temporary:
        folder = args.keep or Path(temporary)
        folder.mkdir(parents=True, exist_ok=True)
        for cases, _ in generated.values():
            write_cases(cases, folder)
        started = time.perf_counter()
        try:
            findings, command = run_linter(folder)
        except RuntimeError as error:
            print(error, file=sys.stderr)
            return 1
        elapsed = time.perf_counter() - started
    scores = [score(family, *generated[family.name], findings) for family in families]

    files = 2 * sum(len(cases) for cases, _ in generated.values())
    print(f"$ {' '.join(['python', *command[1:-1], str(folder)])}")
    print(f"{files} files linted in {elapsed:.1f} s\n")
    print(table(scores), end="")
    for family in families:
        skipped = generated[family.name][1]
        if skipped:
            print(f"\n{family.name}: skipped {len(skipped)}")
            for reason, count in Counter(item.reason for item in skipped).most_common():
                print(f"  {count:4d}  {reason}")
    if args.show_misses:
        for result, family in zip(scores, families):
            print(f"\n{result.family} ({result.code}): {len(result.missed)} missed")
            for name in result.missed:
                print(f"  missed   {name}")
            for name in result.flagged:
                print(f"  flagged  {name}  (twin)")
            for item in generated[family.name][1]:
                print(f"  skipped  {item.label}: {item.reason}")
    if args.markdown:
        args.markdown.write_text(table(scores, markdown=True), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
