"""The layers import the right way round: files -> parse and index -> semantic names -> fact base ->
rules -> engine -> api -> cli / lsp. Read from the import statements of geolint's own files (those
inside functions included), so a lazy import cannot hide a dependency the wrong way."""

from __future__ import annotations

import ast
import re
from functools import lru_cache
from pathlib import Path

import geolint

PACKAGE = Path(geolint.__file__).parent


def _module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {_module_name(path): path for path in PACKAGE.rglob("*.py")}


def _type_checking_only(tree: ast.Module) -> set[int]:
    """The ids of the nodes under `if TYPE_CHECKING:`, which never run."""
    found: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and ast.unparse(node.test) in ("TYPE_CHECKING", "typing.TYPE_CHECKING"):
            found.update(id(inner) for statement in node.body for inner in ast.walk(statement))
    return found


def _imported(module: str, node: ast.Import | ast.ImportFrom) -> set[str]:
    """The geolint modules an import statement of `module` names (a `from pkg import name` names the
    submodule `pkg.name` when there is one, else `pkg`)."""
    if isinstance(node, ast.Import):
        targets = [alias.name for alias in node.names]
    else:
        base = node.module or ""
        if node.level:
            package = module.split(".") if MODULES[module].name == "__init__.py" else module.split(".")[:-1]
            package = package[: len(package) - node.level + 1]
            base = ".".join([*package, *([node.module] if node.module else [])])
        targets = [f"{base}.{alias.name}" if f"{base}.{alias.name}" in MODULES else base for alias in node.names]
    found = set()
    for target in targets:
        while target and target not in MODULES:
            target = target.rpartition(".")[0]
        if target and target != module:
            found.add(target)
    return found


@lru_cache(maxsize=None)
def _imports(run_time_only: bool) -> dict[str, set[str]]:
    """module -> the geolint modules it imports; `run_time_only` leaves out `if TYPE_CHECKING:` imports."""
    graph = {}
    for module, path in MODULES.items():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        skipped = _type_checking_only(tree) if run_time_only else set()
        graph[module] = {
            target
            for node in ast.walk(tree)
            if isinstance(node, (ast.Import, ast.ImportFrom)) and id(node) not in skipped
            for target in _imported(module, node)
        }
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[set[str]]:
    """The strongly connected components of more than one module (Tarjan's algorithm)."""
    index: dict[str, int] = {}
    lowlink: dict[str, int] = {}
    stack: list[str] = []
    found: list[set[str]] = []

    def visit(module: str) -> None:
        index[module] = lowlink[module] = len(index)
        stack.append(module)
        for target in graph[module]:
            if target not in index:
                visit(target)
                lowlink[module] = min(lowlink[module], lowlink[target])
            elif target in stack:
                lowlink[module] = min(lowlink[module], index[target])
        if lowlink[module] == index[module]:
            component = set()
            while True:
                member = stack.pop()
                component.add(member)
                if member == module:
                    break
            if len(component) > 1:
                found.append(component)

    for module in sorted(graph):
        if module not in index:
            visit(module)
    return found


def test_the_fact_base_and_the_semantic_model_never_import_the_rules() -> None:
    """Facts are answered below the rules that ask them: no import statement of a module of
    `geolint.factbase` or `geolint.semantic`, not even one inside a function or under TYPE_CHECKING,
    names `geolint.rules`."""
    offenders = sorted(
        f"{module} imports {target}"
        for module, targets in _imports(run_time_only=False).items()
        if module.startswith(("geolint.factbase", "geolint.semantic"))
        for target in targets
        if target == "geolint.rules" or target.startswith("geolint.rules.")
    )
    assert offenders == []


def test_no_import_cycle() -> None:
    """geolint's modules import each other without a cycle, counting every import that runs (function-level
    ones too; only TYPE_CHECKING imports, for annotations, are left out): a lazy import is for speed,
    never to hide a dependency the wrong way."""
    assert [sorted(cycle) for cycle in _cycles(_imports(run_time_only=True))] == []


def test_the_checks_read_the_real_edges() -> None:
    """The engine's function-level import of the fact base is an edge; bosdyn's TYPE_CHECKING import of
    `model` (for annotations) is one only when those are counted; a cycle of three is one component."""
    assert "geolint.factbase" in _imports(run_time_only=True)["geolint.engine"]
    assert "geolint.factbase.model" in _imports(run_time_only=False)["geolint.factbase.bosdyn"]
    assert "geolint.factbase.model" not in _imports(run_time_only=True)["geolint.factbase.bosdyn"]
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [{"a", "b", "c"}]


def test_the_architecture_section_names_modules_that_exist() -> None:
    """docs/linter.md's Architecture section (the layers' diagram and the fact base by question) names
    files that are there: a module moved or renamed must move in the page too."""
    page = (PACKAGE.parent / "docs" / "linter.md").read_text(encoding="utf-8")
    section = page.split("## Architecture", 1)[1].split("\n## ", 1)[0]
    named = set(re.findall(r"[\w/]+\.py", section))
    assert len(named) > 30
    missing = sorted(
        name
        for name in named
        if not any((folder / name).is_file() for folder in (PACKAGE, PACKAGE / "factbase", PACKAGE / "rules", PACKAGE.parent))
    )
    assert missing == []


# The analysis: what a new fact or rule is added to. Its functions stay small enough to read and
# its modules short enough to find one's way in (radon's cyclomatic complexity, as `radon cc`).
ANALYSIS = ("factbase", "rules", "semantic")
MOST_COMPLEX_BLOCK = 30
LONGEST_MODULE = 1000


def test_no_analysis_block_is_too_complex():
    from radon.complexity import cc_visit

    offenders = []
    for folder in ANALYSIS:
        for path in sorted((PACKAGE / folder).rglob("*.py")):
            for block in cc_visit(path.read_text(encoding="utf-8")):
                for inner in (block, *getattr(block, "methods", ()), *getattr(block, "closures", ())):
                    if inner.complexity > MOST_COMPLEX_BLOCK:
                        offenders.append(f"{path.relative_to(PACKAGE)}:{inner.lineno} {inner.name} ({inner.complexity})")
    assert not offenders, offenders


def test_no_analysis_module_is_too_long():
    lengths = {
        str(path.relative_to(PACKAGE)): len(path.read_text(encoding="utf-8").splitlines())
        for folder in ANALYSIS
        for path in (PACKAGE / folder).rglob("*.py")
    }
    assert all(length <= LONGEST_MODULE for length in lengths.values()), {p: n for p, n in lengths.items() if n > LONGEST_MODULE}
