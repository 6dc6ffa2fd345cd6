"""Shape families about generic operators rather than one API each: transpose spellings (GEO204),
directions through matrix products (GEO101) and Drake's monogram names (GEO202, GEO201).

Each generator writes `Draft`s (a case before `run.py` turns it into two module texts) from what the
knowledge base says: which libraries are array namespaces and which of their functions transpose,
invert, multiply or contract matrices (`ArrayOperation` markers), and which libraries name frames in
monogram notation (METADATA.toml's `frame_naming`). What the stubs do not state is listed here, named
as such: the array objects' own transpose spellings (`.T`, `.mT`, `.permute(...)`), each library's
concatenation that appends w, and Drake's `multiply` and `inverse` methods (its stub has no
RigidTransform).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from geolint.knowledge import KnowledgeBase

TRANSPOSE, INVERSE, MATMUL, EINSUM = "transpose", "inverse", "matmul", "einsum"


@dataclass(frozen=True)
class Draft:
    """One case before it is written: the lines both modules share and the one line where they differ."""

    api: str  # what is measured: a function of the knowledge base or a spelling
    library: str  # the stubs/ folder the fact comes from
    variant: str  # the context or spelling, when one API gives several cases
    imports: tuple[str, ...]
    parameters: tuple[str, ...]
    bug: str  # the bug line's statement, without indentation
    twin: str
    before: tuple[str, ...] = ()
    after: tuple[str, ...] = ()


@dataclass(frozen=True)
class Dropped:
    api: str
    library: str
    reason: str


@dataclass(frozen=True)
class Namespace:
    """An array library's namespace as code spells it, and its functions by what they do to matrices."""

    library: str
    module: str  # `numpy`, `jax.numpy`
    alias: str  # `np`, `jnp`, or the module itself (`torch`)
    functions: dict[str, list[str]]  # ArrayOperation value -> qualified names
    required: dict[str, int]  # qualified name -> required positional parameters (beyond the array)

    @property
    def imports(self) -> tuple[str, ...]:
        return (f"import {self.module}" if self.alias == self.module else f"import {self.module} as {self.alias}",)

    def spelled(self, qualified: str) -> str:
        """`numpy.linalg.inv` -> `np.linalg.inv`: as code that imports the namespace calls it."""
        return self.alias + qualified[len(self.module) :] if qualified.startswith(self.module + ".") else qualified


def namespaces(kb: KnowledgeBase) -> list[Namespace]:
    """Every array library of the knowledge base (METADATA.toml's `array_library`) with array operations:
    the shortest module holding them, spelled by the conventional local name the library states for it."""
    found: dict[str, dict[str, list[str]]] = {}
    required: dict[str, int] = {}
    for api in kb.apis():
        operations = {s.returns.array_operation for s in api.signatures if s.returns is not None}
        if len(operations) != 1 or None in operations:
            continue
        found.setdefault(api.library, {}).setdefault(operations.pop(), []).append(api.qualified_name)  # type: ignore[arg-type]
        signature = api.signatures[0]
        required[api.qualified_name] = sum(1 for p in signature.parameters[1:] if p.positional and not p.has_default and not p.variadic)
    result = []
    for library, functions in sorted(found.items()):
        if not kb.libraries[library].array_library:
            continue  # a library with a few array functions beside others (scipy.linalg) is no namespace
        modules = {name.rpartition(".")[0] for names in functions.values() for name in names}
        module = min(modules, key=lambda m: (m.count("."), m))
        aliases = sorted(alias for alias, target in kb.libraries[library].conventional_modules.items() if target == module)
        alias = aliases[0] if aliases else module
        result.append(Namespace(library, module, alias, {op: sorted(names) for op, names in functions.items()}, required))
    return result


def _inverse(space: Namespace) -> str | None:
    """The namespace's matrix inverse: the function named `inv` if it has one, else its first."""
    names = space.functions.get(INVERSE, [])
    named = [name for name in names if name.endswith(".inv")]
    return space.spelled((named or names)[0]) if names else None


