"""``hg-marl traces``: statistics of recorded play, and the scripted human it resembles most."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer


def _fmt(value: Any, spec: str = ".2f") -> str:
    return "-" if value is None else format(value, spec)


def register(app: typer.Typer) -> None:
    """Add the ``traces`` subcommand."""

    @app.command("traces")
    def traces_command(
        path: Annotated[Path, typer.Argument(help="A trace file or a directory of them (e.g. runs/play).")],
        compare: Annotated[bool, typer.Option(help="Also play each scripted human on the same games.")] = True,
    ) -> None:
        """Sessions, moves per task, handover acceptance, idle share, response times; closest scripted human."""
        from hg_marl.training.play.stats import SCRIPTED, episode_stats, load_games, resemblance, scripted_stats
        from hg_marl.training.play.stats import summarise as summary_of

        games = load_games(path)
        person = [episode_stats(g) for g in games]
        rows = {"recorded": summary_of(person)}
        scripted: dict[str, list[Any]] = {}
        if compare:
            for name in SCRIPTED:
                scripted[name] = [scripted_stats(g, name) for g in games]
                rows[name] = summary_of(scripted[name])
        who = sorted({p.who for p in person})
        robots = sorted({p.robot for p in person})
        typer.echo(f"{len(games)} session(s) by {', '.join(who)} against {', '.join(robots)}")
        typer.echo(
            f"{'who':<12} {'moves':>5} {'tasks':>5} {'moves/task':>10} {'accept':>6} {'idle':>5} {'give':>5} "
            f"{'rt mean':>7} {'rt med':>6}"
        )
        for name, s in rows.items():
            typer.echo(
                f"{name:<12} {s['moves']:>5} {s['tasks']:>5} {_fmt(s['moves_per_task'], '.1f'):>10} "
                f"{_fmt(s['handover_acceptance']):>6} {_fmt(s['idle_share']):>5} {s['shares']['give']:>5.2f} "
                f"{_fmt(s['response_time_mean'], '.1f'):>7} {_fmt(s['response_time_median'], '.1f'):>6}"
            )
        if scripted:
            distance = resemblance(person, scripted)
            best = min(distance, key=lambda k: (distance[k], k))
            ranked = ", ".join(f"{k} {v:.2f}" for k, v in sorted(distance.items(), key=lambda kv: kv[1]))
            typer.echo(f"closest scripted human: {best} (L1 distance of action shares + acceptance: {ranked})")
