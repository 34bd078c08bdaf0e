"""The ``hg-marl`` command line.

Each subcommand lives in its own module under :mod:`hg_marl.training.commands` and
adds itself with ``register(app)``; heavy imports (torch, SB3, matplotlib) happen
inside the commands that need them, so ``hg-marl --help`` stays fast.
"""

from __future__ import annotations

import functools
import importlib
import logging
import os
import sys
from collections.abc import Callable
from typing import Any

import typer
from typer.exceptions import Abort, TyperException

from hg_marl.core.errors import HgMarlError, output_error

COMMANDS = (
    "run",
    "plan",
    "oracle",
    "reproduce",
    "train",
    "compare",
    "convert",
    "play",
    "replay",
    "traces",
    "evaluate",
    "population",
    "headroom",
    "switching",
)
"""Subcommand modules, in the order ``--help`` lists them."""

app = typer.Typer(
    name="hg-marl",
    help="Human-robot table cleaning: run, plan, oracle, reproduce the paper, train baselines.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)


@app.callback()
def _root() -> None:
    """Human-robot table cleaning (Renaudo et al. 2015) from the command line."""


def one_line_errors(callback: Callable[..., Any]) -> Callable[..., Any]:
    """Wrap a command so bad input (HgMarlError) prints one line and exits 2, wherever it is invoked.

    ``functools.wraps`` keeps the signature typer reads the options from. An OSError a
    user can fix (:data:`~hg_marl.core.errors.WRITE_ERRNOS`: a full disk, a forbidden
    folder) is one line too. Any other exception is a bug and keeps its traceback.
    """

    @functools.wraps(callback)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return callback(*args, **kwargs)
        except HgMarlError as exc:
            typer.secho(f"error: {exc}", fg=typer.colors.RED, err=True)
            raise typer.Exit(2) from None
        except OSError as exc:
            # A full disk or a forbidden folder met by a writer outside atomic_write
            # (SB3's zip, a trace being recorded): still one line naming the file.
            error = output_error(exc)
            if error is None:
                raise
            typer.secho(f"error: {error}", fg=typer.colors.RED, err=True)
            raise typer.Exit(2) from None

    return wrapper


def register_all(target: typer.Typer, names: tuple[str, ...] = COMMANDS) -> typer.Typer:
    """Add the named subcommands to ``target``, each wrapped by :func:`one_line_errors`."""
    for name in names:
        importlib.import_module(f"hg_marl.training.commands.{name}").register(target)
    _wrap(target, root=True)
    return target


def _wrap(typer_app: typer.Typer, root: bool = False) -> None:
    """Wrap every command of ``typer_app`` with :func:`one_line_errors`, in its groups too (``train sb3``)."""
    infos: list[Any] = list(typer_app.registered_commands)
    if not root and typer_app.registered_callback is not None:
        infos.append(typer_app.registered_callback)  # a group's own callback (``train --algo``, the old form)
    for info in infos:
        if info.callback is not None and not getattr(info.callback, "_one_line", False):
            info.callback = one_line_errors(info.callback)
            info.callback._one_line = True
    for group in typer_app.registered_groups:
        if group.typer_instance is not None:
            _wrap(group.typer_instance)


register_all(app)


class _AboveBars(logging.Handler):
    """Prints a record's message on stderr above any live tqdm bar (``tqdm.write``)."""

    def emit(self, record: logging.LogRecord) -> None:
        import sys

        from tqdm import tqdm

        tqdm.write(self.format(record), file=sys.stderr)


def _show_store_counts() -> None:
    """Every command that uses the store prints its ``store: N runs made, M reused`` line.

    The sweep logs it at INFO (library code prints nothing); the CLI shows that one
    logger's INFO lines, once however often ``main`` runs in a process (the root's
    handlers stay at WARNING, so the line is not printed twice).
    """
    sweep = logging.getLogger("hg_marl.training.sweep")
    if not any(isinstance(h, _AboveBars) for h in sweep.handlers):
        above = _AboveBars()
        above.setFormatter(logging.Formatter("%(message)s"))
        sweep.addHandler(above)
    sweep.setLevel(logging.INFO)
    for root_handler in logging.getLogger().handlers:  # the root's keep showing warnings only
        root_handler.setLevel(logging.WARNING)


def main() -> None:
    """Entry point of the ``hg-marl`` script."""
    logging.basicConfig(level=logging.WARNING, format="%(levelname)s %(name)s: %(message)s")
    _show_store_counts()
    try:
        code = app(standalone_mode=False)
    except TyperException as exc:
        # A malformed option (a usage error): one line, exit 2, as for any bad input.
        typer.secho(f"error: {' '.join(exc.format_message().split())}", fg=typer.colors.RED, err=True)
        raise SystemExit(exc.exit_code) from None
    except Abort:
        raise SystemExit(130) from None
    except HgMarlError as exc:
        # Raised outside a command: still one line, exit 2.
        typer.secho(f"error: {exc}", fg=typer.colors.RED, err=True)
        raise SystemExit(2) from None
    raise SystemExit(code if isinstance(code, int) else 0)


def script() -> None:
    """The command line as a script: :func:`main`, budgets from the process's start, out at once when refused.

    The exact commands' ``--max-seconds`` count from the process's start
    (:func:`~hg_marl.training.commands.common.command_start`). The console script enters
    through :mod:`hg_marl_start`, which arms the budget before this module's imports.

    An exact command refused over its budget has written nothing, and holds what it had
    computed: a partial model and the planners' memos, millions of small objects. The
    interpreter freeing them at shutdown took about a second past the refusal, which a
    person who asked for ``--max-seconds 5`` waits on. So after the one-line refusal this
    process leaves with ``os._exit(2)``, its streams flushed (forked workers were stopped
    with the refusal). :func:`main` itself returns as usual: tests call it in-process.
    """
    from hg_marl_start import SCRIPT, begin

    begin(sys.argv)  # (done already where the console script's first module called this)
    try:
        main()
    except SystemExit:
        if SCRIPT["over_budget"]:
            sys.stdout.flush()
            sys.stderr.flush()
            os._exit(2)
        raise


if __name__ == "__main__":
    script()
