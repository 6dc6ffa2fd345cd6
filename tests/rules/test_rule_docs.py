"""Every rule documents itself in ruff's sections, and the CLI prints those docs."""

from __future__ import annotations

import inspect
import re
import subprocess
import sys

import pytest

from geolint.rules import all_rules

SECTIONS = ("What it does", "Why is this bad?", "Example", "Use instead", "Fix safety")
GEOLINT = [sys.executable, "-m", "geolint"]


@pytest.mark.parametrize("rule", all_rules(), ids=lambda rule: rule.code)
def test_doc_has_every_section(rule) -> None:
    doc = inspect.getdoc(rule) or ""
    headings = re.findall(r"^## (.+)$", doc, flags=re.MULTILINE)
    missing = [section for section in SECTIONS if section not in headings]
    assert not missing, f"{rule.code} doc lacks {missing}"
    assert doc.splitlines()[0].strip(), f"{rule.code} doc needs a one-line summary"


@pytest.mark.parametrize("rule", all_rules(), ids=lambda rule: rule.code)
def test_code_and_name_shape(rule) -> None:
    assert re.fullmatch(r"GEO\d{3}", rule.code)
    assert re.fullmatch(r"[a-z]+(-[a-z]+)*", rule.name)


def test_issue_3_codes_and_names_are_the_public_contract() -> None:
    contract = {
        "GEO101": "direction-translated",
        "GEO102": "point-not-translated",
        "GEO103": "point-plus-point",
        "GEO104": "normals-left-behind",
        "GEO201": "frame-mismatch-apply",
        "GEO202": "frame-mismatch-compose",
        "GEO203": "frame-mismatch-assign",
        "GEO204": "transpose-as-inverse",
        "GEO301": "quaternion-order",
        "GEO302": "degrees-as-radians",
    }
    registered = {rule.code: rule.name for rule in all_rules()}
    assert {code: registered.get(code) for code in contract} == contract


def test_cli_prints_rule_docs_and_list() -> None:
    shown = subprocess.run([*GEOLINT, "rule", "GEO101"], capture_output=True, text=True, check=True).stdout
    for section in SECTIONS:
        assert section in shown
    listed = subprocess.run([*GEOLINT, "rules"], capture_output=True, text=True, check=True).stdout
    for rule in all_rules():
        assert rule.code in listed and rule.name in listed
