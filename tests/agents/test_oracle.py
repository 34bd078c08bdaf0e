"""The oracle: exact against brute force, consistent with the environment, never beaten."""

from __future__ import annotations

import itertools
from collections import Counter
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.humans import HumanError, make_human
from hg_marl.agents.models import Budget
from hg_marl.agents.oracle import OracleRobot, OracleTooLarge, layout_distribution, oracle_rate
from hg_marl.agents.robots import make_robot
from hg_marl.agents.views import RobotView
from hg_marl.core import Agent, State, World
from hg_marl.core.scenario import parse_scenario
from hg_marl.policy import Actor

# One tape, on the robot's mat or on the human's; bin far from the human: every way to
# dispose of it (robot alone, handover, human moves it to the shared mat) is possible.
TINY = parse_scenario(
    {
        "name": "tiny",
        "robot_locations": ["near", "far"],
        "handover_locations": ["near"],
        "robot_start": ["near", "far"],
        "objects": [{"name": "o1"}],
        "bins": [{"name": "bin", "robot_reach": ["far"]}],
        "spots": [
            {"name": "a", "robot_reach": ["near"]},
            {"name": "h", "human_reach": True},
            {"name": "s", "robot_reach": ["near"], "human_reach": True},
        ],
        "layout": [{"count": 1, "spots": ["a", "h"]}],
    }
)


