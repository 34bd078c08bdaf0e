"""Run the ``hg-marl`` entry point in-process, as a user's shell would, and capture its output."""

from __future__ import annotations

import contextlib
import io
import sys


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


def error_lines(err: str) -> list[str]:
    """The non-empty lines of stderr (a progress bar's carriage-return frames excluded)."""
    # split on newlines only: str.splitlines() also splits at "\r", keeping a bar's frame as a line
    return [line.split("\r")[-1] for line in err.split("\n") if line.split("\r")[-1].strip()]
