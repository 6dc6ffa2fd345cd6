"""The rule registry: every `AstRule` subclass defined under `geolint/rules/<family>/geoNNN_*.py`.

Rules register by existing: adding a rule is adding a file, with no list to edit (a rule class
defined elsewhere registers once its module is imported, as the CLI tests' stand-in rules do).
"""

from __future__ import annotations

import importlib
import pkgutil
from functools import lru_cache

from geolint.rules.base import AstRule, Invalid, RuleContext, Valid

__all__ = ["AstRule", "Invalid", "RuleContext", "Valid", "all_rules", "rule_by_code"]


@lru_cache(maxsize=None)
def all_rules() -> tuple[type[AstRule], ...]:
    """Every registered rule class, sorted by code."""
    for module in pkgutil.walk_packages(__path__, prefix=f"{__name__}."):
        importlib.import_module(module.name)
    found: dict[str, type[AstRule]] = {}
    pending: list[type[AstRule]] = list(AstRule.__subclasses__())
    while pending:
        cls = pending.pop()
        pending.extend(cls.__subclasses__())
        if "code" in cls.__dict__:
            if cls.code in found and found[cls.code] is not cls:
                raise RuntimeError(f"two rules claim {cls.code}: {found[cls.code]} and {cls}")
            found[cls.code] = cls
    return tuple(found[code] for code in sorted(found))


def rule_by_code(code: str) -> type[AstRule] | None:
    """The rule with exactly this code (case-insensitive), or None."""
    code = code.upper()
    return next((rule for rule in all_rules() if rule.code == code), None)
