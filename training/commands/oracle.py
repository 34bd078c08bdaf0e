"""``hg-marl oracle``: the optimal robot's rate against a known human, and the model's size."""

from __future__ import annotations

import typer


def register(app: typer.Typer) -> None:
    """Add the ``oracle`` command to ``app``."""

    @app.command("oracle")
    def oracle(
        scenario: str = typer.Option("paper2015", help="scenario name or TOML path"),
        human: str = typer.Option("cooperative", help="stationary human, e.g. lazy or lazy:p_idle=0.5"),
        max_states: int = typer.Option(1_500_000, min=1, help="states budget (over it: refused, exit 2)"),
        failed_actions: bool = typer.Option(True, help="let the robot use infeasible actions (0.2 s no-ops)"),
        max_seconds: float = typer.Option(60.0, help="wall-time budget in seconds (over it: refused, exit 2)"),
        max_memory: float = typer.Option(4.0, help="resident-memory budget in GB (over it: refused, exit 2)"),
    ) -> None:
        """Optimal tasks per simulated hour by value iteration on the exact model."""
        from hg_marl.agents.humans import HumanError
        from hg_marl.agents.models.budget import MAX_SECONDS, Budget
        from hg_marl.agents.oracle import OracleTooLarge, oracle_rate
        from hg_marl.core.errors import check_finite
        from hg_marl.training.commands.common import command_start, over_budget

        check_finite(max_seconds, "--max-seconds", positive=True, maximum=MAX_SECONDS)
        check_finite(max_memory, "--max-memory", positive=True)
        # the budget counts from the command's start, imports included: what its user waits
        budget = Budget(max_seconds, int(max_memory * 2**30), max_states, start=command_start())
        try:
            result = oracle_rate(
                scenario, human, max_states=max_states, failed_actions=failed_actions, progress=True, budget=budget
            )
        except (HumanError, OracleTooLarge, ValueError) as exc:
            if isinstance(exc, OracleTooLarge):
                over_budget()
            typer.echo(f"error: {exc}", err=True)
            raise typer.Exit(2) from exc
        typer.echo(f"scenario      {result.scenario}")
        typer.echo(f"human         {human}")
        typer.echo(f"optimal rate  {result.rate_per_hour:.3f} tasks per simulated hour")
        typer.echo(f"time per task {result.seconds_per_task:.3f} s")
        typer.echo(
            f"model         {result.n_states} states, {result.n_transitions} transitions, {result.n_layouts} layouts"
        )
        typer.echo(
            f"solve         {result.iterations} iterations (converged: {result.converged}), {result.seconds:.1f} s"
        )
