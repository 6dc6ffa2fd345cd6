#!/usr/bin/env bash
# Runs the typing cases and fixtures under the LOWEST supported mypy (1.10.1) in a throwaway venv.
# The highest supported mypy is the dev venv's, exercised by `pytest tests/typing`.
# Usage: tests/typing/run_lowest_mypy.sh [python-with-numpy-trimesh-pytransform3d]   (default: the current python3)
set -euo pipefail
cd "$(dirname "$0")/../.."
PYTHON_WITH_PACKAGES="${1:-$(command -v python3)}"
VENV="${GEOLINT_LOWEST_MYPY_VENV:-${TMPDIR:-/tmp}/geolint-lowest-mypy}"
[ -x "$VENV/bin/mypy" ] || { python3 -m venv "$VENV" && "$VENV/bin/pip" install -q "mypy==${GEOLINT_LOWEST_MYPY_VERSION:-1.10.1}" numpy; }
"$VENV/bin/mypy" --version
# mypy imports the plugin from the checkout (importing geolint needs numpy); numpy & co. are read from the interpreter given above.
PYTHONPATH="$PWD" "$VENV/bin/python" -m pytest --version >/dev/null 2>&1 || "$VENV/bin/pip" install -q pytest
PYTHONPATH="$PWD" GEOLINT_TYPING_PYTHON="$PYTHON_WITH_PACKAGES" "$VENV/bin/python" -m pytest -q -p no:cacheprovider \
    --import-mode=importlib -o addopts="" tests/typing/test_plugin_cases.py
