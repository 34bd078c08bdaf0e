"""``hg-marl convert``: turn a trusted SB3 ``.zip`` into the safe model file format."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer


def register(app: typer.Typer) -> None:
    """Add the ``convert`` subcommand."""

    @app.command("convert")
    def convert_command(
        path: Annotated[Path, typer.Argument(help="The SB3 .zip to convert.")],
        trust: Annotated[
            bool, typer.Option("--trust", help="Required: loading an SB3 zip runs the code inside it.")
        ] = False,
        out: Annotated[Path | None, typer.Option(help="The new header (default: the zip's name with .json).")] = None,
        algo: Annotated[str | None, typer.Option(help="SB3 class (MaskablePPO, PPO...) if no metadata says.")] = None,
        scenario: Annotated[str | None, typer.Option(help="Scenario it was trained on, if no metadata says.")] = None,
        seat: Annotated[str | None, typer.Option(help="robot or human, if no metadata says.")] = None,
        observation: Annotated[str | None, typer.Option(help="facts, flat or dict, if no metadata says.")] = None,
    ) -> None:
        """Convert a Stable-Baselines3 zip you trust into a model file (JSON header + .npz weights)."""
        from hg_marl.training.baselines.convert import convert_zip
        from hg_marl.training.commands.common import check_out_file

        check_out_file(out if out is not None else path.with_suffix(".json"), "--out", (".json",))

        header = convert_zip(
            path, trust=trust, out=out, algo=algo, scenario=scenario, seat=seat, observation=observation
        )
        typer.echo(f"wrote {header} and {header.with_suffix('.npz')}")
        typer.echo(f"  use it  hg-marl run --robot sb3 --model {header}")
