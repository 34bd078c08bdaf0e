"""Round 51's missed planted bugs, pinned (see mutation/README.md, "Fresh planted bugs")."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.robots.sb3 import SB3Robot
from hg_marl.agents.views import RobotView
from hg_marl.core import Agent, World
from hg_marl.policy import Turn
from hg_marl.training.baselines.bc import behaviour_clone

try:  # imported here, not in the test, so that the test times only what it runs
    import torch
    from stable_baselines3 import DQN
except ImportError:  # the behaviour-cloning test needs neither
    torch = None  # type: ignore[assignment]

SCENARIO = "paper2015"
WORLD = World(SCENARIO)


def test_a_sampling_dqn_robot_stays_greedy_even_while_its_model_would_explore() -> None:
    # agents/robots/sb3.py's docstring: "DQN has no distribution and always acts greedily"
    # (deterministic=False samples only where the policy has a distribution). A DQN's own
    # predict(deterministic=False) is epsilon-greedy with its exploration_rate; set to 1 (as
    # at the start of training) it draws uniformly among the 31 robot actions. The expected
    # action is computed here without predict: the argmax of the Q-network's values on the
    # facts. Twelve tables all matching by chance under uniform draws: about 31 ** -12.
    if torch is None:
        pytest.skip("needs stable_baselines3 and torch")
    torch.set_num_threads(1)
    model: Any = DQN("MlpPolicy", RobotView(SCENARIO), buffer_size=100, learning_starts=0, seed=0, device="cpu")
    model.exploration_rate = 1.0
    robot = SB3Robot(model=model, observation="facts", deterministic=False)
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    for seed in range(12):
        state = WORLD.initial_state(np.random.default_rng(seed))
        facts = WORLD.facts(state)
        with torch.no_grad():
            q = model.q_net(torch.as_tensor(np.asarray(facts, dtype=np.float32)).reshape(1, -1))
        greedy = int(q.argmax(dim=1).item())
        obs = {"observation": facts, "action_mask": WORLD.mask(state, Agent.ROBOT)}
        assert robot.act(Turn(WORLD, state, Agent.ROBOT, obs)) == greedy


@pytest.mark.parametrize("extra", [-1, 1])
def test_traces_recording_another_action_count_than_the_scenario_are_refused(tmp_path: Path, extra: int) -> None:
    # training/baselines/bc.py's behaviour_clone: "ValueError: ... names that differ from the
    # scenario's". paper2015's human seat has 24 facts and 31 actions (counted from the
    # World); a trace whose masks hold 30 or 32 entries (the facts right) must be refused
    # naming both counts, not cloned into a policy of the wrong shape.
    n_facts, n_actions = WORLD.n_facts, WORLD.n_actions(Agent.HUMAN)
    assert (n_facts, n_actions) == (24, 31)
    recorded = n_actions + extra
    names = list(WORLD.action_names[Agent.HUMAN])
    names = names[:recorded] if extra < 0 else [*names, "extra"]
    head = {
        "type": "header",
        "format": "hg_marl.trace",
        "version": 1,
        "episode": 0,
        "scenario": SCENARIO,
        "seat": "human",
        "actor": "hand",
        "fact_names": list(WORLD.fact_names),
        "action_names": names,
        "meta": {},
    }
    step = {
        "type": "step",
        "step": 0,
        "clock": 0.0,
        "tasks_solved": 0,
        "facts": [0] * n_facts,
        "mask": [1] * recorded,
        "action": 0,
    }
    trace = tmp_path / "t.jsonl"
    trace.write_text(json.dumps(head) + "\n" + json.dumps(step) + "\n", encoding="utf-8")
    message = f"traces do not match scenario 'paper2015': 24 facts and {recorded} actions recorded, 24 and 31 expected"
    with pytest.raises(ValueError, match=message):
        behaviour_clone([trace], tmp_path / "out")
    assert not (tmp_path / "out").exists()
