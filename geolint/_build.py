"""What the optional compiled build compiles with mypyc, and whether this install is that build.

The analysis (the fact base, the rules, names and the algebra) is plain, fully annotated Python;
mypyc compiles it to C extensions, the way black and mypy ship. Build it with a C compiler and mypy
in the environment:

    GEOLINT_MYPYC=1 python -m pip install --no-build-isolation .

Without `GEOLINT_MYPYC=1` the build is pure Python, and both give the same findings (a slow test
compares them). Left out: the rule base classes (the tests' stand-in rules subclass them, and a
compiled class cannot have interpreted subclasses) and modules that are not hot (the project's
declared versions, read once per project).
"""

from __future__ import annotations

from pathlib import Path

COMPILED_PACKAGES = ("factbase", "rules", "semantic")
COMPILED_FILES = ("algebra.py",)
INTERPRETED = frozenset({"__init__.py", "rules/base.py", "factbase/project_pins.py"})


def compiled_sources(package: Path) -> list[Path]:
    """The package's modules the compiled build compiles, in a stable order."""
    found = [package / name for name in COMPILED_FILES]
    for folder in COMPILED_PACKAGES:
        found += sorted((package / folder).rglob("*.py"))
    return [path for path in found if path.relative_to(package).as_posix() not in INTERPRETED and path.name != "__init__.py"]


def is_compiled() -> bool:
    """Whether the analysis runs compiled (its modules are extensions, not `.py` files); finds
    the module without importing it."""
    from importlib.util import find_spec

    spec = find_spec("geolint.factbase.model")
    return spec is not None and not (spec.origin or "").endswith(".py")
