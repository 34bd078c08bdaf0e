"""Every ``hg-marl`` command the README and the pages show names a real subcommand and real options.

Why: the README's examples run in tests, but most pages show commands too long to run
here (a study, the headroom of a population). An option renamed in the CLI would leave
them stale with every test green. This reads each ``hg-marl ...`` line of every page (in
fenced blocks and in inline code), resolves its subcommand path in the typer app (``hg-marl
population generate``) and requires every ``--option`` it passes to be one that
subcommand declares. Nothing is run.
"""

from __future__ import annotations

import re
import shlex
from typing import Any

import pytest
import typer

from hg_marl.training.cli import app
from tests.docs_sections import DOCS, ROOT

PAGES = [ROOT / "README.md", *sorted(DOCS.glob("*.md"))]


def _commands(text: str) -> list[str]:
    """The ``hg-marl`` command lines of a page: inline code, and fenced lines (a trailing
    ``\\`` joins the next line); comments after ``#`` dropped."""
    found = re.findall(r"`(hg-marl [^`]+)`", text)
    for block in re.findall(r"```[a-z]*\n(.*?)```", text, flags=re.S):
        joined = re.sub(r"\s*\\\n\s*", " ", block)
        found += [line.strip() for line in joined.splitlines() if line.strip().startswith("hg-marl ")]
    return [re.split(r"\s+#", c)[0].strip() for c in found]


def _resolve(argv: list[str]) -> tuple[Any, list[str], list[str]]:
    """(the command, its path, the arguments after it) for ``argv`` after ``hg-marl``."""
    cmd: Any = typer.main.get_command(app)
    path: list[str] = []
    while hasattr(cmd, "list_commands") and argv and not argv[0].startswith("-"):
        sub = cmd.get_command(type(cmd).context_class(cmd), argv[0])
        if sub is None:
            break
        path.append(argv.pop(0))
        cmd = sub
    return cmd, path, argv


CASES = [
    pytest.param(command, id=f"{page.name}:{command[:60]}")
    for page in PAGES
    for command in dict.fromkeys(_commands(page.read_text()))
]


def test_the_pages_show_commands() -> None:
    assert len(CASES) >= 80  # the pages' commands are read (108 when this test was written)


def _unknown(command: str) -> list[str]:
    """The options ``command`` passes that its subcommand does not declare (or the unknown subcommand)."""
    cmd, _, rest = _resolve(shlex.split(command)[1:])
    if hasattr(cmd, "list_commands"):  # a group shown alone (``hg-marl train ...``), or an unknown name
        return [rest[0]] if rest and not rest[0].startswith("-") and rest[0] != "..." else []
    declared = {opt for p in cmd.params for opt in (*p.opts, *p.secondary_opts)}
    return [t.split("=")[0] for t in rest if t.startswith("--") and t.split("=")[0] not in {*declared, "--help"}]


@pytest.mark.parametrize("command", CASES)
def test_a_documented_command_names_its_options(command: str) -> None:
    assert _unknown(command) == [], command


def test_a_renamed_option_or_command_is_caught() -> None:
    """The check itself, on commands written for it; and the lines a page's blocks give."""
    assert _unknown("hg-marl oracle --scenario paper2015 --max-seconds 5") == []
    assert _unknown("hg-marl oracle --scenario paper2015 --max-secs 5") == ["--max-secs"]
    assert _unknown("hg-marl population generate --scenario paper2015 --candidate 3") == ["--candidate"]
    assert _unknown("hg-marl orcale --scenario paper2015") == ["orcale"]
    page = "run `hg-marl plan --png x.png` and\n```bash\nhg-marl run \\\n  --robot planner  # a comment\n```"
    assert _commands(page) == ["hg-marl plan --png x.png", "hg-marl run --robot planner"]
