"""The base class of the semantic rules: a `Rule` that sees the module's shared `SemanticModel`.

Rules declare `SemanticFactsProvider` as metadata, so the facts are computed once per file by
libcst's metadata machinery, and read `self.model` (memoised per config) in their visitors.
"""

from __future__ import annotations

import libcst as cst
from libcst.metadata import PositionProvider

from geolint.rules.base import Rule
from geolint.semantic.facts import SemanticFactsProvider
from geolint.semantic.model import SemanticModel, model_for


class SemanticRule(Rule):
    """A rule that reasons with the semantic model (set up when the module is entered)."""

    METADATA_DEPENDENCIES = (PositionProvider, SemanticFactsProvider)

    model: SemanticModel

    def visit_Module(self, node: cst.Module) -> None:
        facts = self.get_metadata(SemanticFactsProvider, node)
        self.model = model_for(facts, self.context.config)

    def report(self, node: cst.CSTNode, message: str, **fix: object) -> None:  # type: ignore[override]
        """Report, except inside `with pytest.raises(...)`: code written to fail is not a bug."""
        if self.model.expects_failure(node):
            return
        super().report(node, message, **fix)  # type: ignore[arg-type]

    def code_of(self, node: cst.CSTNode) -> str:
        """The source text of a node, for messages."""
        return self.model.facts.module.code_for_node(node).strip()


def keyword_arg(keyword: str, value: str) -> cst.Arg:
    """`keyword=value` formatted the PEP 8 way (libcst's default puts spaces around `=`)."""
    no_space = cst.SimpleWhitespace("")
    return cst.Arg(
        keyword=cst.Name(keyword),
        value=cst.parse_expression(value),
        equal=cst.AssignEqual(whitespace_before=no_space, whitespace_after=no_space),
    )
