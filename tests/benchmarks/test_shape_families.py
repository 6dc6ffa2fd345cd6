"""The shape-family generator and scorer (benchmarks/shape_families/run.py), without running the linter:
what it writes is valid, marked and twinned as the benchmark says, and a finding counts where it lands."""

from __future__ import annotations

import ast
import importlib.util
import sys
from pathlib import Path
from types import ModuleType

import pytest

SCRIPT = Path(__file__).resolve().parents[2] / "benchmarks" / "shape_families" / "run.py"


def load() -> ModuleType:
    spec = importlib.util.spec_from_file_location("shape_families_run", SCRIPT)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up while the class is made
    spec.loader.exec_module(module)
    return module


run = load()
FAMILY_NAMES = sorted(run.FAMILIES)
API_FAMILIES = [name for name in FAMILY_NAMES if run.FAMILIES[name].drafts is None]  # cases per API, not per spelling
NEW_FAMILIES = [name for name in FAMILY_NAMES if name not in ("degrees-on-radian-apis", "quaternion-order")]


@pytest.fixture(scope="module")
def generated() -> dict[str, tuple[list, list]]:
    kb = run.knowledge.knowledge_base()
    return {name: run.generate(run.FAMILIES[name], kb) for name in FAMILY_NAMES}


@pytest.mark.parametrize("name", FAMILY_NAMES)
def test_every_generated_module_parses(generated: dict[str, tuple[list, list]], name: str) -> None:
    cases, _ = generated[name]
    assert cases
    for case in cases:
        ast.parse(case.bug, f"{case.stem}__bug.py")
        ast.parse(case.twin, f"{case.stem}__twin.py")


@pytest.mark.parametrize("name", FAMILY_NAMES)
def test_every_bug_has_one_marked_line_and_the_twin_differs_only_there(generated: dict[str, tuple[list, list]], name: str) -> None:
    cases, _ = generated[name]
    for case in cases:
        bug, twin = case.bug.splitlines(), case.twin.splitlines()
        marked = [number for number, line in enumerate(bug, 1) if line.rstrip().endswith(run.BUG_MARK)]
        assert marked == [case.bug_line], case.api
        assert run.BUG_MARK not in case.twin, case.api
        assert len(bug) == len(twin), case.api
        differing = [number for number, (a, b) in enumerate(zip(bug, twin), 1) if a != b]
        assert differing == [case.bug_line], case.api


@pytest.mark.parametrize("name", API_FAMILIES)
def test_every_library_with_such_an_api_has_a_case(generated: dict[str, tuple[list, list]], name: str) -> None:
    """Per stubs/ folder, at least one case, where the fact holds unpinned: an API stated only in
    `@versions` overloads holds for no project that pins nothing, as the generated cases do, so a folder
    whose every such API is versioned (kornia's) is only skipped, with that reason."""
    family = run.FAMILIES[name]
    cases, skipped = generated[name]
    apis = run.targets(family, run.knowledge.knowledge_base())
    unpinned = {
        run.stub_folder(api)
        for api in apis
        if any(p.geometry is not None and family.wanted(p.geometry) is not None for s in run._unversioned(api) if family.applies(s) for p in s.parameters)
    }
    ambiguous = {item.library for item in skipped if item.reason == run.AMBIGUOUS} - {
        item.library for item in skipped if item.reason != run.AMBIGUOUS
    }  # only overloads the binder cannot choose between (`Frame * Vector` and `Frame * Frame`)
    assert unpinned - {case.library for case in cases} - ambiguous == set()
    assert {case.api for case in cases} | {item.api for item in skipped} == {api.qualified_name for api in apis}
    assert len({case.stem for case in cases}) == len(cases)


def test_every_array_operation_the_stubs_state_is_spelled() -> None:
    """The spelling families come from the knowledge base: each transpose function of an array library is a
    transpose case, each matrix product a product case, each import of a monogram library a monogram case."""
    kb = run.knowledge.knowledge_base()
    stated: dict[str, set[str]] = {}
    for api in kb.apis():
        if kb.libraries[api.library].array_library:
            for signature in api.signatures:
                if signature.returns is not None and signature.returns.array_operation is not None:
                    stated.setdefault(signature.returns.array_operation, set()).add(api.qualified_name)
    transposes, _ = run.generate(run.FAMILIES["transpose-as-inverse"], kb)
    products, _ = run.generate(run.FAMILIES["directions-through-products"], kb)
    assert stated["transpose"] and stated["transpose"] <= {case.api for case in transposes}
    assert stated["matmul"] | stated["einsum"] <= {case.api for case in products}
    for name in ("monogram-compose", "monogram-apply"):
        cases, _ = run.generate(run.FAMILIES[name], kb)
        for package in kb.monogram_packages():
            assert any(f"import {package}" in case.bug for case in cases), (name, package)


