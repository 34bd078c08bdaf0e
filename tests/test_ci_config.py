"""The CI's own wiring: every nox session is run by ``make test-integrations``.

The Makefile names the sessions (to run them two at a time, longest first); a session
added to ``noxfile.py`` but not to that list would never run in CI.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _nox_sessions() -> set[str]:
    tree = ast.parse((ROOT / "noxfile.py").read_text())
    return {
        node.name
        for node in tree.body
        if isinstance(node, ast.FunctionDef)
        and any(ast.unparse(d).startswith("nox.session") for d in node.decorator_list)
    }


def test_every_nox_session_is_run_by_make_test_integrations() -> None:
    line = re.search(r"^NOX_SESSIONS := (.+)$", (ROOT / "Makefile").read_text(), re.MULTILINE)
    assert line is not None
    named = line.group(1).split()
    assert len(named) == len(set(named))
    assert set(named) == _nox_sessions() == {"cleanrl", "supersuit", "tianshou", "rllib", "core_lowest"}
