"""The oracle's symmetry reduction and budget: exact where it applies, refused beyond the budget."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.registry import HUMANS
from hg_marl.agents.models import Budget
from hg_marl.agents.oracle import OracleRobot, OracleTooLarge, canonical_layouts, layout_distribution, oracle_rate
from hg_marl.agents.planner.space import Relabel
from hg_marl.agents.robots import make_robot
from hg_marl.core import Agent, State, World
from hg_marl.training.runner import RunConfig, run

EQUIVARIANT = tuple(n for n, s in HUMANS.items() if getattr(s.factory(), "equivariant", False))


def test_the_planner_driven_and_random_humans_declare_equivariance() -> None:
    assert set(EQUIVARIANT) == {"cooperative", "noisy", "random"}


def permute_state(state: State, perm: list[int]) -> State:
    """Object ``o`` of ``state`` becomes object ``perm[o]``."""
    where = [0] * len(perm)
    for o, p in enumerate(state.where):
        where[perm[o]] = p
    obj = perm[state.offer_obj] if state.offer_obj >= 0 else -1
    return State(tuple(where), state.robot_at, state.offer_by, obj)


def permute_action(world: World, agent: int, index: int, perm: list[int]) -> int:
    if index < 0:
        return index
    kind, obj, target, _ = world.table.specs[agent][index]
    if obj >= 0:
        obj = perm[obj]
    elif target >= 0 and target < world.n_objects and kind.name == "GOTO":
        target = perm[target]
    return world.table.action_index(agent, kind, obj, target)


@pytest.mark.parametrize("scenario", ["paper2015", "roboergosum"])
@pytest.mark.parametrize("name", EQUIVARIANT)
def test_an_equivariant_humans_answer_at_a_relabelled_state_is_its_answer_relabelled(name: str, scenario: str) -> None:
    seen: list[tuple[State, int]] = []

    class Spy:
        def __init__(self, human: Any) -> None:
            self.human = human

        def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
            self.human.reset(world, agent, rng)

        def act(self, turn: Any) -> int:
            from hg_marl.agents.humans.base import robot_action_of

            seen.append((turn.state, robot_action_of(turn)))
            return int(self.human.act(turn))

    run(make_robot("random"), Spy(make_human(name)), RunConfig(scenario=scenario, duration=600.0, seed=2))
    world = World(scenario)
    human: Any = make_human(name)
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    rng = np.random.default_rng(0)
    classes = Relabel(world).classes
    assert classes
    for state, ra in seen[::5]:
        perm = list(range(world.n_objects))
        for members in classes:
            for o, p in zip(members, rng.permutation(members), strict=True):
                perm[o] = int(p)
        expected = {permute_action(world, 1, a, perm): p for a, p in human.distribution(world, state, ra)}
        got = dict(human.distribution(world, permute_state(state, perm), permute_action(world, 0, ra, perm)))
        assert got == expected, (state, perm)


@pytest.mark.parametrize("scenario", ["paper2015", "roboergosum", "generated:objects=5,bins=2,seed=1"])
def test_canonical_layouts_are_the_exact_layouts_merged_by_relabelling(scenario: str) -> None:
    world = World(scenario)
    relabel = Relabel(world)
    merged: dict[State, float] = {}
    for state, p in layout_distribution(world):
        key = relabel.canonical(state)[0]
        merged[key] = merged.get(key, 0.0) + p
    got = dict(canonical_layouts(world))
    assert got.keys() == merged.keys()
    assert all(got[k] == pytest.approx(merged[k], abs=1e-12) for k in merged)
    assert sum(got.values()) == pytest.approx(1.0)


@pytest.mark.parametrize("name", ["cooperative", "random", "noisy", "cooperative:p_idle=0.3"])
def test_the_reduced_model_gives_the_full_models_rate(name: str) -> None:
    full = oracle_rate("paper2015", name, symmetry=False)
    reduced = oracle_rate("paper2015", name)
    assert reduced.reduced and not full.reduced
    assert reduced.n_states < full.n_states / 3  # 3 interchangeable tapes
    assert reduced.rate_per_hour == pytest.approx(full.rate_per_hour, rel=1e-9)


def test_the_reduced_policy_plays_in_any_labelling() -> None:
    result = oracle_rate("paper2015", "cooperative")
    robot = OracleRobot(result)
    out = run(robot, make_human("cooperative"), RunConfig(scenario="paper2015", duration=3600.0, seed=3))
    assert robot.off_model == 0
    assert out.summary["tasks_solved"] / (out.summary["simulated_time"] / 3600) == pytest.approx(
        result.rate_per_hour, rel=0.1
    )


def test_beyond_its_time_budget_the_oracle_refuses_naming_the_budget() -> None:
    ticks = iter(range(10**9))  # a clock that advances one second per reading: the budget counts checks
    budget = Budget(seconds=3, clock=lambda: float(next(ticks)))
    with pytest.raises(OracleTooLarge, match=r"over its budget of 3 s of wall time .* in phase 'layouts'"):
        oracle_rate("roboergosum", "lazy", budget=budget)
    with pytest.raises(OracleTooLarge, match=r"over its budget of .* GB of memory"):
        oracle_rate("paper2015", "lazy", max_memory=1)


def test_a_layout_enumeration_over_max_states_is_refused_before_it_starts() -> None:
    # 8 objects, all distinguishable up to no relabelling (lazy is not equivariant): 10!/2! deals
    with pytest.raises(OracleTooLarge, match="1,814,400 initial layouts"):
        oracle_rate("generated:objects=8,bins=2", "lazy")


def test_cli_over_budget_exits_2_with_one_line() -> None:
    import typer
    from typer.testing import CliRunner

    from hg_marl.training.commands.oracle import register

    app = typer.Typer()
    register(app)

    @app.command()
    def other() -> None:
        """Placeholder."""

    out = CliRunner().invoke(app, ["oracle", "--scenario", "roboergosum", "--human", "lazy", "--max-states", "3000"])
    assert out.exit_code == 2
    lines = [line for line in out.output.splitlines() if line.startswith("error:")]
    assert len(lines) == 1 and "max_states=3,000" in lines[0] and "'layouts'" in lines[0]  # 5,040 layouts