def test_the_direction_twins_use_what_the_stub_states() -> None:
    """A point-moving API with a direction API beside it (pytorch3d's `transform_normals`) or a keyword that
    picks one (trimesh's `translate=False`) has its twin written with it."""
    kb = run.knowledge.knowledge_base()
    family = run.FAMILIES["directions-through-point-apis"]
    ways: set[str] = set()
    for case in run.generate(family, kb)[0]:
        api = kb.api(case.api)
        target = next(p for s in run._unversioned(api) if family.applies(s) for p in s.parameters if p.geometry is not None and family.wanted(p.geometry))
        twin = run._direction_twin(kb, api, target)
        ways.update(twin)
        line, bug_line = case.twin.splitlines()[case.bug_line - 1], case.bug.splitlines()[case.bug_line - 1]
        if twin:
            assert (twin.get("twin_callee") or twin.get("twin_keyword")) in line, case.label
        else:  # the stub states no way: the twin gives the API points instead of the direction
            assert line.count("points") == bug_line.count("points") + 1 and case.variant not in line.split("(", 1)[1], case.label
    assert ways == {"twin_callee", "twin_keyword"}  # both ways the stubs state are found


@pytest.mark.parametrize("name", NEW_FAMILIES)
def test_a_few_cases_of_each_new_family_run_through_the_linter(tmp_path: Path, name: str) -> None:
    """Three cases of the family (the first, middle and last generated) linted by the real CLI and scored:
    every case is caught or missed, and no correct twin has a finding of the family's rule."""
    family = run.FAMILIES[name]
    cases, _ = run.generate(family, run.knowledge.knowledge_base())
    sample = list({id(case): case for case in (cases[0], cases[len(cases) // 2], cases[-1])}.values())
    run.write_cases(sample, tmp_path)
    findings, _ = run.run_linter(tmp_path)
    result = run.score(family, sample, [], findings)
    assert result.cases == len(sample) == result.caught + len(result.missed)
    assert result.twins_flagged == 0, result.flagged
    on_bug_lines = {
        case.label
        for case in sample
        for finding in findings
        if finding["code"] == family.code and Path(str(finding["path"])).name == f"{case.stem}__bug.py" and finding["line"] == case.bug_line
    }
    assert on_bug_lines == {case.label for case in sample} - set(result.missed)


def test_a_finding_on_the_bug_line_is_caught_and_one_elsewhere_is_not() -> None:
    family = run.FAMILIES["degrees-on-radian-apis"]

    def case(api: str) -> object:
        stem = f"{family.name}__{api}"
        return run.Case(family.name, api, "lib", stem, "bug text", "twin text", bug_line=7)

    cases = [case("on_line"), case("elsewhere"), case("other_code"), case("flagged_twin")]
    findings = [
        {"path": f"/tmp/x/{family.name}__on_line__bug.py", "line": 7, "code": family.code},
        {"path": f"/tmp/x/{family.name}__elsewhere__bug.py", "line": 6, "code": family.code},
        {"path": f"/tmp/x/{family.name}__other_code__bug.py", "line": 7, "code": "GEO301"},
        {"path": f"/tmp/x/{family.name}__flagged_twin__bug.py", "line": 7, "code": family.code},
        {"path": f"/tmp/x/{family.name}__flagged_twin__twin.py", "line": 3, "code": family.code},
        {"path": f"/tmp/x/{family.name}__on_line__twin.py", "line": 7, "code": "GEO301"},  # another rule: no false positive
    ]
    skipped = [run.Skipped(family.name, "left_out", "lib", "a reason")]
    result = run.score(family, cases, skipped, findings)
    assert (result.cases, result.caught, result.twins_flagged, result.skipped) == (4, 2, 1, 1)
    assert result.missed == ["elsewhere", "other_code"]
    assert result.flagged == ["flagged_twin"]
    assert "caught %" in run.table([result]) and "| degrees-on-radian-apis | GEO302 | 4 | 2 | 50.0 | 1 | 1 |" in run.table([result], markdown=True)


def test_the_documented_commands_run(tmp_path: Path) -> None:
    """docs/benchmark.md's commands as written (the folder `--keep` writes to pointed here): each prints its table."""
    import subprocess

    from tests.cli.doc_snippets import block, commands_of

    commands = commands_of(block("docs/benchmark.md", "Shape families: the knowledge base, API by API", 0).body)
    assert [command.split()[:2] for command in commands] == [["python", "benchmarks/shape_families/run.py"]] * 2
    for line in commands:
        words = line.split("  #", 1)[0].split()
        words = [str(tmp_path / "cases") if word == "/tmp/cases" else word for word in words]
        done = subprocess.run([sys.executable, *words[1:]], cwd=SCRIPT.parents[2], capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, done.stderr[-2000:]
        assert "quaternion-order" in done.stdout and "caught" in done.stdout
    assert any((tmp_path / "cases").rglob("*__bug.py"))
