"""The README and the pages under ``docs/``, cut into sections for the tests that run their examples.

Each page's examples are run by a test of the package they show (``section("play.md")`` in
``tests/play/``); this module is the one place that knows where the pages live and how a
section ends, so a page that moves or a heading renamed fails with the page and title named.
"""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"


def path(page: str) -> Path:
    """``README.md`` at the repository root; any other name a page under ``docs/``."""
    return ROOT / page if page == "README.md" else DOCS / page


def _headings(text: str) -> list[tuple[int, int, str]]:
    """``(offset, level, title)`` of every Markdown heading outside fenced code blocks."""
    found, offset, fenced = [], 0, False
    for line in text.splitlines(keepends=True):
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and (m := re.match(r"(#{1,6}) (.+?)\s*$", line)):
            found.append((offset, len(m.group(1)), m.group(2)))
        offset += len(line)
    return found


def section(page: str, title: str | None = None) -> str:
    """The text of ``page`` under the heading ``title`` (any level), up to the next heading of
    the same or a higher level; the whole page when ``title`` is None."""
    text = path(page).read_text()
    if title is None:
        return text
    headings = _headings(text)
    for i, (start, level, name) in enumerate(headings):
        if name == title:
            end = next((o for o, lv, _ in headings[i + 1 :] if lv <= level), len(text))
            return text[start:end]
    raise KeyError(f"{page}: no section titled {title!r}")


def blocks(text: str, kind: str) -> list[str]:
    """The fenced code blocks of ``kind`` (``python``, ``bash``, ``toml``) in ``text``, in order."""
    return re.findall(rf"^```{kind}\n(.*?)^```", text, flags=re.S | re.M)
