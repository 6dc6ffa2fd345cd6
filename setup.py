"""Builds the optional mypyc-compiled analysis when GEOLINT_MYPYC=1 (see geolint/_build.py);
otherwise everything comes from pyproject.toml and the build is pure Python. Either way the
knowledge base's stubs (the top-level `stubs/`) ship inside the package as `geolint/_stubs`."""

import os
import shutil
import sys
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = Path(__file__).parent


class BuildWithStubs(build_py):
    """build_py, plus `stubs/` copied to `geolint/_stubs` (read by geolint.knowledge, never imported)."""

    def run(self) -> None:
        super().run()
        target = Path(self.build_lib) / "geolint" / "_stubs"
        shutil.copytree(HERE / "stubs", target, dirs_exist_ok=True, ignore=shutil.ignore_patterns("__pycache__"))


ext_modules = []
if os.environ.get("GEOLINT_MYPYC") == "1":
    from mypyc.build import mypycify

    sys.path.insert(0, str(HERE))
    from geolint._build import compiled_sources

    package = HERE / "geolint"
    ext_modules = mypycify([str(path.relative_to(package.parent)) for path in compiled_sources(package)], opt_level="3")

setup(ext_modules=ext_modules, cmdclass={"build_py": BuildWithStubs})