def _call(space: Namespace, qualified: str, array: str) -> str:
    """A call of a transpose function on a matrix: the axes it requires are the last two. A variadic
    `swapaxes` (numpy's stub states `*args`) is given them too: numpy requires both."""
    axes = space.required.get(qualified, 0)
    if axes == 0 and qualified.endswith(".swapaxes"):
        axes = 2
    arguments = [array, *["-2", "-1"][:axes]]
    return f"{space.spelled(qualified)}({', '.join(arguments)})"


# Transposes spelled on the array object: no stub states an array's attributes or methods, so this is
# the list of each library's documented spellings (the array classes of numpy, CuPy and jax share
# numpy's; tf.Tensor has none).
ARRAY_TRANSPOSES = {
    "numpy": ("{}.T", "{}.mT", "{}.transpose()", "{}.swapaxes(-2, -1)"),
    "cupy": ("{}.T", "{}.mT", "{}.transpose()", "{}.swapaxes(-2, -1)"),
    "jax": ("{}.T", "{}.mT", "{}.transpose()", "{}.swapaxes(-2, -1)"),
    "torch": ("{}.T", "{}.mT", "{}.t()", "{}.transpose(-2, -1)", "{}.transpose(0, 1)", "{}.permute(1, 0)", "{}.swapaxes(-2, -1)"),
    "tensorflow": (),
}

_POSE = "T_world_cam"


def transpose_drafts(kb: KnowledgeBase) -> tuple[list[Draft], list[Dropped]]:
    """GEO204: for every array namespace, each transpose it has (its stub's `ArrayOperation.TRANSPOSE`
    functions, and the array object's spellings) of a 4x4 pose used as its inverse, applied to a
    homogeneous point or stored under the inverse's name; the twin uses the namespace's inverse. And after
    each import of a monogram-named library, Drake's `X_BW = X_WB.T` (the twin: `X_WB.inverse()`)."""
    drafts: list[Draft] = []
    dropped: list[Dropped] = []
    for space in namespaces(kb):
        spellings = [(name, _call(space, name, _POSE)) for name in space.functions.get(TRANSPOSE, [])]
        spellings += [(f"{space.module} array {pattern.format('x')}", pattern.format(_POSE)) for pattern in ARRAY_TRANSPOSES.get(space.library, ())]
        inverse = _inverse(space)
        if inverse is None:
            dropped += [Dropped(label, space.library, "the namespace has no inverse in the knowledge base for the twin") for label, _ in spellings]
            continue
        for label, spelled in spellings:
            twin = f"{inverse}({_POSE})"
            drafts.append(Draft(label, space.library, "applied", space.imports, (_POSE, "p_world_h"), f"return {spelled} @ p_world_h", f"return {twin} @ p_world_h"))
            drafts.append(Draft(label, space.library, "stored", space.imports, (_POSE,), f"T_cam_world = {spelled}", f"T_cam_world = {twin}", after=("return T_cam_world",)))
    for library, statement in _monogram_imports(kb):  # Drake's poses: `X_WB.T` is no `X_BW`
        for label, bug, twin in MONOGRAM_TRANSPOSES:
            drafts.append(Draft(label, library, statement.removeprefix("import "), (statement,), ("X_WB", "p_WQ"), bug, twin, after=("return X_BW @ p_WQ",)))
    return drafts, dropped


# Drake's RigidTransform used through its transpose (`.T` as numpy's; `inverse()` is Drake's)
MONOGRAM_TRANSPOSES = (("X_BW = X_WB.T", "X_BW = X_WB.T", "X_BW = X_WB.inverse()"),)


