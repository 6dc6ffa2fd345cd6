"""The angle-unit findings GEO302 (degrees as radians) and GEO305 (radians as degrees) share: a
conversion of a value already in the unit it converts into, and a project helper handed an angle
in the unit it does not read. The units themselves come from `geolint.factbase.angle_units`."""

from __future__ import annotations

import ast
from ast import BinOp, Call, Div, Mult

from geolint.factbase.angle_units import DEGREES, RADIANS, AngleUnits, unit_word
from geolint.factbase.helper_units import helper_reads
from geolint.factbase.model import FactBase


def report_hand_conversion_of_converted(rule, node: BinOp, into: str, units: AngleUnits) -> None:  # type: ignore[no-untyped-def]
    """`yaw * 180 / np.pi` (into degrees) or `yaw * np.pi / 180` (into radians) written by hand, of a
    value already in that unit: the twin of `np.degrees(yaw_deg)` / `np.radians(yaw)`."""
    if not isinstance(node.op, (Mult, Div)):
        return
    converted = units.converts_by_hand(node)
    if converted is not None and converted[0] == into:
        report_conversion_of_converted(rule, node, rule.code_of(node), converted[1], into, units)


def report_conversion_of_converted(rule, node: ast.expr, conversion: str, argument: ast.expr, into: str, units: AngleUnits) -> None:  # type: ignore[no-untyped-def]
    """`conversion` (into unit `into`, `np.radians(x)` or `x * 180 / pi`) applied to `argument`, reported
    on `rule` (GEO302, GEO305) when the argument is already in that unit."""
    unit = units.unit_of(argument)
    if unit is None or unit.unit != into:
        return
    rule.report(
        node,
        f"`{conversion}` converts {unit_word(RADIANS if into == DEGREES else DEGREES)} to {unit_word(into)}, but "
        f"`{rule.code_of(argument)}` is already in {unit_word(into)} ({unit.evidence})",
        replacement=rule.facts.index.segment(argument) or None,
        applicability="unsafe",
        fix_description="drop the conversion",
        evidence=(unit.evidence,),
    )


def wrong_unit_passed(
    facts: FactBase, call: Call, read: str, units: AngleUnits
) -> tuple[ast.expr, str, tuple[str, str]] | None:
    """The first argument of a call to a project helper that reads `read` (`helper_reads`) whose
    value is in the other unit: (argument, message, evidence). A name against a name is too weak."""
    given = RADIANS if read == DEGREES else DEGREES
    for argument, how, by_name in helper_reads(facts, call, read, units):
        unit = units.unit_of(argument)
        if unit is not None and unit.unit == given and not (by_name and unit.by_name):
            message = f"{how}, but `{facts.code_of(argument)}` is in {unit_word(given)} ({unit.evidence})"
            return argument, message, (how, unit.evidence)
    return None
