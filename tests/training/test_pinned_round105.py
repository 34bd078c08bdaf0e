"""Values that round 105's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

import numpy as np
import pytest
import torch

from hg_marl.agents.headroom import JointModel
from hg_marl.agents.memory_policy import MemoryNet
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.oracle import oracle_rate
from hg_marl.agents.robots.uniform import RandomRobot
from hg_marl.core import Agent, World
from hg_marl.policy import decision_of
from tests.agents.test_meta import N, controller, plan, view
from tests.agents.test_oracle import TINY
from tests.training.test_pinned_round44 import _turn


def test_entropy_and_cost_reports_the_planners_own_entropy_beside_the_habits() -> None:
    # agents/meta/entropy_cost.py: before the planner was consulted in a state its distribution
    # there is the committed one, 1 - (N - 1) * 0.01 on one action and 0.01 on each other. For
    # N = 18 by hand: H = -(0.83 log2 0.83 + 17 * 0.01 log2 0.01) = 0.22312 + 1.12946 = 1.35257
    # bits, over log2 18 = 4.16993: 0.32436. A uniform habit's normalised entropy is 1.
    assert N == 18
    committed = -(0.83 * math.log2(0.83) + 17 * 0.01 * math.log2(0.01)) / math.log2(18)
    assert committed == pytest.approx(0.32436, abs=1e-5)
    mc = controller("entropy_and_cost")
    first = mc.decide(view(), plan())
    assert first.stats["h_habit"] == pytest.approx(1.0, abs=1e-12)
    assert first.stats["h_planner"] == pytest.approx(committed, abs=1e-12)
    assert first.record["h_planner"] == pytest.approx(committed, abs=1e-12)


def test_the_python_joint_models_first_answers_see_the_robots_completing_wait() -> None:
    # The robot completes a table with its wait, so a partner that reads the robot's action gives
    # its first answer on the re-drawn table having seen that wait (the array builder's re-draw
    # does). The noisy human scores each answer by the cycle it makes, max(d_robot, d_human)
    # plus what is left: with a 3 s wait, every answer of 3 s or less makes a 3 s cycle, so what
    # it saw changes its first answers' probabilities and so the rate. The control is the
    # oracle's optimum (its model is built on arrays, another enumeration): the policy optimal
    # against the partner, played with it, reaches it.
    scenario = dataclasses.replace(TINY, durations=dataclasses.replace(TINY.durations, wait=3.0))
    world = World(scenario)
    model = JointModel(world, [stationary_human("noisy", world)])
    assert float(model.chain(0).regen_prob.sum()) == pytest.approx(1.0, abs=1e-12)
    expected = oracle_rate(world, "noisy", cache=None).rate_per_hour
    assert expected > 0
    assert model.rate(model.optimal_policy(0), 0) == pytest.approx(expected, rel=1e-9)


def test_a_fresh_memory_nets_first_policy_is_nearly_uniform() -> None:
    # The actor starts small (orthogonal weights of gain 0.01, zero bias: the usual PPO start), so
    # the first policy explores evenly. Property of an orthogonal (n_actions x hidden) matrix of
    # gain g, n_actions <= hidden: its rows are orthogonal of norm g, W W^T = g^2 I = 1e-4 I. The
    # encoder ends in tanh, so |x| < sqrt(hidden) = 8 and each logit is below 0.08 in size: every
    # feasible action's probability is within a factor exp(0.16) of uniform.
    torch.manual_seed(0)
    net = MemoryNet(10, 6, hidden=64, recurrent=True)
    weight = net.actor.weight.detach()
    torch.testing.assert_close(weight @ weight.T, 1e-4 * torch.eye(6), atol=1e-9, rtol=0.0)
    assert torch.count_nonzero(net.actor.bias) == 0
    obs = torch.rand((32, 10), generator=torch.Generator().manual_seed(1))
    with torch.no_grad():
        logits, _, _ = net.step(obs, net.initial(32))
        probs = MemoryNet.masked(logits, torch.ones_like(logits, dtype=torch.bool)).probs
    assert float(probs.max()) < math.exp(0.16) / 6 and float(probs.min()) > math.exp(-0.16) / 6


def test_the_random_robots_record_names_the_action_it_played() -> None:
    # hg_marl.policy.Decision.action: "The executed action's index". At paper2015's start the robot
    # has several feasible actions; over 40 seeded turns it plays more than one of them (the odds
    # of one action 40 times: 4 * (1/4) ** 40 at most), and each turn's record names that turn's.
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    mask = world.mask(state, Agent.ROBOT)
    robot = RandomRobot()
    robot.reset(world, Agent.ROBOT, np.random.default_rng(4))
    played = []
    for _ in range(40):
        action = robot.act(_turn(world, state, mask))
        record = decision_of(robot)
        assert (record.expert, record.action) == ("random", action)
        played.append(action)
    assert len(set(played)) > 1


def test_a_recurrent_sb3_models_header_lists_every_partner_it_trained_with(tmp_path: Path) -> None:
    # training/baselines/recurrent_ppo_sb3.py trains against a partner drawn from ``humans`` per
    # episode, and the model file's header says with which: here both of them, in order.
    pytest.importorskip("sb3_contrib")
    from hg_marl.training.baselines.recurrent_ppo_sb3 import train
    from tests.training.test_recurrent_ppo_sb3 import _config

    config = _config(tmp_path, humans=("preference", "cooperative"), steps=1, num_envs=2, n_steps=4, batch_size=8)
    result = train(config)
    header = json.loads(result.path.read_text())
    assert header["partners"] == ["preference", "cooperative"]
    assert header["algo"] == "RecurrentPPO"
