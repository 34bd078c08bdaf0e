"""The belief robot: a posterior over a population's members, acting on their exact best responses."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from partners import PARTNERS, Fixed

from hg_marl.agents.humans import make_human
from hg_marl.agents.oracle import oracle_rate
from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.belief import BeliefRobot
from hg_marl.core import Agent, World
from hg_marl.core.errors import RobotError
from hg_marl.training.runner import RunConfig, run

FORCED = "forced_coordination"
HARD_LAYOUTS = Path(__file__).resolve().parents[2] / "populations" / "hard_layouts.toml"
MEMBERS = {
    "coop": ("train", "preference"),
    "mat": ("train", "preference:handover=-1.0,shared=1.0"),
    "idler": ("validation", "preference:p_idle=0.5,accept=0.3"),
    "other": ("held_out", "preference:handover=-0.5,shared=0.8,accept=0.2"),
}


def _population(tmp_path: Path, scenario: str = "paper2015") -> str:
    text = f'name = "t"\nscenario = "{scenario}"\n'
    for name, (split, spec) in MEMBERS.items():
        text += f'\n[[members]]\nname = "{name}"\nsplit = "{split}"\nspec = "{spec}"\n'
    path = tmp_path / "population.toml"
    path.write_text(text)
    return str(path)


def test_belief_follows_a_switch_within_the_bound_worked_by_hand(tmp_path: Path) -> None:
    """decay 0.9, epsilon 0.05, two members each sure of a different action.

    Each telling action moves the log-odds by L = log((0.95 + 0.05/n) / (0.05/n)). After
    many actions of A the odds saturate at -L / (1 - 0.9) = -10 L; after k actions of B
    they are 10 L (1 - 2 * 0.9**k), which passes log(9) (90% on B) at the first k with
    0.9**k <= (1 - log(9) / (10 L)) / 2.
    """
    robot = BeliefRobot(population=_population(tmp_path), splits="train", decay=0.9, epsilon=0.05, unknown=0.0)
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    feasible = world.feasible_indices(state, Agent.HUMAN)
    a, b = feasible[0], feasible[-1]
    post = robot.posterior
    post.humans = [Fixed(a), Fixed(b)]
    for _ in range(200):
        post.observe(world, state, -1, a)
    n = len(feasible)
    big_l = math.log((0.95 + 0.05 / n) / (0.05 / n))
    expected = next(k for k in range(1, 100) if 0.9**k <= (1 - math.log(9) / (10 * big_l)) / 2)
    steps = 0
    while post.posterior()[post.types[1]] < 0.9:
        post.observe(world, state, -1, b)
        steps += 1
    assert steps == expected


def test_the_open_world_posterior_worked_by_hand(tmp_path: Path) -> None:
    """Two members sure of action a, "none of them" (uniform) with prior u = 0.05.

    The partner does b != a. Each member gives it 0.05 / n, the uniform partner
    (0.95 + 0.05) / n = 1 / n: a likelihood ratio of 20 for "none of them". After one such
    action its posterior is 20 u / (20 u + (1 - u)) = 1 / 1.95, above each member's
    (1 - u) / 2 / 1.95: the robot hands over to the planner.
    """
    robot = BeliefRobot(population=_population(tmp_path), splits="train", decay=0.9, epsilon=0.05, unknown=0.05)
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    feasible = world.feasible_indices(state, Agent.HUMAN)
    a, b = feasible[0], feasible[-1]
    post = robot.posterior
    post.humans = [Fixed(a), Fixed(a), post.humans[-1]]  # the last is the uniform partner
    assert post.types[-1] == "random"
    post.observe(world, state, -1, b)
    got = post.posterior()
    assert got["random"] == pytest.approx(1 / 1.95)
    assert got[post.types[0]] == pytest.approx(0.95 / 2 / 1.95)


def _disagreeing_pair(n: int) -> float:
    """Nats told by two equally believed members each sure of a different one of ``n`` replies.

    With slack epsilon = 0.05 a member gives its reply q = 0.95 + 0.05/n and every other reply
    r = 0.05/n; the mixture gives the two replies (q + r)/2 each, the rest r. Mutual
    information = H(mixture) - H(member) (both members have the same entropy).
    """
    q, r = 0.95 + 0.05 / n, 0.05 / n

    def h(ps: list[float]) -> float:
        return -sum(p * math.log(p) for p in ps)

    return h([(q + r) / 2] * 2 + [r] * (n - 2)) - h([q] + [r] * (n - 1))


def test_the_information_of_a_reply_worked_by_hand(tmp_path: Path) -> None:
    """Two members, equally believed: one sure of reply a, the other of reply b.

    With n feasible replies and slack epsilon, member i gives its reply q = 0.95 + 0.05/n
    and every other reply r = 0.05/n. The mixture gives a and b (q + r)/2 each, the rest
    r. Mutual information = H(mixture) - H(member) (both members have the same entropy).
    A member set that agrees on every reply tells nothing: 0 nats.
    """
    robot = BeliefRobot(population=_population(tmp_path), splits="train", epsilon=0.05, unknown=0.0)
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    wait = world.n_actions(Agent.ROBOT) - 1
    mid, _, _ = world.table.successor(state, Agent.ROBOT, wait)
    replies = world.feasible_indices(mid, Agent.HUMAN)
    a, b = replies[0], replies[-1]
    robot.posterior.humans = [Fixed(a), Fixed(b)]
    assert robot.information(world, state, wait, [0.5, 0.5]) == pytest.approx(_disagreeing_pair(len(replies)))
    robot.posterior.humans = [Fixed(a), Fixed(a)]
    assert robot.information(world, state, wait, [0.5, 0.5]) == pytest.approx(0.0, abs=1e-12)


class _Seer:
    """A stand-in member that reads the robot's action: reply ``failed`` when it saw a failure (-1), else ``other``."""

    uses_robot_action = True

    def __init__(self, failed: int, other: int) -> None:
        self.failed, self.other = failed, other

    def distribution(self, world: World, state: object, robot_action: int = -1) -> list[tuple[int, float]]:
        return [(self.failed if robot_action == -1 else self.other, 1.0)]


