"""The example commands of the project's Markdown files, as a user would type them.

A fenced block is an example when it is Python (```python) or a shell block (no language,
sh, bash) whose first line starts with a command (`essaim`, `build/essaim`, `.venv/bin/...`,
`scripts/...`, `tools/...`, `bash`, `cp`, `sed`, ...). Other shell blocks are output, file listings or
`--set` fragments; a block written with placeholders (`[--ticks N]`, `<experiment>`) is a
synopsis. Neither is run.

An HTML comment right above a block changes how it is run (the Markdown shows nothing):

    <!-- doc-test: skip: WHY -->              not run (illustrative: needs a cluster, ...)
    <!-- doc-test: replace OLD => NEW -->     run with OLD replaced by NEW (shortened)
    <!-- doc-test: before: COMMAND -->        COMMAND is run first (shortens an input file)

Several comments may stack above one block.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

COMMANDS = ("essaim", "build/essaim", ".venv/bin/", "scripts/", "tools/", "bash", "python3", "ctest",
            "cp", "sed", "cat", "mkdir", "ls", "cd", "ESSAIM=")
SHELL_LANGS = ("", "sh", "bash", "shell")
SYNOPSIS = re.compile(r"\[--|<[a-z][\w-]*>|\]\.\.\.")
DIRECTIVE = re.compile(r"<!--\s*doc-test:\s*(skip|replace|before)\s*:?\s*(.*?)\s*-->")


@dataclass
class Example:
    file: str
    line: int                 # of the opening fence
    lang: str                 # "shell" or "python"
    text: str                 # as written
    skip: str | None = None   # why it is not run
    replace: list[tuple[str, str]] = field(default_factory=list)
    before: list[str] = field(default_factory=list)

    def runnable(self) -> str:
        text = self.text
        for old, new in self.replace:
            if old not in text:
                raise ValueError(f"{self.where}: doc-test replace: {old!r} is not in the block")
            text = text.replace(old, new)
        return text

    @property
    def where(self) -> str:
        return f"{self.file}:{self.line}"


def is_command(line: str) -> bool:
    return line.startswith(COMMANDS)


def examples(path: Path, root: Path) -> list[Example]:
    """The examples of one Markdown file, in order."""
    lines = path.read_text(encoding="utf-8").splitlines()
    name = str(path.relative_to(root))
    found, pending, i = [], [], 0
    while i < len(lines):
        d = DIRECTIVE.search(lines[i])
        fence = re.match(r"^```(\w*)\s*$", lines[i])
        if d:
            pending.append((d.group(1), d.group(2)))
        elif fence:
            end = next(j for j in range(i + 1, len(lines)) if lines[j].startswith("```"))
            block = lines[i + 1:end]
            ex = classify(name, i + 1, fence.group(1), block)
            if ex is not None:
                apply(ex, pending)
                found.append(ex)
            elif pending:
                raise ValueError(f"{name}:{i + 1}: doc-test comment above a block that is "
                                 "not an example")
            pending, i = [], end
        elif lines[i].strip():
            pending = []
        i += 1
    return found


def classify(name: str, line: int, lang: str, block: list[str]) -> Example | None:
    text = "\n".join(block) + "\n"
    if lang == "python":
        return Example(name, line, "python", text)
    if lang not in SHELL_LANGS:
        return None
    first = next((b for b in block if b.strip() and not b.lstrip().startswith("#")), "")
    if not is_command(first) or any(SYNOPSIS.search(b.split("#")[0]) for b in block):
        return None
    return Example(name, line, "shell", text)


def apply(ex: Example, directives: list[tuple[str, str]]) -> None:
    for kind, arg in directives:
        if kind == "skip":
            ex.skip = arg or "illustrative"
        elif kind == "before":
            ex.before.append(arg)
        else:
            old, sep, new = arg.partition(" => ")
            if not sep:
                raise ValueError(f"{ex.where}: doc-test replace needs 'OLD => NEW'")
            ex.replace.append((old, new))
