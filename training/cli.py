"""The ``hg-marl`` command line.

Each subcommand lives in its own module under :mod:`hg_marl.training.commands` and
adds itself with ``register(app)``; heavy imports (torch, SB3, matplotlib) happen
inside the commands that need them, so ``hg-marl --help`` stays fast.
"""

from __future__ import annotations

import importlib
import logging

import typer

COMMANDS = ("run", "plan", "oracle", "reproduce", "train", "compare", "evaluate")
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


for _name in COMMANDS:
    importlib.import_module(f"hg_marl.training.commands.{_name}").register(app)


def main() -> None:
    """Entry point of the ``hg-marl`` script."""
    logging.basicConfig(level=logging.WARNING, format="%(levelname)s %(name)s: %(message)s")
    from hg_marl.core.errors import HgMarlError

    try:
        app()
    except HgMarlError as exc:
        # Bad input: one line, exit 2. Anything else is a bug and keeps its traceback.
        typer.secho(f"error: {exc}", fg=typer.colors.RED, err=True)
        raise SystemExit(2) from None


if __name__ == "__main__":
    main()
