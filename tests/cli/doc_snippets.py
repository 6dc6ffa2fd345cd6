"""The fenced code blocks of README.md and docs/*.md, found by the section they sit in.

Tests run the blocks exactly as written (a copied snippet must work); `block(file, heading, n)`
names one by the markdown heading above it, so editing prose does not break the tests, and
`all_blocks()` lets a test insist that every block is accounted for.
"""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parents[2]
# The public repository URL the snippets name; tests point it at a local clone instead.
PUBLIC_URL = "https://github.com/geolint/geolint"
# Docs whose blocks other tests run (the editors guide: tests/integrations/test_lsp_docs.py; the
# typing guide: tests/typing/test_docs_examples.py) and the generated rules page, whose examples the
# rule tests run.
NOT_HERE = ("docs/editors.md", "docs/typing.md", "docs/rules.md")

FENCE = re.compile(r"^```(?P<language>[\w-]*)\n(?P<body>.*?)^```$", re.S | re.M)
HEADING = re.compile(r"^#{1,6} (.+)$|^\*\*(.+?)\*\*", re.M)


@dataclass(frozen=True)
class Block:
    file: str  # relative to the repository root
    heading: str  # the nearest markdown heading (or bold paragraph lead) above the block
    index: int  # 0-based among the blocks under that heading
    language: str
    body: str
    line: int

    @property
    def key(self) -> tuple[str, str, int]:
        return (self.file, self.heading, self.index)


def blocks_of(relative: str) -> list[Block]:
    text = (REPO_ROOT / relative).read_text(encoding="utf-8")
    # Headings outside the blocks only (a `# comment` in a block is not one); offsets stay the same.
    prose = FENCE.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)
    headings = [(m.start(), (m.group(1) or m.group(2)).strip()) for m in HEADING.finditer(prose)]
    found: list[Block] = []
    counts: dict[str, int] = {}
    for match in FENCE.finditer(text):
        heading = next((name for start, name in reversed(headings) if start < match.start()), "")
        index = counts.get(heading, 0)
        counts[heading] = index + 1
        line = text.count("\n", 0, match.start()) + 1
        found.append(Block(relative, heading, index, match.group("language"), match.group("body"), line))
    return found


def all_blocks() -> list[Block]:
    files = ["README.md", *sorted(f"docs/{p.name}" for p in (REPO_ROOT / "docs").glob("*.md"))]
    return [block for relative in files if relative not in NOT_HERE for block in blocks_of(relative)]


def block(relative: str, heading: str, index: int = 0) -> Block:
    for candidate in blocks_of(relative):
        if candidate.heading == heading and candidate.index == index:
            return candidate
    raise LookupError(f"no code block {index} under {heading!r} in {relative}")


def project_version() -> str:
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover
        import tomli as tomllib

    with open(REPO_ROOT / "pyproject.toml", "rb") as stream:
        return str(tomllib.load(stream)["project"]["version"])


def commands_of(body: str) -> list[str]:
    """Shell lines of a bash/sh/console block: `$ ` prompts dropped, comments and blanks skipped."""
    lines = []
    for raw in body.splitlines():
        line = raw.removeprefix("$ ").strip()
        if line and not line.startswith("#"):
            lines.append(line)
    return lines


def ci_commands(yaml_body: str) -> list[str]:
    """The shell commands of a GitHub Actions (`run:`) or GitLab CI (`script:`) snippet, in order."""
    import yaml

    document = yaml.safe_load(yaml_body)
    commands: list[str] = []

    def walk(node: object) -> None:
        if isinstance(node, dict):
            for key, value in node.items():
                if key == "run" and isinstance(value, str):
                    commands.append(value)
                elif key == "script" and isinstance(value, list):
                    commands.extend(str(item) for item in value)
                else:
                    walk(value)
        elif isinstance(node, list):
            for item in node:
                walk(item)

    walk(document)
    return commands
