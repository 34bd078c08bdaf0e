"""Run the ``hg-marl`` entry point in-process, as a user's shell would, and capture its output."""

from __future__ import annotations

import contextlib
import io
import re
import sys

HANG_GUARD = 600
"""Seconds before a hung subprocess is killed: never what decides a test (a refusal takes
seconds on a quiet machine; a loaded one may take many times that, and must still pass)."""


def run_main(args: list[str]) -> tuple[int, str, str]:
    """Run ``hg-marl ARGS`` through ``main``; return exit code, stdout, stderr."""
    from hg_marl.training.cli import main

    out, err = io.StringIO(), io.StringIO()
    old = sys.argv
    sys.argv = ["hg-marl", *args]
    code = 0
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            main()
    except SystemExit as exc:
        code = int(exc.code or 0)
    finally:
        sys.argv = old
    return code, out.getvalue(), err.getvalue()


_BAR_FRAME = re.compile(r"\[\d+:\d+(?::\d+)?(?:<[^\]]*)?(?:, [^\]]*)?\]\s*$")
"""The tail of a tqdm frame: ``[elapsed<remaining, rate, postfix]``."""


def error_lines(err: str) -> list[str]:
    """The non-empty lines of stderr that are not progress-bar frames.

    A long command shows progress before it refuses (an oracle over its budget); outside
    a terminal tqdm may leave a frame on a line of its own. What the user is told is the
    rest, which must be one line.
    """
    # split on newlines only: str.splitlines() also splits at "\r", keeping a bar's frame as a line
    tails = [line.split("\r")[-1] for line in err.split("\n")]
    return [t for t in tails if t.strip() and not _BAR_FRAME.search(t)]
