"""The base of the rules that reason with the fact base, and the frame checks GEO201/GEO202 share."""

from __future__ import annotations

from ast import AST, BinOp, Call, Module, Mult
from typing import Callable, ClassVar, Final, NamedTuple, Sequence

from geolint.factbase.bosdyn import frame_comparison
from geolint.factbase.model import FactBase, FrameFact, MatMul
from geolint.factbase.vocabulary import GATE_TRIGGER
from geolint.lint_types import Applicability
from geolint.rules.base import AstRule, RuleTrigger
from geolint.semantic.names import NameFrames, same_frame


# How a rule compares two frames: `same_frame`, or the Spot SDK's with its role words (`bosdyn.frame_comparison`).
SameFrame = Callable[[str | None, str | None], bool | None]

# The `[tool.geolint]` table of examples whose frames rest on names alone: names are frame evidence
# only where the convention is stated (see geolint.factbase.conventions).
STATED: Final = {"naming": "dst-first"}

# The `## Options` section of every rule that reads frames from names (`documents_naming = True`; one text).
NAMING_OPTIONS: Final = """\
## Options
`naming = "auto" | "dst-first" | "src-first"` says how `T_a_b` / `R_a_b` read: dst-first maps b
into a, src-first (autolab_core's `T_obj_world`) maps a into b. With `"auto"` (the default) the
order is learned from the project: `from_frame=`/`to_frame=` declarations bound to such names,
then the consistency of its compositions; only what is wrong in every reading left open is
reported. A table of switches turns single conventions off; Drake's monogram names (`X_WB`,
`p_BQ`) are read only in projects that import pydrake unless `monogram = true` (elsewhere
`X_EQ` is a state vector), and there they are evidence on their own: the notation is the
library's documented convention, not a project's habit. `frame-aliases` declares synonyms
(cam = camera).

Names are frame evidence on their own only where the convention is **stated**: by
`naming = "dst-first"` or `"src-first"`, or by the project's own declarations, all in one order.
Elsewhere a finding needs an explicit declaration: `from_frame=`/`to_frame=`, `.as_frames(a, b)`,
tf2's `lookup_transform(target, source, t)`, pycolmap's `cam_from_world`, BOP's `cam_R_w2c`,
geolint's types (`T: TransformMatrix["world", "cam"]`, `p: Point[Camera]`)."""

class FactRule(AstRule):
    """An `AstRule` that reads the module's shared fact base (`self.facts`)."""

    needs_facts = True
    triggers: ClassVar[RuleTrigger | None] = GATE_TRIGGER
    # The module's fact base, set by `check` before `run`: an attribute, not a property reading
    # `self.context.facts`, since rules ask for it hundreds of thousands of times a run.
    facts: FactBase

    def check(self, tree: Module) -> None:
        facts = self.context.facts
        if facts is not None:
            self.facts = facts
            self.run()

    def run(self) -> None:
        raise NotImplementedError

    def report(
        self,
        node: AST,
        message: str,
        *,
        replacement: str | None = None,
        applicability: Applicability = "safe",
        fix_description: str = "",
        evidence: Sequence[str] = (),
        frames: tuple[str, str] | None = None,
    ) -> None:
        """Report, except inside `with pytest.raises(...)`: code written to fail is not a bug."""
        if self.facts.expects_failure(node):
            return
        super().report(
            node,
            message,
            replacement=replacement,
            applicability=applicability,
            fix_description=fix_description,
            evidence=evidence,
            frames=frames,
        )

    def code_of(self, node: AST) -> str:
        return self.facts.code_of(node)


def product_operands(facts: FactBase, node: AST, order: str) -> MatMul | None:
    """A matrix product in any spelling, plus `A * B` when the left operand is a transform
    (spatialmath `SE3 * SE3`, PyKDL `Frame * Vector`, autolab_core `RigidTransform * x`)."""
    product = facts.matmul(node)
    if product is not None:
        return product
    if isinstance(node, BinOp) and isinstance(node.op, Mult):
        left = facts.frames_of(node.left, order)
        if left is not None and left.is_operator and left.operator == "transform":
            return MatMul(node, node.left, node.right)
    return None


class Mismatch(NamedTuple):
    """What a frame check found: the message, and the frames that differ as (expected, found)."""

    message: str
    frames: tuple[str, str]


class ProductRule(FactRule):
    """A rule about products whose two operands both have known frames (GEO201, GEO202).

    `problem` says what is wrong with one reading of the names (or None); the rule reports only
    when every reading the project's naming order leaves open has a problem, with the first.
    Names on both sides are evidence only where the project states its convention
    (`FactBase.names_stated`); elsewhere one operand's frames must be declared.
    """

    def run(self) -> None:
        facts = self.facts
        for node in facts.index.nodes(BinOp, Call):
            found: list[tuple[Mismatch, tuple[str, ...]]] = []
            for order in facts.readings():
                product = product_operands(facts, node, order)
                if product is None:
                    break
                left, right = facts.frame_fact(product.left, order), facts.frame_fact(product.right, order)
                if left is None or right is None:
                    # an operand inconsistent in this reading: the reading has its problem already
                    if self._inconsistent(product.left, order) or self._inconsistent(product.right, order):
                        continue
                    break
                if not (facts.names_stated or left.declared or right.declared) or self.too_weak(left, right):
                    break
                mismatch = self.problem(product, left.frames, right.frames, frame_comparison(left, right))
                if mismatch is None:
                    break
                found.append((mismatch, left.evidence + right.evidence))
            else:
                if found:
                    mismatch, evidence = found[0]
                    self.report(node, mismatch.message, evidence=evidence, frames=mismatch.frames)

    def problem(self, product: MatMul, left: NameFrames, right: NameFrames, same: SameFrame) -> Mismatch | None:
        """`same` compares two frames (`same_frame`, or the Spot SDK's with its role words)."""
        raise NotImplementedError

    def too_weak(self, left: FrameFact, right: FrameFact) -> bool:
        """Whether what the operands' frames rest on is too weak for this rule to judge them."""
        return False

    def _inconsistent(self, node: AST, order: str, depth: int = 0) -> bool:
        """Whether a product inside `node` composes operators whose inner frames disagree in `order`."""
        facts = self.facts
        product = product_operands(facts, node, order)
        if product is None or depth > 20:
            return False
        left, right = facts.frames_of(product.left, order), facts.frames_of(product.right, order)
        if left is not None and right is not None and left.is_operator and right.is_operator:
            return same_frame(left.src, right.dst) is False
        return self._inconsistent(product.left, order, depth + 1) or self._inconsistent(product.right, order, depth + 1)


def with_keyword(call_text: str, argument: str) -> str:
    """A call's source text with `argument` (`translate=False`) added last, after a trailing comma if any."""
    body = call_text.rstrip()
    inner = body[:-1].rstrip()
    separator = " " if inner.endswith((",", "(")) else ", "
    return f"{inner}{separator}{argument})"