# Appending w to an (n, 3) array, per library: no stub states the concatenations.
_APPEND_W = {
    "numpy": "{ns}.concatenate([normals, {ns}.{w}s_like(normals[..., :1])], axis=-1)",
    "cupy": "{ns}.concatenate([normals, {ns}.{w}s_like(normals[..., :1])], axis=-1)",
    "jax": "{ns}.concatenate([normals, {ns}.{w}s_like(normals[..., :1])], axis=-1)",
    "torch": "{ns}.cat([normals, {ns}.{w}s_like(normals[..., :1])], dim=-1)",
    "tensorflow": "{ns}.concat([normals, {ns}.{w}s_like(normals[..., :1])], axis=-1)",
}


def _products(space: Namespace, left: str, right: str, subscripts: str) -> list[tuple[str, str]]:
    """(label, text) for `left @ right` spelled by the operator and by each of the namespace's matrix
    products (`ArrayOperation.MATMUL`, `EINSUM` with `subscripts`)."""
    found = [(f"{space.module} @", f"{left} @ {right}")]
    found += [(name, f"{space.spelled(name)}({left}, {right})") for name in space.functions.get(MATMUL, [])]
    found += [(name, f'{space.spelled(name)}("{subscripts}", {left}, {right})') for name in space.functions.get(EINSUM, [])]
    return found


def direction_product_drafts(kb: KnowledgeBase) -> tuple[list[Draft], list[Dropped]]:
    """GEO101: for every array namespace and each product it spells, a direction moved by a full 4x4
    pose: rotated by its block and then translated (`R @ n + t`, one direction or a batch of them with an
    added axis; the twin without `+ t`), and made homogeneous with w = 1 before the product with the
    pose's transpose, of one pose or of a stack (its last two axes swapped by the namespace's own
    transpose function); the twin with w = 0."""
    drafts: list[Draft] = []
    dropped: list[Dropped] = []
    for space in namespaces(kb):
        ns = space.alias
        for label, rotated in _products(space, "T_world_obj[:3, :3]", "normal", "ij,j->i"):
            drafts.append(
                Draft(label, space.library, "rotated-then-translated", space.imports, ("T_world_obj", "normal"),
                      f"return {rotated} + T_world_obj[:3, 3]", f"return {rotated}")
            )  # fmt: skip
        for label, rotated in _products(space, "T_world_obj[..., :3, :3]", "normals[..., None]", "...ij,...jk->...ik"):
            drafts.append(
                Draft(label, space.library, "batched-rotated-then-translated", space.imports, ("T_world_obj", "normals"),
                      f"return ({rotated})[..., 0] + T_world_obj[..., :3, 3]", f"return ({rotated})[..., 0]")
            )  # fmt: skip
        pattern = _APPEND_W.get(space.library)
        products = _products(space, "normals_h", "T_world_obj.T", "ni,ij->nj")
        if pattern is None:
            dropped += [Dropped(label, space.library, "no concatenation known for this library") for label, _ in products]
            continue
        swap = _matrix_transpose(space)
        batched = _products(space, "normals_h", swap, "...ni,...ij->...nj") if swap is not None else []
        for variant, found in (("homogeneous-w1", products), ("batched-homogeneous-w1", batched)):
            for label, product in found:
                drafts.append(
                    Draft(label, space.library, variant, space.imports, ("T_world_obj", "normals"),
                          f"normals_h = {pattern.format(ns=ns, w='one')}", f"normals_h = {pattern.format(ns=ns, w='zero')}",
                          after=(f"return ({product})[..., :3]",))
                )  # fmt: skip
    return drafts, dropped


def _matrix_transpose(space: Namespace) -> str | None:
    """The namespace's transpose of the last two axes of a stack of poses: a function named for it
    (`matrix_transpose`, `swapaxes`), else one that takes the two axes (`torch.transpose`)."""
    names = space.functions.get(TRANSPOSE, [])
    for wanted in (".matrix_transpose", ".swapaxes"):
        for name in names:
            if name.endswith(wanted):
                return _call(space, name, "T_world_obj")
    taking_axes = [name for name in names if space.required.get(name, 0) == 2]
    return _call(space, taking_axes[0], "T_world_obj") if taking_axes else None


