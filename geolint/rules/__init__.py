"""The rule registry: every `AstRule` or `Rule` subclass defined under `geolint/rules/<family>/geoNNN_*.py`.

Rules register by existing: adding a rule is adding a file, with no list to edit (a rule class
defined elsewhere registers once its module is imported, as the CLI tests' stand-in rules do).
"""

from __future__ import annotations

import importlib
import pkgutil
import sys
from functools import lru_cache
from typing import TYPE_CHECKING

from geolint.rules.base import AnyRule, AstRule, Invalid, RuleContext, Valid

if TYPE_CHECKING:
    from geolint.rules.cst_base import Rule

_CST_BASE = f"{__name__}.cst_base"

__all__ = ["AnyRule", "AstRule", "Invalid", "Rule", "RuleContext", "Valid", "all_rules", "rule_by_code"]


@lru_cache(maxsize=None)
def all_rules() -> tuple[AnyRule, ...]:
    """Every registered rule class (`AstRule`s and libcst `Rule`s), sorted by code."""
    for module in pkgutil.walk_packages(__path__, prefix=f"{__name__}."):
        if module.name != _CST_BASE:  # libcst is imported only by a rule that needs it
            importlib.import_module(module.name)
    found: dict[str, AnyRule] = {}
    pending: list[AnyRule] = list(AstRule.__subclasses__())
    cst_base = sys.modules.get(_CST_BASE)
    if cst_base is not None:
        pending += cst_base.Rule.__subclasses__()
    while pending:
        cls = pending.pop()
        pending.extend(cls.__subclasses__())
        if "code" in cls.__dict__:
            if cls.code in found and found[cls.code] is not cls:
                raise RuntimeError(f"two rules claim {cls.code}: {found[cls.code]} and {cls}")
            found[cls.code] = cls
    return tuple(found[code] for code in sorted(found))


def rule_by_code(code: str) -> AnyRule | None:
    """The rule with exactly this code (case-insensitive), or None."""
    code = code.upper()
    return next((rule for rule in all_rules() if rule.code == code), None)


def __getattr__(name: str) -> object:
    if name == "Rule":  # the libcst rule base, imported on first use
        from geolint.rules.cst_base import Rule

        return Rule
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
