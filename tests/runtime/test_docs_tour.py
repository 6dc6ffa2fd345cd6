"""The tour in docs/runtime.md (also the README's) runs, and the results it shows are what it prints.

The tour is a Python prompt session, so doctest checks every shown result, the intentional
errors included (tests/cli/test_doc_snippets.py runs the README's copy the same way).
"""

from __future__ import annotations

import doctest
import re
from pathlib import Path

import geolint

DOC = Path(geolint.__file__).resolve().parent.parent / "docs" / "runtime.md"


def test_the_tour_runs_as_documented() -> None:
    block = re.search(r"## Tour\n\n(?:.*\n\n)?```pycon\n(.*?)```", DOC.read_text(), re.S)
    assert block, "docs/runtime.md lost its tour"
    test = doctest.DocTestParser().get_doctest(block.group(1), {}, "tour", str(DOC), 0)
    runner = doctest.DocTestRunner()
    runner.run(test)
    assert runner.summarize(verbose=False) == doctest.TestResults(failed=0, attempted=19)
    assert "FrameMismatchError: Transform[World <- Tool] applied to Point[camera_optical]" in block.group(1)
