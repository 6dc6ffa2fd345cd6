"""GEO401 unfixed-copy: a statement still has a shape that the project fixed elsewhere."""

from __future__ import annotations

import ast
from ast import Module
from typing import Final

from geolint.history import FixedShape, fixed_shapes
from geolint.history.fix_edits import SIMPLE_STATEMENTS, shape_key
from geolint.history.mining import imported_modules
from geolint.lint_types import Config
from geolint.rules.base import AstRule, Invalid, Valid

_KNOWN: Final = {"known-fixes": [{"before": "error = current - target", "after": "error = current * target.conjugate()", "reason": "quaternions compare by their relative rotation"}]}


class _HasFixes:
    """The rule runs only where the project's history is read or it names fixes itself."""

    def search(self, source: str, /) -> bool:
        return True  # without the config nothing can be told

    def search_with(self, source: str, config: Config, /) -> bool:
        return config.history or bool(config.known_fixes)


class UnfixedCopy(AstRule):
    """A statement has the shape that one of the project's own commits fixed somewhere else.

    ## What it does
    With `history = true` (or `geolint check --history`), reads the git history of the repository
    (the newest `history-limit` commits) for edits shaped like the fix of a geometric bug: quaternion
    components reordered, the operands of a product swapped, `.T` replaced by an inverse, an angle
    conversion added or removed, a term negated, `c2w` swapped for `w2c`, a componentwise
    difference of rotations replaced by their relative rotation. The statement as it was before
    such a fix is a shape the project itself calls wrong; every statement that still has it, in
    another copy of the code, is reported, with the commit that fixed the first one.

    A project can also name shapes it knows are wrong, with the statement that replaces them:
    `known-fixes = [{ before = "...", after = "...", reason = "..." }]`.

    ## Why is this bad?
    Research and robot code is copied: environments, dataset loaders and ROS callbacks exist in
    several near-identical files, and a fix lands in the one someone was debugging. The other copies
    keep the bug the project already found and understood.

    ## Example
    ```python
    # commit 013bd22 ("fixes rew") changed this line in envs/mara_v0.py; this copy kept it
    quat_error = current_quaternion - tgt_quaternion
    ```

    ## Use instead
    ```python
    quat_error = current_quaternion * tgt_quaternion.conjugate()
    ```

    ## Fix safety
    The fix replaces the statement with the one the project's commit wrote, when the copy's text is
    the same as the fixed line's was and its module imports what the fixed file imports (the same
    names may hold other kinds of values elsewhere: numpy arrays where the fix had quaternion
    objects). It is unsafe: the copy may still differ in what it needs.

    ## Options
    `history` (default false), `history-limit` (commits read, newest first; default 1000),
    `known-fixes`.

    ## Known problems
    A statement matches only as a whole and by its names (a copy that renamed a variable is not
    found); an edit counts as a fix when its commit message says so or the commit is small, so a
    small refactor of one of these shapes can be read as a fix. A shape the history also changed
    back, or whose fixed statement is gone from its file, is never reported. A shallow clone (CI's default) holds few commits: `geolint check` says
    so; fetch the history (`fetch-depth: 0`) to use it.
    """

    code = "GEO401"
    name = "unfixed-copy"
    triggers = _HasFixes()

    VALID = [
        Valid("error = current * target.conjugate()\n", options=_KNOWN),
        Valid("error = current - target\n"),  # no fixes known
    ]
    INVALID = [
        Invalid(
            "def observe(current, target):\n    error = current - target\n    return error.w\n",
            options=_KNOWN,
            expected_fix="def observe(current, target):\n    error = current * target.conjugate()\n    return error.w\n",
            message="this statement has a shape the project marks as wrong (`known-fixes`: quaternions compare by their relative "
            "rotation); the fix writes `error = current * target.conjugate()`",
            range=(2, 5, 2, 29),
        ),
    ]

    def check(self, tree: Module) -> None:
        shapes = fixed_shapes(self.context.path, self.context.config)
        if not shapes:
            return
        source = self.context.source
        imports = imported_modules(tree)
        for node in ast.walk(tree):
            if not isinstance(node, SIMPLE_STATEMENTS):
                continue
            fixed = shapes.get(shape_key(node))
            if fixed is None:
                continue
            text = ast.get_source_segment(source, node)
            # the same text, in a module with the fixed file's imports (else its names may hold other kinds:
            # numpy arrays where the fix had numpy-quaternion's objects)
            applies = text is not None and text.strip() == fixed.before and imports.issuperset(fixed.imports)
            self.report(
                node,
                _message(fixed),
                replacement=fixed.after if applies else None,
                applicability="unsafe",
                fix_description=f"Write `{fixed.after}`",
            )


def _message(fixed: FixedShape) -> str:
    if not fixed.commit:
        reason = f": {fixed.subject}" if fixed.subject else ""
        return f"this statement has a shape the project marks as wrong (`known-fixes`{reason}); the fix writes `{fixed.after}`"
    return (
        f"this statement has the shape that commit {fixed.commit[:7]} ({fixed.subject!r}) fixed in {fixed.path}:{fixed.line} "
        f"({fixed.shape}): `{fixed.before}` became `{fixed.after}`; the same change applies here"
    )