def _monogram_imports(kb: KnowledgeBase) -> list[tuple[str, str]]:
    """(library, import statement) for each module of each library named in monogram notation: the
    package itself and every module its stubs describe (`import pydrake`, `import pydrake.math`)."""
    found: set[tuple[str, str]] = set()
    for library in kb.libraries.values():
        if not set(library.packages) & set(kb.monogram_packages()):
            continue
        found.update((library.name, f"import {package}") for package in library.packages)
        for api in kb.apis():
            if api.library == library.name:
                parts = Path(api.stub).with_suffix("").parts[1:]
                parts = parts[:-1] if parts and parts[-1] == "__init__" else parts
                found.add((library.name, f"import {'.'.join(parts)}"))
    return sorted(found)


# Drake's spellings of a composition and of applying a pose or rotation (RigidTransform and
# RotationMatrix `@`, `multiply`, `inverse`; the stub lists no RigidTransform, so they are listed here):
# (label, bug, twin, parameters). `X_AB` is B's pose in A, `p_AQ` Q's position in A.
MONOGRAM_COMPOSE = (
    ("X_WB @ X_CG", "X_WB @ X_CG", "X_WB @ X_BG", ("X_WB", "X_CG", "X_BG")),
    ("X_WB.multiply(X_CG)", "X_WB.multiply(X_CG)", "X_WB.multiply(X_BG)", ("X_WB", "X_CG", "X_BG")),
    ("R_WB @ R_CG", "R_WB @ R_CG", "R_WB @ R_BG", ("R_WB", "R_CG", "R_BG")),
    ("R_WB.multiply(R_CG)", "R_WB.multiply(R_CG)", "R_WB.multiply(R_BG)", ("R_WB", "R_CG", "R_BG")),
    ("X_WB.inverse() @ X_CG", "X_WB.inverse() @ X_CG", "X_WB.inverse() @ X_WG", ("X_WB", "X_CG", "X_WG")),
)
MONOGRAM_APPLY = (
    ("X_WB @ p_CQ", "X_WB @ p_CQ", "X_WB @ p_BQ", ("X_WB", "p_CQ", "p_BQ")),
    ("X_WB.multiply(p_CQ)", "X_WB.multiply(p_CQ)", "X_WB.multiply(p_BQ)", ("X_WB", "p_CQ", "p_BQ")),
    ("R_WB @ p_CQ", "R_WB @ p_CQ", "R_WB @ p_BQ", ("R_WB", "p_CQ", "p_BQ")),
    ("X_WB.inverse() @ p_CQ", "X_WB.inverse() @ p_CQ", "X_WB.inverse() @ p_WQ", ("X_WB", "p_CQ", "p_WQ")),
)


def _monogram(kb: KnowledgeBase, spellings: tuple[tuple[str, str, str, tuple[str, ...]], ...]) -> tuple[list[Draft], list[Dropped]]:
    drafts = [
        Draft(label, library, statement.removeprefix("import "), (statement,), parameters, f"return {bug}", f"return {twin}")
        for library, statement in _monogram_imports(kb)
        for label, bug, twin, parameters in spellings
    ]
    return drafts, []


def monogram_compose_drafts(kb: KnowledgeBase) -> tuple[list[Draft], list[Dropped]]:
    """GEO202: after each import of a monogram-named library, a composition whose inner frames differ
    (`X_WB @ X_CG`); the twin composes `X_WB @ X_BG`."""
    return _monogram(kb, MONOGRAM_COMPOSE)


def monogram_apply_drafts(kb: KnowledgeBase) -> tuple[list[Draft], list[Dropped]]:
    """GEO201: after each import of a monogram-named library, a pose or rotation applied to a position
    measured in another frame (`X_WB @ p_CQ`); the twin applies it to `p_BQ`."""
    return _monogram(kb, MONOGRAM_APPLY)
