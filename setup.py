"""Builds the optional mypyc-compiled analysis when GEOLINT_MYPYC=1 (see geolint/_build.py);
otherwise everything comes from pyproject.toml and the build is pure Python."""

import os
import sys
from pathlib import Path

from setuptools import setup

ext_modules = []
if os.environ.get("GEOLINT_MYPYC") == "1":
    from mypyc.build import mypycify

    sys.path.insert(0, str(Path(__file__).parent))
    from geolint._build import compiled_sources

    package = Path(__file__).parent / "geolint"
    ext_modules = mypycify([str(path.relative_to(package.parent)) for path in compiled_sources(package)], opt_level="3")

setup(ext_modules=ext_modules)
