"""Values that round 104's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.compiled import compile_human
from hg_marl.agents.robots.belief import BeliefRobot
from hg_marl.core import Agent, World
from hg_marl.envs.batched import BatchState
from hg_marl.envs.table_cleaning import raw_env
from tests.agents.partners import Fixed
from tests.population_files import train_members


def test_the_information_weighs_the_members_by_their_share_of_the_kept_mass(tmp_path: Path) -> None:
    # Two members believed 0.3 each (the other 0.4 on "none of them"), one sure of reply a, the
    # other of reply b: the information is about which member, so only their relative weights
    # count, 1/2 each. With n replies and eps 0.05 a member gives its reply q = 0.95 + 0.05/n and
    # r = 0.05/n elsewhere; the mixture gives a and b (q + r)/2 each, the rest r, and
    # I = H(mixture) - H(member).
    robot = BeliefRobot(population=train_members(tmp_path, a="cooperative", b="lazy"), splits="train", unknown=0.0)
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    wait = world.n_actions(Agent.ROBOT) - 1
    mid, _, _ = world.table.successor(state, Agent.ROBOT, wait)
    replies = world.feasible_indices(mid, Agent.HUMAN)
    n = len(replies)
    assert n >= 2
    q, r = 0.95 + 0.05 / n, 0.05 / n

    def h(ps: list[float]) -> float:
        return -sum(p * math.log(p) for p in ps)

    expected = h([(q + r) / 2] * 2 + [r] * (n - 2)) - h([q] + [r] * (n - 1))
    robot.posterior.humans = [Fixed(replies[0]), Fixed(replies[-1])]
    assert robot.information(world, state, wait, [0.3, 0.3]) == pytest.approx(expected, rel=1e-12)
    assert robot.information(world, state, wait, [0.5, 0.5]) == pytest.approx(expected, rel=1e-12)


def test_the_live_fallback_draws_each_of_two_answers_with_its_probability() -> None:
    # The registry's lazy human (p_idle 0.3 by default) at the initial table of seed 0 answers its
    # cooperative move with probability 0.7 and waits with 0.3. The human's own offer of the last
    # object is outside its compiled table (its packed key sorts past every key), so each of 400
    # such tables is answered by the live human: the waits are Binomial(400, 0.3), mean 120, sd 9.2;
    # 80-160 is over four sd either side.
    world = World("paper2015")
    table = compile_human(world, "lazy", cache=None)
    state = world.initial_state(np.random.default_rng(0))
    batch = BatchState.of([state] * 400)
    batch.offer_by[:], batch.offer_obj[:] = 1, world.table.n_objects - 1
    assert (table.packer.pack(batch, np.full(400, -1)) > table.keys.max()).all()  # the premise
    live = dict(table.human.distribution(world, batch.state(0), -1))
    wait = world.n_actions(Agent.HUMAN) - 1
    assert len(live) == 2 and live[wait] == pytest.approx(0.3)
    (move,) = set(live) - {wait}
    actions = table.act(batch, np.full(400, -1), np.random.default_rng(0)).tolist()
    assert table.fallbacks == 400
    assert set(actions) == {move, wait}
    assert 80 <= actions.count(wait) <= 160


def test_the_robots_info_after_its_move_holds_its_own_idle_seconds() -> None:
    # paper2015, seed 0: in cycle 1 the robot waits (1 s) while the human picks (2 s), so the cycle
    # lasts 2 s, the robot idles 2 s (it waited the whole cycle) and the human 0 s. After the
    # robot's move of cycle 2 its info still reads the clock and idle of the end of cycle 1:
    # idle 2.0 (the human's would be 0.0).
    env = raw_env(scenario="paper2015")
    env.reset(seed=0)
    robot_wait = len(env.action_names("robot")) - 1
    human_names = env.action_names("human")
    env.step(robot_wait)
    pick = next(i for i in np.flatnonzero(env.observe("human")["action_mask"]) if human_names[i].startswith("pick"))
    env.step(int(pick))
    assert env.infos["robot"]["idle"] == 2.0 and env.infos["human"]["idle"] == 0.0
    env.step(robot_wait)
    info = env.infos["robot"]
    assert (info["clock"], info["cycle"], info["idle"], info["effort"]) == (2.0, 1, 2.0, 0.0)
