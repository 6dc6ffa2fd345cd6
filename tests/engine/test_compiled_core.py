"""The optional compiled build (mypyc, `GEOLINT_MYPYC=1`; geolint/_build.py): its modules type-check
cleanly, and the wheel it builds finds what pure Python finds and documents the rules the same way."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

import pytest

import geolint
from geolint._build import compiled_sources

PACKAGE = Path(geolint.__file__).parent
PROJECT = PACKAGE.parent
FIXTURES = PROJECT / "fixtures"


def test_the_readme_builds_it_the_way_the_test_does():
    """The README's command and the wheel the slow test builds use the same switch and flag (the test
    builds a wheel rather than installing over the environment it runs in), and the README installs
    first what a build without isolation needs: the build system's requirements, mypy (mypyc), and the
    project's dependencies, which mypy must find to type-check the compiled modules."""
    from tests.cli.doc_snippets import block, commands_of

    prepare, command = commands_of(block("README.md", "Compiled build (optional, about a quarter faster).").body)
    assert command.split("  #")[0].split() == ["GEOLINT_MYPYC=1", "pip", "install", "--no-build-isolation", "."]
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover
        import tomli as tomllib
    with open(PROJECT / "pyproject.toml", "rb") as stream:
        pyproject = tomllib.load(stream)
    needed = [*pyproject["build-system"]["requires"], "mypy"]
    needed += [r for r in pyproject["project"]["dependencies"] if ";" not in r]  # tomli: only below 3.11
    installed = prepare.split()
    assert installed[:2] == ["pip", "install"]
    named = {word.strip("'\"").split(">")[0].split("=")[0].split("<")[0] for word in installed[2:]}
    assert {r.split(">")[0].split("=")[0].split("<")[0] for r in needed} <= named, installed


@pytest.mark.slow  # mypy over the whole package; the wheel build checks the compiled part too
def test_the_package_type_checks_cleanly():
    """mypyc refuses a compiled module, or any module it imports, that mypy does not accept, and
    checks the annotations at run time; the rest of the package is held to the same standard."""
    sources = compiled_sources(PACKAGE)
    assert PACKAGE / "factbase" / "model.py" in sources and PACKAGE / "rules" / "base.py" not in sources
    result = subprocess.run(
        [sys.executable, "-m", "mypy", "--no-incremental", "-p", "geolint"], capture_output=True, text=True, check=False, cwd=PROJECT
    )
    assert result.returncode == 0, result.stdout + result.stderr


# Kept as `ast.List`...: read bare, they look like typing's names.
_SPELLED_WITH_AST = frozenset({"List", "Tuple", "Dict", "Set"})


def test_the_compiled_modules_name_node_classes_without_a_module_lookup():
    """mypyc compiles `ast.Name` into a lookup on the `ast` module at every use (7% of the compiled
    run's instructions before the node classes were imported by name), so compiled modules import
    them: `from ast import Call, Name`. Annotations are never evaluated and may say either."""
    import ast

    node_classes = {name for name in dir(ast) if name[:1].isupper() and isinstance(getattr(ast, name), type)}
    offenders = []
    for path in compiled_sources(PACKAGE):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        annotations = {
            id(inner)
            for node in ast.walk(tree)
            for annotation in _annotations_of(node)
            for inner in ast.walk(annotation)
        }
        offenders += [
            f"{path.relative_to(PROJECT)}:{node.lineno} ast.{node.attr}"
            for node in ast.walk(tree)
            if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == "ast"
            and node.attr in node_classes and node.attr not in _SPELLED_WITH_AST and id(node) not in annotations
        ]
    assert not offenders, offenders[:20]


def _annotations_of(node: object) -> list:
    import ast

    if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
        arguments = node.args
        every = [*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs, arguments.vararg, arguments.kwarg]
        return [a.annotation for a in every if a is not None and a.annotation is not None] + ([node.returns] if node.returns else [])
    if isinstance(node, ast.AnnAssign):
        return [node.annotation]
    return []


def _geolint(site: Path | None, *arguments: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    """The CLI from the unpacked wheel at `site`, or (None) from the installed pure-Python package."""
    env = {**os.environ, "GEOLINT_CACHE_DIR": str(cwd / ".geolint-cache")}
    if site is not None:
        env["PYTHONPATH"] = str(site)
    return subprocess.run([sys.executable, "-m", "geolint", *arguments], capture_output=True, text=True, check=False, env=env, cwd=cwd)


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("cc") is None and shutil.which("gcc") is None, reason="no C compiler")
@pytest.mark.skipif(not (Path(sysconfig.get_paths()["include"]) / "Python.h").is_file(), reason="no Python headers")
def test_the_compiled_wheel_finds_what_pure_python_finds(tmp_path):
    pytest.importorskip("mypyc")
    source = tmp_path / "source"  # a clean copy: no stale build/ or egg-info of the editable install
    shutil.copytree(PROJECT, source, ignore=shutil.ignore_patterns(".*", "build", "*.egg-info", "__pycache__", "*.so", "tests", "docs", "benchmarks"))
    build = subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "-q", "--no-build-isolation", "--no-deps", "-w", str(tmp_path / "wheel"), str(source)],
        capture_output=True, text=True, check=False, env={**os.environ, "GEOLINT_MYPYC": "1"},
    )  # fmt: skip
    assert build.returncode == 0, build.stdout[-3000:] + build.stderr[-3000:]
    site = tmp_path / "site"
    with zipfile.ZipFile(next((tmp_path / "wheel").glob("*.whl"))) as wheel:
        wheel.extractall(site)
    assert len(list((site / "geolint" / "factbase").glob("model.*.so"))) == 1

    assert "(compiled)" in _geolint(site, "--version", cwd=tmp_path).stdout
    assert "(compiled)" not in _geolint(None, "--version", cwd=tmp_path).stdout
    check = ("check", "--no-cache", "--exit-zero", "--format", "json", "--jobs", "1", str(FIXTURES))
    compiled, pure = _geolint(site, *check, cwd=tmp_path), _geolint(None, *check, cwd=tmp_path)
    assert "internal error" not in compiled.stderr, compiled.stderr
    assert compiled.stdout == pure.stdout and len(pure.stdout) > 1000
    # mypyc drops class docstrings: the docs are read from the sources the wheel ships
    compiled_doc, pure_doc = (_geolint(site, "rule", "GEO201", cwd=tmp_path).stdout, _geolint(None, "rule", "GEO201", cwd=tmp_path).stdout)
    assert compiled_doc == pure_doc and "## Options" in pure_doc
