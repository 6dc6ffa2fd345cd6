"""Library knowledge lives in stubs/: once a library has a folder there, the analysis code (rules, fact
base, semantic names, mypy plugin) must not name it in a table key or an import test (a word of a set of
name words, such as `tf` among `pose`, `transform`, `extrinsic`, is how variables are named, not a library). The modules that
still do are listed below, each with the stubbed packages it names; the list may only shrink (a pair
that disappears must be struck from it, so the ratchet stays tight)."""

from __future__ import annotations

import ast
from pathlib import Path

import geolint
from geolint.knowledge import knowledge_base

PACKAGE = Path(geolint.__file__).parent
ANALYSIS = ("rules", "factbase", "semantic", "mypy")

# module -> stubbed packages it still names in code (not in docstrings): what is left to move to stubs/. Empty:
# a library stubbed from now on is moved out of the analysis in the same change.
STILL_NAMED: dict[str, set[str]] = {}


def _docstrings(tree: ast.Module) -> set[int]:
    found = set()
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if isinstance(body, list) and body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
            found.add(id(body[0].value))
    return found


def _name_words(tree: ast.Module, packages: set[str]) -> set[int]:
    """The words of name vocabularies: the string members of a set literal of four or more identifier words
    with one stubbed import name among them, or one in ten at most (`{"pose", "transform", "tf", "extrinsic"}`:
    `tf` there is the abbreviation in variable names; `.numpy()` among `copy`, `clone`, `detach` a method). A
    table of module names is no such set."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Set) and all(isinstance(item, ast.Constant) and isinstance(item.value, str) for item in node.elts):
            words = [item.value for item in node.elts]  # type: ignore[attr-defined]
            named = sum(word in packages for word in words)
            if len(words) >= 4 and all(word.isidentifier() for word in words) and (named <= 1 or 10 * named <= len(words)):
                found.update(id(item) for item in node.elts)
    return found


def _named_packages() -> dict[str, set[str]]:
    """module -> the stubbed packages its string constants name (`"scipy.spatial..."`, `"tf"`), outside
    docstrings and name vocabularies."""
    packages = {package for library in knowledge_base().libraries.values() for package in library.packages}
    found: dict[str, set[str]] = {}
    for folder in ANALYSIS:
        for path in sorted((PACKAGE / folder).rglob("*.py")):
            tree = ast.parse(path.read_text(encoding="utf-8"))
            skipped = _docstrings(tree) | _name_words(tree, packages)
            for node in ast.walk(tree):
                if isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in skipped:
                    head = node.value.split(".")[0]
                    if head in packages:
                        found.setdefault(path.relative_to(PACKAGE).as_posix(), set()).add(head)
    return found


def _still_named() -> dict[str, set[str]]:
    return STILL_NAMED


def test_no_analysis_module_names_a_stubbed_library_anew() -> None:
    named = _named_packages()
    new = {module: packages - _still_named().get(module, set()) for module, packages in named.items()}
    assert {module: packages for module, packages in new.items() if packages} == {}, "library knowledge belongs in stubs/"


def test_the_list_of_what_is_left_only_shrinks() -> None:
    named = _named_packages()
    stale = {module: packages - named.get(module, set()) for module, packages in _still_named().items()}
    assert {module: packages for module, packages in stale.items() if packages} == {}, "strike these from STILL_NAMED"


def test_a_table_of_module_names_is_not_a_name_vocabulary() -> None:
    packages = {"numpy", "torch", "jax", "cupy", "tf"}
    words = ast.parse('WORDS = {"pose", "poses", "transform", "tf", "extrinsic"}\n')
    table = ast.parse('ROOTS = {"numpy", "torch", "jax", "cupy", "math", "os"}\n')
    assert len(_name_words(words, packages)) == 5
    assert _name_words(table, packages) == set()