def test_a_member_that_reads_the_robot_action_sees_a_failure_as_minus_one(tmp_path: Path) -> None:
    """A failing robot action is shown to the members as -1. The seer then replies a, the
    fixed member b: the two disagree, and the information is the worked value of the test
    above; had the seer been shown anything else, both would reply b (0 nats)."""
    robot = BeliefRobot(population=_population(tmp_path), splits="train", epsilon=0.05, unknown=0.0)
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    failing = next(
        a for a in range(world.n_actions(Agent.ROBOT)) if a not in world.feasible_indices(state, Agent.ROBOT)
    )
    mid, ok, _ = world.table.successor(state, Agent.ROBOT, failing)
    assert not ok
    replies = world.feasible_indices(mid, Agent.HUMAN)
    a, b = replies[0], replies[-1]
    robot.posterior.humans = [_Seer(a, b), Fixed(b)]
    assert robot.information(world, state, failing, [0.5, 0.5]) == pytest.approx(_disagreeing_pair(len(replies)))


def test_a_probe_costs_at_most_its_budget_and_no_budget_never_probes() -> None:
    import re

    config = RunConfig(scenario=FORCED, duration=900, seed=0)
    partner = "preference:handover=1.0,shared=-0.5,accept=0.3,p_idle=0.2"  # h_hesitant, held out
    never = run(make_robot("belief", population=str(HARD_LAYOUTS)), make_human(partner), config).log
    assert not never["reason"].str.startswith("probe").any()
    log = run(make_robot("belief", population=str(HARD_LAYOUTS), probe=20.0), make_human(partner), config).log
    probes = log.loc[log["reason"].str.startswith("probe"), "reason"]
    assert len(probes) > 0
    costs = [float(re.search(r"for (-?[\d.]+) s", x).group(1)) for x in probes]  # type: ignore[union-attr]
    assert all(0.0 <= c <= 20.0 for c in costs), costs


