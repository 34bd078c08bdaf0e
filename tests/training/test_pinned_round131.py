"""Values that round 131's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import hg_marl
from hg_marl.agents.humans.learned import LearnedHuman
from hg_marl.agents.model_file import save_model_file, world_fields
from hg_marl.agents.partner import PartnerMonitor
from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.base import LearningRobot
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.errors import ModelFileError
from hg_marl.policy import Turn
from hg_marl.training.play.stats import PlayStats, summarise
from hg_marl.wrappers import audit_v0


def test_the_habit_robot_acts_on_the_q_values_of_the_facts_it_sees() -> None:
    # Tabular habit (alpha 0.6, beta 50, Q = 0 at the start): acting in SOLVED_FROM, then ending the
    # run with reward 1, makes Q(SOLVED_FROM, first) = 0.6 and every other action's Q there 0. Asked
    # again in SOLVED_FROM, the Boltzmann policy puts 1 / (1 + 17 exp(-30)) on `first`: it is chosen.
    # (Proposing from any other facts, an unseen state, would draw uniformly among the 18.)
    world = World("paper2015")
    solved_from = State(where=(0, 2, 4), robot_at=1, offer_by=-1, offer_obj=-1)
    robot = make_robot("habit", share_objects=False, q_config={"features": "tabular"})
    assert isinstance(robot, LearningRobot)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))

    def turn(reward: float) -> Turn:
        observation = {"observation": world.facts(solved_from), "action_mask": world.mask(solved_from, Agent.ROBOT)}
        return Turn(world, solved_from, Agent.ROBOT, observation, reward=reward)

    first = robot.act(turn(0.0))
    robot.end(turn(1.0), terminated=True)
    assert [robot.act(turn(0.0)) for _ in range(3)] == [first] * 3


def test_a_table_policy_whose_facts_are_not_0_or_1_is_refused(tmp_path: Path) -> None:
    # The module docstring: "0/1 facts" are checked on load; a row holding -1 is no fact vector.
    # save_learned_policy refuses to write one, so the file is written as another tool would.
    world = World("paper2015")
    row = np.zeros(world.n_facts, dtype=np.int8)
    row[0] = -1
    (tmp_path / "p").mkdir()
    header = {**world_fields(world, Agent.HUMAN), "kind": "table"}
    save_model_file(tmp_path / "p" / "policy.json", header, {"facts": row[None, :], "actions": np.zeros(1, np.int64)})
    with pytest.raises(ModelFileError, match="table facts must be 0 or 1"):
        LearnedHuman(tmp_path / "p")


def test_an_unobserved_human_action_is_no_refusal_of_the_expected_one() -> None:
    # actual = -1 (nothing observed): the monitor learns nothing, even with block_after = 1.
    world = World("paper2015")
    give = next(i for i, a in enumerate(world.actions(Agent.HUMAN)) if a.kind is Kind.GIVE)
    monitor = PartnerMonitor(block_after=1, stall_after=1)
    monitor.observe(world, give, -1, solved=False)
    assert monitor.misses == 0 and monitor.refusals == {} and not monitor.blocked and not monitor.stalled


def test_the_summarys_handover_acceptance_is_the_mean_over_the_games() -> None:
    # Three games accepting 0, 0 and all offers: (0 + 0 + 1) / 3 = 1/3 (their median would be 0).
    games = [PlayStats("p", "planner", 4, 1, share, {"wait": 1.0}) for share in (0.0, 0.0, 1.0)]
    assert summarise(games)["handover_acceptance"] == pytest.approx(1 / 3)


def test_the_audit_counts_each_infeasible_action_not_just_the_first() -> None:
    # The robot sends an in-range action its real mask rules out at three robot turns in a row
    # (the human waits between them, so nothing changes): three infeasible actions.
    env = audit_v0(hg_marl.env())
    env.reset(seed=0)
    for _ in range(3):
        mask = env.unwrapped.observe("robot")["action_mask"]
        env.step(int(np.flatnonzero(mask == 0)[0]))
        env.step(int(np.flatnonzero(env.unwrapped.observe("human")["action_mask"])[-1]))
    assert env.sent == {"robot": 3, "human": 3}
    assert env.infeasible == {"robot": 3, "human": 0}