def brute_force_rate(world: World, human_name: str) -> float:
    """Best long-run rate over every deterministic stationary policy (feasible actions).

    Independent of the oracle's renewal argument: each policy's continuing Markov chain
    (re-draw included) is built explicitly and its long-run reward per second from the
    start distribution is the Cesàro limit, computed exactly enough by squaring the lazy
    chain ``(P + I) / 2``.
    """
    human = make_human(human_name)
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    acts_r, acts_h = world.actions(Agent.ROBOT), world.actions(Agent.HUMAN)

    def replies(mid: State, out_ok: bool, a: int, d: float) -> list[tuple[State, float, float]]:
        dist = human.distribution(world, mid, a if out_ok else -1)
        return [
            (
                world.apply(mid, Agent.HUMAN, acts_h[h]).state,
                p,
                max(d, world.apply(mid, Agent.HUMAN, acts_h[h]).duration),
            )
            for h, p in dist
        ]

    layouts = layout_distribution(world)
    wait = world.n_actions(Agent.ROBOT) - 1
    regen = [
        r
        for table, q in layouts
        for r in ((s, q * p, tau) for s, p, tau in replies(table, True, wait, world.durations.wait))
    ]
    states = [s for s, _ in layouts]
    index = {s: i for i, s in enumerate(states)}
    rows: list[list[tuple[dict[int, float], float, float]]] = []
    k = 0
    while k < len(states):
        options = []
        for a in world.feasible_indices(states[k], Agent.ROBOT):
            out = world.apply(states[k], Agent.ROBOT, acts_r[a])
            succ = regen if out.reward else replies(out.state, out.ok, a, out.duration)
            row: dict[int, float] = {}
            for s, p, _ in succ:
                if s not in index:
                    index[s] = len(states)
                    states.append(s)
                row[index[s]] = row.get(index[s], 0.0) + p
            options.append((row, out.reward, sum(p * tau for _, p, tau in succ)))
        rows.append(options)
        k += 1
    n, width = len(states), max(len(o) for o in rows)
    mu = np.zeros(n)
    for s, q in layouts:
        mu[index[s]] += q
    # options[s, c]: the lazy chain's row, reward and time of choice c at state s.
    trans, reward, time = np.zeros((n, width, n)), np.zeros((n, width)), np.ones((n, width))
    for i, options in enumerate(rows):
        for c, (row, r, tau) in enumerate(options):
            trans[i, c, i] = 0.5
            for j, q in row.items():
                trans[i, c, j] += q / 2
            reward[i, c], time[i, c] = r, tau
    policies = np.array(list(itertools.product(*(range(len(o)) for o in rows))), dtype=np.int64)
    best = 0.0
    for chunk in np.array_split(policies, max(1, len(policies) // 20_000)):
        states_idx = np.arange(n)
        p = trans[states_idx, chunk]  # (B, n, n)
        for _ in range(12):
            p = p @ p
        pi = np.einsum("i,bij->bj", mu, p)
        rate = (pi * reward[states_idx, chunk]).sum(1) / (pi * time[states_idx, chunk]).sum(1)
        best = max(best, float(rate.max()))
    return best * 3600


@pytest.mark.parametrize("human", ["no_handover", "cooperative", "lazy:p_idle=0.5"])
def test_oracle_matches_brute_force_on_a_tiny_scenario(human: str) -> None:
    world = World(TINY)
    result = oracle_rate(world, human, failed_actions=False)
    assert result.converged
    assert result.rate_per_hour == pytest.approx(brute_force_rate(world, human), rel=1e-6)


def test_layout_distribution_is_exact() -> None:
    world = World("paper2015")
    layouts = layout_distribution(world)
    assert len(layouts) == 36 and sum(p for _, p in layouts) == pytest.approx(1.0)
    rng = np.random.default_rng(0)
    counts = Counter(world.initial_state(rng) for _ in range(18_000))
    assert set(counts) == {s for s, _ in layouts}
    for state, p in layouts:
        assert counts[state] / 18_000 == pytest.approx(p, abs=0.008)


def measured_rate(robot: Actor, human: str, hours: float, seed: int = 0) -> float:
    view = RobotView("paper2015", human=human, continuing=True, max_cycles=None, time_budget=3600.0 * hours)
    view.reset(seed=seed)
    robot.reset(view.world, Agent.ROBOT, np.random.default_rng(seed))
    total, done = 0.0, False
    while not done:
        _, r, term, trunc, info = view.step(robot.act(view.env.turn("robot")))
        total += r
        done = term or trunc
    return total / (info["clock"] / 3600.0)


@pytest.fixture(scope="module")
def cooperative_oracle():
    return oracle_rate("paper2015", "cooperative")


def test_oracle_robot_achieves_the_predicted_rate_in_the_env(cooperative_oracle) -> None:
    for human in ("lazy", "random"):
        result = oracle_rate("paper2015", human)
        assert measured_rate(OracleRobot(result), human, hours=5) == pytest.approx(result.rate_per_hour, rel=0.03)
    robot = OracleRobot(cooperative_oracle)
    assert measured_rate(robot, "cooperative", hours=3) == pytest.approx(cooperative_oracle.rate_per_hour, rel=0.03)
    assert robot.off_model == 0


def test_planner_robot_reaches_95_percent_and_nobody_beats_the_oracle(cooperative_oracle) -> None:
    planner = measured_rate(make_robot("planner"), "cooperative", hours=2)
    assert planner >= 0.95 * cooperative_oracle.rate_per_hour
    assert planner <= cooperative_oracle.rate_per_hour * 1.03  # sampling noise of the layouts only
    random_robot = measured_rate(make_human("random"), "cooperative", hours=2)
    assert random_robot <= cooperative_oracle.rate_per_hour


def test_reference_figures_for_paper2015() -> None:
    lazy = oracle_rate("paper2015", "lazy")
    no_handover = oracle_rate("paper2015", "no_handover")
    assert lazy.n_states > 100 and lazy.converged
    assert 0 < no_handover.rate_per_hour < 200
    assert oracle_rate("paper2015", "adversarial").rate_per_hour == 0.0  # the hidden tape never comes back


def test_non_stationary_human_and_cap_are_refused_clearly() -> None:
    with pytest.raises(HumanError, match="stationary"):
        oracle_rate("paper2015", "switching")
    with pytest.raises(OracleTooLarge, match="max_states=50"):
        oracle_rate("paper2015", "lazy", max_states=50)


def test_cli_command_prints_rate_and_size() -> None:
    import typer
    from typer.testing import CliRunner

    from hg_marl.training.commands.oracle import register

    app = typer.Typer()
    register(app)

    @app.command()
    def other() -> None:  # a second command, so typer keeps the command names
        """Placeholder."""

    out = CliRunner().invoke(app, ["oracle", "--scenario", "paper2015", "--human", "no_handover"])
    assert out.exit_code == 0, out.output
    assert "tasks per simulated hour" in out.output and "states" in out.output
    bad = CliRunner().invoke(app, ["oracle", "--human", "replay"])
    assert bad.exit_code == 2


@pytest.mark.slow
def test_roboergosum_no_handover() -> None:
    result = oracle_rate("roboergosum", "no_handover")
    assert result.converged and result.n_layouts == 5040 and result.rate_per_hour > 100


# One tape on the robot's mat; the human reaches nothing, so its only move is wait.
ALONE = parse_scenario(
    {
        "name": "alone",
        "robot_locations": ["bin_side", "table"],
        "handover_locations": ["table"],
        "robot_start": ["bin_side"],
        "objects": [{"name": "tape"}],
        "bins": [{"name": "bin", "robot_reach": ["bin_side"]}],
        "spots": [{"name": "mat", "robot_reach": ["table"]}],
        "layout": [{"count": 1, "spots": ["mat"]}],
    }
)


@pytest.mark.parametrize(("failed_actions", "transitions"), [(False, 14), (True, 20)])
def test_model_size_counts_every_option_including_a_failed_one_after_the_completing_wait(
    failed_actions: bool, transitions: int
) -> None:
    # Robot actions: pick, throw, give, take, goto(tape), goto(bin), goto(human), wait.
    # The six robot-turn states (tape where, robot where) and their feasible actions:
    #   mat,  bin_side: goto(tape), goto(human), wait      3
    #   mat,  table:    pick, goto(bin), wait              3
    #   hand, table:    give, goto(bin), wait              3  (the offer lapses on the human's wait)
    #   hand, bin_side: throw, goto(human), wait           3
    #   bin,  bin_side: goto(human), wait                  2
    #   bin,  table:    goto(bin), wait                    2
    # 16 options; the 2 waits on a clean table complete the task (terminal, no reply);
    # every other option has one reply (the human's wait): 14 transitions. With failed
    # actions each state also has one infeasible representative (every state has one),
    # listed after its feasible actions, so also after the completing wait: 6 more, 20.
    # The best cycle: goto 3 + pick 2 + goto 3 + throw 2 + completing wait 1 = 11 s.
    result = oracle_rate(World(ALONE), "no_handover", failed_actions=failed_actions)
    assert (result.n_states, result.n_transitions, result.n_layouts) == (6, transitions, 1)
    assert result.seconds_per_task == pytest.approx(11.0)
    assert result.rate_per_hour == pytest.approx(3600.0 / 11.0)


def test_low_memory_stops_the_build_with_the_limit_named() -> None:
    """Below 512 MB of available memory the build stops with one message naming it, the phase and the progress."""
    budget = Budget(free_memory=lambda: 100 * 2**20)
    with pytest.raises(OracleTooLarge) as refused:
        oracle_rate("roboergosum", "no_handover", budget=budget)
    message = str(refused.value)
    assert "less than 512 MB of memory left" in message and "\n" not in message
    assert "in phase 'layouts' (0 of 5,040 layouts)" in message  # the first memory reading refuses


def test_memory_is_read_again_while_the_model_grows() -> None:
    """Memory that runs low after the layouts stops the exploration at its next memory reading."""
    # plenty during the layouts (5,040 deals: one reading) and the first answers (one per 1,024 answers)
    readings = iter([8 * 2**30] * 7)
    budget = Budget(free_memory=lambda: next(readings, 100 * 2**20))
    with pytest.raises(OracleTooLarge, match=r"less than 512 MB of memory left in phase 'explore"):
        oracle_rate("roboergosum", "no_handover", budget=budget)


def test_the_progress_bar_ends_at_the_models_state_count(capsys: pytest.CaptureFixture[str]) -> None:
    # The bar counted states in blocks of 2048, so a model of a few hundred states ended at
    # "0 states"; its last frame must read the model's count, explored and known alike.
    result = oracle_rate("paper2015", "lazy", progress=True)
    frames = capsys.readouterr().err.replace("\r", "\n").splitlines()
    last = [f for f in frames if ": states" in f][-1]
    assert f" {result.n_states} states" in last and f"known={result.n_states}" in last


def test_an_oracle_robot_reset_on_other_durations_solves_that_table() -> None:
    from dataclasses import fields

    from hg_marl.core.durations import Durations

    base = World("paper2015")
    doubled = World("paper2015", Durations(**{f.name: 2 * getattr(base.durations, f.name) for f in fields(Durations)}))
    robot = OracleRobot(human="no_handover")
    robot.reset(base, Agent.ROBOT, np.random.default_rng(0))
    assert robot.result is not None
    once = robot.result.seconds_per_task
    robot.reset(doubled, Agent.ROBOT, np.random.default_rng(0))
    # every duration doubled: every cycle takes twice as long, the same policy is optimal
    assert robot.result.seconds_per_task == pytest.approx(2 * once, rel=1e-9)
    given = robot.result
    robot.reset(doubled, Agent.ROBOT, np.random.default_rng(0))  # the same table: kept
    assert robot.result is given


@pytest.mark.parametrize("scenario", ["paper2015", "asymmetric_advantages"])
def test_a_solve_from_one_table_gives_its_states_the_whole_models_values(scenario: str, tmp_path: Path) -> None:
    """``roots``: the states reachable from one table until a task is solved, each valued as in
    the model of every layout (the expected seconds to the next success do not depend on the
    tables drawn after it); fewer states, never cached, never reduced."""
    human = "preference:handover=-1.0,shared=1.0"
    whole = oracle_rate(scenario, human, cache=False, symmetry=False)
    table = World(scenario).initial_state(np.random.default_rng(3))
    part = oracle_rate(scenario, human, cache=str(tmp_path), roots=(table,))
    assert not part.reduced and part.n_layouts == 1 and 0 < part.n_states < whole.n_states
    assert not list(tmp_path.iterdir())  # nothing cached
    world = World(scenario)
    for state in part.values:
        assert part.value_at(world, state) == pytest.approx(whole.value_at(world, state), rel=1e-6)
    assert part.action_at(world, table) is not None and part.value_at(world, table) < np.inf