def test_a_partner_no_member_explains_is_left_to_the_planner() -> None:
    """On asymmetric_advantages, a partner who keeps to its own side and never hands over
    is none of the hard layouts' believed members; a believed one (t_giver) is."""
    config = RunConfig(scenario="asymmetric_advantages", duration=600, seed=0)

    def share(spec: str, **params: float) -> float:
        robot = make_robot("belief", population=str(HARD_LAYOUTS), **params)
        log = run(robot, make_human(spec), config).log
        return float(log["reason"].str.startswith("no member explains").mean())

    own_side = "preference:handover=-1.0,shared=-1.0,self_work=1.0,robot_side=-2.0"
    assert share(own_side) > 0.5
    assert share(own_side, unknown=0.0) == 0.0
    assert share("preference:handover=1.0,shared=-0.5") == 0.0


def test_a_robot_that_knows_its_partner_plays_near_its_best_response(tmp_path: Path) -> None:
    """Forced coordination with an idle partner who rarely accepts: the fixed-model planner
    waits at the handover place in vain; the belief robot identifies the member and plays
    its exact best response (within 10% of the oracle's expected tasks)."""
    population = _population(tmp_path, FORCED)
    partner = MEMBERS["idler"][1]
    config = RunConfig(scenario=FORCED, duration=1100, seed=0)
    oracle_tasks = oracle_rate(FORCED, partner).rate_per_hour * 1100 / 3600
    belief = run(make_robot("belief", population=population), make_human(partner), config)
    planner = run(make_robot("planner"), make_human(partner), config)
    assert belief.summary["tasks_solved"] >= 0.9 * oracle_tasks
    assert belief.summary["tasks_solved"] > planner.summary["tasks_solved"]
    assert belief.log["partner"].iloc[-1] == "idler"


@pytest.mark.parametrize("partner", sorted(PARTNERS))
def test_off_every_members_model_the_robot_keeps_solving(tmp_path: Path, partner: str) -> None:
    log = run(
        make_robot("belief", population=_population(tmp_path)), PARTNERS[partner](), RunConfig(duration=600, seed=0)
    ).log
    second_half = log[log["time"] > 300]
    assert second_half["tasks_solved"].max() > log[log["time"] <= 300]["tasks_solved"].max()


def test_bad_settings_are_one_line(tmp_path: Path) -> None:
    with pytest.raises(RobotError, match="population"):
        make_robot("belief")
    with pytest.raises(RobotError, match="hedge"):
        make_robot("belief", population=_population(tmp_path), hedge="maybe")
    with pytest.raises(RobotError, match="splits"):
        make_robot("belief", population=_population(tmp_path), splits=",")
    for bad in (1.0, -0.1, math.nan):
        with pytest.raises(RobotError, match="unknown"):
            make_robot("belief", population=_population(tmp_path), unknown=bad)
    for bad in (-1.0, math.inf, math.nan):
        with pytest.raises(RobotError, match="probe"):
            make_robot("belief", population=_population(tmp_path), probe=bad)


def test_the_readme_command_runs_as_written() -> None:
    import shlex
    import subprocess
    import sys

    from tests.docs_sections import section

    page = section("hard-layouts.md")
    line = next(x for x in page.splitlines() if x.startswith("hg-marl run --robot belief"))
    args = shlex.split(line)[1:]
    proc = subprocess.run(
        [sys.executable, "-c", "from hg_marl.training.cli import main; main()", *args],
        capture_output=True,
        text=True,
        timeout=600,
        cwd=Path(__file__).resolve().parents[2],
    )
    assert proc.returncode == 0, proc.stderr[-2000:]
    solved = int(next(x for x in proc.stdout.splitlines() if "tasks solved" in x).split()[-1])
    assert solved > 0
